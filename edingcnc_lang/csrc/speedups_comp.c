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

/* comp_geometry.Frame.poses for one pose: ``pose`` as a tuple with its in-plane values replaced. */
static PyObject *comp_pose(PyObject *pose, int first, int second, double x, double y)
{
    PyObject *made = PyTuple_New(6);
    Py_ssize_t k;
    for (k = 0; made != NULL && k < 6; k++) {
        PyObject *item = k == first ? PyFloat_FromDouble(x) : k == second ? PyFloat_FromDouble(y)
                                                                           : PySequence_GetItem(pose, k);
        if (item == NULL || PyTuple_SetItem(made, k, item) < 0)
            Py_CLEAR(made);
    }
    return made;
}

/* comp_runs.comp_lines, compiled: see its docstring for the arguments and what it returns. */
static PyObject *comp_lines(PyObject *self, PyObject *args)
{
    PyObject *ends, *poses = NULL, *previous = NULL, *result = NULL;
    Py_ssize_t index, stop, k;
    int first, second, side;
    double radius, sx, sy, cx, cy, qx, qy, px, py, gamma, held_x = 0.0, held_y = 0.0;
    (void)self;
    if (!PyArg_ParseTuple(args, "Onniiid(dd)(dd)(dd)(dd)", &ends, &index, &stop, &first, &second, &side, &radius,
                          &sx, &sy, &cx, &cy, &qx, &qy, &px, &py))
        return NULL;
    if (first < 0 || first > 5 || second < 0 || second > 5 || first == second) {
        PyErr_SetString(PyExc_ValueError, "the plane's axes are two of the six");
        return NULL;
    }
    if ((poses = PyList_New(0)) == NULL)
        return NULL;
    gamma = side == COMP_LEFT ? M_PI / 2 : -M_PI / 2;  /* comp_geometry.side_angle */
    for (k = index; k < stop; k++) {
        double tx, ty, theta, alpha, beta, hx, hy;
        int concave;
        PyObject *pose = PySequence_GetItem(ends, k);
        if (pose == NULL)
            goto done;
        if (comp_point(pose, first, second, &tx, &ty) < 0) {
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
        concave = beta < -COMP_TOLERANCE || beta > M_PI + COMP_TOLERANCE;  /* inside_corner */
        if (!concave && beta > COMP_TOLERANCE) {  /* outside_corner: the tool goes round it */
            Py_DECREF(pose);
            break;
        }
        if (concave) {
            double half = (beta + M_PI) / 2.0, distance;  /* half_corner, cut_back */
            if (half == 0.0) {
                Py_DECREF(pose);
                break;
            }
            distance = radius / tan(half);
            theta = theta + gamma;
            hx = cx + distance * cos(theta);
            hy = cy + distance * sin(theta);
            if (qx * (hx - px) + qy * (hy - py) < 0) {  /* reverses: the stage refuses it */
                Py_DECREF(pose);
                break;
            }
        } else {
            hx = cx;
            hy = cy;
        }
        /* the move before this one ends at (hx, hy): the one the stage holds, or the run's last */
        if (previous == NULL) {
            held_x = hx;
            held_y = hy;
        } else if (append_new(poses, comp_pose(previous, first, second, hx, hy)) < 0) {
            Py_DECREF(pose);
            goto done;
        }
        Py_XDECREF(previous);
        previous = pose;
        qx = tx - sx;
        qy = ty - sy;
        px = hx;
        py = hy;
        alpha = alpha + gamma;  /* at(target, radius, alpha + gamma) */
        cx = tx + radius * cos(alpha);
        cy = ty + radius * sin(alpha);
        sx = tx;
        sy = ty;
    }
    result = Py_BuildValue("(n(dd)O(dddddddd))", k - index, held_x, held_y, poses, cx, cy, qx, qy, px, py, sx, sy);
done:
    Py_XDECREF(previous);
    Py_DECREF(poses);
    return result;
}
