/* Part of _speedups.c (one translation unit: included there, in this order). The planner's window of
 * straight moves (motion/planner/stage.py's Planner._commit with segments.py, junctions.py, profile.py):
 * the same operations in the same order, so every time comes out to the bit.
 *
 * Only +, -, *, / and sqrt decide a number here (IEEE, correctly rounded, and -ffp-contract=off keeps
 * a * b + c rounded twice), and every numpy call of the reference has its element rule below: np.minimum
 * and np.maximum keep a NaN, np.clip is max-then-min with the NaN kept, sums are added in order (cumsum). */

#include <float.h>

#define PLAN_AXES 6
#define KIND_STRAIGHT (-1)
#define KIND_RAPID 0
#define KIND_LINEAR 1
#define KIND_ARC 2
#define ARC_ROW 10  /* an ArcTable row: move index, u, v, cu, cv, r0, r1, start angle, sweep, XYZ length */
#define KIND_PROBE 3
#define KIND_HOME 4

static inline double np_minimum(double a, double b) { return (a <= b || isnan(a)) ? a : b; }
static inline double np_maximum(double a, double b) { return (a >= b || isnan(a)) ? a : b; }

/* np.clip(x, low, high): the larger of x and low, then the smaller of that and high (a NaN x stays). */
static inline double np_clip(double x, double low, double high)
{
    double t = isnan(x) ? x : (x > low ? x : low);
    return isnan(t) ? t : (t < high ? t : high);
}

#include "speedups_plan_read.c"  /* reading the window from Python: plan_item ... plan_list */

typedef struct {
    double *length, *xyz, *vmax, *accel, *tan_in, *duration, *peak, *node2, *cap2, *reach;
    double *m_length, *m_accel;  /* the moving moves' lengths and accelerations, gathered */
    double *tan_out;             /* the arcs' directions at their ends, six per arc (a straight move's is tan_in) */
    long *kind, *state;
    Py_ssize_t *moving, *arc_of; /* arc_of: the move's row in the arc table, -1 for a straight move */
    char *exact;
} PlanWork;

static void plan_free(PlanWork *w)
{
    PyMem_Free(w->length); PyMem_Free(w->xyz); PyMem_Free(w->vmax); PyMem_Free(w->accel);
    PyMem_Free(w->tan_in); PyMem_Free(w->duration); PyMem_Free(w->peak); PyMem_Free(w->node2);
    PyMem_Free(w->cap2); PyMem_Free(w->reach); PyMem_Free(w->m_length); PyMem_Free(w->m_accel); PyMem_Free(w->kind);
    PyMem_Free(w->state); PyMem_Free(w->moving); PyMem_Free(w->exact); PyMem_Free(w->arc_of); PyMem_Free(w->tan_out);
}

static int plan_alloc(PlanWork *w, Py_ssize_t n, Py_ssize_t arcs)
{
    size_t d = sizeof(double), m = (size_t)n + 1;
    memset(w, 0, sizeof(*w));
    w->length = PyMem_Malloc(m * d); w->xyz = PyMem_Malloc(m * d); w->vmax = PyMem_Malloc(m * d);
    w->accel = PyMem_Malloc(m * d); w->tan_in = PyMem_Malloc(m * PLAN_AXES * d);
    w->duration = PyMem_Malloc(m * d); w->peak = PyMem_Malloc(m * d); w->node2 = PyMem_Malloc(m * d);
    w->cap2 = PyMem_Malloc(m * d); w->reach = PyMem_Malloc(m * d);
    w->m_length = PyMem_Malloc(m * d); w->m_accel = PyMem_Malloc(m * d);
    w->kind = PyMem_Malloc(m * sizeof(long)); w->state = PyMem_Malloc(m * sizeof(long));
    w->moving = PyMem_Malloc(m * sizeof(Py_ssize_t)); w->exact = PyMem_Malloc(m);
    w->arc_of = PyMem_Malloc(m * sizeof(Py_ssize_t)); w->tan_out = PyMem_Malloc(((size_t)arcs + 1) * PLAN_AXES * d);
    if (!w->arc_of || !w->tan_out || !w->length || !w->xyz || !w->vmax || !w->accel || !w->tan_in || !w->duration || !w->peak || !w->node2
        || !w->cap2 || !w->reach || !w->m_length || !w->m_accel || !w->kind || !w->state || !w->moving || !w->exact) {
        plan_free(w);
        PyErr_NoMemory();
        return -1;
    }
    return 0;
}

