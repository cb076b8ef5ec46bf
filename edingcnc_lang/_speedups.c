/* The optional compiled core: the hot loops of a big job, byte for byte as the Python reference.
 *
 * non_plain_lines: syntax/parser.py's non_plain_lines (the check pass's scan for lines that are not plain).
 * plain_moves:     machine/bulk.py's plain_moves (runs of plain G0/G1 lines into targets).
 * plain_arc:       machine/bulk.py's BulkPath._arc_of_words (an arc line with centre words).
 * arc_frame:       kinematics/trajectory.py's arc_frame (an arc's circle, for the planner).
 * column_bounds:   motion/reach.py's column_bounds (the bounds of a batch, for the limit check).
 * trace_rows:      motion/sinks.py's trace_rows (the trace CSV rows of a batch, repr() of every number).
 *
 * Built by setuptools as an optional extension against the stable ABI (abi3, Python 3.10+);
 * without it the Python functions run (edingcnc_lang/speedups.py chooses).  Compiled with
 * -ffp-contract=off so a * b + c is rounded twice, as Python rounds it.
 */
#define Py_LIMITED_API 0x030A0000
#define PY_SSIZE_T_CLEAN
#include <Python.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#define G0 0
#define G1 10
#define NO_MOTION (-1)
#define NUMBER_BUFFER 512

static PyObject *linear_kind;
static PyObject *rapid_kind;

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

