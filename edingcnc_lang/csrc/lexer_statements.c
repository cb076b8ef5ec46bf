/* Part of _lexer.c (one translation unit: included there, in this order). Whole macro lines: statement() and statements(). */

/* ------------------------------------------------------------------------------------------
 * statement(text, path, line, integer_digits, fraction_digits): what fastparse.parse_fast makes of a
 * line without '(' before its ';' comment (the caller checks that, and the input limits): None for a
 * blank or comment line, the Block of words and assignments (as block() above), the Open/Close of a Sub/If/While head or
 * end line, a GoSub, a message or a dlgmsg, the same nodes as the Python methods build; the give-up
 * marker of setup() where that function gives up or this one does not try (logfile, home, ...).
 */
enum { K_ENDSUB, K_ENDIF, K_ENDWHILE, K_ELSE, K_MSG, K_WARNMSG, K_ERRMSG, K_LOGMSG, K_SUB, K_GOSUB, K_IF,
       K_WHILE, K_DLGMSG, N_HANDLED };
static const char *const HANDLED[N_HANDLED] = {"ENDSUB", "ENDIF", "ENDWHILE", "ELSE", "MSG", "WARNMSG", "ERRMSG",
                                               "LOGMSG", "SUB", "GOSUB", "IF", "WHILE", "DLGMSG"};
/* the text each keeps: a closer's or opener's kind (fastparse._CLOSERS), a message's kind (lower-case) */
static const char *const HANDLED_TEXT[N_HANDLED] = {"EndSub", "EndIf", "EndWhile", "Else", "msg", "warnmsg",
                                                    "errmsg", "logmsg", "Sub", "", "If", "While", ""};
static PyObject *handled_text[N_HANDLED], *give_up_marker, *keywords;

static int is_name_char(unsigned char c) { return is_letter(c) || is_digit(c) || c == '_'; }

/* [ \t]*(?:;.*)?\Z from byte i: only blanks and a comment (without a newline) are left. */
static int blank_from(const char *s, Py_ssize_t size, Py_ssize_t i)
{
    while (i < size && (s[i] == ' ' || s[i] == '\t'))
        i++;
    return i == size || (s[i] == ';' && memchr(s + i, '\n', (size_t)(size - i)) == NULL);
}

/* The strings and values of a msg/dlgmsg from byte (and code point) ``pos`` on, as _Line.items reads
 * them, and the end column (``*end`` comes in as the keyword's). */
static PyObject *read_items(const char *s, Py_ssize_t size, Py_ssize_t pos, PyObject *path, PyObject *line,
                            Py_ssize_t integer_digits, Py_ssize_t fraction_digits, Py_ssize_t *end)
{
    PyObject *items = NULL, *item, *result = NULL;
    Token stack[STACK_TOKENS], *found = stack;
    Parser p;
    Py_ssize_t count, start;
    if (size - pos + 1 > STACK_TOKENS && (found = PyMem_New(Token, size - pos + 1)) == NULL)
        return PyErr_NoMemory();
    count = scan(s, size, pos, pos, integer_digits, fraction_digits, found);
    if (count < 1 || (items = PyList_New(0)) == NULL)
        goto done;
    parser_start(&p, s, path, line, found, count);
    for (;;) {
        Token *token = at(&p, p.i);
        if (token->kind == T_END)
            break;
        if (token->kind == T_STRING) {
            item = PyUnicode_DecodeUTF8(s + token->start + 1, token->stop - token->start - 2, NULL);
            *end = token->end;
            p.i++;
        } else {
            item = operand(&p, &start, end);
        }
        if (append_new(items, item) < 0)
            goto done;
    }
    result = PyList_AsTuple(items);
done:
    Py_XDECREF(items);
    if (found != stack)
        PyMem_Free(found);
    return result;
}

