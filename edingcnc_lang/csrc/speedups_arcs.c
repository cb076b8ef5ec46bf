/* Part of _speedups.c (one translation unit: included there, in this order). A batch's bounds (column_bounds), runs of arc lines (plain_arcs) and an arc's frame (arc_frame). */

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
 * machine/bulk.py's BulkPath._arc_of_words, compiled: the words of the line, its target (as plain_moves finds
 * it), the centre from centre words or R, the radius check, the sweep and the length of machine/geometry.py's
 * center_from_radius, check_radius and sweep.  Every double is computed as Python computes it:
 * math.hypot and math.dist are CPython's vector_norm (below; not libm's hypot, which rounds differently),
 * atan2 is CPython's m_atan2 and % is float's remainder. */

/* ---------------------------------------------------------------- math.hypot
 * CPython's math.hypot of two numbers (Modules/mathmodule.c, vector_norm): lossless scaling by a power of two,
 * exact squares, compensated summation and a differential correction of the square root.  Two versions of it
 * exist among the Pythons this abi3 extension loads into: 3.10 and 3.11 square by Veltkamp-Dekker splitting
 * and divide subnormals by the largest; 3.12 on square with fma and scale subnormals up by DBL_MIN.
 * hypot_init picks the running interpreter's and checks it against math.hypot on a table of hard and random
 * inputs; on any difference (or an unknown version) py_hypot calls math.hypot itself. */
static PyObject *math_hypot;
static enum { HYPOT_CALL, HYPOT_310, HYPOT_312 } hypot_kind = HYPOT_CALL;
static double py_nan = NAN;  /* CPython's Py_NAN: 3.10's is -nan (HUGE_VAL * 0.), later ones +nan */

/* frexp's exponent of max (> 0, finite) and ldexp(1.0, -exponent), by the bits where both are normal numbers
   (the same values; the library calls otherwise). */
static inline double norm_scale(double max, int *max_e)
{
    uint64_t bits;
    int field;
    memcpy(&bits, &max, sizeof bits);
    field = (int)((bits >> 52) & 0x7ff);
    if (field >= 2 && field <= 2044) {
        double scale;
        *max_e = field - 1022;
        bits = (uint64_t)(1023 - *max_e) << 52;
        memcpy(&scale, &bits, sizeof scale);
        return scale;
    }
    frexp(max, max_e);
    return *max_e < -1023 ? 0.0 : ldexp(1.0, -*max_e);
}

static double norm_310(const double *vec, double max)  /* 3.10 and 3.11, n = 2 */
{
    const double T27 = 134217729.0;  /* ldexp(1.0, 27) + 1.0 */
    double x, scale, oldcsum, csum = 1.0, frac1 = 0.0, frac2 = 0.0, frac3 = 0.0, t, hi, lo, h;
    int max_e, i;
    scale = norm_scale(max, &max_e);
    if (max_e >= -1023) {
        for (i = 0; i < 2; i++) {
            x = vec[i] * scale;
            t = x * T27;
            hi = t - (t - x);
            lo = x - hi;
            x = hi * hi;
            oldcsum = csum;
            csum += x;
            frac1 += (oldcsum - csum) + x;
            x = 2.0 * hi * lo;
            oldcsum = csum;
            csum += x;
            frac2 += (oldcsum - csum) + x;
            frac3 += lo * lo;
        }
        h = sqrt(csum - 1.0 + (frac1 + frac2 + frac3));
        x = h;
        t = x * T27;
        hi = t - (t - x);
        lo = x - hi;
        x = -hi * hi;
        oldcsum = csum;
        csum += x;
        frac1 += (oldcsum - csum) + x;
        x = -2.0 * hi * lo;
        oldcsum = csum;
        csum += x;
        frac2 += (oldcsum - csum) + x;
        x = -lo * lo;
        oldcsum = csum;
        csum += x;
        frac3 += (oldcsum - csum) + x;
        x = csum - 1.0 + (frac1 + frac2 + frac3);
        return (h + x / (2.0 * h)) / scale;
    }
    for (i = 0; i < 2; i++) {  /* ldexp(1.0, -max_e) would overflow: divide by max */
        x = vec[i] / max;
        x = x * x;
        oldcsum = csum;
        csum += x;
        frac1 += (oldcsum - csum) + x;
    }
    return max * sqrt(csum - 1.0 + frac1);
}

