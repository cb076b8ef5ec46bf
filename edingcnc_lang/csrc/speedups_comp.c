/* Part of _speedups.c (one translation unit: included there, in this order). Runs of corners of cutter
 * compensation (pipeline/comp_runs.py's comp_lines): the straight-on, inside and outside corners of a run of
 * straight moves under G41/G42, one after the other, as pipeline/cutter_comp.py's _straight computes each
 * (comp_geometry's line_corner, at, cut_back and reverses), the moves it hands on made as a batch's columns.
 * Every double is computed as Python computes it: atan2 is CPython's m_atan2 (py_atan2, speedups_arcs.c), cos,
 * sin and tan are the C library's, as math's are; the file is compiled with -ffp-contract=off. */

#define COMP_LEFT 1
#define COMP_TOLERANCE 0.05  /* comp_geometry.CONCAVE_TOLERANCE */

/* The in-plane point (pose[first], pose[second]) of a pose of six numbers: 0, or -1 on an error. */
static int comp_point(PyObject *pose, int first, int second, double *x, double *y)
{
    PyObject *a, *b;
    if (PySequence_Size(pose) != 6) {
        if (!PyErr_Occurred())
            PyErr_SetString(PyExc_ValueError, "a pose has six values");
        return -1;
    }
    a = PySequence_GetItem(pose, first);
    b = a == NULL ? NULL : PySequence_GetItem(pose, second);
    *x = a == NULL ? -1.0 : PyFloat_AsDouble(a);
    *y = b == NULL ? -1.0 : PyFloat_AsDouble(b);
    Py_XDECREF(a);
    Py_XDECREF(b);
    return PyErr_Occurred() ? -1 : 0;
}

/* ``pose`` as a tuple with its values on the axes ``at[0..count-1]`` replaced by ``value``. */
static PyObject *comp_pose(PyObject *pose, const int *at, const double *value, int count)
{
    PyObject *made = PyTuple_New(6);
    Py_ssize_t k;
    for (k = 0; made != NULL && k < 6; k++) {
        PyObject *item;
        int j;
        for (j = 0; j < count && at[j] != k; j++)
            ;
        item = j < count ? PyFloat_FromDouble(value[j]) : PySequence_GetItem(pose, k);
        if (item == NULL || PyTuple_SetItem(made, k, item) < 0)
            Py_CLEAR(made);
    }
    return made;
}

/* The columns a run hands on (comp_runs.Made): kinds, lines, ends, feeds and the arcs (NULL until the first
 * arc). */
struct comp_made {
    PyObject *column[4], *arcs;
};

/* Append one move to ``made``: its kind, line and feed (borrowed), its end (a new reference, stolen: NULL
 * after a failure) and its arc (a new reference, or NULL for a straight move).  -1 on an error. */
static int comp_append(struct comp_made *made, PyObject *kind, PyObject *line, PyObject *end, PyObject *feed,
                       PyObject *arc)
{
    PyObject *items[4] = {kind, line, end, feed};
    int k, failed = end == NULL;
    if (!failed && arc != NULL && made->arcs == NULL) {  /* the first arc: the moves before it are straight */
        Py_ssize_t count = PyList_Size(made->column[0]), j;
        made->arcs = PyList_New(count);
        for (j = 0; made->arcs != NULL && j < count; j++) {
            Py_INCREF(Py_None);
            PyList_SetItem(made->arcs, j, Py_None);
        }
        failed = made->arcs == NULL;
    }
    for (k = 0; !failed && k < 4; k++)
        failed = PyList_Append(made->column[k], items[k]) < 0;
    if (!failed && made->arcs != NULL)
        failed = PyList_Append(made->arcs, arc == NULL ? Py_None : arc) < 0;
    Py_XDECREF(end);
    Py_XDECREF(arc);
    return failed ? -1 : 0;
}