/* segments(): length, XYZ length, direction, speed limit and acceleration of move i from start to end. */
static void plan_segment(PlanWork *w, Py_ssize_t i, const double start[PLAN_AXES], const double end[PLAN_AXES],
                         const double *vlim, const double *alim, double speed)
{
    double delta[PLAN_AXES], square[PLAN_AXES], linear2, rotary2, linear, length, norm, v_ratio, a_ratio;
    int k;
    for (k = 0; k < PLAN_AXES; k++) {
        delta[k] = end[k] - start[k];
        square[k] = delta[k] * delta[k];
    }
    linear2 = square[0] + square[1] + square[2];
    rotary2 = square[3] + square[4] + square[5];
    linear = sqrt(linear2);
    length = linear2 > 0.0 ? linear : sqrt(rotary2);
    norm = sqrt(linear2 + rotary2);
    v_ratio = fabs(delta[0]) / vlim[0];
    a_ratio = fabs(delta[0]) / alim[0];
    for (k = 0; k < PLAN_AXES; k++) {
        /* an axis that does not move: its direction is its delta (+-0; only moving moves' directions are
         * read, and their norm is above 0), its share 0 / limit = +0 (limits above 0), which changes no
         * maximum of shares that is not below 0: the divisions are skipped, the bits are the same */
        if (delta[k] == 0.0
            && (k == 0 || (vlim[k] > 0.0 && alim[k] > 0.0 && !(v_ratio < 0.0) && !(a_ratio < 0.0)))) {
            w->tan_in[PLAN_AXES * i + k] = delta[k];
            continue;
        }
        w->tan_in[PLAN_AXES * i + k] = delta[k] / norm;
        if (k) {
            v_ratio = np_maximum(v_ratio, fabs(delta[k]) / vlim[k]);
            a_ratio = np_maximum(a_ratio, fabs(delta[k]) / alim[k]);
        }
    }
    w->length[i] = length;
    w->xyz[i] = linear;
    w->vmax[i] = np_minimum(length / v_ratio, speed);
    w->accel[i] = length / a_ratio;
}

/* segments._arcs for move i, arc table row `row` (its a-th row): what plan_segment worked out for it is
 * replaced by the arc's length, in-plane shares, tangents at both ends and limits (`speed`: its own speed
 * limit, before the arc's; `share`: segments.curvature_share).  sin and cos are libm's, which agree with
 * numpy's float64 ones on the machines the project is built on (docs/planner.md). */
