/* Part of _speedups.c (one translation unit: included there, in this order). Runs of plain corners of cutter
 * compensation (pipeline/comp_runs.py's comp_lines): the straight-on and inside line-line corners of a run of
 * straight moves under G41/G42, one after the other, as pipeline/cutter_comp.py's _straight computes each
 * (comp_geometry's line_corner, at, cut_back and reverses).  Every double is computed as Python computes it:
 * atan2 is CPython's m_atan2 (py_atan2, speedups_arcs.c), cos, sin and tan are the C library's, as math's are. */

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
        PyObject *item = NULL;
        int j;
        for (j = 0; j < count && at[j] != k; j++)
            ;
        item = j < count ? PyFloat_FromDouble(value[j]) : PySequence_GetItem(pose, k);
        if (item == NULL || PyTuple_SetItem(made, k, item) < 0)
            Py_CLEAR(made);
    }
    return made;
}

/* comp_runs.comp_lines, compiled: see its docstring for the arguments and what it returns. */
static PyObject *comp_lines(PyObject *self, PyObject *args)
{
    PyObject *ends, *poses = NULL, *corners = NULL, *previous = NULL, *result = NULL;
    Py_ssize_t index, stop, k;
    int axes[3], side;
    double radius, sx, sy, cx, cy, qx, qy, px, py, level, gamma, held[2] = {0.0, 0.0};
    (void)self;
    if (!PyArg_ParseTuple(args, "Onn(iii)id(ddddddddd)", &ends, &index, &stop, &axes[0], &axes[1], &axes[2], &side,
                          &radius, &sx, &sy, &cx, &cy, &qx, &qy, &px, &py, &level))
        return NULL;
    if (axes[0] < 0 || axes[0] > 5 || axes[1] < 0 || axes[1] > 5 || axes[2] < 0 || axes[2] > 5
        || axes[0] == axes[1] || axes[0] == axes[2] || axes[1] == axes[2]) {
        PyErr_SetString(PyExc_ValueError, "the plane's axes are three of the six");
        return NULL;
    }
    if ((poses = PyList_New(0)) == NULL || (corners = PyList_New(0)) == NULL)
        goto done;
    gamma = side == COMP_LEFT ? M_PI / 2 : -M_PI / 2;  /* comp_geometry.side_angle */
    for (k = index; k < stop; k++) {
        double tx, ty, theta, alpha, beta, hx, hy;
        PyObject *pose = PySequence_GetItem(ends, k);
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
            if (half == 0.0) {
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
            PyObject *corner;
            if (qx * (cx - px) + qy * (cy - py) < 0) {  /* reverses */
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
            corner = comp_pose(pose, axes, value, 3);
            if (corner == NULL || append_new(corners, Py_BuildValue("(nNdd)", k, corner, sx, sy)) < 0) {
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
            if (append_new(poses, comp_pose(previous, axes, value, 2)) < 0) {
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
    result = Py_BuildValue("(n(dd)OO(ddddddddd))", k - index, held[0], held[1], poses, corners, sx, sy, cx, cy, qx, qy,
                           px, py, level);
done:
    Py_XDECREF(previous);
    Py_XDECREF(poses);
    Py_XDECREF(corners);
    return result;
}