/* Item ``k`` of each of the batch's columns kinds, lines and feeds (new references): -1 on an error. */
static int comp_items(PyObject *const columns[4], Py_ssize_t k, PyObject **kind, PyObject **line, PyObject **feed)
{
    *kind = PySequence_GetItem(columns[1], k);
    *line = *kind == NULL ? NULL : PySequence_GetItem(columns[2], k);
    *feed = *line == NULL ? NULL : PySequence_GetItem(columns[3], k);
    if (*feed != NULL)
        return 0;
    Py_XDECREF(*kind);
    Py_XDECREF(*line);
    return -1;
}

/* comp_runs.comp_lines, compiled: see its docstring for the arguments and what it returns. */
static PyObject *comp_lines(PyObject *self, PyObject *args)
{
    static PyObject *arc_kind = NULL;
    PyObject *columns[4], *plane, *arc_class, *previous = NULL, *result = NULL;
    struct comp_made made = {{NULL, NULL, NULL, NULL}, NULL};
    Py_ssize_t index, stop, k;
    int axes[3], side, after_arc, turn, j;
    double radius, sx, sy, cx, cy, qx, qy, px, py, level, gamma, held[2] = {0.0, 0.0};
    (void)self;
    if (!PyArg_ParseTuple(args, "(OOOO)nn(iiiU)id(ddddddddd)pO", &columns[1], &columns[2], &columns[0], &columns[3],
                          &index, &stop, &axes[0], &axes[1], &axes[2], &plane, &side, &radius, &sx, &sy, &cx, &cy,
                          &qx, &qy, &px, &py, &level, &after_arc, &arc_class))
        return NULL;
    if (axes[0] < 0 || axes[0] > 5 || axes[1] < 0 || axes[1] > 5 || axes[2] < 0 || axes[2] > 5
        || axes[0] == axes[1] || axes[0] == axes[2] || axes[1] == axes[2]) {
        PyErr_SetString(PyExc_ValueError, "the plane's axes are three of the six");
        return NULL;
    }
    if (arc_kind == NULL && (arc_kind = PyUnicode_InternFromString("arc")) == NULL)
        return NULL;
    for (j = 0; j < 4; j++)
        if ((made.column[j] = PyList_New(0)) == NULL)
            goto done;
    gamma = side == COMP_LEFT ? M_PI / 2 : -M_PI / 2;  /* comp_geometry.side_angle */
    turn = side == COMP_LEFT ? -1 : 1;
    for (k = index; k < stop; k++) {
        double tx, ty, theta, alpha, beta, hx, hy;
        PyObject *corner = NULL, *pose = PySequence_GetItem(columns[0], k);
        if (pose == NULL)
            goto done;
        if (comp_point(pose, axes[0], axes[1], &tx, &ty) < 0) {
            Py_DECREF(pose);
            goto done;
        }
        if (tx == sx && ty == sy) {  /* no motion in the plane */
            Py_DECREF(pose);
            break;
        }
        theta = py_atan2(cy - sy, cx - sx);  /* line_corner(heading(start, current), heading(start, target)) */
        alpha = py_atan2(ty - sy, tx - sx);
        if (side == COMP_LEFT) {
            if (theta < alpha)
                theta = theta + 2 * M_PI;
            beta = theta - alpha - M_PI / 2;
        } else {
            if (alpha < theta)
                alpha = alpha + 2 * M_PI;
            beta = alpha - theta - M_PI / 2;
        }
        alpha = alpha + gamma;
        if (beta < -COMP_TOLERANCE || beta > M_PI + COMP_TOLERANCE) {  /* inside_corner: half_corner, cut_back */
            double half = (beta + M_PI) / 2.0, distance;
            if (half == 0.0 || (after_arc && previous == NULL)) {  /* after an arc: only a tangent here */
                Py_DECREF(pose);
                break;
            }
            distance = radius / tan(half);
            theta = theta + gamma;
            hx = cx + distance * cos(theta);
            hy = cy + distance * sin(theta);
            if (qx * (hx - px) + qy * (hy - py) < 0) {  /* reverses */
                Py_DECREF(pose);
                break;
            }
            px = hx;
            py = hy;
        } else if (beta > COMP_TOLERANCE) {  /* outside_corner: round the corner point */
            double value[3];
            if ((after_arc && previous == NULL) || qx * (cx - px) + qy * (cy - py) < 0) {  /* reverses */
                Py_DECREF(pose);
                break;
            }
            px = sx + radius * cos(alpha);  /* at(start, radius, alpha + gamma) */
            py = sy + radius * sin(alpha);
            if (fabs(px - cx) < 1e-9 && fabs(py - cy) < 1e-9) {  /* an arc that may be closed */
                Py_DECREF(pose);
                break;
            }
            hx = cx;
            hy = cy;
            value[0] = px;
            value[1] = py;
            value[2] = level;
            if ((corner = comp_pose(pose, axes, value, 3)) == NULL) {
                Py_DECREF(pose);
                goto done;
            }
        } else {
            hx = px = cx;
            hy = py = cy;
        }
        /* the move before this one ends at (hx, hy): the one the stage holds, or the run's last */
        if (previous == NULL) {
            held[0] = hx;
            held[1] = hy;
        } else {
            double value[2] = {hx, hy};
            PyObject *kind, *line, *feed;
            int failed = comp_items(columns, k - 1, &kind, &line, &feed) < 0;
            if (!failed) {
                failed = comp_append(&made, kind, line, comp_pose(previous, axes, value, 2), feed, NULL) < 0;
                Py_DECREF(kind);
                Py_DECREF(line);
                Py_DECREF(feed);
            }
            if (failed) {
                Py_XDECREF(corner);
                Py_DECREF(pose);
                goto done;
            }
        }
        if (corner != NULL) {  /* the tool goes round the corner: an arc, or straight for a rapid */
            PyObject *kind, *line, *feed, *arc = NULL, *zero = NULL;
            int failed = comp_items(columns, k, &kind, &line, &feed) < 0, straight = 1;
            if (!failed) {
                straight = PyUnicode_CompareWithASCIIString(kind, "linear") != 0;
                if (straight)
                    failed = (zero = PyFloat_FromDouble(0.0)) == NULL;
                else  /* centred on the corner point, in the plane's name order (XZ: its first axis is Z) */
                    failed = (arc = PyObject_CallFunction(arc_class, "(dd)Oii", axes[0] == 2 ? sy : sx,
                                                          axes[0] == 2 ? sx : sy, plane, turn, 0)) == NULL;
                if (!failed) {  /* it takes the corner and the arc */
                    failed = comp_append(&made, straight ? rapid_kind : arc_kind, line, corner, straight ? zero : feed,
                                         arc) < 0;
                    corner = NULL;
                }
                Py_DECREF(kind);
                Py_DECREF(line);
                Py_DECREF(feed);
                Py_XDECREF(zero);
            }
            Py_XDECREF(corner);
            if (failed) {
                Py_DECREF(pose);
                goto done;
            }
        }
        Py_XDECREF(previous);
        previous = pose;
        qx = tx - sx;
        qy = ty - sy;
        cx = tx + radius * cos(alpha);  /* at(target, radius, alpha + gamma) */
        cy = ty + radius * sin(alpha);
        sx = tx;
        sy = ty;
        {
            PyObject *item = PySequence_GetItem(pose, axes[2]);
            level = item == NULL ? -1.0 : PyFloat_AsDouble(item);
            Py_XDECREF(item);
            if (PyErr_Occurred())
                goto done;
        }
    }
    result = Py_BuildValue("(n(dd)(OOOOO)(ddddddddd))", k - index, held[0], held[1], made.column[0], made.column[1],
                           made.column[2], made.column[3], made.arcs == NULL ? Py_None : made.arcs, sx, sy, cx, cy,
                           qx, qy, px, py, level);
done:
    Py_XDECREF(previous);
    for (j = 0; j < 4; j++)
        Py_XDECREF(made.column[j]);
    Py_XDECREF(made.arcs);
    return result;
}
