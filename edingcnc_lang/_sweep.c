/* The optional compiled core of the 3-axis sim: a cutter swept along straight segments into the
 * height field, in place, segment after segment (sim/sweep.py's ``_carve``).
 *
 * carve: for each segment, the cells of sweep.footprint, the bound and skip of envelope.Geometry
 * (a cell already at or below the lowest the tool can reach over it is passed by), then for the
 * rest the lowest height of envelope.lowest (or of a flat bottom), each number computed with the
 * same operations in the same precision as numpy computes it (float32 where it keeps float32,
 * float64 where it promotes), and the field lowered to it.  The field is the minimum over all
 * (segment, cell) pairs, which does not depend on their order; cutting segment by segment only lets
 * more pairs be skipped, as each sees the field its predecessors already lowered.  No findings are
 * worked out here: sweep.py calls this only for chunks where no pair can be one.
 *
 * Its own extension, apart from _speedups.c: it reads numpy's arrays through the buffer protocol,
 * which the stable ABI has from Python 3.11 (the Python 3.10 headers do not declare it, so there the
 * build is skipped and numpy runs).  Compiled with -ffp-contract=off so a * b + c is rounded twice,
 * as numpy rounds it.
 */
#define Py_LIMITED_API 0x030B0000
#define PY_SSIZE_T_CLEAN
#include <Python.h>
#include <math.h>
#include <stdint.h>
#include <string.h>

#define STILL 1e-10          /* envelope.STILL: a segment shorter than this in XY is vertical */
#define ROUNDING 1e-5        /* envelope.ROUNDING, as numpy's float32 scalar */
#define FAR 1e9              /* envelope.FAR */
#define GOLDEN_STEPS 40      /* envelope.GOLDEN_STEPS */

enum { FLAT, BALL, VEE, BULL };  /* the cutter's shape: its profile and its envelope */

typedef struct {
    int kind;
    double radius, corner, slope;  /* tools.Tool's radius, corner_radius and cone_slope */
} Shape;

/* numpy's maximum/minimum: a NaN in the first argument wins (the second is never NaN here) */
static inline double np_max(double a, double b) { return (a >= b || a != a) ? a : b; }
static inline double np_min(double a, double b) { return (a <= b || a != a) ? a : b; }
static inline double np_clip(double x, double lo, double hi) { return np_min(np_max(x, lo), hi); }

/* tools.Tool.profile: the cutting edge's height above the tip at distance d (float64) */
static inline double profile(const Shape *s, double d)
{
    switch (s->kind) {
    case BALL:
        return s->radius - sqrt(np_max(s->radius * s->radius - d * d, 0.0));
    case VEE:
        return s->slope * d;
    case BULL: {
        double out = np_max(d - (s->radius - s->corner), 0.0);
        return s->corner - sqrt(np_max(s->corner * s->corner - out * out, 0.0));
    }
    default:
        return 0.0;
    }
}

/* One (segment, cell) pair's geometry: envelope.Geometry's per-pair values */
typedef struct {
    double uu, ud, lo, hi, p, e2;
    float az, dz, l2;
    int still;
} Pair;

static inline double d2_at(const Pair *g, double t)
{
    return np_max(g->uu - 2.0 * t * g->ud + t * t * (double)g->l2, 0.0);
}

static inline double height_at(const Shape *s, const Pair *g, double t)
{
    return (double)g->az + t * (double)g->dz + profile(s, sqrt(d2_at(g, t)));
}

/* envelope.Geometry.clamp */
static inline double clamp(const Pair *g, double step)
{
    double t = g->still ? (g->dz < 0.0f ? 1.0 : 0.0) : g->p + step;
    return np_clip(t, g->lo, g->hi);
}

/* envelope.lowest (a flat end mill: its downhill end, as sweep._chunk takes it) */
static double lowest(const Shape *s, const Pair *g)
{
    float sign, l2, dz2;
    double t;
    if (s->kind == FLAT)
        return (double)g->az + (g->dz >= 0.0f ? g->lo : g->hi) * (double)g->dz;
    sign = g->dz > 0.0f ? -1.0f : (g->dz < 0.0f ? 1.0f : -0.0f);
    l2 = g->still ? 1.0f : g->l2;
    dz2 = g->dz * g->dz;
    if (s->kind == BALL) {
        double w = np_max(s->radius * s->radius - g->e2, 0.0);
        t = clamp(g, (double)sign * sqrt((double)dz2 * w / (double)(l2 * (l2 + dz2))));
    } else if (s->kind == VEE) {
        float k2l2 = (float)(s->slope * s->slope) * l2;
        int steep = k2l2 <= dz2;
        double step = sqrt((double)dz2 * g->e2 / (double)(l2 * (steep ? 1.0f : k2l2 - dz2)));
        t = clamp(g, (double)sign * (steep ? FAR : step));
    } else {  /* envelope._golden */
        const double golden = (sqrt(5.0) - 1.0) / 2.0;
        double lo = g->lo, hi = g->hi;
        int k;
        for (k = 0; k < GOLDEN_STEPS; k++) {
            double left = hi - golden * (hi - lo), right = lo + golden * (hi - lo);
            if (height_at(s, g, left) < height_at(s, g, right))
                hi = right;
            else
                lo = left;
        }
        t = (lo + hi) / 2.0;
    }
    return height_at(s, g, t);
}

