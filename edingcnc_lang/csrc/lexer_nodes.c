/* Part of _lexer.c (one translation unit: included there, in this order). The node classes, their fields and spans, made as their frozen __init__ makes them. */

/* ------------------------------------------------------------------------------------------
 * block(text, path, line, integer_digits, fraction_digits): the Block node of a line of words and
 * assignments, exactly as fastparse._Line.block builds it over the tokens above; None where that
 * method gives up, or on anything this function does not take (the Python method then decides).
 * The node classes come from setup(nodes_module); nodes are made as ``object.__new__`` and
 * ``object.__setattr__`` make them (their frozen ``__init__`` does no more).
 */
enum { NUMBER, PARAM, UNARY, BINARY, COMPARE, CALL, WORD, ASSIGN, BLOCK, MESSAGE, DIALOG, GOSUB, IF, WHILE, SUB,
       COMMAND, STAMP, N_CLASSES, OPEN = N_CLASSES, CLOSE, N_ALL_CLASSES };
static const char *const CLASS_NAMES[N_ALL_CLASSES] = {"Number", "Param", "Unary", "Binary", "Compare", "Call",
                                                       "Word", "Assign", "Block", "Message", "Dialog", "GoSub", "If",
                                                       "While", "Sub", "Command", "Stamp", "Open", "Close"};
static PyObject *classes[N_ALL_CLASSES], *span_class;
enum { F_VALUE, F_SPAN, F_INDEX, F_OP, F_OPERAND, F_LEFT, F_RIGHT, F_NAME, F_ARGS, F_LETTER, F_TARGET,
       F_WORDS, F_ASSIGNS, F_MESSAGE, F_LINE_NUMBER, F_BLOCK_DELETE, F_KIND, F_ITEMS, F_COND, F_EXTRA, F_BODY,
       F_THEN, F_ORELSE, F_SUB, F_GUARDED, N_FIELDS };
static const char *const FIELD_NAMES[N_FIELDS] = {"value", "span", "index", "op", "operand", "left", "right",
                                                  "name", "args", "letter", "target", "words", "assigns",
                                                  "message", "line_number", "block_delete", "kind", "items",
                                                  "cond", "extra", "body", "then", "orelse", "sub", "guarded"};
static PyObject *fields[N_FIELDS];
static const char *const FUNCTIONS[] = {"ABS", "ACOS", "ASIN", "COS", "EXP", "FIX", "FUP", "LN", "ROUND", "SIN",
                                        "SQRT", "TAN", "ATAN"};
#define N_FUNCTIONS (sizeof(FUNCTIONS) / sizeof(FUNCTIONS[0]))
static PyObject *function_names[N_FUNCTIONS];
static const char *const WORD_OPERATORS[] = {"EQ", "NE", "GT", "GE", "LT", "LE", "OR", "XOR", "AND", "MOD"};
#define N_WORD_OPERATORS (sizeof(WORD_OPERATORS) / sizeof(WORD_OPERATORS[0]))
static PyObject *word_operator_text[N_WORD_OPERATORS];
static const int WORD_LEVEL[N_WORD_OPERATORS] = {1, 1, 1, 1, 1, 1, 2, 2, 2, 3};
/* what each comparison is normalised to (fastparse._COMPARE_OPS), by word and by symbol */
static const char *const WORD_COMPARE[N_WORD_OPERATORS] = {"==", "<>", ">", ">=", "<", "<=", 0, 0, 0, 0};
static PyObject *letters[26];

typedef struct {
    const char *s;
    Token *tokens;
    Py_ssize_t i, count;
    PyObject *path, *line;
    int gave_up;
} Parser;

/* A parser at the first of the ``count`` tokens ``tokens`` of the line ``s`` (file ``path``, line ``line``). */
static void parser_start(Parser *p, const char *s, PyObject *path, PyObject *line, Token *tokens, Py_ssize_t count)
{
    p->s = s;
    p->path = path;
    p->line = line;
    p->tokens = tokens;
    p->count = count;
    p->i = 0;
    p->gave_up = 0;
}

/* Which operator or function a letters token is, case-insensitively: its index in ``table``, or -1. */
static int lookup(const char *s, Py_ssize_t length, const char *const *table, size_t size)
{
    size_t k;
    Py_ssize_t j;
    for (k = 0; k < size; k++) {
        const char *name = table[k];
        for (j = 0; j < length && name[j] != '\0'; j++)
            if ((s[j] & ~0x20) != name[j])
                break;
        if (j == length && name[j] == '\0')
            return (int)k;
    }
    return -1;
}

static PyObject *give_up(Parser *p)
{
    p->gave_up = 1;
    return NULL;
}

static Token *at(Parser *p, Py_ssize_t i) { return &p->tokens[i < p->count ? i : p->count - 1]; }

