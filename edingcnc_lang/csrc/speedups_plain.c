/* Part of _speedups.c (one translation unit: included there, in this order). Plain lines: the check pass scan (non_plain_lines) and their targets (plain_moves). */

static int read_six(PyObject *sequence, double out[6])
{
    Py_ssize_t k;
    if (PySequence_Size(sequence) != 6) {
        PyErr_SetString(PyExc_ValueError, "a pose has six values");
        return -1;
    }
    for (k = 0; k < 6; k++) {
        PyObject *item = PySequence_GetItem(sequence, k);
        if (item == NULL)
            return -1;
        out[k] = PyFloat_AsDouble(item);
        Py_DECREF(item);
        if (out[k] == -1.0 && PyErr_Occurred())
            return -1;
    }
    return 0;
}

static PyObject *pose_tuple(const double values[6])
{
    PyObject *tuple = PyTuple_New(6);
    Py_ssize_t k;
    if (tuple == NULL)
        return NULL;
    for (k = 0; k < 6; k++) {
        PyObject *number = PyFloat_FromDouble(values[k]);
        if (number == NULL) {
            Py_DECREF(tuple);
            return NULL;
        }
        PyTuple_SetItem(tuple, k, number);
    }
    /* Six floats can be in no reference cycle: the collector need not walk the pose (the planner
     * holds thousands of them; it would untrack them itself only after walking each once). */
    PyObject_GC_UnTrack(tuple);
    return tuple;
}

/* The end of a ( ) comment that opens at s[i] and that the grammar drops, or -1 for anything else
 * (no ')', or an operator message "(msg ...)"); plain_words.py's FAST_COMMENT, byte for byte. */
static Py_ssize_t skip_comment(const char *s, Py_ssize_t len, Py_ssize_t i)
{
    Py_ssize_t j = i + 1;
    while (j < len && (s[j] == ' ' || s[j] == '\t'))
        j++;
    if (j < len) {
        unsigned char c = (unsigned char)s[j];
        if (c < 0x20 || c > 0x7e)  /* a control or non-ASCII character: the parser decides */
            return -1;
        if (j + 2 < len && (s[j] | 0x20) == 'm' && (s[j + 1] | 0x20) == 's' && (s[j + 2] | 0x20) == 'g') {
            unsigned char after = j + 3 < len ? (unsigned char)s[j + 3] : 0;
            if (!((after >= 'A' && after <= 'Z') || (after >= 'a' && after <= 'z')
                  || (after >= '0' && after <= '9') || after == '_'))
                return -1;
        }
    }
    for (j = i + 1; j < len && s[j] != ')' && s[j] != '\n'; j++)
        ;
    return j < len && s[j] == ')' ? j + 1 : -1;
}

/* The words of a plain line: value[letter] and seen[letter]; 0 if a letter comes twice or the line
 * is not made of words (the caller then leaves it to Python). */
static int scan_words(const char *s, Py_ssize_t len, double value[26], int seen[26])
{
    char buffer[NUMBER_BUFFER];
    Py_ssize_t i = 0;
    while (i < len) {
        char c = s[i], letter;
        Py_ssize_t start, digits;
        char *stop;
        double number;
        if (c == ' ' || c == '\t') {
            i++;
            continue;
        }
        if (c == '(') {
            i = skip_comment(s, len, i);
            if (i < 0)
                return 0;
            continue;
        }
        if (c == ';')
            break;
        if (c >= 'a' && c <= 'z')
            letter = (char)(c - 'a' + 'A');
        else if (c >= 'A' && c <= 'Z')
            letter = c;
        else
            return 0;
        i++;
        while (i < len && (s[i] == ' ' || s[i] == '\t'))
            i++;
        start = i;
        if (i < len && (s[i] == '+' || s[i] == '-'))
            i++;
        digits = i;
        while (i < len && ((s[i] >= '0' && s[i] <= '9') || s[i] == '.'))
            i++;
        if (i == digits || i - start >= NUMBER_BUFFER)
            return 0;
        memcpy(buffer, s + start, (size_t)(i - start));
        buffer[i - start] = '\0';
        number = PyOS_string_to_double(buffer, &stop, NULL);
        if (number == -1.0 && PyErr_Occurred()) {
            PyErr_Clear();
            return 0;
        }
        if (*stop != '\0' || seen[letter - 'A'])
            return 0;
        seen[letter - 'A'] = 1;
        value[letter - 'A'] = number;
    }
    return 1;
}