static void plan_arc(PlanWork *w, Py_ssize_t i, Py_ssize_t a, const double *row, const double start[PLAN_AXES],
                     const double end[PLAN_AXES], const double *vlim, const double *alim, double speed, double share,
                     double min_arc_length)
{
    int u = (int)row[1], v = (int)row[2], k, side;
    double r0 = row[5], r1 = row[6], angle = row[7], sweep = row[8], linear = row[9];
    double delta[PLAN_AXES], fraction[PLAN_AXES], tangent[PLAN_AXES], in_plane, arc_len, v_ratio, a_ratio;
    double vmax, accel, radius;
    for (k = 0; k < PLAN_AXES; k++)
        delta[k] = end[k] - start[k];
    in_plane = fabs(sweep) * (r0 + r1) / 2.0;
    arc_len = linear > 0.0 ? linear : sqrt(delta[3] * delta[3] + delta[4] * delta[4] + delta[5] * delta[5]);
    for (k = 0; k < PLAN_AXES; k++)
        fraction[k] = arc_len > 0.0 ? fabs(delta[k]) / arc_len : 0.0;
    fraction[u] = fraction[v] = arc_len > 0.0 ? in_plane / arc_len : 0.0;
    w->length[i] = arc_len;
    w->xyz[i] = linear;
    for (side = 0; side < 2; side++) {
        double at = side ? angle + sweep : angle, r = side ? r1 : r0, norm;
        double *out = side ? w->tan_out + PLAN_AXES * a : w->tan_in + PLAN_AXES * i;
        memcpy(tangent, delta, sizeof(tangent));
        tangent[u] = -sin(at) * sweep * r;
        tangent[v] = cos(at) * sweep * r;
        norm = tangent[0] * tangent[0];
        for (k = 1; k < PLAN_AXES; k++)
            norm = norm + tangent[k] * tangent[k];
        norm = sqrt(norm);
        for (k = 0; k < PLAN_AXES; k++)
            out[k] = norm > 0.0 ? tangent[k] / norm : tangent[k];
    }
    v_ratio = fraction[0] / vlim[0];
    a_ratio = fraction[0] / alim[0];
    for (k = 1; k < PLAN_AXES; k++) {
        v_ratio = np_maximum(v_ratio, fraction[k] / vlim[k]);
        a_ratio = np_maximum(a_ratio, fraction[k] / alim[k]);
    }
    vmax = 1.0 / v_ratio;
    accel = 1.0 / a_ratio;
    radius = (r0 + r1) / 2.0;
    if (arc_len >= min_arc_length && radius > 0.0) {  /* it turns: v^2 / r within its share of the plane's */
        double plane_accel = np_minimum(alim[u], alim[v]), centripetal = plane_accel * share;
        speed = np_minimum(np_minimum(speed, vmax), sqrt(centripetal * radius));
        accel = np_minimum(accel, plane_accel - speed * speed / radius);
    }
    w->vmax[i] = np_minimum(vmax, speed);
    w->accel[i] = accel;
}

/* junctions.corner_speeds2 for the corner between moves b and a (no G64 R programmed), then what the
 * stage makes of it: 0 next to an exact stop, never above either move's speed limit. */
static double plan_corner(const PlanWork *w, Py_ssize_t b, Py_ssize_t a, double tolerance, double sharp_cos)
{
    const double *out = w->arc_of[b] >= 0 ? w->tan_out + PLAN_AXES * w->arc_of[b] : w->tan_in + PLAN_AXES * b, *in = w->tan_in + PLAN_AXES * a;
    double cos_phi = out[0] * in[0], cos_half, tan_half, fit, within, radius, speed2, limit;
    int k;
    if (w->exact[b] || w->exact[a])
        return 0.0;
    for (k = 1; k < PLAN_AXES; k++)
        cos_phi = cos_phi + out[k] * in[k];
    cos_phi = np_clip(cos_phi, -1.0, 1.0);
    cos_half = sqrt((1.0 + cos_phi) / 2.0);
    tan_half = sqrt((1.0 - cos_phi) / (1.0 + cos_phi));
    fit = np_minimum(w->length[b], w->length[a]) / 2.0 / tan_half;
    within = tolerance > 0.0 ? tolerance * cos_half / (1.0 - cos_half) : INFINITY;
    radius = np_minimum(fit, within);
    speed2 = radius > 0.0 ? np_minimum(w->accel[b], w->accel[a]) * radius : 0.0;
    if (cos_phi < sharp_cos || isnan(speed2))
        speed2 = 0.0;
    limit = np_minimum(w->vmax[b], w->vmax[a]);
    return np_minimum(speed2, limit * limit);
}

/* profile.plan_nodes over the m moving moves (m_length, m_accel; caps in cap2): node2 gets the m + 1 squared
 * node speeds. */