static double norm_312(const double *vec, double max)  /* 3.12 on, n = 2 */
{
    double x, h, scale, csum = 1.0, frac1 = 0.0, frac2 = 0.0, hi, lo, sum;
    int max_e, i;
    scale = norm_scale(max, &max_e);
    if (max_e < -1023) {  /* subnormals to normals */
        double scaled[2] = {vec[0] / DBL_MIN, vec[1] / DBL_MIN};
        return DBL_MIN * norm_312(scaled, max / DBL_MIN);
    }
    for (i = 0; i < 2; i++) {
        x = vec[i] * scale;
        hi = x * x;  /* dl_mul */
        lo = fma(x, x, -hi);
        sum = csum + hi;  /* dl_fast_sum */
        frac2 += (csum - sum) + hi;
        csum = sum;
        frac1 += lo;
    }
    h = sqrt(csum - 1.0 + (frac1 + frac2));
    hi = -h * h;
    lo = fma(-h, h, -hi);
    sum = csum + hi;
    frac2 += (csum - sum) + hi;
    csum = sum;
    frac1 += lo;
    x = csum - 1.0 + (frac1 + frac2);
    h += x / (2.0 * h);
    return h / scale;
}

/* math.hypot(a, b) by the algorithm of ``kind`` (math_hypot_impl's checks, then vector_norm). */
static double hypot_of(int kind, double a, double b)
{
    double vec[2] = {fabs(a), fabs(b)}, max = vec[0] > vec[1] ? vec[0] : vec[1];
    if (isinf(vec[0]) || isinf(vec[1]))
        return INFINITY;
    if (isnan(vec[0]) || isnan(vec[1]))
        return py_nan;
    if (max == 0.0)
        return max;
    return kind == HYPOT_310 ? norm_310(vec, max) : norm_312(vec, max);
}

static int call_hypot(double a, double b, double *out)
{
    /* the arguments as objects, no format to read and no tuple: the call goes the vector way */
    PyObject *first = PyFloat_FromDouble(a), *second = PyFloat_FromDouble(b), *result = NULL;
    if (first != NULL && second != NULL)
        result = PyObject_CallFunctionObjArgs(math_hypot, first, second, NULL);
    Py_XDECREF(first);
    Py_XDECREF(second);
    if (result == NULL)
        return -1;
    *out = PyFloat_AsDouble(result);
    Py_DECREF(result);
    return *out == -1.0 && PyErr_Occurred() ? -1 : 0;
}

/* Python's math.hypot(a, b) into *out: -1 only with an error set (when math.hypot itself is called). */
static inline int py_hypot(double a, double b, double *out)
{
    if (hypot_kind == HYPOT_CALL)
        return call_hypot(a, b, out);
    *out = hypot_of(hypot_kind, a, b);
    return 0;
}

/* Whether ``kind`` gives math.hypot's bits on hard inputs (zeros, subnormals, the largest, equal, inf, nan)
   and on random ones (a fixed sequence: random bits, and numbers of every size): 1 yes, 0 no, -1 an error. */
static int hypot_agrees(int kind)
{
    static const double hard[] = {0.0, -0.0, 5e-324, -5e-324, 1e-320, 2.2250738585072009e-308, DBL_MIN, 1e-300,
                                  0.5, 1.0, 3.0, 4.0, 1e-8, 2.0 / 3.0, 1e16, 1e300, DBL_MAX, -DBL_MAX, INFINITY,
                                  -INFINITY, NAN};
    const size_t count = sizeof hard / sizeof hard[0];
    unsigned long long state = 0x9E3779B97F4A7C15ULL;
    size_t i, j;
    double want;
    for (i = 0; i < count + 600; i++) {
        for (j = 0; j < (i < count ? count : 1); j++) {
            double a = hard[i < count ? i : 0], b = hard[j];
            if (i >= count) {  /* xorshift64*: a random pair */
                unsigned long long bits[2];
                int k;
                for (k = 0; k < 2; k++) {
                    state ^= state >> 12, state ^= state << 25, state ^= state >> 27;
                    bits[k] = state * 0x2545F4914F6CDD1DULL;
                }
                if (i % 3 == 0) {
                    memcpy(&a, &bits[0], sizeof a);
                    memcpy(&b, &bits[1], sizeof b);
                } else {  /* numbers of a machine's size, and their neighbours */
                    a = ldexp((double)(bits[0] >> 11), (int)(bits[1] % 80) - 90);
                    b = i % 3 == 1 ? ldexp((double)(bits[1] >> 11), (int)(bits[0] % 80) - 90) : nextafter(a, 0.0);
                }
            }
            if (call_hypot(a, b, &want) < 0)
                return -1;
            {
                double got = hypot_of(kind, a, b);
                if (memcmp(&got, &want, sizeof got) != 0)
                    return 0;
            }
        }
    }
    return 1;
}

