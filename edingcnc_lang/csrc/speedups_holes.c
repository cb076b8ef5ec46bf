/* Part of _speedups.c (one translation unit: included there, in this order). Runs of hole lines: the moves
 * of the holes that lines naming only the next hole drill (machine/hole_runs.py's hole_moves). */

#define HOLE_NUMBER_BUFFER 1024  /* a plain line's number has at most 1 + 300 + 1 + 400 characters */

/* The number text s[start:end] as Python's float() reads it; 0 if it is none. */
static int hole_number(const char *s, Py_ssize_t start, Py_ssize_t end, double *value)
{
    char small[HOLE_NUMBER_BUFFER], *buffer = small, *stop;
    Py_ssize_t size = end - start;
    int ok;
    if (size >= HOLE_NUMBER_BUFFER && (buffer = PyMem_Malloc((size_t)size + 1)) == NULL)
        return 0;
    memcpy(buffer, s + start, (size_t)size);
    buffer[size] = '\0';
    *value = PyOS_string_to_double(buffer, &stop, NULL);
    ok = !(*value == -1.0 && PyErr_Occurred()) && *stop == '\0';
    PyErr_Clear();
    if (buffer != small)
        PyMem_Free(buffer);
    return ok;
}

/* One hole line's words: 1 if it holds an N word first (or not) and then words of the letters a and b only,
 * at least one, each once (no comment); value[k] and have[k] say what the line gives the axis a (k = 0) and
 * b (k = 1).  0 for any other line. */
static int hole_words(const char *s, Py_ssize_t len, char a, char b, double value[2], int have[2])
{
    Py_ssize_t i = 0, start;
    int words = 0, slot;
    double number;
    have[0] = have[1] = 0;
    for (;;) {
        char letter;
        while (i < len && (s[i] == ' ' || s[i] == '\t'))
            i++;
        if (i == len)
            return have[0] || have[1];
        letter = s[i] >= 'a' && s[i] <= 'z' ? (char)(s[i] - 'a' + 'A') : s[i];
        if (letter == 'N' && words == 0)
            slot = -1;
        else if (letter == a || letter == b)
            slot = letter == a ? 0 : 1;
        else
            return 0;
        if (slot >= 0 && have[slot])
            return 0;
        for (i++; i < len && (s[i] == ' ' || s[i] == '\t'); i++)
            ;
        start = i;
        if (i < len && (s[i] == '+' || s[i] == '-'))
            i++;
        while (i < len && ((s[i] >= '0' && s[i] <= '9') || s[i] == '.'))
            i++;
        if (!hole_number(s, start, i, &number))
            return 0;
        if (slot >= 0) {
            have[slot] = 1;
            value[slot] = number;
        }
        words++;
    }
}

/* A pose of six float objects shared with other poses (a hole's moves share its position, the holes their
 * levels): new references to them, as pose_tuple's, not tracked by the collector. */
static PyObject *shared_pose(PyObject *const values[6])
{
    PyObject *tuple = PyTuple_New(6);
    Py_ssize_t k;
    if (tuple == NULL)
        return NULL;
    for (k = 0; k < 6; k++) {
        Py_INCREF(values[k]);
        PyTuple_SetItem(tuple, k, values[k]);
    }
    PyObject_GC_UnTrack(tuple);
    return tuple;
}

/* Replace *slot by a new float object of ``value``: -1 if it cannot be made. */
static int set_float(PyObject **slot, double value)
{
    PyObject *made = PyFloat_FromDouble(value);
    if (made == NULL)
        return -1;
    Py_XDECREF(*slot);
    *slot = made;
    return 0;
}

