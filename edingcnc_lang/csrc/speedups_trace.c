/* Part of _speedups.c (one translation unit: included there, in this order). The trace rows: repr() of every number, fixed_repr for the usual ones. */

/* A growing text buffer. */
typedef struct {
    char *data;
    size_t used, size;
} Text;

/* Room for n more bytes at text->data + text->used. */
static int text_room(Text *text, size_t n)
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
    return 0;
}

static int text_add(Text *text, const char *s, size_t n)
{
    if (text->used + n > text->size && text_room(text, n) < 0)
        return -1;
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
/* 10^0 ... 10^21 (10^21 < 2^70). */
#define TEN_E18 ((Wide)1000000000000000000ULL)
static const Wide ten_to[22] = {
    1, 10, 100, 1000, 10000, 100000, 1000000, 10000000, 100000000, 1000000000, 10000000000ULL,
    100000000000ULL, 1000000000000ULL, 10000000000000ULL, 100000000000000ULL, 1000000000000000ULL,
    10000000000000000ULL, 100000000000000000ULL, TEN_E18, TEN_E18 * 10, TEN_E18 * 100, TEN_E18 * 1000,
};

/* The least k in 0..21 for which a multiple of 2^shift lies strictly between low * 10^k and high * 10^k
 * (22 if none).  Once one does, one does for every larger k (ten times it), so a binary search finds it
 * in five steps where trying k = 0, 1, ... takes up to seventeen for a time such as 0.7052213595499957. */
static int fewest_decimals(Wide low, Wide high, int shift)
{
    int lo = 0, hi = 22;
    while (lo < hi) {
        int mid = (lo + hi) / 2;
        Wide below = ((high * ten_to[mid] - 1) >> shift) << shift;  /* the largest multiple under the top */
        if (below > low * ten_to[mid])
            hi = mid;
        else
            lo = mid + 1;
    }
    return lo;
}

static int fixed_repr(double v, char *out)
{
    double magnitude = v < 0 ? -v : v;
    int n = 0, exponent, shift, k;
    Wide f, scaled, low, high, one, half;
    unsigned long long bits;
    if (v == 0.0) {
        if (1.0 / v < 0)
            out[n++] = '-';
        memcpy(out + n, "0.0", 3);
        return n + 3;
    }
    if (!(magnitude >= 1e-4 && magnitude < 562949953421312.0))
        return -1;
    memcpy(&bits, &magnitude, sizeof bits);  /* normal here: the mantissa with its hidden bit, as frexp gives it */
    f = (Wide)((bits & 0xFFFFFFFFFFFFFULL) | (1ULL << 52));
    exponent = (int)(bits >> 52) - 1022;
    shift = 53 - exponent + 2;  /* 6 ... 68 */
    one = (Wide)1 << shift;
    half = one >> 1;
    scaled = f << 2;
    high = scaled + 2;
    low = f == ((Wide)1 << 52) ? scaled - 1 : scaled - 2;
    k = fewest_decimals(low, high, shift);
    scaled *= ten_to[k];
    low *= ten_to[k];
    high *= ten_to[k];
    for (; k <= 21; k++, scaled *= 10, low *= 10, high *= 10) {
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
        double v = PyFloat_AsDouble(value);
        int n;
        char *digits;
        if (text_room(text, 64) < 0)  /* fixed_repr writes at most 41 */
            return -1;
        n = fixed_repr(v, text->data + text->used);
        if (n >= 0) {
            text->used += (size_t)n;
            return 0;
        }
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
    PyObject *lines, *kinds, *ends, *name, *times, *result = NULL, *name_keep;
    const char *name_s;
    Py_ssize_t name_n, count, i, size;
    Text text = {NULL, 0, 0}, coords = {NULL, 0, 0};
    (void)self;
    if (!PyArg_ParseTuple(args, "OOOUO", &lines, &kinds, &ends, &name, &times))
        return NULL;
    name_s = utf8_pass(name, &name_n, &name_keep);
    if (name_s == NULL)
        return NULL;
    /* zip() stops at the shortest: the rows of min(lines, kinds, ends, times[1:]) */
    if ((count = PySequence_Size(lines)) < 0 || (size = PySequence_Size(kinds)) < 0)
        goto done;
    count = size < count ? size : count;
    if ((size = PySequence_Size(ends)) < 0)
        goto done;
    count = size < count ? size : count;
    if ((size = PySequence_Size(times)) < 0)
        goto done;
    count = size - 1 < count ? size - 1 : count;
    for (i = 0; i < count; i++) {
        PyObject *line = PySequence_GetItem(lines, i), *kind = NULL, *end = NULL, *t = NULL, *kind_keep = NULL;
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
            kind_s = utf8_pass(kind, &kind_n, &kind_keep);
            failed = kind_s == NULL
                || text_str(&text, line) < 0 || text_add(&text, ",", 1) < 0
                || text_add(&text, kind_s, (size_t)kind_n) < 0 || text_add(&text, ",", 1) < 0
                || text_add(&text, coords.data, coords.used) < 0 || text_add(&text, ",", 1) < 0
                || text_add(&text, coords.data, coords.used) < 0 || text_add(&text, ",", 1) < 0
                || text_add(&text, name_s, (size_t)name_n) < 0 || text_add(&text, ",", 1) < 0
                || text_repr(&text, t) < 0 || text_add(&text, "\n", 1) < 0;
        }
        Py_XDECREF(kind_keep);
        Py_XDECREF(line);
        Py_XDECREF(kind);
        Py_XDECREF(end);
        Py_XDECREF(t);
        if (failed)
            goto done;
    }
    result = PyUnicode_DecodeUTF8(text.data ? text.data : "", (Py_ssize_t)text.used, "surrogatepass");
done:
    Py_XDECREF(name_keep);
    PyMem_Free(text.data);
    PyMem_Free(coords.data);
    return result;
}
