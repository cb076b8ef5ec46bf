/* Part of _speedups.c (one translation unit: included there, in this order). A batch's bounds (column_bounds),
 * an arc's frame (arc_frame), the frames of a batch's arcs (arc_frame_rows, arc_frame_bytes) and whether they
 * reach outside the limits (arcs_beyond). */

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
