/* Part of _speedups.c (one translation unit: included there, in this order). Runs of arc lines (plain_arcs). */

/* ---------------------------------------------------------------- plain arcs
 * machine/bulk.py's BulkPath._arc_of_words, compiled: the words of the line, its target (as plain_moves finds
 * it), the centre from centre words or R, the radius check, the sweep and the length of machine/geometry.py's
 * center_from_radius, check_radius and sweep.  Every double is computed as Python computes it:
 * math.hypot and math.dist are CPython's vector_norm (speedups_math.c; not libm's hypot, which rounds differently),
 * atan2 is CPython's m_atan2 and % is float's remainder. */

/* (a, b) as a new tuple of two floats; NULL with an error set. */
static PyObject *pair_tuple(double a, double b)
{
    PyObject *pair = PyTuple_New(2), *first = PyFloat_FromDouble(a), *second = PyFloat_FromDouble(b);
    if (pair == NULL || first == NULL || second == NULL) {
        Py_XDECREF(pair);
        Py_XDECREF(first);
        Py_XDECREF(second);
        return NULL;
    }
    PyTuple_SetItem(pair, 0, first);
    PyTuple_SetItem(pair, 1, second);
    return pair;
}

/* The names of canon.Arc's fields, in order (set in PyInit__speedups). */
static PyObject *arc_fields[4];

/* How each of canon.Arc's fields is set past the frozen __setattr__: by its slot's member descriptor (what
   PyObject_GenericSetAttr finds and calls, found once per run of lines), else the generic way (setter NULL). */
struct arc_setters {
    PyObject *descr[4];
    descrsetfunc set[4];
};

static void find_setters(PyObject *cls, struct arc_setters *out)
{
    int k;
    for (k = 0; k < 4; k++) {
        out->descr[k] = PyObject_GetAttr(cls, arc_fields[k]);
        out->set[k] = out->descr[k] == NULL ? NULL : (descrsetfunc)PyType_GetSlot(Py_TYPE(out->descr[k]),
                                                                                  Py_tp_descr_set);
    }
    PyErr_Clear();  /* a field without a class attribute is set the generic way */
}

static void release_setters(struct arc_setters *setters)
{
    int k;
    for (k = 0; k < 4; k++)
        Py_CLEAR(setters->descr[k]);
}

/* A canon.Arc record made as its own __init__ makes it: each field set past the frozen __setattr__.
   Steals the references to the values (any may be NULL after a failure: then nothing is made). */
static PyObject *new_arc(PyObject *cls, const struct arc_setters *setters, PyObject *center, PyObject *plane,
                         PyObject *turn, PyObject *full)
{
    PyObject *values[4] = {center, plane, turn, full}, *made = NULL;
    int k;
    if (center != NULL && plane != NULL && turn != NULL && full != NULL)
        made = PyType_GenericAlloc((PyTypeObject *)cls, 0);
    for (k = 0; made != NULL && k < 4; k++)
        if ((setters->set[k] != NULL ? setters->set[k](setters->descr[k], made, values[k])
             : PyObject_GenericSetAttr(made, arc_fields[k], values[k])) < 0)
            Py_CLEAR(made);
    for (k = 0; k < 4; k++)
        Py_XDECREF(values[k]);
    /* a frozen record of a pair of floats, a str and two ints can be in no reference cycle: the collector need
       not walk the thousands a job keeps (as pose_tuple's poses) */
    if (made != NULL) {
        PyObject_GC_UnTrack(made);
        PyObject_GC_UnTrack(center);
    }
    return made;
}

/* machine/geometry.py's center_from_radius: the centre of the arc from (s1, s2) to (e1, e2) with signed
   radius r (negative: more than half a circle).  1 with the centre, 0 when there is none (the Python
   function's ArcError), -1 on an error.  cos, sin and asin are the C library's, as math's are. */
static int centre_from_radius(double s1, double s2, double e1, double e2, double r, int clockwise, double tolerance,
                              double tiny, double *c1, double *c2)
{
    double chord, abs_r = fabs(r), mid1 = (s1 + e1) / 2.0, mid2 = (s2 + e2) / 2.0, half, theta, offset;
    if (py_hypot(e1 - s1, e2 - s2, &chord) < 0)
        return -1;
    if (chord < tiny)
        return 0;
    if (py_hypot(mid1 - e1, mid2 - e2, &half) < 0)
        return -1;
    if (half - abs_r > tolerance || abs_r == 0.0)
        return 0;
    if (half / abs_r > 1.0 - tiny)
        half = abs_r;
    theta = py_atan2(e2 - s2, e1 - s1) + (clockwise == (r > 0) ? -M_PI / 2 : M_PI / 2);
    offset = abs_r * cos(asin(half / abs_r));
    *c1 = mid1 + offset * cos(theta);
    *c2 = mid2 + offset * sin(theta);
    return 1;
}