static void plan_nodes_c(PlanWork *w, Py_ssize_t m, double start2)
{
    double *reach = w->reach, *node = w->node2, *cap = w->cap2, running;
    Py_ssize_t i;
    reach[0] = 0.0;
    for (i = 0; i < m; i++)
        reach[i + 1] = reach[i] + 2.0 * w->m_accel[i] * w->m_length[i];
    running = cap[m] + reach[m];
    node[m] = running - reach[m];
    for (i = m - 1; i >= 0; i--) {
        running = np_minimum(running, cap[i] + reach[i]);
        node[i] = running - reach[i];
    }
    if (start2 < node[0])  /* Python's min(backward[0], start2) */
        node[0] = start2;
    running = node[0] - reach[0];
    node[0] = running + reach[0];
    for (i = 1; i <= m; i++) {
        running = np_minimum(running, node[i] - reach[i]);
        node[i] = running + reach[i];
    }
    for (i = 0; i <= m; i++)
        node[i] = np_clip(node[i], 0.0, np_maximum(cap[i], 0.0));
}

/* profile.profiles of one move: its duration (what the stage keeps of a moving move) and its peak speed. */
static void plan_profile(double length, double vmax, double accel, double v0_2, double v1_2, double *duration,
                         double *peak_out)
{
    double peak2 = np_minimum(vmax * vmax, 0.5 * (v0_2 + v1_2) + accel * length), peak, v0, v1;
    double t_accel = 0.0, t_decel = 0.0, ramps = 0.0, cruise, crawl, t_cruise;
    peak2 = np_maximum(peak2, np_maximum(v0_2, v1_2));
    peak = sqrt(peak2);
    v0 = sqrt(v0_2);
    v1 = sqrt(v1_2);
    if (isfinite(accel)) {
        t_accel = (peak - v0) / accel;
        t_decel = (peak - v1) / accel;
        ramps = (2.0 * peak2 - v0_2 - v1_2) / (2.0 * accel);
    }
    cruise = np_maximum(length - ramps, 0.0);
    crawl = np_minimum(length / vmax, DBL_MAX);
    t_cruise = peak > 0.0 ? cruise / peak : (vmax > 0.0 ? crawl : 0.0);
    if (!isfinite(t_cruise))
        t_cruise = 0.0;
    *duration = t_accel + t_cruise + t_decel;
    *peak_out = peak;
}

/* plan_window(origin, ends, feeds, n, count, kind_runs, state_runs, states, limit_sets, sharp_cos, start2,
 *               time, arc_rows, arc_share, min_arc_length) -> (t_end, peak (bytes of doubles: few sinks read it), start2, rapid_seconds, feed_seconds, rapid_distance, feed_distance,
 *                         low, high)
 * Plans the first n collected moves (straight ones and arcs: arc_rows holds the window's ArcTable rows as
 * bytes of doubles, rows of moves from n on ignored; no samples, no joints' caps, no G64 R) and
 * commits the first count: their end times and peak speeds, the squared speed the next window starts
 * from, the estimate's sums (in order) and the extremes the limits report widens by (None, None when
 * count is 0). */