/* A Span: a tuple subclass, allocated and filled as tuple.__new__ fills one (without an argument tuple). */
static PyObject *make_span(PyObject *path, PyObject *line, Py_ssize_t col, Py_ssize_t end)
{
    PyObject *made = PyType_GenericAlloc((PyTypeObject *)span_class, 5), *number;
    Py_ssize_t k;
    if (made == NULL)
        return NULL;
    Py_INCREF(path);
    PyTuple_SetItem(made, 0, path);
    Py_INCREF(line);
    PyTuple_SetItem(made, 1, line);
    Py_INCREF(line);
    PyTuple_SetItem(made, 3, line);
    for (k = 0; k < 2; k++) {
        number = PyLong_FromSsize_t(k ? end : col);
        if (number == NULL) {
            Py_DECREF(made);
            return NULL;
        }
        PyTuple_SetItem(made, k ? 4 : 2, number);
    }
    return made;
}

static PyObject *span(Parser *p, Py_ssize_t col, Py_ssize_t end)
{
    return make_span(p->path, p->line, col, end);
}

/* A node of class ``which`` with ``count`` fields; steals the references to ``values`` (any may be NULL
 * after a failure, then nothing is made). */
/* Each node class's slot descriptor of each field and its setter, found by setup(): setting a field
 * through them is what object.__setattr__ does once it has looked the descriptor up. */
static PyObject *descriptors[N_ALL_CLASSES][N_FIELDS];
static descrsetfunc setters[N_ALL_CLASSES][N_FIELDS];
static descrgetfunc getters[N_ALL_CLASSES][N_FIELDS];

/* ``obj.<field>`` for an object most likely of class ``which``: through the slot descriptor when it is. */
static PyObject *get_field(PyObject *obj, int which, int field)
{
    if (getters[which][field] != NULL && Py_IS_TYPE(obj, (PyTypeObject *)classes[which]))
        return getters[which][field](descriptors[which][field], obj, (PyObject *)Py_TYPE(obj));
    return PyObject_GetAttr(obj, fields[field]);
}

static int set_field(int which, PyObject *made, int field, PyObject *value)
{
    if (setters[which][field] != NULL)
        return setters[which][field](descriptors[which][field], made, value);
    return PyObject_GenericSetAttr(made, fields[field], value);
}

/* The slot descriptors of class ``which`` (none for a class without __slots__, such as Open). */
static void find_setters(int which)
{
    int f;
    for (f = 0; f < N_FIELDS; f++) {
        PyObject *found = PyObject_GetAttr(classes[which], fields[f]);
        descrsetfunc set = NULL;
        Py_XDECREF(descriptors[which][f]);
        descriptors[which][f] = NULL;
        setters[which][f] = NULL;
        getters[which][f] = NULL;
        if (found == NULL) {
            PyErr_Clear();
            continue;
        }
        /* a member descriptor of this very class: a slot (a class attribute holding a default is not) */
        if (PyObject_HasAttrString(found, "__objclass__") && !PyType_Check(found)
                && Py_TYPE(found) != &PyUnicode_Type)
            set = (descrsetfunc)PyType_GetSlot(Py_TYPE(found), Py_tp_descr_set);
        if (set != NULL) {
            descriptors[which][f] = found;
            setters[which][f] = set;
            getters[which][f] = (descrgetfunc)PyType_GetSlot(Py_TYPE(found), Py_tp_descr_get);
        } else {
            Py_DECREF(found);
        }
    }
}

static PyObject *node(int which, int count, const int *names, PyObject **values)
{
    PyObject *made = NULL;
    int k;
    for (k = 0; k < count; k++)
        if (values[k] == NULL)
            goto done;
    made = PyType_GenericAlloc((PyTypeObject *)classes[which], 0);
    if (made == NULL)
        goto done;
    for (k = 0; k < count; k++) {
        if (set_field(which, made, names[k], values[k]) < 0) {
            Py_CLEAR(made);
            goto done;
        }
    }
done:
    for (k = 0; k < count; k++)
        Py_XDECREF(values[k]);
    return made;
}

static PyObject *number(Parser *p, Token *token, double sign, Py_ssize_t col, Py_ssize_t end)
{
    static const int names[] = {F_VALUE, F_SPAN};
    char buffer[1024];
    Py_ssize_t length = token->stop - token->start;
    double value;
    PyObject *values[2];
    if (length >= (Py_ssize_t)sizeof(buffer))
        return give_up(p);
    memcpy(buffer, p->s + token->start, (size_t)length);
    buffer[length] = '\0';
    value = PyOS_string_to_double(buffer, NULL, NULL);
    if (value == -1.0 && PyErr_Occurred())
        return NULL;
    values[0] = PyFloat_FromDouble(sign * value);
    values[1] = span(p, col, end);
    return node(NUMBER, 2, names, values);
}

