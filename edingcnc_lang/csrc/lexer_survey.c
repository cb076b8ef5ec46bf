/* Part of _lexer.c (one translation unit: included there, in this order). The linter's walk: survey(). */

/* survey(code_key, literal_index, scope_class, simulation_branches, other_reads, codes_class, end_keys,
 * simulation, into, body, scope): lint.facts._Survey.visit(body, scope) on ``into`` (a _Survey, whose
 * lists and dicts it fills), the same walk in the same order; the Python method is the reference.
 * The callables are the Python ones: Scope, walk.simulation_branches (for an If that reads #5380),
 * the reads of the rare statements (logfile, KIN, ...), BlockCodes. */
typedef struct {
    PyObject *walked, *coded, *uses, *targets, *dialogs, *commands, *callers, *heads, *reads_of, *codes_of,
             *ending, *unreachable;
    PyObject *code_key, *literal_index, *scope_class, *simulation_branches, *other_reads, *codes_class,
             *end_keys, *simulation;
} Survey;

static const char *const SURVEY_LISTS[] = {"walked", "coded", "reads", "targets", "dialogs", "commands", "callers",
                                           "heads", "reads_of", "codes_of", "ending", "unreachable"};
#define N_SURVEY_LISTS (sizeof(SURVEY_LISTS) / sizeof(SURVEY_LISTS[0]))

static int append_pair(PyObject *list, PyObject *first, PyObject *second)
{
    return append_new(list, PyTuple_Pack(2, first, second)) < 0 ? -1 : 0;
}

static int set_by_id(PyObject *dict, PyObject *stmt, PyObject *value)
{
    PyObject *key = PyLong_FromVoidPtr(stmt);  /* id(stmt) */
    int failed = key == NULL || PyDict_SetItem(dict, key, value) < 0;
    Py_XDECREF(key);
    return failed ? -1 : 0;
}

/* The reads of a statement other than a block: reads_of[id(stmt)] and the uses, when there are any. */
static int add_reads(Survey *sv, PyObject *stmt, PyObject *pairs, PyObject *here)
{
    PyObject *found;
    int failed;
    if (PyList_Size(pairs) == 0)
        return 0;
    if ((found = PyList_AsTuple(pairs)) == NULL)
        return -1;
    failed = set_by_id(sv->reads_of, stmt, found) < 0 || uses_into(sv->uses, pairs, here) < 0;
    Py_DECREF(found);
    return failed ? -1 : 0;
}

static int survey_list(Survey *sv, PyObject *body, PyObject *scope);

static int survey_attr(Survey *sv, PyObject *stmt, int field, PyObject *scope)
{
    PyObject *body = PyObject_GetAttr(stmt, fields[field]);
    int failed = body == NULL || survey_list(sv, body, scope) < 0;
    Py_XDECREF(body);
    return failed ? -1 : 0;
}

/* A block: its facts (block_facts above), the coded ones as BlockCodes, the callers, the ends. */
static int survey_block(Survey *sv, PyObject *stmt, PyObject *here, int *ends)
{
    PyObject *facts = block_facts_of(sv->code_key, sv->literal_index, stmt, here, sv->uses, sv->targets), *g, *m;
    Py_ssize_t i, count;
    int failed = -1;
    if (facts == NULL)
        return -1;
    g = PyTuple_GetItem(facts, 0);
    m = PyTuple_GetItem(facts, 1);
    if (PyTuple_Size(PyTuple_GetItem(facts, 3)) > 0 && set_by_id(sv->reads_of, stmt, PyTuple_GetItem(facts, 3)) < 0)
        goto done;
    if (PyTuple_GetItem(facts, 2) == Py_True) {
        PyObject *codes = PyType_GenericAlloc((PyTypeObject *)sv->codes_class, 4), *items[4] = {stmt, here, g, m};
        int k, bad;
        if (codes == NULL)
            goto done;
        for (k = 0; k < 4; k++) {
            Py_INCREF(items[k]);
            PyTuple_SetItem(codes, k, items[k]);
        }
        bad = PyList_Append(sv->coded, codes) < 0 || set_by_id(sv->codes_of, stmt, codes) < 0;
        Py_DECREF(codes);
        if (bad)
            goto done;
    }
    count = PyTuple_Size(m);
    if (count > 0) {
        PyObject *block_delete;
        int deleted;
        if (append_pair(sv->callers, stmt, here) < 0 || (block_delete = get_field(stmt, BLOCK, F_BLOCK_DELETE)) == NULL)
            goto done;
        deleted = PyObject_IsTrue(block_delete);
        Py_DECREF(block_delete);
        if (deleted < 0)
            goto done;
        for (i = 0; i < count && !deleted && !*ends; i++) {
            int found = PySet_Contains(sv->end_keys, PyTuple_GetItem(PyTuple_GetItem(m, i), 0));
            if (found < 0)
                goto done;
            *ends = found;
        }
    }
    failed = 0;
done:
    Py_DECREF(facts);
    return failed;
}