typedef struct {
    float *top;
    Py_ssize_t nx, ny;
    double x0, y0, r, bottom;
} Field;

/* sweep._spans for one axis: the first cell and how many the segment's box widened by ``radius`` spans */
static void span(double u, double v, double radius, double origin, double r, Py_ssize_t count,
                 int64_t *first, int64_t *many)
{
    double low = u < v ? u : v, high = u < v ? v : u;
    double f = np_max(ceil((low - radius - origin) / r - 0.5), 0.0);
    double l = np_min(floor((high + radius - origin) / r - 0.5), (double)(count - 1));
    *first = (int64_t)f;
    *many = (int64_t)l - *first + 1;
    if (*many < 0)
        *many = 0;
}

static void carve_segment(const Field *f, const Shape *s, const double *a, const double *b)
{
    double dx = b[0] - a[0], dy = b[1] - a[1], l2 = dx * dx + dy * dy;
    int still = l2 < STILL;
    double r = f->r, radius = s->radius;
    int64_t i0, wide, j0, tall, row;
    float step = (float)r, radius_f = (float)radius, r2_f = (float)(radius * radius);
    float mx0, my0, half_len, tip, pdx, pdy, l2p, inv;
    double low_x = a[0] < b[0] ? a[0] : b[0], high_x = a[0] < b[0] ? b[0] : a[0];
    double low_y = a[1] < b[1] ? a[1] : b[1], high_y = a[1] < b[1] ? b[1] : a[1], quick;
    Pair g;

    span(a[0], b[0], radius, f->x0, r, f->nx, &i0, &wide);
    span(a[1], b[1], radius, f->y0, r, f->ny, &j0, &tall);
    if (wide <= 0)
        return;
    mx0 = (float)(f->x0 + ((double)i0 + 0.5) * r - a[0] - dx / 2.0);
    my0 = (float)(f->y0 + ((double)j0 + 0.5) * r - a[1] - dy / 2.0);
    half_len = (float)sqrt((still ? 0.0 : l2) / 4.0);
    tip = (float)(a[2] < b[2] ? a[2] : b[2]);
    pdx = (float)dx;
    pdy = (float)dy;
    l2p = (float)(still ? 0.0 : l2);
    inv = 1.0f / (still ? 1.0f : l2p);
    /* the bound with the profile at its least (0 at the axis, where a ball's or bull's may come out an
     * ulp of the radius below 0): rounding is monotonic, so no bound is below it */
    quick = ((double)tip - radius * 1e-12) - (double)(float)ROUNDING;
    g.az = (float)a[2];
    g.dz = (float)(b[2] - a[2]);
    g.l2 = l2p;
    g.still = still;
    for (row = 0; row < tall; row++) {
        int64_t j = j0 + row, first, last, i;
        double y = f->y0 + ((double)j + 0.5) * r;
        double off = np_max(np_max(low_y - y, y - high_y), 0.0);
        double reach = sqrt(np_max(radius * radius - off * off, 0.0));
        double my = (double)my0 + (double)(int32_t)row * (double)step, uy = my + (double)(pdy * 0.5f);
        float *line = f->top + j * f->nx;
        if (!(off <= radius))
            continue;
        first = (int64_t)np_max(ceil((low_x - reach - f->x0) / r - 0.5), (double)i0);
        last = (int64_t)np_min(floor((high_x + reach - f->x0) / r - 0.5), (double)(i0 + wide - 1));
        for (i = first; i <= last; i++) {
            double mx, nearest, bound, ux, root, h;
            float hf;
            if ((double)line[i] <= quick)  /* at or below the lowest tip: the bound below would skip it too */
                continue;
            mx = (double)mx0 + (double)(int32_t)(i - i0) * (double)step;
            nearest = sqrt(mx * mx + my * my) - (double)half_len;
            if (!(nearest <= (double)radius_f))
                continue;
            bound = ((double)tip + profile(s, np_clip(nearest, 0.0, (double)radius_f))) - (double)(float)ROUNDING;
            if (!((double)line[i] > bound))
                continue;
            ux = mx + (double)(pdx * 0.5f);
            g.uu = ux * ux + uy * uy;
            g.ud = ux * (double)pdx + uy * (double)pdy;
            root = sqrt(g.ud * g.ud - (double)l2p * (g.uu - (double)r2_f));
            g.lo = still ? 0.0 : np_max((g.ud - root) * (double)inv, 0.0);
            g.hi = still ? 1.0 : np_min((g.ud + root) * (double)inv, 1.0);
            if (!(g.lo <= g.hi))
                continue;
            g.p = still ? 0.0 : g.ud * (double)inv;
            g.e2 = np_max(g.uu - g.ud * g.p, 0.0);
            h = np_max(lowest(s, &g), f->bottom);
            hf = (float)h;
            if (hf < line[i])
                line[i] = hf;
        }
    }
}