#define G2 20
#define G3 30
#define SEEN(letter) seen[(letter) - 'A']
#define VALUE(letter) value[(letter) - 'A']

/* What stays the same over a run of arc lines (the state the bulk path reads cannot change within a run). */
struct arc_setting {
    double offset[6], scale, tolerance, epsilon, tiny;
    int incremental, plane, reverse;
    PyObject *arc_class, *plane_name;
    struct arc_setters setters;
};

/* One arc line from start: 1 an arc (target, a new canon.Arc in *arc, its length; *motion and *feed those in
   force after it), 0 not a simple arc (the Python None), 2 a line the scan cannot read (False: the Python
   reference reads it), -1 an error. */
static int read_arc_line(PyObject *text, const double *start, const struct arc_setting *set, int *motion_io,
                         double *feed_io, double *target, PyObject **arc, double *length)
{
    /* plane: 0 XY, 1 XZ, 2 YZ (PLANES order: first, second in-plane axes) */
    static const int first_axis[3] = {0, 2, 1}, second_axis[3] = {1, 0, 2}, normal_axis[3] = {2, 1, 0};
    static const char first_word[3] = {'I', 'K', 'J'}, second_word[3] = {'J', 'I', 'K'};
    PyObject *keep;
    const char *s;
    Py_ssize_t len;
    double value[26], scale = set->scale, tolerance = set->tolerance, tiny = set->tiny, feed = *feed_io;
    double s1, s2, e1, e2, c1, c2, r1, r2, a0, a1, delta, dist;
    int seen[26] = {0}, motion = *motion_io, plane = set->plane, clockwise, full, k, axes = 0, centre_words;
    s = utf8_pass(text, &len, &keep);
    if (s == NULL)
        return -1;
    k = scan_words(s, len, value, seen);
    Py_XDECREF(keep);
    if (!k)
        return 2;
    if (SEEN('G')) {
        double g = VALUE('G');
        motion = g == 2.0 ? G2 : g == 3.0 ? G3 : NO_MOTION;
    }
    for (k = 0; k < 26; k++) {
        char letter = (char)('A' + k);
        if (!seen[k] || letter == 'G' || letter == 'N' || letter == 'F')
            continue;
        if (strchr("XYZABC", letter) != NULL)
            axes = 1;
        else if (letter != 'R' && letter != first_word[plane] && letter != second_word[plane])
            return 0;
    }
    if ((motion != G2 && motion != G3) || !axes)
        return 0;
    if (SEEN('F')) {
        if (VALUE('F') < 0)
            return 0;
        feed = VALUE('F') * scale;
    }
    centre_words = SEEN(first_word[plane]) || SEEN(second_word[plane]);
    if (feed <= 0 || (SEEN('R') ? centre_words : !centre_words))
        return 0;
    memcpy(target, start, 6 * sizeof(double));
    for (k = 0; k < 6; k++) {
        char letter = "XYZABC"[k];
        if (SEEN(letter)) {
            double number = VALUE(letter) * (k < 3 ? scale : 1.0);
            target[k] = set->incremental ? start[k] + number : number + set->offset[k];
        }
    }
    s1 = start[first_axis[plane]];
    s2 = start[second_axis[plane]];
    e1 = target[first_axis[plane]];
    e2 = target[second_axis[plane]];
    clockwise = (motion == G2) != set->reverse;
    if (SEEN('R')) {
        int found = centre_from_radius(s1, s2, e1, e2, VALUE('R') * scale, clockwise, tolerance, tiny, &c1, &c2);
        if (found <= 0)
            return found;  /* 0: no circle, the general path reports it */
        if (py_hypot(s1 - c1, s2 - c2, &r1) < 0)
            return -1;
    } else {
        c1 = s1 + (SEEN(first_word[plane]) ? VALUE(first_word[plane]) : 0.0) * scale;
        c2 = s2 + (SEEN(second_word[plane]) ? VALUE(second_word[plane]) : 0.0) * scale;
        if (py_hypot(s1 - c1, s2 - c2, &r1) < 0 || py_hypot(e1 - c1, e2 - c2, &r2) < 0)
            return -1;
        if (r1 < tiny || fabs(r1 - r2) > tolerance)  /* manual p. 20: 0.002 mm, whatever the radius */
            return 0;  /* the general path reports it */
    }
    a0 = py_atan2(s2 - c2, s1 - c1);
    a1 = py_atan2(e2 - c2, e1 - c1);
    delta = py_mod(clockwise ? a0 - a1 : a1 - a0, 2 * M_PI);
    full = delta == 0.0;
    if (!full && !SEEN('R') && delta < set->epsilon) {  /* the chord only matters for an arc this close to a full circle */
        if (py_hypot(s1 - e1, s2 - e2, &dist) < 0)
            return -1;
        full = dist <= tolerance;
    }
    /* machine/state.py's path_length, the helix GetJobDistance counts: the angle turned is delta (a turn of
       -1 makes (a1 - a0) * turn the a0 - a1 above), a full circle one more turn */
    if (py_hypot(r1 * (delta + 2 * M_PI * (double)full), target[normal_axis[plane]] - start[normal_axis[plane]],
                 length) < 0)
        return -1;
    /* the centre named in the plane's name order: XZ is (x, z), its axes run (z, x) */
    Py_INCREF(set->plane_name);
    *arc = new_arc(set->arc_class, &set->setters, pair_tuple(plane == 1 ? c2 : c1, plane == 1 ? c1 : c2), set->plane_name,
                   PyLong_FromLong(clockwise ? -1 : 1), PyLong_FromLong(full));
    if (*arc == NULL)
        return -1;
    *motion_io = motion;
    *feed_io = feed;
    return 1;
}