static PyObject *hole_moves(PyObject *self, PyObject *args)
{
    PyObject *lines, *pos_obj, *offset_obj, *levels_obj, *lines_of = NULL, *ends = NULL, **level_objects = NULL;
    PyObject *pose[6] = {NULL, NULL, NULL, NULL, NULL, NULL};
    Py_ssize_t first, stop, index, count, k;
    int a1, a2, normal, incremental, steady = 1, holes = 0;
    double scale, pos[6], offset[6], rest[6];
    char letter1, letter2;
    (void)self;
    if (!PyArg_ParseTuple(args, "Onn(iii)OOdpO", &lines, &first, &stop, &a1, &a2, &normal, &pos_obj, &offset_obj,
                          &scale, &incremental, &levels_obj))
        return NULL;
    if (read_six(pos_obj, pos) < 0 || read_six(offset_obj, offset) < 0)
        return NULL;
    if (a1 < 0 || a1 > 2 || a2 < 0 || a2 > 2 || normal < 0 || normal > 2) {
        PyErr_SetString(PyExc_ValueError, "the plane's axes are X, Y or Z");
        return NULL;
    }
    if ((count = PySequence_Size(levels_obj)) < 0)
        return NULL;
    if ((level_objects = PyMem_Calloc((size_t)(count ? count : 1), sizeof(PyObject *))) == NULL)
        return PyErr_NoMemory();
    for (k = 0; k < count; k++) {  /* the levels as float objects, shared by every hole */
        PyObject *item = PySequence_GetItem(levels_obj, k);
        double level;
        if (item == NULL)
            goto fail;
        level = PyFloat_AsDouble(item);
        Py_DECREF(item);
        if ((level == -1.0 && PyErr_Occurred()) || (level_objects[k] = PyFloat_FromDouble(level)) == NULL)
            goto fail;
    }
    letter1 = "XYZ"[a1];
    letter2 = "XYZ"[a2];
    /* the other axes stay, each at the work position plus the offset, as the general path writes them */
    for (k = 3; k < 6; k++) {
        rest[k] = (pos[k] - offset[k]) + offset[k];
        steady = steady && (rest[k] - offset[k]) + offset[k] == rest[k];
    }
    if (stop > PySequence_Size(lines))
        stop = PySequence_Size(lines);
    if (stop < 0 || (lines_of = PyList_New(0)) == NULL || (ends = PyList_New(0)) == NULL)
        goto fail;
    for (index = first; index < stop; index++) {
        PyObject *pair = PySequence_GetItem(lines, index), *lineno = NULL, *text = NULL, *keep;
        const char *s;
        Py_ssize_t len;
        double value[2], w1, w2;
        int have[2], hole;
        if (pair == NULL)
            goto fail;
        lineno = PySequence_GetItem(pair, 0);
        text = PySequence_GetItem(pair, 1);
        Py_DECREF(pair);
        s = lineno == NULL || text == NULL ? NULL : utf8_pass(text, &len, &keep);
        if (s == NULL) {
            Py_XDECREF(lineno);
            Py_XDECREF(text);
            goto fail;
        }
        hole = hole_words(s, len, letter1, letter2, value, have);
        Py_XDECREF(keep);
        Py_DECREF(text);
        if (!hole) {
            Py_DECREF(lineno);
            break;
        }
        w1 = have[0] && !incremental ? value[0] * scale : pos[a1] - offset[a1];
        if (have[0] && incremental)
            w1 = w1 + value[0] * scale;
        w2 = have[1] && !incremental ? value[1] * scale : pos[a2] - offset[a2];
        if (have[1] && incremental)
            w2 = w2 + value[1] * scale;
        pos[a1] = w1 + offset[a1];
        pos[a2] = w2 + offset[a2];
        if (holes && !steady)
            for (k = 3; k < 6; k++)
                rest[k] = (rest[k] - offset[k]) + offset[k];
        if (set_float(&pose[a1], pos[a1]) < 0 || set_float(&pose[a2], pos[a2]) < 0) {
            Py_DECREF(lineno);
            goto fail;
        }
        for (k = 3; k < 6; k++)
            if ((!holes || !steady) && set_float(&pose[k], rest[k]) < 0) {
                Py_DECREF(lineno);
                goto fail;
            }
        holes++;
        for (k = 0; k < count; k++) {
            Py_XDECREF(pose[normal]);
            Py_INCREF(level_objects[k]);
            pose[normal] = level_objects[k];
            if (PyList_Append(lines_of, lineno) < 0 || append_new(ends, shared_pose(pose)) < 0) {
                Py_DECREF(lineno);
                goto fail;
            }
        }
        Py_DECREF(lineno);
    }
    for (k = 0; k < 6; k++)
        Py_XDECREF(pose[k]);
    for (k = 0; k < count; k++)
        Py_XDECREF(level_objects[k]);
    PyMem_Free(level_objects);
    return Py_BuildValue("nNN", index, lines_of, ends);
fail:
    for (k = 0; k < 6; k++)
        Py_XDECREF(pose[k]);
    if (level_objects != NULL)
        for (k = 0; k < count; k++)
            Py_XDECREF(level_objects[k]);
    PyMem_Free(level_objects);
    Py_XDECREF(lines_of);
    Py_XDECREF(ends);
    return NULL;
}