/* One plain line's words: 1 if it is a straight move (or F/G/N only), 0 if anything else. */
static int scan_line(const char *s, Py_ssize_t len, const double *base, double scale, double target[6],
                     int *motion, double *feed, int *moved)
{
    double value[26];
    int seen[26] = {0}, k;
    if (!scan_words(s, len, value, seen))
        return 0;
    for (k = 0; k < 26; k++) {
        char letter = (char)('A' + k);
        if (!seen[k])
            continue;
        switch (letter) {
        case 'X': case 'Y': case 'Z':
            target[letter - 'X'] = base[letter - 'X'] + value[k] * scale;
            *moved = 1;
            break;
        case 'A': case 'B': case 'C':
            target[3 + letter - 'A'] = base[3 + letter - 'A'] + value[k];
            *moved = 1;
            break;
        case 'F':
            if (!(value[k] >= 0))
                return 0;
            *feed = value[k] * scale;
            break;
        case 'G':
            if (value[k] == 0.0)
                *motion = G0;
            else if (value[k] == 1.0)
                *motion = G1;
            else
                return 0;
            break;
        case 'N':
            break;
        default:
            return 0;
        }
    }
    return 1;
}

static PyObject *plain_moves(PyObject *self, PyObject *args)
{
    PyObject *lines, *pos_obj, *offset_obj;
    Py_ssize_t first, room, count, index, done = 0;
    double scale, feed, position[6], offset[6];
    int incremental, motion;
    PyObject *kinds = NULL, *numbers = NULL, *ends = NULL, *feeds = NULL, *in_force = NULL;
    (void)self;
    if (!PyArg_ParseTuple(args, "OnOOdpidn", &lines, &first, &pos_obj, &offset_obj, &scale, &incremental,
                          &motion, &feed, &room))
        return NULL;
    if (read_six(pos_obj, position) < 0 || read_six(offset_obj, offset) < 0)
        return NULL;
    count = PySequence_Size(lines);
    if (count < 0)
        return NULL;
    kinds = PyList_New(0);
    numbers = PyList_New(0);
    ends = PyList_New(0);
    feeds = PyList_New(0);
    in_force = PyList_New(0);
    if (!kinds || !numbers || !ends || !feeds || !in_force)
        goto fail;
    for (index = first; index < count && done < room; index++) {
        PyObject *pair = PySequence_GetItem(lines, index), *lineno, *text, *keep;
        const char *s;
        Py_ssize_t len;
        double target[6], new_feed = feed;
        int line_motion = motion, moved = 0, simple;
        if (pair == NULL)
            goto fail;
        lineno = PySequence_GetItem(pair, 0);
        text = PySequence_GetItem(pair, 1);
        Py_DECREF(pair);
        if (lineno == NULL || text == NULL) {
            Py_XDECREF(lineno);
            Py_XDECREF(text);
            goto fail;
        }
        s = utf8_pass(text, &len, &keep);
        if (s == NULL) {
            Py_DECREF(lineno);
            Py_DECREF(text);
            goto fail;
        }
        memcpy(target, position, sizeof target);
        simple = scan_line(s, len, incremental ? position : offset, scale, target, &line_motion, &new_feed, &moved);
        Py_XDECREF(keep);
        Py_DECREF(text);
        if (!simple || line_motion == NO_MOTION || (moved && line_motion == G1 && new_feed <= 0)) {
            Py_DECREF(lineno);
            break;
        }
        if (moved) {
            int linear = line_motion == G1;
            if (PyList_Append(kinds, linear ? linear_kind : rapid_kind) < 0
                || PyList_Append(numbers, lineno) < 0
                || append_new(ends, pose_tuple(target)) < 0
                || append_new(feeds, PyFloat_FromDouble(linear ? new_feed : 0.0)) < 0
                || append_new(in_force, PyFloat_FromDouble(new_feed)) < 0) {
                Py_DECREF(lineno);
                goto fail;
            }
            memcpy(position, target, sizeof position);
        }
        Py_DECREF(lineno);
        feed = new_feed;
        motion = line_motion;
        done++;
    }
    return Py_BuildValue("nnidNNNNN", index, done, motion, feed, kinds, numbers, ends, feeds, in_force);
fail:
    Py_XDECREF(kinds);
    Py_XDECREF(numbers);
    Py_XDECREF(ends);
    Py_XDECREF(feeds);
    Py_XDECREF(in_force);
    return NULL;
}