static int check_plane(int plane)
{
    if (plane >= 0 && plane <= 2)
        return 0;
    PyErr_SetString(PyExc_ValueError, "plane must be 0 (XY), 1 (XZ) or 2 (YZ)");
    return -1;
}

/* machine/bulk.py's arc_run, compiled: the arc lines of lines[first:] (pairs of line number and text) one after
   another, at most room of them, each as BulkPath._arc_of_words reads it (read_arc_line), as columns: (index of the first line not taken,
   whether that line was scanned (False: the Python reference reads it), the motion and feed in force,
   line numbers, ends, feeds, arcs, lengths). */
static PyObject *plain_arcs(PyObject *self, PyObject *args)
{
    PyObject *lines, *start_obj, *offset_obj, *numbers = NULL, *ends = NULL, *feeds = NULL, *arcs = NULL;
    PyObject *lengths = NULL;
    struct arc_setting set;
    Py_ssize_t first, room, count, index;
    double position[6], feed;
    int motion, scanned = 1;
    (void)self;
    if (!PyArg_ParseTuple(args, "OnOOdpidnipdddO!U", &lines, &first, &start_obj, &offset_obj, &set.scale,
                          &set.incremental, &motion, &feed, &room, &set.plane, &set.reverse, &set.tolerance,
                          &set.epsilon, &set.tiny, &PyType_Type, &set.arc_class, &set.plane_name))
        return NULL;
    if (check_plane(set.plane) < 0 || read_six(start_obj, position) < 0 || read_six(offset_obj, set.offset) < 0)
        return NULL;
    count = PySequence_Size(lines);
    if (count < 0)
        return NULL;
    find_setters(set.arc_class, &set.setters);
    numbers = PyList_New(0);
    ends = PyList_New(0);
    feeds = PyList_New(0);
    arcs = PyList_New(0);
    lengths = PyList_New(0);
    if (!numbers || !ends || !feeds || !arcs || !lengths)
        goto fail;
    for (index = first; index < count && index - first < room; index++) {
        PyObject *pair = PySequence_GetItem(lines, index), *lineno, *text, *arc = NULL;
        double target[6], length;
        int found;
        if (pair == NULL)
            goto fail;
        lineno = PySequence_GetItem(pair, 0);
        text = PySequence_GetItem(pair, 1);
        Py_DECREF(pair);
        if (lineno == NULL || text == NULL || !PyUnicode_Check(text)) {
            if (text != NULL && lineno != NULL)
                PyErr_SetString(PyExc_TypeError, "a line's text must be str");
            Py_XDECREF(lineno);
            Py_XDECREF(text);
            goto fail;
        }
        found = read_arc_line(text, position, &set, &motion, &feed, target, &arc, &length);
        Py_DECREF(text);
        if (found != 1) {
            Py_DECREF(lineno);
            if (found < 0)
                goto fail;
            scanned = found == 0;
            break;
        }
        if (append_new(arcs, arc) < 0 || append_new(numbers, lineno) < 0 || append_new(ends, pose_tuple(target)) < 0
            || append_new(feeds, PyFloat_FromDouble(feed)) < 0 || append_new(lengths, PyFloat_FromDouble(length)) < 0)
            goto fail;
        memcpy(position, target, sizeof position);
    }
    release_setters(&set.setters);
    return Py_BuildValue("nNidNNNNN", index, PyBool_FromLong(scanned), motion, feed, numbers, ends, feeds, arcs,
                         lengths);
fail:
    release_setters(&set.setters);
    Py_XDECREF(numbers);
    Py_XDECREF(ends);
    Py_XDECREF(feeds);
    Py_XDECREF(arcs);
    Py_XDECREF(lengths);
    return NULL;
}