static PyObject *read_statement(const char *s, Py_ssize_t size, PyObject *path, PyObject *line,
                                Py_ssize_t integer_digits, Py_ssize_t fraction_digits)
{
    static const int close_names[] = {F_KIND, F_SPAN};
    static const int open_names[] = {F_KIND, F_SPAN, F_NAME, F_COND, F_EXTRA};
    static const int message_names[] = {F_KIND, F_ITEMS, F_SPAN};
    static const int dialog_names[] = {F_ITEMS, F_SPAN};
    static const int gosub_names[] = {F_NAME, F_SPAN};
    PyObject *values[5];
    Py_ssize_t i = 0, head, pos, end, extra;
    int k;
    while (i < size && (s[i] == ' ' || s[i] == '\t'))
        i++;
    if (blank_from(s, size, i))
        Py_RETURN_NONE;
    head = i;
    while (i < size && is_name_char((unsigned char)s[i]))
        i++;
    k = i > head ? lookup(s + head, i - head, HANDLED, N_HANDLED) : -1;
    if (k < 0) {
        Py_ssize_t j;
        int letters_only = 1;
        for (j = head; j < i; j++)
            letters_only = letters_only && is_letter((unsigned char)s[j]);
        if (letters_only && i - head >= 2 && i - head < 64) {  /* another keyword (logfile, kin, ...): not here */
            char lower[64];
            PyObject *name;
            int known;
            for (j = head; j < i; j++)
                lower[j - head] = (char)(is_letter((unsigned char)s[j]) ? s[j] | 0x20 : s[j]);
            if ((name = PyUnicode_FromStringAndSize(lower, i - head)) == NULL)
                return NULL;
            known = PySequence_Contains(keywords, name);
            Py_DECREF(name);
            if (known != 0)
                return NULL;  /* given up, or the error */
        }
        return read_block(s, size, path, line, integer_digits, fraction_digits);
    }
    pos = i;  /* the keyword and the blanks before it are ASCII: bytes are code points here */
    end = pos + 1;
    if (k <= K_ELSE) {
        if (!blank_from(s, size, pos))
            return NULL;
        values[0] = handled_text[k];
        Py_INCREF(values[0]);
        values[1] = make_span(path, line, head + 1, end);
        return node(CLOSE, 2, close_names, values);
    }
    if (k == K_SUB || k == K_GOSUB) {
        Py_ssize_t name_start;
        while (i < size && (s[i] == ' ' || s[i] == '\t'))
            i++;
        name_start = i;
        while (i < size && is_name_char((unsigned char)s[i]))
            i++;
        if (i == name_start || !blank_from(s, size, i))
            return NULL;
        if (k == K_GOSUB) {
            values[0] = PyUnicode_FromStringAndSize(s + name_start, i - name_start);
            values[1] = make_span(path, line, head + 1, i + 1);
            return node(GOSUB, 2, gosub_names, values);
        }
        values[0] = handled_text[k];
        Py_INCREF(values[0]);
        values[1] = make_span(path, line, head + 1, i + 1);
        values[2] = PyUnicode_FromStringAndSize(s + name_start, i - name_start);
        values[3] = Py_None;
        Py_INCREF(Py_None);
        values[4] = PyLong_FromLong(0);
        return node(OPEN, 5, open_names, values);
    }
    if (k == K_IF || k == K_WHILE) {
        PyObject *cond = read_condition(s, size, pos, pos, path, line, k == K_IF, integer_digits, fraction_digits,
                                        &end, &extra);
        if (cond == NULL)
            return NULL;
        values[0] = handled_text[k];
        Py_INCREF(values[0]);
        values[1] = make_span(path, line, head + 1, end);
        values[2] = PyUnicode_FromStringAndSize("", 0);
        values[3] = cond;
        values[4] = PyLong_FromSsize_t(extra);
        return node(OPEN, 5, open_names, values);
    }
    {  /* a message or a dlgmsg */
        PyObject *items = read_items(s, size, pos, path, line, integer_digits, fraction_digits, &end);
        if (items == NULL)
            return NULL;
        if (k == K_DLGMSG) {
            values[0] = items;
            values[1] = make_span(path, line, head + 1, end);
            return node(DIALOG, 2, dialog_names, values);
        }
        values[0] = handled_text[k];
        Py_INCREF(values[0]);
        values[1] = items;
        values[2] = make_span(path, line, head + 1, end);
        return node(MESSAGE, 3, message_names, values);
    }
}