static int is_blank(char c)
{
    return c == ' ' || c == '\t';
}

static int is_digit(char c)
{
    return c >= '0' && c <= '9';
}

/* Whether a line matches line_parser.FAST_LINE: words (letter, number) only, then a ; comment. */
/* Blanks and ( ) comments from s[i] on: the index after them, or -1 at a comment the parser must read. */
static Py_ssize_t skip_gap(const char *s, Py_ssize_t len, Py_ssize_t i)
{
    for (;;) {
        while (i < len && is_blank(s[i]))
            i++;
        if (i == len || s[i] != '(')
            return i;
        i = skip_comment(s, len, i);
        if (i < 0)
            return -1;
    }
}

static int plain_line(const char *s, Py_ssize_t len, Py_ssize_t integer_digits, Py_ssize_t max_digits)
{
    Py_ssize_t i = skip_gap(s, len, 0), words = 0, run;
    int line_number;
    if (i < 0)
        return 0;
    for (;;) {
        if (i == len || s[i] == ';')
            return words > 0;
        if (!((s[i] >= 'A' && s[i] <= 'Z') || (s[i] >= 'a' && s[i] <= 'z')))
            return 0;
        line_number = s[i] == 'N' || s[i] == 'n';
        i++;
        while (i < len && is_blank(s[i]))
            i++;
        if (i < len && (s[i] == '+' || s[i] == '-'))
            i++;
        if (i < len && is_digit(s[i])) {
            for (run = 0; i < len && is_digit(s[i]); i++)
                run++;
            if (run > integer_digits || (line_number && run > 5))  /* N: five digits at most (manual 3.4.1) */
                return 0;
            if (i < len && s[i] == '.') {
                for (i++, run = 0; i < len && is_digit(s[i]); i++)
                    run++;
                if (run > max_digits)
                    return 0;
            }
        } else if (i < len && s[i] == '.') {
            for (i++, run = 0; i < len && is_digit(s[i]); i++)
                run++;
            if (run < 1 || run > max_digits)
                return 0;
        } else {
            return 0;
        }
        words++;
        i = skip_gap(s, len, i);
        if (i < 0)
            return 0;
    }
}

static PyObject *non_plain_lines(PyObject *self, PyObject *args)
{
    PyObject *chunk, *found;
    Py_ssize_t max_length, integer_digits, max_digits, count, i;
    (void)self;
    if (!PyArg_ParseTuple(args, "nnnO", &max_length, &integer_digits, &max_digits, &chunk))
        return NULL;
    count = PySequence_Size(chunk);
    found = count < 0 ? NULL : PyList_New(0);
    if (found == NULL)
        return NULL;
    for (i = 0; i < count; i++) {
        PyObject *text = PySequence_GetItem(chunk, i), *keep;
        const char *s;
        Py_ssize_t len;
        int plain;
        if (text == NULL)
            goto fail;
        s = utf8_pass(text, &len, &keep);
        plain = s != NULL && PyUnicode_GetLength(text) <= max_length && plain_line(s, len, integer_digits, max_digits);
        Py_XDECREF(keep);
        Py_DECREF(text);
        if (s == NULL)
            goto fail;
        if (!plain && append_new(found, PyLong_FromSsize_t(i)) < 0)
            goto fail;
    }
    return found;
fail:
    Py_DECREF(found);
    return NULL;
}