/* An If or a While: its condition's reads, then its branches or body (an If that reads #5380 or #5397 with
 * the scopes walk.simulation_branches gives); ``*here`` becomes the guarded scope after an If that
 * ends the program in simulation. */
static int survey_head(Survey *sv, PyObject *stmt, PyObject *scope, PyObject **here, int is_while)
{
    PyObject *cond, *pairs = PyList_New(0), *guarded = NULL, *branches = NULL, *sub = NULL;
    Py_ssize_t i;
    int failed = -1, reads_simulation = 0;
    if (pairs == NULL || PyList_Append(sv->heads, stmt) < 0 || (cond = PyObject_GetAttr(stmt, fields[F_COND])) == NULL)
        goto done;
    i = reads_into(pairs, cond, sv->literal_index);
    Py_DECREF(cond);
    if (i < 0 || add_reads(sv, stmt, pairs, *here) < 0)
        goto done;
    if (is_while) {
        failed = survey_attr(sv, stmt, F_BODY, *here);
        goto done;
    }
    for (i = 0; i < PyList_Size(pairs) && !reads_simulation; i++) {
        reads_simulation = PySequence_Contains(sv->simulation, PyTuple_GetItem(PyList_GetItem(pairs, i), 1));
        if (reads_simulation < 0)
            goto done;
    }
    if (!reads_simulation) {
        failed = survey_attr(sv, stmt, F_THEN, *here) < 0 || survey_attr(sv, stmt, F_ORELSE, *here) < 0 ? -1 : 0;
        goto done;
    }
    {
        int then_guard, else_guard, exits, was_guarded;
        PyObject *flag;
        if ((branches = PyObject_CallFunctionObjArgs(sv->simulation_branches, stmt, NULL)) == NULL
                || (sub = PyObject_GetAttr(scope, fields[F_SUB])) == NULL
                || (guarded = PyObject_CallFunctionObjArgs(sv->scope_class, sub, Py_True, NULL)) == NULL)
            goto done;
        if (!PyTuple_Check(branches) || PyTuple_Size(branches) != 3) {
            PyErr_SetString(PyExc_TypeError, "simulation_branches must give three flags");
            goto done;
        }
        if ((then_guard = PyObject_IsTrue(PyTuple_GetItem(branches, 0))) < 0
                || (else_guard = PyObject_IsTrue(PyTuple_GetItem(branches, 1))) < 0
                || (exits = PyObject_IsTrue(PyTuple_GetItem(branches, 2))) < 0)
            goto done;
        if (survey_attr(sv, stmt, F_THEN, then_guard ? guarded : *here) < 0
                || survey_attr(sv, stmt, F_ORELSE, else_guard ? guarded : *here) < 0
                || (flag = PyObject_GetAttr(*here, fields[F_GUARDED])) == NULL)
            goto done;
        was_guarded = PyObject_IsTrue(flag);
        Py_DECREF(flag);
        if (was_guarded < 0)
            goto done;
        if (!was_guarded && exits) {  /* the rest of this list only runs on a real machine */
            Py_INCREF(guarded);
            Py_DECREF(*here);
            *here = guarded;
        }
        failed = 0;
    }
done:
    Py_XDECREF(pairs);
    Py_XDECREF(guarded);
    Py_XDECREF(branches);
    Py_XDECREF(sub);
    return failed;
}

