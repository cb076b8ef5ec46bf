/* Part of _speedups.c (one translation unit: included there, in this order). Python's math as the arc parts
 * compute it: math.hypot (CPython's own algorithm, checked at import), atan2 and float's %. */

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