/* The order of the segments of a block of BLOCK consecutive ones: bit-reversed (0, 32, 16, 48, 8, ...), so
 * the first few already cut near the lowest over a cell, and most of the rest are skipped by the bound.
 * In program order each of the ~60 segments of a finishing pass that reach a cell would lower it a little
 * more than the one before; the field, their minimum, is the same in any order. */
#define BLOCK 64

static inline int spread(int m)
{
    int out = 0, bit;
    for (bit = 0; bit < 6; bit++)
        out |= ((m >> bit) & 1) << (5 - bit);
    return out;
}

static const char *const KINDS[] = {"flat", "ball", "vee", "bull"};

/* carve(top, a, b, x0, y0, r, bottom, shape, radius, corner_radius, cone_slope) */
static PyObject *carve(PyObject *self, PyObject *args)
{
    PyObject *top_obj, *a_obj, *b_obj;
    const char *kind;
    Field f;
    Shape s;
    Py_buffer top, a, b;
    Py_ssize_t n, k;
    (void)self;
    if (!PyArg_ParseTuple(args, "OOOddddsddd", &top_obj, &a_obj, &b_obj, &f.x0, &f.y0, &f.r, &f.bottom, &kind,
                          &s.radius, &s.corner, &s.slope))
        return NULL;
    for (s.kind = 0; s.kind < 4 && strcmp(kind, KINDS[s.kind]) != 0; s.kind++)
        ;
    if (s.kind == 4) {
        PyErr_Format(PyExc_ValueError, "unknown cutter shape %s", kind);
        return NULL;
    }
    if (PyObject_GetBuffer(top_obj, &top, PyBUF_WRITABLE | PyBUF_FORMAT | PyBUF_ND | PyBUF_C_CONTIGUOUS) < 0)
        return NULL;
    if (top.ndim != 2 || top.itemsize != 4 || strcmp(top.format, "f") != 0) {
        PyBuffer_Release(&top);
        PyErr_SetString(PyExc_TypeError, "the field must be a 2-D float32 array");
        return NULL;
    }
    if (PyObject_GetBuffer(a_obj, &a, PyBUF_FORMAT | PyBUF_C_CONTIGUOUS) < 0) {
        PyBuffer_Release(&top);
        return NULL;
    }
    if (PyObject_GetBuffer(b_obj, &b, PyBUF_FORMAT | PyBUF_C_CONTIGUOUS) < 0) {
        PyBuffer_Release(&a);
        PyBuffer_Release(&top);
        return NULL;
    }
    if (a.itemsize != 8 || b.itemsize != 8 || strcmp(a.format, "d") != 0 || strcmp(b.format, "d") != 0
        || a.len != b.len || a.len % 24 != 0) {
        PyBuffer_Release(&b);
        PyBuffer_Release(&a);
        PyBuffer_Release(&top);
        PyErr_SetString(PyExc_TypeError, "the segment ends must be two (N, 3) float64 arrays");
        return NULL;
    }
    f.top = (float *)top.buf;
    f.ny = top.shape[0];
    f.nx = top.shape[1];
    n = a.len / 24;
    Py_BEGIN_ALLOW_THREADS
    for (k = 0; k < n; k += BLOCK) {
        int m;
        for (m = 0; m < BLOCK; m++) {
            Py_ssize_t at = k + spread(m);
            if (at < n)
                carve_segment(&f, &s, (const double *)a.buf + 3 * at, (const double *)b.buf + 3 * at);
        }
    }
    Py_END_ALLOW_THREADS
    PyBuffer_Release(&b);
    PyBuffer_Release(&a);
    PyBuffer_Release(&top);
    Py_RETURN_NONE;
}

static PyMethodDef methods[] = {
    {"carve", carve, METH_VARARGS, "sim.sweep._carve, compiled: a cutter swept along segments into the field."},
    {NULL, NULL, 0, NULL},
};

static struct PyModuleDef module = {
    PyModuleDef_HEAD_INIT, "_sweep", "The 3-axis sim's sweep, compiled (see sim/sweep.py).", -1, methods,
    NULL, NULL, NULL, NULL,
};

PyMODINIT_FUNC PyInit__sweep(void)
{
    return PyModule_Create(&module);
}
