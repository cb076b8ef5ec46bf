/* Part of _lexer.c (one translation unit: included there, in this order). The block structure of the
 * lines read inside a block: assemble().
 *
 * assemble(results, k, lines, offset, stack, frame_class, max_depth): what syntax.parser.StatementReader
 * does (StatementReader._fit, the reference, which the pure-Python reader runs for every line) with
 * statements()'s results from index ``k`` on while a block is open: a blank line is skipped, a
 * statement is added to the innermost open block (its Else part after an Else), an If or While head
 * opens a block (``frame_class(opener, line)`` pushed on ``stack``, the list of open _Frame objects),
 * an end line that matches the innermost block closes it (``frame.close(span)``, added to the block
 * around it) and an Else switches an If to its Else part. It stops, leaving the line to the Python
 * path, at anything else: a give-up marker, a dlgmsg, a Sub head, an end line that does not match,
 * a second Else, a block nested ``max_depth`` deep. Returns (the index it stopped at, the statement
 * that closed the outermost block or None); with that statement it stops right after its end line.
 * The line of ``results[i]`` is ``lines[offset + i]``.
 */
enum { A_OPENER, A_BODY, A_ORELSE, A_IN_ELSE, A_CLOSE, N_ATTRS };
static const char *const ATTR_NAMES[N_ATTRS] = {"opener", "body", "orelse", "in_else", "close"};
static PyObject *attrs[N_ATTRS];

/* The list a frame adds to: its orelse after an Else, else its body (a new reference). */
static PyObject *frame_list(PyObject *frame)
{
    PyObject *in_else = PyObject_GetAttr(frame, attrs[A_IN_ELSE]);
    int yes;
    if (in_else == NULL)
        return NULL;
    yes = PyObject_IsTrue(in_else);
    Py_DECREF(in_else);
    return yes < 0 ? NULL : PyObject_GetAttr(frame, attrs[yes ? A_ORELSE : A_BODY]);
}

/* 1 if ``obj.kind`` is ``want``, 0 if not, -1 on an error. */
static int kind_is(PyObject *obj, PyObject *want)
{
    PyObject *kind = get_field(obj, OPEN, F_KIND);
    int same;
    if (kind == NULL)
        return -1;
    same = PyUnicode_Check(kind) && PyUnicode_Compare(kind, want) == 0;
    Py_DECREF(kind);
    return PyErr_Occurred() ? -1 : same;
}

/* The opener kind an end line's kind closes (Else belongs to an If); NULL for another kind. */
static PyObject *opener_of(PyObject *close)
{
    static const int pairs[][2] = {{K_ENDSUB, K_SUB}, {K_ENDIF, K_IF}, {K_ENDWHILE, K_WHILE}, {K_ELSE, K_IF}};
    size_t k;
    for (k = 0; k < sizeof pairs / sizeof pairs[0]; k++) {
        int same = kind_is(close, handled_text[pairs[k][0]]);
        if (same != 0)
            return same < 0 ? NULL : handled_text[pairs[k][1]];
    }
    return NULL;
}

/* An end line or Else ``close`` on the innermost frame: 1 done (``*finished`` set when the outermost
 * block closed), 0 left to the Python path, -1 on an error. */