/* Set math_hypot, py_nan and hypot_kind (see above): -1 with an error set. */
static int hypot_init(void)
{
    PyObject *math = PyImport_ImportModule("math"), *sys = NULL, *version = NULL, *nan_result;
    long major = 0, minor = 0;
    int agrees;
    if (math == NULL)
        return -1;
    math_hypot = PyObject_GetAttrString(math, "hypot");
    Py_DECREF(math);
    if (math_hypot == NULL || (sys = PyImport_ImportModule("sys")) == NULL)
        return -1;
    version = PyObject_GetAttrString(sys, "version_info");
    Py_DECREF(sys);
    if (version == NULL)
        return -1;
    {
        PyObject *first = PySequence_GetItem(version, 0), *second = PySequence_GetItem(version, 1);
        if (first != NULL && second != NULL) {
            major = PyLong_AsLong(first);
            minor = PyLong_AsLong(second);
        }
        Py_XDECREF(first);
        Py_XDECREF(second);
        Py_DECREF(version);
        if (PyErr_Occurred())
            return -1;
    }
    nan_result = PyObject_CallFunction(math_hypot, "dd", 1.0, (double)NAN);  /* this Python's Py_NAN */
    if (nan_result == NULL)
        return -1;
    py_nan = PyFloat_AsDouble(nan_result);
    Py_DECREF(nan_result);
    if (major != 3 || minor < 10)
        return 0;
    agrees = hypot_agrees(minor < 12 ? HYPOT_310 : HYPOT_312);
    if (agrees < 0)
        return -1;
    if (agrees)
        hypot_kind = minor < 12 ? HYPOT_310 : HYPOT_312;
    return 0;
}

/* The test entry point: math.hypot(a, b) as the compiled core computes it, and which way ("3.10" or "3.12":
   whose algorithm; "call": math.hypot itself). */
static PyObject *hypot_entry(PyObject *self, PyObject *args)
{
    double a, b, out;
    (void)self;
    if (!PyArg_ParseTuple(args, "dd", &a, &b) || py_hypot(a, b, &out) < 0)
        return NULL;
    return Py_BuildValue("ds", out, hypot_kind == HYPOT_310 ? "3.10" : hypot_kind == HYPOT_312 ? "3.12" : "call");
}

