/* Part of csrc/speedups_plan.c (included there, after its constants and the np_* element rules): the
 * planner's window read from Python values (poses, Runs columns, the states and limit sets) and times
 * handed back as a list. */

/* Item i of a list or tuple (any sequence) as a double: -1 with an error set if it is no number. */
static int plan_item(PyObject *seq, Py_ssize_t i, double *out)
{
    PyObject *item;
    int owned = 0;
    if (PyList_Check(seq))
        item = PyList_GetItem(seq, i);
    else if (PyTuple_Check(seq))
        item = PyTuple_GetItem(seq, i);
    else {
        item = PySequence_GetItem(seq, i);
        owned = 1;
    }
    if (item == NULL)
        return -1;
    *out = PyFloat_AsDouble(item);
    if (owned)
        Py_DECREF(item);
    return (*out == -1.0 && PyErr_Occurred()) ? -1 : 0;
}

/* The six numbers of a pose (a sequence of six; a tuple, the usual case, read directly). */
static int plan_pose(PyObject *pose, double out[PLAN_AXES])
{
    int k, failed = 0;
    if (!PyTuple_Check(pose) || PyTuple_Size(pose) != PLAN_AXES) {
        for (k = 0; k < PLAN_AXES; k++)
            if (plan_item(pose, k, &out[k]) < 0)
                return -1;
        return 0;
    }
    for (k = 0; k < PLAN_AXES; k++) {
        out[k] = PyFloat_AsDouble(PyTuple_GetItem(pose, k));
        failed |= out[k] == -1.0;
    }
    return failed && PyErr_Occurred() ? -1 : 0;
}

/* A Runs column (values, counts) as one int per move, for the first n moves. */
static int plan_runs(PyObject *values, PyObject *counts, Py_ssize_t n, long *out)
{
    Py_ssize_t runs = PySequence_Size(values), r, at = 0;
    if (runs < 0)
        return -1;
    for (r = 0; r < runs && at < n; r++) {
        PyObject *v = PySequence_GetItem(values, r), *c = PySequence_GetItem(counts, r);
        long value = v ? PyLong_AsLong(v) : -1;
        Py_ssize_t count = c ? PyLong_AsSsize_t(c) : -1;
        Py_XDECREF(v);
        Py_XDECREF(c);
        if (PyErr_Occurred())
            return -1;
        for (; count > 0 && at < n; count--)
            out[at++] = value;
    }
    if (at < n) {
        PyErr_SetString(PyExc_ValueError, "plan_window: the runs hold fewer moves than the window");
        return -1;
    }
    return 0;
}

/* One machine state (Planner._states): exact stop, G64 P, feed factor, the limit sets of rapids and of the rest. */
typedef struct {
    int exact;
    double tolerance, factor;
    long rapid_limits, other_limits;
} PlanState;

/* The states table and the limit sets (velocity, acceleration: six each) as C values. */
static PlanState *plan_states(PyObject *table, Py_ssize_t *count)
{
    Py_ssize_t size = PySequence_Size(table), i;
    PlanState *states;
    if (size < 0 || (states = PyMem_Malloc(((size_t)size + 1) * sizeof(PlanState))) == NULL)
        return NULL;
    for (i = 0; i < size; i++) {
        PyObject *row = PySequence_GetItem(table, i), *item;
        int bad = row == NULL;
        if (!bad) {
            item = PySequence_GetItem(row, 0);
            states[i].exact = item ? PyObject_IsTrue(item) : -1;
            Py_XDECREF(item);
            bad = states[i].exact < 0 || plan_item(row, 1, &states[i].tolerance) < 0
                  || plan_item(row, 2, &states[i].factor) < 0;
            if (!bad) {
                PyObject *r = PySequence_GetItem(row, 3), *o = PySequence_GetItem(row, 4);
                states[i].rapid_limits = r ? PyLong_AsLong(r) : -1;
                states[i].other_limits = o ? PyLong_AsLong(o) : -1;
                Py_XDECREF(r);
                Py_XDECREF(o);
                bad = PyErr_Occurred() != NULL;
            }
        }
        Py_XDECREF(row);
        if (bad) {
            PyMem_Free(states);
            return NULL;
        }
    }
    *count = size;
    return states;
}

static double *plan_limits(PyObject *sets, Py_ssize_t *count)
{
    Py_ssize_t size = PySequence_Size(sets), i;
    double *limits;
    if (size < 0 || (limits = PyMem_Malloc(((size_t)size + 1) * 2 * PLAN_AXES * sizeof(double))) == NULL)
        return NULL;
    for (i = 0; i < size; i++) {
        PyObject *pair = PySequence_GetItem(sets, i), *v = NULL, *a = NULL;
        int bad = pair == NULL;
        if (!bad) {
            v = PySequence_GetItem(pair, 0);
            a = PySequence_GetItem(pair, 1);
            bad = v == NULL || a == NULL || plan_pose(v, limits + 2 * PLAN_AXES * i) < 0
                  || plan_pose(a, limits + 2 * PLAN_AXES * i + PLAN_AXES) < 0;
        }
        Py_XDECREF(v);
        Py_XDECREF(a);
        Py_XDECREF(pair);
        if (bad) {
            PyMem_Free(limits);
            return NULL;
        }
    }
    *count = size;
    return limits;
}

static PyObject *plan_list(const double *values, Py_ssize_t count)
{
    PyObject *list = PyList_New(count);
    Py_ssize_t i;
    if (list == NULL)
        return NULL;
    for (i = 0; i < count; i++) {
        PyObject *f = PyFloat_FromDouble(values[i]);
        if (f == NULL || PyList_SetItem(list, i, f) < 0) {
            Py_DECREF(list);
            return NULL;
        }
    }
    return list;
}