static int close_block(PyObject *stack, PyObject *close, PyObject **finished)
{
    Py_ssize_t depth = PyList_Size(stack);
    PyObject *frame = PyList_GetItem(stack, depth - 1), *opener, *want, *span, *stmt, *in_else, *list;
    int fits, is_else, failed;
    if (frame == NULL || (want = opener_of(close)) == NULL)
        return PyErr_Occurred() ? -1 : 0;
    if ((opener = PyObject_GetAttr(frame, attrs[A_OPENER])) == NULL)
        return -1;
    fits = kind_is(opener, want);
    Py_DECREF(opener);
    if (fits <= 0)
        return fits;
    if ((is_else = kind_is(close, handled_text[K_ELSE])) != 0) {
        if (is_else < 0 || (in_else = PyObject_GetAttr(frame, attrs[A_IN_ELSE])) == NULL)
            return -1;
        fits = PyObject_Not(in_else);
        Py_DECREF(in_else);
        if (fits <= 0)  /* a second Else: S206, from the Python path */
            return fits;
        return PyObject_SetAttr(frame, attrs[A_IN_ELSE], Py_True) < 0 ? -1 : 1;
    }
    if ((span = get_field(close, CLOSE, F_SPAN)) == NULL)
        return -1;
    Py_INCREF(frame);  /* kept through its removal from the stack */
    stmt = PyObject_CallMethodObjArgs(frame, attrs[A_CLOSE], span, NULL);
    Py_DECREF(span);
    failed = stmt == NULL || PyList_SetSlice(stack, depth - 1, depth, NULL) < 0;
    Py_DECREF(frame);
    if (failed) {
        Py_XDECREF(stmt);
        return -1;
    }
    if (depth == 1) {
        *finished = stmt;
        return 1;
    }
    if ((list = frame_list(PyList_GetItem(stack, depth - 2))) == NULL) {
        Py_DECREF(stmt);
        return -1;
    }
    failed = PyList_Append(list, stmt);
    Py_DECREF(list);
    Py_DECREF(stmt);
    return failed < 0 ? -1 : 1;
}

static PyObject *assemble(PyObject *self, PyObject *args)
{
    PyObject *results, *lines, *stack, *frame_class, *list = NULL, *finished = NULL;
    Py_ssize_t k, offset, max_depth, count;
    int done = 0;
    (void)self;
    if (!ready() || !PyArg_ParseTuple(args, "O!nO!nO!On", &PyList_Type, &results, &k, &PyList_Type, &lines,
                                      &offset, &PyList_Type, &stack, &frame_class, &max_depth))
        return NULL;
    if (give_up_marker == NULL || classes[OPEN] == NULL) {
        PyErr_SetString(PyExc_RuntimeError, "_lexer.setup() was not given the block module");
        return NULL;
    }
    if (attrs[0] == NULL && intern_all(attrs, ATTR_NAMES, N_ATTRS) < 0)
        return NULL;
    for (count = PyList_Size(results); k < count && PyList_Size(stack) > 0 && !done; k++) {
        PyObject *result = PyList_GetItem(results, k), *frame;
        int sub;
        if (result == Py_None)  /* a blank or comment line */
            continue;
        if (result == give_up_marker || Py_IS_TYPE(result, (PyTypeObject *)classes[DIALOG]))
            break;
        if (Py_IS_TYPE(result, (PyTypeObject *)classes[OPEN])) {
            if ((sub = kind_is(result, handled_text[K_SUB])) != 0 || PyList_Size(stack) >= max_depth) {
                if (sub < 0)
                    goto error;
                break;
            }
            frame = PyObject_CallFunctionObjArgs(frame_class, result, PyList_GetItem(lines, offset + k), NULL);
            if (append_new(stack, frame) < 0)
                goto error;
            Py_CLEAR(list);
        } else if (Py_IS_TYPE(result, (PyTypeObject *)classes[CLOSE])) {
            if ((done = close_block(stack, result, &finished)) <= 0) {
                if (done < 0)
                    goto error;
                break;
            }
            done = finished != NULL;
            Py_CLEAR(list);
        } else {
            if (list == NULL && (list = frame_list(PyList_GetItem(stack, PyList_Size(stack) - 1))) == NULL)
                goto error;
            if (PyList_Append(list, result) < 0)
                goto error;
        }
    }
    Py_XDECREF(list);
    return Py_BuildValue("(nN)", k, finished != NULL ? finished : (Py_INCREF(Py_None), Py_None));
error:
    Py_XDECREF(list);
    Py_XDECREF(finished);
    return NULL;
}