static double py_atan2(double y, double x)  /* CPython's m_atan2 */
{
    if (isnan(x) || isnan(y))
        return py_nan;
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

/* kinematics/trajectory.py's arc_frame, compiled: the same doubles, from Python's own math.hypot, CPython's
 * atan2 and float's remainder.  out: r0, r1, start angle, sweep, linear. */
static int frame_of(const double *start, const double *end, double cu, double cv, int normal, int turns,
                    double epsilon, double *out)
{
    int u = (normal + 1) % 3, v = (normal + 2) % 3;
    double r0, r1, a0, a1, sweep, direction, linear;
    if (py_hypot(start[u] - cu, start[v] - cv, &r0) < 0 || py_hypot(end[u] - cu, end[v] - cv, &r1) < 0)
        return -1;
    a0 = py_atan2(start[v] - cv, start[u] - cu);
    a1 = py_atan2(end[v] - cv, end[u] - cu);
    /* arc_sweep */
    direction = turns > 0 ? 1.0 : -1.0;
    sweep = py_mod(direction * (a1 - a0), 2.0 * M_PI);
    if (sweep <= epsilon || sweep == 0.0)
        sweep = 2.0 * M_PI;
    sweep = direction * (sweep + 2.0 * M_PI * (double)(abs(turns) - 1));
    if (py_hypot(fabs(sweep) * (r0 + r1) / 2.0, end[normal] - start[normal], &linear) < 0)
        return -1;
    out[0] = r0;
    out[1] = r1;
    out[2] = a0;
    out[3] = sweep;
    out[4] = linear;
    return 0;
}

static int item_double(PyObject *sequence, Py_ssize_t index, double *out)
{
    PyObject *item = PySequence_GetItem(sequence, index);
    *out = item == NULL ? -1.0 : PyFloat_AsDouble(item);
    Py_XDECREF(item);
    return *out == -1.0 && PyErr_Occurred() ? -1 : 0;
}

/* The planner asks for the frame of every arc of a job: one at a time here (a plain tuple), or a batch's
 * at once (arc_frame_rows). */
static PyObject *arc_frame(PyObject *self, PyObject *args)
{
    PyObject *start_obj, *end_obj, *center_obj;
    double start[6], end[6], cu, cv, out[5];
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
    if (item_double(center_obj, u, &cu) < 0 || item_double(center_obj, v, &cv) < 0)
        return NULL;
    if (frame_of(start, end, cu, cv, normal, turns, epsilon, out) < 0)
        return NULL;
    return Py_BuildValue("ii(dd)ddddd", u, v, cu, cv, out[0], out[1], out[2], out[3], out[4]);
}

/* The frame numbers of a batch's arcs, ARC_ROW (10) doubles each, grown as the arcs are read. */
struct frame_buffer {
    double *rows;
    Py_ssize_t count, room;
};

/* A canon.Arc record as arc_geometry reads it: its centre in the plane's axis order (c1, c2), the normal axis of
   canon.PLANES (its in-plane axes (first, second) are (u, v) = ((normal + 1) % 3, (normal + 2) % 3)), the signed
   turns and arc_sweep's epsilon.  -1 with an error set. */
static int read_arc_record(PyObject *arc, double *c1, double *c2, int *normal, int *turns, double *epsilon)
{
    PyObject *center = NULL, *plane = NULL, *turn = NULL, *full = NULL;
    const char *name = NULL;
    long turn_value = 0, full_turns = 0;
    int failed = (center = PyObject_GetAttr(arc, arc_fields[0])) == NULL
        || (plane = PyObject_GetAttr(arc, arc_fields[1])) == NULL
        || (turn = PyObject_GetAttr(arc, arc_fields[2])) == NULL
        || (full = PyObject_GetAttr(arc, arc_fields[3])) == NULL
        || item_double(center, 0, c1) < 0 || item_double(center, 1, c2) < 0
        || (name = PyUnicode_AsUTF8AndSize(plane, NULL)) == NULL
        || ((turn_value = PyLong_AsLong(turn)) == -1 && PyErr_Occurred())
        || ((full_turns = PyLong_AsLong(full)) == -1 && PyErr_Occurred());
    Py_XDECREF(center);
    Py_XDECREF(plane);
    Py_XDECREF(turn);
    Py_XDECREF(full);
    if (failed)
        return -1;
    if (strcmp(name, "XZ") == 0) {
        double swap = *c1;
        *normal = 1;
        *c1 = *c2, *c2 = swap;  /* the canon names the XZ centre (x, z) */
    } else if (strcmp(name, "YZ") == 0) {
        *normal = 0;
    } else if (strcmp(name, "XY") == 0) {
        *normal = 2;
    } else {
        PyErr_SetString(PyExc_ValueError, "an arc's plane is XY, XZ or YZ");
        return -1;
    }
    if (turn_value == 0) {
        PyErr_SetString(PyExc_ValueError, "an arc's turn is non-zero");
        return -1;
    }
    *turns = (int)(turn_value * (full_turns > 1 ? full_turns : 1));
    *epsilon = full_turns ? INFINITY : -1.0;
    return 0;
}

/* Visit each arc of a batch (moves from start through ends, arcs[i] None for a straight move) with its start and
   end poses and record: visit returns 0 to go on, 1 to stop (then this returns 1), -1 on an error (with it set). */
/* read_six of a batch's pose: a tuple of six floats (every pose the canon hands on) read in place, else read_six. */
static inline int read_pose(PyObject *pose, double out[6])
{
    Py_ssize_t k;
    if (!PyTuple_CheckExact(pose) || PyTuple_Size(pose) != 6)
        return read_six(pose, out);
    for (k = 0; k < 6; k++) {
        PyObject *item = PyTuple_GetItem(pose, k);  /* borrowed */
        if (!PyFloat_CheckExact(item))
            return read_six(pose, out);
        out[k] = PyFloat_AsDouble(item);
    }
    return 0;
}

typedef int (*arc_visit)(void *data, Py_ssize_t index, const double *start, const double *end, PyObject *arc);

static int each_arc(PyObject *start_obj, PyObject *ends, PyObject *arcs, arc_visit visit, void *data)
{
    double previous[6], end[6];
    Py_ssize_t count, index;
    if (read_six(start_obj, previous) < 0 || (count = PySequence_Size(arcs)) < 0)
        return -1;
    for (index = 0; index < count; index++) {
        PyObject *end_obj = PySequence_GetItem(ends, index), *arc = PySequence_GetItem(arcs, index);
        int done = end_obj == NULL || arc == NULL || read_pose(end_obj, end) < 0 ? -1 : 0;
        if (done == 0 && arc != Py_None)
            done = visit(data, index, previous, end, arc);
        Py_XDECREF(end_obj);
        Py_XDECREF(arc);
        if (done != 0)
            return done;
        memcpy(previous, end, sizeof previous);
    }
    return 0;
}

static int frame_row(void *data, Py_ssize_t index, const double *start, const double *end, PyObject *arc)
{
    struct frame_buffer *out = data;
    double c1, c2, epsilon, *row;
    int normal, turns;
    if (read_arc_record(arc, &c1, &c2, &normal, &turns, &epsilon) < 0)
        return -1;
    if (out->count == out->room) {
        Py_ssize_t room = out->room ? 2 * out->room : 64;
        double *grown = PyMem_Realloc(out->rows, (size_t)room * 10 * sizeof(double));
        if (grown == NULL) {
            PyErr_NoMemory();
            return -1;
        }
        out->rows = grown;
        out->room = room;
    }
    row = out->rows + 10 * out->count;
    row[0] = (double)index;
    row[1] = (double)((normal + 1) % 3);
    row[2] = (double)((normal + 2) % 3);
    row[3] = c1;
    row[4] = c2;
    if (frame_of(start, end, c1, c2, normal, turns, epsilon, row + 5) < 0)
        return -1;
    out->count++;
    return 0;
}

/* The frames of a batch's arcs (canon.Arc records, None for a straight move) into ``out``, as arc_geometry and
 * arc_frame make them: -1 with an error set (``out`` is freed). */
static int fill_frame_rows(PyObject *start_obj, PyObject *ends, PyObject *arcs, struct frame_buffer *out)
{
    out->rows = NULL;
    out->count = out->room = 0;
    if (each_arc(start_obj, ends, arcs, frame_row, out) < 0) {
        PyMem_Free(out->rows);
        out->rows = NULL;
        return -1;
    }
    return 0;
}

/* ---------------------------------------------------------------- the reach of arcs
 * motion/reach.py's arcs_beyond, compiled: whether an arc of a batch reaches outside lower..upper, as beyond
 * finds it arc by arc: its end, and when its whole circle (the larger radius) does not lie within the limits
 * (machine/geometry.py's circle_within), the extremes of its circle it sweeps over (frame_extremes). */
struct limits {
    double lower[6], upper[6];
};

static inline int inside(const struct limits *limits, int axis, double value)
{
    return limits->lower[axis] <= value && value <= limits->upper[axis];
}

static int arc_outside(void *data, Py_ssize_t index, const double *start, const double *end, PyObject *arc)
{
    const struct limits *limits = data;
    double c1, c2, epsilon, r0, r1, radius, frame[5], sweep, direction;
    int normal, turns, u, v, k;
    (void)index;
    if (read_arc_record(arc, &c1, &c2, &normal, &turns, &epsilon) < 0)
        return -1;
    u = (normal + 1) % 3;
    v = (normal + 2) % 3;
    for (k = 0; k < 6; k++)
        if (!inside(limits, k, end[k]))
            return 1;
    if (py_hypot(start[u] - c1, start[v] - c2, &r0) < 0 || py_hypot(end[u] - c1, end[v] - c2, &r1) < 0)
        return -1;
    radius = r1 > r0 ? r1 : r0;  /* max(r0, r1) */
    if (limits->lower[u] <= c1 - radius && c1 + radius <= limits->upper[u] && limits->lower[v] <= c2 - radius
        && c2 + radius <= limits->upper[v])
        return 0;  /* circle_within */
    if (frame_of(start, end, c1, c2, normal, turns, epsilon, frame) < 0)
        return -1;
    /* frame_extremes: machine/geometry.py's arc_extremes over min(|sweep|, 2 pi), the larger radius */
    radius = frame[1] > frame[0] ? frame[1] : frame[0];
    direction = frame[3] < 0.0 ? -1.0 : 1.0;
    sweep = fabs(frame[3]);
    if (2.0 * M_PI < sweep)
        sweep = 2.0 * M_PI;
    for (k = 0; k < 4; k++) {
        double quadrant = (double)k * M_PI / 2;
        if (py_mod(direction * (quadrant - frame[2]), 2 * M_PI) <= sweep + 1e-12) {
            double point[6];
            int axis;
            memcpy(point, end, sizeof point);
            point[u] = c1 + radius * cos(quadrant);
            point[v] = c2 + radius * sin(quadrant);
            for (axis = 0; axis < 6; axis++)
                if (!inside(limits, axis, point[axis]))
                    return 1;
        }
    }
    return 0;
}

static PyObject *arcs_beyond(PyObject *self, PyObject *args)
{
    PyObject *start_obj, *ends, *arcs, *lower, *upper;
    struct limits limits;
    int found;
    (void)self;
    if (!PyArg_ParseTuple(args, "OOOOO", &start_obj, &ends, &arcs, &lower, &upper)
        || read_six(lower, limits.lower) < 0 || read_six(upper, limits.upper) < 0)
        return NULL;
    found = each_arc(start_obj, ends, arcs, arc_outside, &limits);
    if (found < 0)
        return NULL;
    return PyBool_FromLong(found);
}

/* kinematics/trajectory.py's arc_frame_rows, compiled: the frames of a batch's arcs, ARC_ROW numbers each
 * (one flat list). */
static PyObject *arc_frame_rows(PyObject *self, PyObject *args)
{
    PyObject *start_obj, *ends, *arcs, *rows;
    struct frame_buffer frames;
    Py_ssize_t k;
    (void)self;
    if (!PyArg_ParseTuple(args, "OOO", &start_obj, &ends, &arcs) || fill_frame_rows(start_obj, ends, arcs, &frames) < 0)
        return NULL;
    rows = PyList_New(10 * frames.count);
    for (k = 0; rows != NULL && k < 10 * frames.count; k++) {
        PyObject *number = PyFloat_FromDouble(frames.rows[k]);
        if (number == NULL)
            Py_CLEAR(rows);
        else
            PyList_SetItem(rows, k, number);
    }
    PyMem_Free(frames.rows);
    return rows;
}

/* The same frames as the doubles of a bytearray (native order): what motion/arc_table.py's ArcTable reads
 * as an array without a float object per number (array("d", arc_frame_rows(...)).tobytes()). */
static PyObject *arc_frame_bytes(PyObject *self, PyObject *args)
{
    PyObject *start_obj, *ends, *arcs, *made;
    struct frame_buffer frames;
    (void)self;
    if (!PyArg_ParseTuple(args, "OOO", &start_obj, &ends, &arcs) || fill_frame_rows(start_obj, ends, arcs, &frames) < 0)
        return NULL;
    made = PyByteArray_FromStringAndSize((const char *)frames.rows, frames.count * 10 * (Py_ssize_t)sizeof(double));
    PyMem_Free(frames.rows);
    return made;
}