static PyObject *statement(PyObject *self, PyObject *args)
{
    PyObject *text, *path, *line, *result;
    Py_ssize_t integer_digits, fraction_digits, size;
    const char *s;
    (void)self;
    if (!ready() || !PyArg_ParseTuple(args, "UOOnn", &text, &path, &line, &integer_digits, &fraction_digits))
        return NULL;
    if (give_up_marker == NULL) {
        PyErr_SetString(PyExc_RuntimeError, "_lexer.setup() was not given the block module");
        return NULL;
    }
    s = PyUnicode_AsUTF8AndSize(text, &size);
    if (s == NULL) {  /* a lone surrogate: the Python path reads it */
        PyErr_Clear();
        result = NULL;
    } else {
        result = read_statement(s, size, path, line, integer_digits, fraction_digits);
    }
    if (result == NULL && !PyErr_Occurred()) {
        Py_INCREF(give_up_marker);
        return give_up_marker;
    }
    return result;
}

/* statements(lines, path, first_line, shortest_problem, integer_digits, fraction_digits): statement()
 * of each line of a list (line numbers from ``first_line`` on), the give-up marker for a line that
 * is longer than ``shortest_problem`` code points or holds a '(' before its ';' comment (line_parser.parse_line
 * asks the compiled reader about the other lines only). */
/* Whether a '(' stands before the line's ';' comment, strings ("..." without a newline) left out: a ( )
 * comment or an operator message, the grammar's; a '(' in the ';' comment is only its text. The same as
 * fastparse.paren_before_comment. */
static int paren_before_comment(const char *s, Py_ssize_t size)
{
    Py_ssize_t i, j;
    for (i = 0; i < size; i++) {
        if (s[i] == '"') {
            for (j = i + 1; j < size && s[j] != '"' && s[j] != '\n'; j++)
                ;
            if (j < size && s[j] == '"')
                i = j;  /* past the string */
        } else if (s[i] == ';') {
            return 0;
        } else if (s[i] == '(') {
            return 1;
        }
    }
    return 0;
}

static PyObject *statements(PyObject *self, PyObject *args)
{
    PyObject *lines, *path, *out;
    Py_ssize_t first, shortest, integer_digits, fraction_digits, count, i, size;
    (void)self;
    if (!ready() || !PyArg_ParseTuple(args, "O!Onnnn", &PyList_Type, &lines, &path, &first, &shortest,
                                      &integer_digits, &fraction_digits))
        return NULL;
    if (give_up_marker == NULL) {
        PyErr_SetString(PyExc_RuntimeError, "_lexer.setup() was not given the block module");
        return NULL;
    }
    count = PyList_Size(lines);
    if ((out = PyList_New(count)) == NULL)
        return NULL;
    for (i = 0; i < count; i++) {
        PyObject *text = PyList_GetItem(lines, i), *result = NULL, *line;
        const char *s;
        if (PyUnicode_Check(text) && PyUnicode_GetLength(text) <= shortest) {
            s = PyUnicode_AsUTF8AndSize(text, &size);
            if (s == NULL) {  /* a lone surrogate: the Python path reads it */
                PyErr_Clear();
            } else if (!paren_before_comment(s, size)) {
                if ((line = PyLong_FromSsize_t(first + i)) == NULL) {
                    Py_DECREF(out);
                    return NULL;
                }
                result = read_statement(s, size, path, line, integer_digits, fraction_digits);
                Py_DECREF(line);
                if (result == NULL && PyErr_Occurred()) {
                    Py_DECREF(out);
                    return NULL;
                }
            }
        }
        if (result == NULL) {
            result = give_up_marker;
            Py_INCREF(result);
        }
        PyList_SetItem(out, i, result);  /* steals the reference */
    }
    return out;
}

/* new(cls, values): a node of a frozen dataclass ``cls`` with ``values`` for its fields in the order of
 * its __match_args__, made as its __init__ makes it (object.__new__, then object.__setattr__ for each
 * field) without the Python-level call of that __init__. The slot descriptors of a node class of
 * setup() are looked up once (new_slots), those of another class on each call. */
#define NEW_MAX_FIELDS 8
static PyObject *new_descriptors[N_ALL_CLASSES][NEW_MAX_FIELDS];
static descrsetfunc new_setters[N_ALL_CLASSES][NEW_MAX_FIELDS];
static Py_ssize_t new_counts[N_ALL_CLASSES];  /* 0: not looked up yet (every node class has a field) */

/* The slot descriptors of class ``k``'s __match_args__, in order; 0 if one is not a slot (then new()
 * sets the fields by name). */