static PyObject *plan_window(PyObject *self, PyObject *args)
{
    PyObject *origin, *ends, *feeds, *kind_runs, *state_runs, *table, *sets, *result = NULL;
    PyObject *t_list = NULL, *peak_list = NULL, *low_list = NULL, *high_list = NULL;
    Py_ssize_t n, count, i, m = 0, n_states = 0, n_sets = 0, done = 0;
    double sharp_cos, start2, time, start[PLAN_AXES], end[PLAN_AXES], low[PLAN_AXES], high[PLAN_AXES];
    double sums[4] = {0.0, 0.0, 0.0, 0.0}, cum = 0.0, first, next2, arc_share, min_arc_length;
    double *arc_rows = NULL;
    char *row_bytes;
    Py_ssize_t n_arcs, row_size;
    PyObject *rows;
    PlanState *states = NULL;
    double *limits = NULL, *t_end = NULL;
    PlanWork w;
    int k;
    (void)self;
    if (!PyArg_ParseTuple(args, "OOOnnOOOOdddSdd", &origin, &ends, &feeds, &n, &count, &kind_runs, &state_runs,
                          &table, &sets, &sharp_cos, &start2, &time, &rows, &arc_share, &min_arc_length))
        return NULL;
    if (PyBytes_AsStringAndSize(rows, &row_bytes, &row_size) < 0)
        return NULL;
    n_arcs = row_size / (Py_ssize_t)(ARC_ROW * sizeof(double));
    if (n < 0 || count < 0 || count > n || row_size % (Py_ssize_t)(ARC_ROW * sizeof(double))) {
        PyErr_SetString(PyExc_ValueError, "plan_window: 0 <= count <= n, whole arc rows");
        return NULL;
    }
    if (plan_alloc(&w, n, n_arcs) < 0)
        return NULL;
    /* (copied: the bytes' data need not be aligned for doubles) */
    if ((arc_rows = PyMem_Malloc((size_t)row_size + sizeof(double))) == NULL) {
        plan_free(&w);
        return PyErr_NoMemory();
    }
    memcpy(arc_rows, row_bytes, (size_t)row_size);
    for (i = 0; i < n; i++)
        w.arc_of[i] = -1;
    for (i = 0; i < n_arcs; i++) {  /* an ArcTable row: its move's index first, then its frame */
        const double *row = arc_rows + ARC_ROW * i;
        if (!(row[0] >= 0.0) || !(row[1] >= 0.0 && row[1] < PLAN_AXES) || !(row[2] >= 0.0 && row[2] < PLAN_AXES)
            || row[1] == row[2]) {
            PyErr_SetString(PyExc_ValueError, "plan_window: an arc row without a move or a plane");
            goto done;
        }
        if (row[0] < (double)n)
            w.arc_of[(Py_ssize_t)row[0]] = i;
    }
    if ((states = plan_states(table, &n_states)) == NULL || (limits = plan_limits(sets, &n_sets)) == NULL
        || (t_end = PyMem_Malloc(((size_t)count + 1) * sizeof(double))) == NULL)
        goto done;
    {
        PyObject *v = PySequence_GetItem(kind_runs, 0), *c = PySequence_GetItem(kind_runs, 1);
        int bad = v == NULL || c == NULL || plan_runs(v, c, n, w.kind) < 0;
        Py_XDECREF(v);
        Py_XDECREF(c);
        if (bad)
            goto done;
        v = PySequence_GetItem(state_runs, 0);
        c = PySequence_GetItem(state_runs, 1);
        bad = v == NULL || c == NULL || plan_runs(v, c, n, w.state) < 0;
        Py_XDECREF(v);
        Py_XDECREF(c);
        if (bad)
            goto done;
    }
    if (plan_pose(origin, start) < 0)
        goto done;
    for (k = 0; k < PLAN_AXES; k++)
        low[k] = high[k] = start[k];
    /* segments: every move's length, direction and limits */
    if (!PyList_Check(ends) || PyList_Size(ends) < n || !PyList_Check(feeds) || PyList_Size(feeds) < n) {
        PyErr_SetString(PyExc_TypeError, "plan_window: ends and feeds must be lists of at least n moves");
        goto done;
    }
    for (i = 0; i < n; i++) {
        PyObject *pose = PyList_GetItem(ends, i);
        double feed = PyFloat_AsDouble(PyList_GetItem(feeds, i)), speed;
        long kind, s;
        const PlanState *st;
        const double *limit;
        if ((feed == -1.0 && PyErr_Occurred()) || plan_pose(pose, end) < 0)
            goto done;
        s = w.state[i];
        kind = w.kind[i];
        if (w.arc_of[i] >= 0)
            kind = w.kind[i] = KIND_ARC;
        else if (kind == KIND_STRAIGHT)
            kind = w.kind[i] = feed > 0.0 ? KIND_LINEAR : KIND_RAPID;
        if (s < 0 || s >= n_states || kind < KIND_RAPID || kind > KIND_HOME) {
            PyErr_SetString(PyExc_ValueError, "plan_window: a move of a kind or state it does not plan");
            goto done;
        }
        st = &states[s];
        {
            long set = kind == KIND_RAPID ? st->rapid_limits : st->other_limits;
            if (set < 0 || set >= n_sets) {
                PyErr_SetString(PyExc_ValueError, "plan_window: no such limit set");
                goto done;
            }
            limit = limits + 2 * PLAN_AXES * set;
        }
        w.exact[i] = (char)(st->exact || kind == KIND_RAPID || kind == KIND_PROBE || kind == KIND_HOME);
        speed = (kind == KIND_RAPID || kind == KIND_HOME) ? INFINITY : feed * st->factor / 60.0;
        plan_segment(&w, i, start, end, limit, limit + PLAN_AXES, speed);
        if (w.arc_of[i] >= 0)
            plan_arc(&w, i, w.arc_of[i], arc_rows + ARC_ROW * w.arc_of[i], start, end, limit, limit + PLAN_AXES, speed,
                     arc_share, min_arc_length);
        if (w.length[i] > 0.0)
            w.moving[m++] = i;
        if (i < count)
            for (k = 0; k < PLAN_AXES; k++) {
                low[k] = end[k] < low[k] ? end[k] : low[k];
                high[k] = end[k] > high[k] ? end[k] : high[k];
            }
        memcpy(start, end, sizeof(start));
    }
    /* the corners between moving moves, the node caps, the look-ahead passes */
    first = (m && w.exact[w.moving[0]]) ? 0.0 : start2;
    w.cap2[0] = first;
    for (i = 0; i + 1 < m; i++)
        w.cap2[i + 1] = plan_corner(&w, w.moving[i], w.moving[i + 1], states[w.state[w.moving[i + 1]]].tolerance,
                                    sharp_cos);
    if (m)
        w.cap2[m] = 0.0;
    for (i = 0; i < m; i++) {
        w.m_length[i] = w.length[w.moving[i]];
        w.m_accel[i] = w.accel[w.moving[i]];
    }
    for (i = 0; i < n; i++)
        w.duration[i] = w.peak[i] = 0.0;
    plan_nodes_c(&w, m, first);
    for (i = 0; i < m; i++) {
        Py_ssize_t at = w.moving[i];
        plan_profile(w.length[at], w.vmax[at], w.accel[at], w.node2[i], w.node2[i + 1], &w.duration[at], &w.peak[at]);
        if (at < count)
            done = i + 1;
    }
    next2 = count < n ? w.node2[done] : 0.0;
    /* the committed moves: end times, the estimate's sums, the extremes */
    for (i = 0; i < count; i++) {
        int rapid = w.kind[i] == KIND_RAPID || w.kind[i] == KIND_HOME;
        cum = cum + w.duration[i];
        t_end[i] = time + cum;
        sums[rapid ? 0 : 1] += w.duration[i];
        sums[rapid ? 2 : 3] += w.xyz[i];
    }
    if ((t_list = plan_list(t_end, count)) == NULL || (peak_list = PyBytes_FromStringAndSize((const char *)w.peak, count * (Py_ssize_t)sizeof(double))) == NULL)
        goto done;
    if (count) {
        if ((low_list = plan_list(low, PLAN_AXES)) == NULL || (high_list = plan_list(high, PLAN_AXES)) == NULL)
            goto done;
    } else {
        low_list = Py_NewRef(Py_None);
        high_list = Py_NewRef(Py_None);
    }
    result = Py_BuildValue("(OOdddddOO)", t_list, peak_list, next2, sums[0], sums[1], sums[2], sums[3], low_list,
                           high_list);
done:
    Py_XDECREF(t_list);
    Py_XDECREF(peak_list);
    Py_XDECREF(low_list);
    Py_XDECREF(high_list);
    PyMem_Free(states);
    PyMem_Free(limits);
    PyMem_Free(t_end);
    plan_free(&w);
    PyMem_Free(arc_rows);
    return result;
}
