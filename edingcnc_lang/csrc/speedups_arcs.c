/* Part of _speedups.c (one translation unit: included there, in this order). A batch's bounds (column_bounds), arc lines (plain_arc) and an arc's frame (arc_frame). */

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
