/* Part of _lexer.c (one translation unit: included there, in this order). The linter's look at a block: block_facts() and expr_reads(). */

/* ------------------------------------------------------------------------------------------
 * The linter's look at a block (lint/facts.py, whose Python functions are the reference).
 *
 * block_facts(code_key, literal_index, block, scope, uses, targets): (g, m, coded, reads) as
 * facts.block_facts gives them: the literal G and M numbers of the block as (code_key(value), word)
 * in line order, whether it has a G, M or T word at all, and every parameter it reads as (param,
 * literal index) in walk.reads order, each also appended to ``uses`` as (param, literal index,
 * scope); every assignment target is appended to ``targets`` the same way.  expr_reads(literal_index, expr): the (param, literal index) pairs of one expression in
 * evaluate.params_in order.  The two callables are the Python ones, called where the value is not
 * the plain case (a computed index, a number too large to round here).
 */

/* literal_index(param) for a #n whose n is a Number (the Python function for any other). */
static PyObject *literal_of(PyObject *param, PyObject *literal_index)
{
    PyObject *index = get_field(param, PARAM, F_INDEX), *result;
    double value;
    if (index == NULL)
        return NULL;
    if (!Py_IS_TYPE(index, (PyTypeObject *)classes[NUMBER])) {
        Py_DECREF(index);
        return PyObject_CallFunctionObjArgs(literal_index, param, NULL);
    }
    result = get_field(index, NUMBER, F_VALUE);
    Py_DECREF(index);
    if (result == NULL)
        return NULL;
    value = PyFloat_AsDouble(result);
    Py_DECREF(result);
    if (value == -1.0 && PyErr_Occurred())
        return NULL;
    if (isfinite(value) && floor(value) == value)  /* float.is_integer() */
        return PyLong_FromDouble(value);
    Py_RETURN_NONE;
}

/* Append (param, literal index) for every parameter of ``expr`` to ``out``, outer ones first, left to
 * right (evaluate.params_in); 0, or -1 with an exception. */
static int reads_into(PyObject *out, PyObject *expr, PyObject *literal_index)
{
    static const int two[] = {F_LEFT, F_RIGHT};
    PyTypeObject *type = Py_TYPE(expr);
    PyObject *child;
    int k, failed;
    if (type == (PyTypeObject *)classes[NUMBER])
        return 0;
    if (type == (PyTypeObject *)classes[PARAM]) {
        PyObject *literal = literal_of(expr, literal_index), *pair;
        if (literal == NULL)
            return -1;
        pair = PyTuple_Pack(2, expr, literal);
        Py_DECREF(literal);
        if (append_new(out, pair) < 0)
            return -1;
        if ((child = get_field(expr, PARAM, F_INDEX)) == NULL)
            return -1;
        failed = reads_into(out, child, literal_index);
        Py_DECREF(child);
        return failed;
    }
    if (type == (PyTypeObject *)classes[BINARY] || type == (PyTypeObject *)classes[COMPARE]) {
        for (k = 0; k < 2; k++) {
            if ((child = get_field(expr, type == (PyTypeObject *)classes[BINARY] ? BINARY : COMPARE, two[k])) == NULL)
                return -1;
            failed = reads_into(out, child, literal_index);
            Py_DECREF(child);
            if (failed)
                return -1;
        }
        return 0;
    }
    if (type == (PyTypeObject *)classes[UNARY]) {
        if ((child = get_field(expr, UNARY, F_OPERAND)) == NULL)
            return -1;
        failed = reads_into(out, child, literal_index);
        Py_DECREF(child);
        return failed;
    }
    if (type == (PyTypeObject *)classes[CALL]) {
        PyObject *args = get_field(expr, CALL, F_ARGS);
        Py_ssize_t i, count;
        if (args == NULL)
            return -1;
        count = PyTuple_Size(args);
        for (i = 0; i < count; i++)
            if (reads_into(out, PyTuple_GetItem(args, i), literal_index) < 0) {
                Py_DECREF(args);
                return -1;
            }
        Py_DECREF(args);
    }
    return 0;
}

static PyObject *expr_reads(PyObject *self, PyObject *args)
{
    PyObject *expr, *literal_index, *out;
    (void)self;
    if (!ready() || !PyArg_ParseTuple(args, "OO", &literal_index, &expr))
        return NULL;
    if ((out = PyList_New(0)) != NULL && reads_into(out, expr, literal_index) < 0)
        Py_CLEAR(out);
    return out;
}

/* (code_key(value), word) appended to ``out``: integer tenths, rounded half to even as round() does. */
static int code_into(PyObject *out, PyObject *number, PyObject *word, PyObject *code_key)
{
    PyObject *value = get_field(number, NUMBER, F_VALUE), *key, *pair;
    double tenths;
    if (value == NULL)
        return -1;
    tenths = PyFloat_AsDouble(value) * 10.0;
    if (tenths == -10.0 && PyErr_Occurred()) {
        Py_DECREF(value);
        return -1;
    }
    if (isfinite(tenths) && fabs(tenths) < 1e15)
        key = PyLong_FromDouble(nearbyint(tenths));
    else
        key = PyObject_CallFunctionObjArgs(code_key, value, NULL);  /* the Python function decides (or raises) */
    Py_DECREF(value);
    if (key == NULL)
        return -1;
    pair = PyTuple_Pack(2, key, word);
    Py_DECREF(key);
    return append_new(out, pair) < 0 ? -1 : 0;
}