static int new_slots(int k)
{
    PyObject *names = PyObject_GetAttrString(classes[k], "__match_args__"), *found;
    Py_ssize_t count = names != NULL && PyTuple_Check(names) ? PyTuple_Size(names) : -1, f;
    descrsetfunc set;
    for (f = 0; f < count && f < NEW_MAX_FIELDS; f++) {
        if ((found = PyObject_GetAttr(classes[k], PyTuple_GetItem(names, f))) == NULL)
            break;
        set = PyObject_HasAttrString(found, "__objclass__") && !PyType_Check(found)
              ? (descrsetfunc)PyType_GetSlot(Py_TYPE(found), Py_tp_descr_set) : NULL;
        if (set == NULL) {
            Py_DECREF(found);
            break;
        }
        Py_XDECREF(new_descriptors[k][f]);
        new_descriptors[k][f] = found;
        new_setters[k][f] = set;
    }
    Py_XDECREF(names);
    PyErr_Clear();
    if (count < 1 || f < count)
        return 0;
    new_counts[k] = count;
    return 1;
}

static PyObject *new_node(PyObject *self, PyObject *args)
{
    PyObject *cls, *values, *names, *made;
    Py_ssize_t k, count;
    int which;
    (void)self;
    if (!PyArg_ParseTuple(args, "O!O!", &PyType_Type, &cls, &PyTuple_Type, &values))
        return NULL;
    for (which = 0; which < N_ALL_CLASSES && classes[which] != cls; which++)
        ;
    if (which < N_ALL_CLASSES && (new_counts[which] > 0 || new_slots(which))) {
        if ((count = new_counts[which]) != PyTuple_Size(values)) {
            PyErr_SetString(PyExc_TypeError, "new(): one value for each field expected");
            return NULL;
        }
        made = PyType_GenericAlloc((PyTypeObject *)cls, 0);
        for (k = 0; made != NULL && k < count; k++)
            if (new_setters[which][k](new_descriptors[which][k], made, PyTuple_GetItem(values, k)) < 0)
                Py_CLEAR(made);
        return made;
    }
    if ((names = PyObject_GetAttrString(cls, "__match_args__")) == NULL)
        return NULL;
    count = PyTuple_Check(names) ? PyTuple_Size(names) : -1;
    if (count != PyTuple_Size(values)) {
        Py_DECREF(names);
        PyErr_SetString(PyExc_TypeError, "new(): one value for each field expected");
        return NULL;
    }
    made = PyType_GenericAlloc((PyTypeObject *)cls, 0);
    for (k = 0; made != NULL && k < count; k++)
        if (PyObject_GenericSetAttr(made, PyTuple_GetItem(names, k), PyTuple_GetItem(values, k)) < 0)
            Py_CLEAR(made);
    Py_DECREF(names);
    return made;
}

/* setup(nodes_module[, blocks_module, give_up, keywords]): the node classes block() makes; with the
 * blocks module (Open, Close), the marker statement() gives up with and the keywords it leaves to the
 * Python path, also those statement() makes. */
static PyObject *setup(PyObject *self, PyObject *args)
{
    PyObject *module, *blocks = NULL, *marker = NULL, *names = NULL;
    int k;
    (void)self;
    if (!PyArg_ParseTuple(args, "O|OOO", &module, &blocks, &marker, &names))
        return NULL;
    for (k = 0; k < N_ALL_CLASSES; k++) {
        PyObject *found;
        if (k >= N_CLASSES && blocks == NULL)
            break;
        found = PyObject_GetAttrString(k < N_CLASSES ? module : blocks, CLASS_NAMES[k]);
        if (found == NULL || !PyType_Check(found)) {
            Py_XDECREF(found);
            return found == NULL ? NULL : (PyErr_SetString(PyExc_TypeError, "a node class expected"), NULL);
        }
        Py_XDECREF(classes[k]);
        classes[k] = found;
        find_setters(k);
        new_counts[k] = 0;  /* new() looks its slots up again */
    }
    if (marker != NULL && names != NULL) {
        Py_INCREF(marker);
        Py_XDECREF(give_up_marker);
        give_up_marker = marker;
        Py_INCREF(names);
        Py_XDECREF(keywords);
        keywords = names;
    }
    Py_XDECREF(span_class);
    span_class = PyObject_GetAttrString(module, "Span");
    if (span_class == NULL)
        return NULL;
    Py_RETURN_NONE;
}