static int append_new(PyObject *list, PyObject *item)
{
    int failed;
    if (item == NULL)
        return -1;
    failed = PyList_Append(list, item);
    Py_DECREF(item);
    return failed;
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

/* One plain line's words: 1 if it is a straight move (or F/G/N only), 0 if anything else. */
static int scan_line(const char *s, Py_ssize_t len, const double *base, double scale, double target[6],
                     int *motion, double *feed, int *moved)
{
    char buffer[NUMBER_BUFFER];
    int seen[26] = {0};
    Py_ssize_t i = 0;
    while (i < len) {
        char c = s[i], letter;
        Py_ssize_t start, digits;
        double value;
        char *stop;
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
        value = PyOS_string_to_double(buffer, &stop, NULL);
        if (value == -1.0 && PyErr_Occurred()) {
            PyErr_Clear();
            return 0;
        }
        if (*stop != '\0')
            return 0;
        if (seen[letter - 'A'])
            return 0;
        seen[letter - 'A'] = 1;
        switch (letter) {
        case 'X': case 'Y': case 'Z': {
            int axis = letter - 'X';
            target[axis] = base[axis] + value * scale;
            *moved = 1;
            break;
        }
        case 'A': case 'B': case 'C': {
            int axis = 3 + letter - 'A';
            target[axis] = base[axis] + value;
            *moved = 1;
            break;
        }
        case 'F':
            if (!(value >= 0))
                return 0;
            *feed = value * scale;
            break;
        case 'G':
            if (value == 0.0)
                *motion = G0;
            else if (value == 1.0)
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
        PyObject *pair = PySequence_GetItem(lines, index), *lineno, *text;
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
        s = PyUnicode_AsUTF8AndSize(text, &len);
        if (s == NULL) {
            Py_DECREF(lineno);
            Py_DECREF(text);
            goto fail;
        }
        memcpy(target, position, sizeof target);
        simple = scan_line(s, len, incremental ? position : offset, scale, target, &line_motion, &new_feed, &moved);
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

/* A growing text buffer. */
typedef struct {
    char *data;
    size_t used, size;
} Text;

static int text_add(Text *text, const char *s, size_t n)
{
    if (text->used + n > text->size) {
        size_t size = text->size ? text->size : 1 << 16;
        char *grown;
        while (size < text->used + n)
            size *= 2;
        grown = (char *)PyMem_Realloc(text->data, size);
        if (grown == NULL) {
            PyErr_NoMemory();
            return -1;
        }
        text->data = grown;
        text->size = size;
    }
    memcpy(text->data + text->used, s, n);
    text->used += n;
    return 0;
}

#ifdef __SIZEOF_INT128__
typedef unsigned __int128 Wide;

/* repr() of a double in fixed notation (0, and 1e-4 <= |v| < 2^49), without Python's general routine.
 *
 * |v| = f / 2^(s-2) exactly (f: the 53-bit mantissa), and the texts that read back as v are the
 * decimals strictly between the midpoints to its neighbours, (4f - 2) / 2^s and (4f + 2) / 2^s (the
 * lower one is (4f - 1) / 2^s when f is a power of two).  Scaled by 10^k and 2^s these are integers
 * of at most 125 bits, so the search is exact: the first k (number of decimals) for which an integer
 * lies inside gives the shortest text, and the inside integer nearest to v * 10^k is the one repr()
 * chooses (of two equally near, the even one).  In this range no midpoint can be that integer: it
 * would need at least s - 1 decimals, more than the 17 digits the shortest text has at most.
 * Returns the text's length, or -1 out of range (the caller then asks Python's routine).
 */
static int fixed_repr(double v, char *out)
{
    double magnitude = v < 0 ? -v : v;
    int n = 0, exponent, shift, k;
    Wide f, scaled, low, high, one, half;
    if (v == 0.0) {
        if (1.0 / v < 0)
            out[n++] = '-';
        memcpy(out + n, "0.0", 3);
        return n + 3;
    }
    if (!(magnitude >= 1e-4 && magnitude < 562949953421312.0))
        return -1;
    f = (Wide)(unsigned long long)ldexp(frexp(magnitude, &exponent), 53);
    shift = 53 - exponent + 2;  /* 6 ... 68 */
    one = (Wide)1 << shift;
    half = one >> 1;
    scaled = f << 2;
    high = scaled + 2;
    low = f == ((Wide)1 << 52) ? scaled - 1 : scaled - 2;
    for (k = 0; k <= 21; k++, scaled *= 10, low *= 10, high *= 10) {
        Wide candidate = (scaled + half) >> shift, at = candidate << shift;
        unsigned long long digits_of;
        char digits[24];
        int width = 0, j;
        if ((scaled & (one - 1)) == half && (candidate & 1)) {  /* a tie: to the even one, as repr() does */
            at -= one;
            candidate -= 1;
        }
        if (at <= low) {  /* below a power of two the interval is lopsided: the next integer up may be in */
            at += one;
            candidate += 1;
        }
        if (at <= low || at >= high)
            continue;
        if (candidate >> 63)
            return -1;
        digits_of = (unsigned long long)candidate;
        if (v < 0)
            out[n++] = '-';
        do {  /* the digits, last first */
            digits[width++] = (char)('0' + digits_of % 10);
            digits_of /= 10;
        } while (digits_of > 0);
        while (width <= k)  /* at least one digit before the point */
            digits[width++] = '0';
        for (j = width - 1; j >= k; j--)
            out[n++] = digits[j];
        out[n++] = '.';
        if (k == 0)
            out[n++] = '0';
        for (j = k - 1; j >= 0; j--)
            out[n++] = digits[j];
        return n;
    }
    return -1;
}
#else
static int fixed_repr(double v, char *out)  /* no 128-bit integers (MSVC): Python's routine for all */
{
    (void)v;
    (void)out;
    return -1;
}
#endif

/* Add a str() or repr() result to the text and release it (NULL: the call that made it failed). */
static int text_shown(Text *text, PyObject *shown)
{
    const char *s;
    Py_ssize_t n;
    int failed;
    if (shown == NULL)
        return -1;
    s = PyUnicode_AsUTF8AndSize(shown, &n);
    failed = s == NULL ? -1 : text_add(text, s, (size_t)n);
    Py_DECREF(shown);
    return failed;
}

/* repr() of a number: float_repr's own formatting for floats, repr() for anything else. */
static int text_repr(Text *text, PyObject *value)
{
    int failed;
    if (PyFloat_CheckExact(value)) {
        char quick[64];
        double v = PyFloat_AsDouble(value);
        int n = fixed_repr(v, quick);
        char *digits;
        if (n >= 0)
            return text_add(text, quick, (size_t)n);
        digits = PyOS_double_to_string(v, 'r', 0, Py_DTSF_ADD_DOT_0, NULL);
        if (digits == NULL)
            return -1;
        failed = text_add(text, digits, strlen(digits));
        PyMem_Free(digits);
        return failed;
    }
    return text_shown(text, PyObject_Repr(value));
}

/* str() of a value: the digits of an int that fits a long long written here, anything else by str(). */
static int text_str(Text *text, PyObject *value)
{
    if (PyLong_CheckExact(value)) {
        int overflow;
        long long number = PyLong_AsLongLongAndOverflow(value, &overflow);
        if (!overflow && number >= 0) {
            char digits[24];
            int width = sizeof digits;
            do {
                digits[--width] = (char)('0' + number % 10);
                number /= 10;
            } while (number > 0);
            return text_add(text, digits + width, sizeof digits - (size_t)width);
        }
        if (PyErr_Occurred())
            return -1;
    }
    return text_shown(text, PyObject_Str(value));
}

static PyObject *trace_rows(PyObject *self, PyObject *args)
{
    PyObject *lines, *kinds, *ends, *name, *times, *result = NULL;
    const char *name_s;
    Py_ssize_t name_n, count, i;
    Text text = {NULL, 0, 0}, coords = {NULL, 0, 0};
    (void)self;
    if (!PyArg_ParseTuple(args, "OOOUO", &lines, &kinds, &ends, &name, &times))
        return NULL;
    name_s = PyUnicode_AsUTF8AndSize(name, &name_n);
    if (name_s == NULL)
        return NULL;
    count = PySequence_Size(lines);
    if (count < 0 || PySequence_Size(kinds) < count || PySequence_Size(ends) < count)
        goto done;
    if (PySequence_Size(times) - 1 < count)
        count = PySequence_Size(times) - 1;  /* zip() stops at the shortest */
    for (i = 0; i < count; i++) {
        PyObject *line = PySequence_GetItem(lines, i), *kind = NULL, *end = NULL, *t = NULL;
        const char *kind_s;
        Py_ssize_t kind_n, k;
        int failed = line == NULL;
        coords.used = 0;
        if (!failed) {
            kind = PySequence_GetItem(kinds, i);
            end = PySequence_GetItem(ends, i);
            t = PySequence_GetItem(times, i + 1);
            failed = kind == NULL || end == NULL || t == NULL;
        }
        if (!failed && PySequence_Size(end) != 6) {
            PyErr_SetString(PyExc_TypeError, "not all arguments converted during string formatting");
            failed = 1;
        }
        for (k = 0; !failed && k < 6; k++) {
            PyObject *value = PySequence_GetItem(end, k);
            failed = value == NULL || (k && text_add(&coords, ",", 1) < 0) || text_repr(&coords, value) < 0;
            Py_XDECREF(value);
        }
        if (!failed) {
            kind_s = PyUnicode_AsUTF8AndSize(kind, &kind_n);
            failed = kind_s == NULL
                || text_str(&text, line) < 0 || text_add(&text, ",", 1) < 0
                || text_add(&text, kind_s, (size_t)kind_n) < 0 || text_add(&text, ",", 1) < 0
                || text_add(&text, coords.data, coords.used) < 0 || text_add(&text, ",", 1) < 0
                || text_add(&text, coords.data, coords.used) < 0 || text_add(&text, ",", 1) < 0
                || text_add(&text, name_s, (size_t)name_n) < 0 || text_add(&text, ",", 1) < 0
                || text_repr(&text, t) < 0 || text_add(&text, "\n", 1) < 0;
        }
        Py_XDECREF(line);
        Py_XDECREF(kind);
        Py_XDECREF(end);
        Py_XDECREF(t);
        if (failed)
            goto done;
    }
    result = PyUnicode_FromStringAndSize(text.data ? text.data : "", (Py_ssize_t)text.used);
done:
    PyMem_Free(text.data);
    PyMem_Free(coords.data);
    return result;
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

static int plain_line(const char *s, Py_ssize_t len, Py_ssize_t max_digits)
{
    Py_ssize_t i = skip_gap(s, len, 0), words = 0, run;
    if (i < 0)
        return 0;
    for (;;) {
        if (i == len || s[i] == ';')
            return words > 0;
        if (!((s[i] >= 'A' && s[i] <= 'Z') || (s[i] >= 'a' && s[i] <= 'z')))
            return 0;
        i++;
        while (i < len && is_blank(s[i]))
            i++;
        if (i < len && (s[i] == '+' || s[i] == '-'))
            i++;
        if (i < len && is_digit(s[i])) {
            for (run = 0; i < len && is_digit(s[i]); i++)
                run++;
            if (run > 300)
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
    Py_ssize_t max_length, max_digits, count, i;
    (void)self;
    if (!PyArg_ParseTuple(args, "nnO", &max_length, &max_digits, &chunk))
        return NULL;
    count = PySequence_Size(chunk);
    found = count < 0 ? NULL : PyList_New(0);
    if (found == NULL)
        return NULL;
    for (i = 0; i < count; i++) {
        PyObject *text = PySequence_GetItem(chunk, i);
        const char *s;
        Py_ssize_t len;
        int plain;
        if (text == NULL)
            goto fail;
        s = PyUnicode_AsUTF8AndSize(text, &len);
        plain = s != NULL && PyUnicode_GetLength(text) <= max_length && plain_line(s, len, max_digits);
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

/* motion.reach.column_bounds, compiled: the least and greatest value of each of the six columns of a
   sequence of poses of floats, as min() and max() of each column find them (the first of equal values;
   a NaN is never less or greater than another value), as two lists. */
static PyObject *column_bounds(PyObject *self, PyObject *args)
{
    PyObject *ends, *low = NULL, *high = NULL;
    double least[6], most[6];
    Py_ssize_t count, i, k;
    (void)self;
    if (!PyArg_ParseTuple(args, "O", &ends))
        return NULL;
    count = PySequence_Size(ends);
    if (count < 0)
        return NULL;
    if (count == 0) {
        PyErr_SetString(PyExc_ValueError, "min() arg is an empty sequence");
        return NULL;
    }
    for (i = 0; i < count; i++) {
        PyObject *end = PySequence_GetItem(ends, i);
        if (end == NULL)
            return NULL;
        if (PySequence_Size(end) != 6) {
            Py_DECREF(end);
            PyErr_SetString(PyExc_ValueError, "a pose has six values");
            return NULL;
        }
        for (k = 0; k < 6; k++) {
            PyObject *item = PySequence_GetItem(end, k);
            double value = item == NULL ? -1.0 : PyFloat_AsDouble(item);
            Py_XDECREF(item);
            if (value == -1.0 && PyErr_Occurred()) {
                Py_DECREF(end);
                return NULL;
            }
            if (i == 0) {
                least[k] = most[k] = value;
            } else {
                if (value < least[k])
                    least[k] = value;
                if (value > most[k])
                    most[k] = value;
            }
        }
        Py_DECREF(end);
    }
    low = PyList_New(6);
    high = PyList_New(6);
    for (k = 0; low != NULL && high != NULL && k < 6; k++) {
        PyObject *a = PyFloat_FromDouble(least[k]), *b = PyFloat_FromDouble(most[k]);
        if (a == NULL || b == NULL) {
            Py_XDECREF(a);
            Py_XDECREF(b);
            break;
        }
        PyList_SetItem(low, k, a);
        PyList_SetItem(high, k, b);
    }
    if (low == NULL || high == NULL || k < 6) {
        Py_XDECREF(low);
        Py_XDECREF(high);
        return NULL;
    }
    return Py_BuildValue("(NN)", low, high);
}

/* ---------------------------------------------------------------- plain arcs
 * machine/bulk.py's BulkPath._arc_of_words for an arc with centre words, compiled: the words of the line,
 * its target (as plain_moves finds it), the centre, the radius check and the sweep of
 * machine/geometry.py's check_radius and sweep.  Every double is computed as Python computes it:
 * math.hypot and math.dist are Python's own (called, not libm's hypot, which rounds differently),
 * atan2 is CPython's m_atan2 and % is float's remainder. */
static PyObject *math_hypot;

static int py_hypot(double a, double b, double *out)
{
    PyObject *result = PyObject_CallFunction(math_hypot, "dd", a, b);
    if (result == NULL)
        return -1;
    *out = PyFloat_AsDouble(result);
    Py_DECREF(result);
    return *out == -1.0 && PyErr_Occurred() ? -1 : 0;
}

static double py_atan2(double y, double x)  /* CPython's m_atan2 */
{
    if (isnan(x) || isnan(y))
        return NAN;
    if (isinf(y)) {
        if (isinf(x))
            return copysign(copysign(1., x) == 1. ? 0.25 * M_PI : 0.75 * M_PI, y);
        return copysign(0.5 * M_PI, y);
    }
    if (isinf(x) || y == 0.)
        return copysign(copysign(1., x) == 1. ? 0. : M_PI, y);
    return atan2(y, x);
}

static double py_mod(double vx, double wx)  /* float's % (float_rem) */
{
    double mod = fmod(vx, wx);
    if (mod) {
        if ((wx < 0) != (mod < 0))
            mod += wx;
    } else {
        mod = copysign(0.0, wx);
    }
    return mod;
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

#define G2 20
#define G3 30
#define SEEN(letter) seen[(letter) - 'A']
#define VALUE(letter) value[(letter) - 'A']

static PyObject *plain_arc(PyObject *self, PyObject *args)
{
    /* plane: 0 XY, 1 XZ, 2 YZ (PLANES order: first, second in-plane axes) */
    static const int first_axis[3] = {0, 2, 1}, second_axis[3] = {1, 0, 2};
    static const char first_word[3] = {'I', 'K', 'J'}, second_word[3] = {'J', 'I', 'K'};
    PyObject *text, *start_obj, *offset_obj, *end = NULL;
    const char *s;
    Py_ssize_t len;
    double start[6], offset[6], target[6], value[26], scale, feed, tolerance, epsilon, rel, tiny;
    double s1, s2, e1, e2, c1, c2, r1, r2, a0, a1, delta, dist, limit;
    int seen[26] = {0}, incremental, motion, plane, reverse, clockwise, full, k, axes = 0;
    (void)self;
    if (!PyArg_ParseTuple(args, "UOOdpidipdddd", &text, &start_obj, &offset_obj, &scale, &incremental, &motion,
                          &feed, &plane, &reverse, &tolerance, &epsilon, &rel, &tiny))
        return NULL;
    if (plane < 0 || plane > 2) {
        PyErr_SetString(PyExc_ValueError, "plane must be 0 (XY), 1 (XZ) or 2 (YZ)");
        return NULL;
    }
    if (read_six(start_obj, start) < 0 || read_six(offset_obj, offset) < 0)
        return NULL;
    s = PyUnicode_AsUTF8AndSize(text, &len);
    if (s == NULL)
        return NULL;
    if (!scan_words(s, len, value, seen))
        Py_RETURN_FALSE;
    if (SEEN('R'))
        Py_RETURN_FALSE;  /* an R arc: the Python function takes it */
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
        else if (letter != first_word[plane] && letter != second_word[plane])
            Py_RETURN_NONE;
    }
    if ((motion != G2 && motion != G3) || !axes)
        Py_RETURN_NONE;
    if (SEEN('F')) {
        if (VALUE('F') < 0)
            Py_RETURN_NONE;
        feed = VALUE('F') * scale;
    }
    if (feed <= 0 || (!SEEN(first_word[plane]) && !SEEN(second_word[plane])))
        Py_RETURN_NONE;
    memcpy(target, start, sizeof target);
    for (k = 0; k < 6; k++) {
        char letter = "XYZABC"[k];
        if (SEEN(letter)) {
            double number = VALUE(letter) * (k < 3 ? scale : 1.0);
            target[k] = incremental ? start[k] + number : number + offset[k];
        }
    }
    s1 = start[first_axis[plane]];
    s2 = start[second_axis[plane]];
    e1 = target[first_axis[plane]];
    e2 = target[second_axis[plane]];
    c1 = s1 + (SEEN(first_word[plane]) ? VALUE(first_word[plane]) : 0.0) * scale;
    c2 = s2 + (SEEN(second_word[plane]) ? VALUE(second_word[plane]) : 0.0) * scale;
    if (py_hypot(s1 - c1, s2 - c2, &r1) < 0 || py_hypot(e1 - c1, e2 - c2, &r2) < 0)
        return NULL;
    limit = rel * r1 > tolerance ? rel * r1 : tolerance;
    if (r1 < tiny || fabs(r1 - r2) > limit)
        Py_RETURN_NONE;  /* the general path reports it */
    clockwise = (motion == G2) != reverse;
    a0 = py_atan2(s2 - c2, s1 - c1);
    a1 = py_atan2(e2 - c2, e1 - c1);
    delta = py_mod(clockwise ? a0 - a1 : a1 - a0, 2 * M_PI);
    if (py_hypot(s1 - e1, s2 - e2, &dist) < 0)
        return NULL;
    full = delta == 0.0 || (dist <= tolerance && delta < epsilon);
    end = pose_tuple(target);
    if (end == NULL)
        return NULL;
    /* the centre named in the plane's name order: XZ is (x, z), its axes run (z, x) */
    return Py_BuildValue("idN(dd)ii", motion, feed, end, plane == 1 ? c2 : c1, plane == 1 ? c1 : c2,
                         clockwise ? -1 : 1, full);
}

/* kinematics/trajectory.py's arc_frame, compiled (the planner asks for one per arc of a job): the same
 * doubles, from Python's own math.hypot, CPython's atan2 and float's remainder. */
static PyObject *arc_frame(PyObject *self, PyObject *args)
{
    PyObject *start_obj, *end_obj, *center_obj, *item;
    double start[6], end[6], cu, cv, r0, r1, a0, a1, sweep, direction, linear;
    int normal, turns, u, v;
    double epsilon;
    (void)self;
    if (!PyArg_ParseTuple(args, "OOOiid", &start_obj, &end_obj, &center_obj, &normal, &turns, &epsilon))
        return NULL;
    if (normal < 0 || normal > 2 || turns == 0) {
        PyErr_SetString(PyExc_ValueError, "normal must be 0..2 and turns non-zero");
        return NULL;
    }
    if (read_six(start_obj, start) < 0 || read_six(end_obj, end) < 0)
        return NULL;
    u = (normal + 1) % 3;
    v = (normal + 2) % 3;
    item = PySequence_GetItem(center_obj, u);
    cu = item == NULL ? -1.0 : PyFloat_AsDouble(item);
    Py_XDECREF(item);
    if (cu == -1.0 && PyErr_Occurred())
        return NULL;
    item = PySequence_GetItem(center_obj, v);
    cv = item == NULL ? -1.0 : PyFloat_AsDouble(item);
    Py_XDECREF(item);
    if (cv == -1.0 && PyErr_Occurred())
        return NULL;
    if (py_hypot(start[u] - cu, start[v] - cv, &r0) < 0 || py_hypot(end[u] - cu, end[v] - cv, &r1) < 0)
        return NULL;
    a0 = py_atan2(start[v] - cv, start[u] - cu);
    a1 = py_atan2(end[v] - cv, end[u] - cu);
    /* arc_sweep */
    direction = turns > 0 ? 1.0 : -1.0;
    sweep = py_mod(direction * (a1 - a0), 2.0 * M_PI);
    if (sweep <= epsilon || sweep == 0.0)
        sweep = 2.0 * M_PI;
    sweep = direction * (sweep + 2.0 * M_PI * (double)(abs(turns) - 1));
    if (py_hypot(fabs(sweep) * (r0 + r1) / 2.0, end[normal] - start[normal], &linear) < 0)
        return NULL;
    return Py_BuildValue("ii(dd)ddddd", u, v, cu, cv, r0, r1, a0, sweep, linear);
}

static PyMethodDef methods[] = {
    {"non_plain_lines", non_plain_lines, METH_VARARGS, "parser.non_plain_lines, compiled: (max_length, max_digits, chunk)."},
    {"plain_moves", plain_moves, METH_VARARGS, "interpreter.bulk.plain_moves, compiled."},
    {"trace_rows", trace_rows, METH_VARARGS, "outputs.trace_rows, compiled."},
    {"column_bounds", column_bounds, METH_VARARGS, "motion.reach.column_bounds, compiled."},
    {"arc_frame", arc_frame, METH_VARARGS, "kinematics.trajectory.arc_frame, compiled (a plain tuple)."},
    {"plain_arc", plain_arc, METH_VARARGS, "machine.bulk.BulkPath._arc_of_words for centre-word arcs, compiled."},
    {NULL, NULL, 0, NULL},
};

static struct PyModuleDef module = {
    PyModuleDef_HEAD_INIT, "_speedups", "The optional compiled core (see speedups.py).", -1, methods,
    NULL, NULL, NULL, NULL,
};

PyMODINIT_FUNC PyInit__speedups(void)
{
    linear_kind = PyUnicode_InternFromString("linear");
    rapid_kind = PyUnicode_InternFromString("rapid");
    if (linear_kind == NULL || rapid_kind == NULL)
        return NULL;
    {
        PyObject *math = PyImport_ImportModule("math");
        if (math == NULL)
            return NULL;
        math_hypot = PyObject_GetAttrString(math, "hypot");
        Py_DECREF(math);
        if (math_hypot == NULL)
            return NULL;
    }
    return PyModule_Create(&module);
}