/* Append (param, literal index, scope) to ``uses`` for every pair of ``pairs``. */
static int uses_into(PyObject *uses, PyObject *pairs, PyObject *scope)
{
    Py_ssize_t i, count = PyList_Size(pairs);
    for (i = 0; i < count; i++) {
        PyObject *pair = PyList_GetItem(pairs, i);
        if (append_new(uses, PyTuple_Pack(3, PyTuple_GetItem(pair, 0), PyTuple_GetItem(pair, 1), scope)) < 0)
            return -1;
    }
    return 0;
}

static PyObject *block_facts_of(PyObject *code_key, PyObject *literal_index, PyObject *block, PyObject *scope,
                                PyObject *uses, PyObject *targets)
{
    PyObject *words = NULL, *assigns = NULL, *g = NULL, *m = NULL, *reads = NULL, *result = NULL,
             *g_tuple = NULL, *m_tuple = NULL, *reads_tuple = NULL;
    Py_ssize_t i, count;
    int coded = 0;
    if ((words = get_field(block, BLOCK, F_WORDS)) == NULL
            || (assigns = get_field(block, BLOCK, F_ASSIGNS)) == NULL
            || (g = PyList_New(0)) == NULL || (m = PyList_New(0)) == NULL || (reads = PyList_New(0)) == NULL)
        goto done;
    count = PyTuple_Size(words);
    for (i = 0; i < count; i++) {
        PyObject *word = PyTuple_GetItem(words, i), *letter, *value;
        Py_UCS4 c = 0;
        int failed = 0;
        if ((letter = get_field(word, WORD, F_LETTER)) == NULL)
            goto done;
        if (PyUnicode_GetLength(letter) == 1)
            c = PyUnicode_ReadChar(letter, 0);
        Py_DECREF(letter);
        if ((value = get_field(word, WORD, F_VALUE)) == NULL)
            goto done;
        if (c == 'G' || c == 'M' || c == 'T')
            coded = 1;
        if (Py_IS_TYPE(value, (PyTypeObject *)classes[NUMBER])) {
            if (c == 'G' || c == 'M')
                failed = code_into(c == 'G' ? g : m, value, word, code_key);
        } else {
            failed = reads_into(reads, value, literal_index);
        }
        Py_DECREF(value);
        if (failed)
            goto done;
    }
    count = PyTuple_Size(assigns);
    for (i = 0; i < count; i++) {
        PyObject *assign = PyTuple_GetItem(assigns, i), *target, *index = NULL, *value = NULL;
        int failed = -1;
        if ((target = get_field(assign, ASSIGN, F_TARGET)) != NULL
                && (index = get_field(target, PARAM, F_INDEX)) != NULL
                && (value = get_field(assign, ASSIGN, F_VALUE)) != NULL)
            failed = reads_into(reads, index, literal_index) || reads_into(reads, value, literal_index);
        Py_XDECREF(index);
        Py_XDECREF(value);
        if (!failed) {  /* the target, its literal index and where: one of the file's assignments */
            PyObject *literal = literal_of(target, literal_index);
            failed = append_new(targets, literal ? PyTuple_Pack(3, target, literal, scope) : NULL) < 0;
            Py_XDECREF(literal);
        }
        Py_XDECREF(target);
        if (failed)
            goto done;
    }
    if (uses_into(uses, reads, scope) < 0 || (g_tuple = PyList_AsTuple(g)) == NULL
            || (m_tuple = PyList_AsTuple(m)) == NULL || (reads_tuple = PyList_AsTuple(reads)) == NULL)
        goto done;
    result = PyTuple_Pack(4, g_tuple, m_tuple, coded ? Py_True : Py_False, reads_tuple);
done:
    Py_XDECREF(words);
    Py_XDECREF(assigns);
    Py_XDECREF(g);
    Py_XDECREF(m);
    Py_XDECREF(reads);
    Py_XDECREF(g_tuple);
    Py_XDECREF(m_tuple);
    Py_XDECREF(reads_tuple);
    return result;
}

static PyObject *block_facts(PyObject *self, PyObject *args)
{
    PyObject *block, *code_key, *literal_index, *scope, *uses, *targets;
    (void)self;
    if (!ready() || !PyArg_ParseTuple(args, "OOOOO!O!", &code_key, &literal_index, &block, &scope, &PyList_Type,
                                      &uses, &PyList_Type, &targets))
        return NULL;
    return block_facts_of(code_key, literal_index, block, scope, uses, targets);
}