static int survey_list(Survey *sv, PyObject *body, PyObject *scope)
{
    PyObject *here = scope, *end = NULL, *seq = PySequence_Tuple(body);
    Py_ssize_t i, count;
    int dead = 0, failed = -1;
    if (seq == NULL)
        return -1;
    Py_INCREF(here);
    count = PyTuple_Size(seq);
    for (i = 0; i < count; i++) {
        PyObject *stmt = PyTuple_GetItem(seq, i);
        int ends = 0, is_sub = 0;
        if (append_pair(sv->walked, stmt, here) < 0)
            goto done;
        if (PyObject_TypeCheck(stmt, (PyTypeObject *)classes[BLOCK])) {
            if (survey_block(sv, stmt, here, &ends) < 0)
                goto done;
        } else if (PyObject_TypeCheck(stmt, (PyTypeObject *)classes[SUB])) {
            PyObject *inner = PyObject_CallFunctionObjArgs(sv->scope_class, stmt, Py_False, NULL);
            int bad = inner == NULL || survey_attr(sv, stmt, F_BODY, inner) < 0;
            Py_XDECREF(inner);
            if (bad)
                goto done;
            is_sub = 1;
        } else if (PyObject_TypeCheck(stmt, (PyTypeObject *)classes[IF])
                   || PyObject_TypeCheck(stmt, (PyTypeObject *)classes[WHILE])) {
            if (survey_head(sv, stmt, scope, &here, PyObject_TypeCheck(stmt, (PyTypeObject *)classes[WHILE])) < 0)
                goto done;
        } else if (PyObject_TypeCheck(stmt, (PyTypeObject *)classes[DIALOG])) {
            if (append_pair(sv->dialogs, stmt, here) < 0)
                goto done;
        } else {
            PyObject *pairs;
            int bad;
            if (PyObject_TypeCheck(stmt, (PyTypeObject *)classes[MESSAGE])) {
                PyObject *items = get_field(stmt, MESSAGE, F_ITEMS), *kind;
                Py_ssize_t k;
                if (items == NULL || (pairs = PyList_New(0)) == NULL) {
                    Py_XDECREF(items);
                    goto done;
                }
                for (k = 0, bad = 0; k < PyTuple_Size(items) && !bad; k++) {
                    PyObject *item = PyTuple_GetItem(items, k);
                    if (!PyUnicode_Check(item) && !PyObject_TypeCheck(item, (PyTypeObject *)classes[STAMP]))
                        bad = reads_into(pairs, item, sv->literal_index) < 0;
                }
                Py_DECREF(items);
                if (!bad && (kind = get_field(stmt, MESSAGE, F_KIND)) != NULL) {
                    ends = PyUnicode_Check(kind) && PyUnicode_CompareWithASCIIString(kind, "errmsg") == 0;
                    Py_DECREF(kind);
                } else {
                    bad = 1;
                }
            } else {
                if ((pairs = PyObject_CallFunctionObjArgs(sv->other_reads, stmt, NULL)) == NULL)
                    goto done;
                if (!PyList_Check(pairs)) {
                    Py_DECREF(pairs);
                    PyErr_SetString(PyExc_TypeError, "other_reads must give a list");
                    goto done;
                }
                bad = 0;
                if (PyObject_TypeCheck(stmt, (PyTypeObject *)classes[GOSUB]))
                    bad = append_pair(sv->callers, stmt, here) < 0;
                else if (PyObject_TypeCheck(stmt, (PyTypeObject *)classes[COMMAND]))
                    bad = PyList_Append(sv->commands, stmt) < 0;
            }
            bad = bad || add_reads(sv, stmt, pairs, here) < 0;
            Py_DECREF(pairs);
            if (bad)
                goto done;
        }
        if (end != NULL) {
            if (!dead && !is_sub) {
                if (append_pair(sv->unreachable, end, stmt) < 0)
                    goto done;
                dead = 1;
            }
        } else if (ends) {
            end = stmt;
        }
        if (ends) {
            PyObject *key = PyLong_FromVoidPtr(stmt);
            int bad = key == NULL || PySet_Add(sv->ending, key) < 0;
            Py_XDECREF(key);
            if (bad)
                goto done;
        }
    }
    failed = 0;
done:
    Py_DECREF(here);
    Py_DECREF(seq);
    return failed;
}

static PyObject *survey(PyObject *self, PyObject *args)
{
    Survey sv;
    PyObject *into, *body, *scope, **lists[N_SURVEY_LISTS] = {&sv.walked, &sv.coded, &sv.uses, &sv.targets,
        &sv.dialogs, &sv.commands, &sv.callers, &sv.heads, &sv.reads_of, &sv.codes_of, &sv.ending, &sv.unreachable};
    size_t k;
    int failed = 0;
    (void)self;
    if (!ready() || !PyArg_ParseTuple(args, "OOOOOOOOOOO", &sv.code_key, &sv.literal_index, &sv.scope_class,
                                      &sv.simulation_branches, &sv.other_reads, &sv.codes_class, &sv.end_keys,
                                      &sv.simulation, &into, &body, &scope))
        return NULL;
    for (k = 0; k < N_SURVEY_LISTS; k++)
        *lists[k] = NULL;
    for (k = 0; k < N_SURVEY_LISTS && !failed; k++) {
        *lists[k] = PyObject_GetAttrString(into, SURVEY_LISTS[k]);
        failed = *lists[k] == NULL;
    }
    if (!failed && (!PyList_Check(sv.walked) || !PyDict_Check(sv.reads_of) || !PyDict_Check(sv.codes_of)
                    || !PySet_Check(sv.ending) || !PyList_Check(sv.uses) || !PyList_Check(sv.targets))) {
        PyErr_SetString(PyExc_TypeError, "survey: a _Survey expected");
        failed = 1;
    }
    if (!failed)
        failed = survey_list(&sv, body, scope) < 0;
    for (k = 0; k < N_SURVEY_LISTS; k++)
        Py_XDECREF(*lists[k]);
    if (failed)
        return NULL;
    Py_RETURN_NONE;
}

