/* The optional compiled tokenizer of the macro line fast path (see syntax/fastparse.py).
 *
 * tokens(text, pos, integer_digits, fraction_digits) splits ``text`` from ``pos`` on exactly as
 * fastparse._tokens_python does with its regular expression: a list of (kind, text, column, end
 * column) tuples, blanks and the ';' comment left out, ending with the ("", "", end, end)
 * sentinel; None where that function gives up (a character no token covers, a number with too
 * many digits), and NotImplemented for a text UTF-8 cannot hold (a lone surrogate), which the
 * Python tokenizer then reads.  Columns count code points, 1-based.  The Python function is the
 * reference: tests/parser/test_lexer.py compares the two on generated lines.
 *
 * A second extension beside _speedups.c, built the same way (optional, stable ABI).
 */
#define PY_SSIZE_T_CLEAN
#define Py_LIMITED_API 0x030A0000
#include <Python.h>
#include <math.h>

static PyObject *kind_number, *kind_string, *kind_letters, *empty;
/* The operators, each once: a token's kind is its own text (the same object, as in Python). */
static const char *const OPERATORS[] = {"**", "==", "<>", "!=", "<=", ">=", "-", "+", "*", "/", "<", ">",
                                        "[", "]", "#", "="};
#define N_OPERATORS (sizeof(OPERATORS) / sizeof(OPERATORS[0]))
static PyObject *operator_text[N_OPERATORS];

static int is_digit(unsigned char c) { return c >= '0' && c <= '9'; }
static int is_letter(unsigned char c) { return (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z'); }

/* The operator at s (two characters first, as the regular expression tries them); -1 if none. */
static int operator_at(const char *s, Py_ssize_t left)
{
    size_t k;
    for (k = 0; k < N_OPERATORS; k++) {
        const char *op = OPERATORS[k];
        if (op[1] == '\0') {
            if (s[0] == op[0])
                return (int)k;
        } else if (left >= 2 && s[0] == op[0] && s[1] == op[1]) {
            return (int)k;
        }
    }
    return -1;
}

/* One token: its kind (an index into OPERATORS, or one of the kinds below), where it is in the
 * UTF-8 text (bytes) and in the line (1-based code point columns, end exclusive). */
enum { T_END = -1, T_NUMBER = -2, T_STRING = -3, T_LETTERS = -4 };
typedef struct {
    int kind;
    Py_ssize_t start, stop, col, end;
} Token;

/* Split s[i:] (the code point before byte i is number ``chars``) into tokens, the T_END sentinel
 * last; returns how many, or -1 where fastparse gives up (no token covers a character). ``out``
 * has room for size - i + 1 tokens (each takes at least a byte). */
static Py_ssize_t scan(const char *s, Py_ssize_t size, Py_ssize_t i, Py_ssize_t chars,
                       Py_ssize_t integer_digits, Py_ssize_t fraction_digits, Token *out)
{
    Py_ssize_t count = 0, start, start_char;
    int k;
    while (i < size) {
        unsigned char c = (unsigned char)s[i];
        start = i;
        start_char = chars;
        if (c == ' ' || c == '\t') {
            while (i < size && (s[i] == ' ' || s[i] == '\t'))
                i++;
            chars += i - start;
            continue;
        }
        if (c == ';') {  /* a comment runs to the end of the line ('.' stops at a newline) */
            while (i < size && s[i] != '\n') {
                if (((unsigned char)s[i] & 0xC0) != 0x80)
                    chars++;
                i++;
            }
            continue;
        }
        if (c == '"') {
            i++;
            while (i < size && s[i] != '"' && s[i] != '\n') {
                if (((unsigned char)s[i] & 0xC0) != 0x80)
                    chars++;
                i++;
            }
            if (i >= size || s[i] != '"')
                return -1;
            i++;
            chars += 2;
            k = T_STRING;
        } else if (is_digit(c) || c == '.') {
            Py_ssize_t digits = 0;
            while (i < size && is_digit((unsigned char)s[i])) {
                i++;
                digits++;
            }
            if (digits > integer_digits)
                return -1;
            if (i < size && s[i] == '.') {
                Py_ssize_t fraction = 0;
                i++;
                while (i < size && is_digit((unsigned char)s[i])) {
                    i++;
                    fraction++;
                }
                /* more digits than allowed, or a lone '.': no token covers it */
                if (fraction > fraction_digits || (digits == 0 && fraction == 0))
                    return -1;
            } else if (digits == 0) {
                return -1;
            }
            chars += i - start;
            k = T_NUMBER;
        } else if (is_letter(c)) {
            while (i < size && is_letter((unsigned char)s[i]))
                i++;
            chars += i - start;
            k = T_LETTERS;
        } else {
            k = operator_at(s + i, size - i);
            if (k < 0)
                return -1;
            i += (Py_ssize_t)strlen(OPERATORS[k]);
            chars += i - start;
        }
        out[count].kind = k;
        out[count].start = start;
        out[count].stop = i;
        out[count].col = start_char + 1;
        out[count].end = chars + 1;
        count++;
    }
    out[count].kind = T_END;
    out[count].start = out[count].stop = i;
    out[count].col = out[count].end = chars + 1;
    return count + 1;
}

/* The UTF-8 text of ``text`` and the byte where code point ``pos`` starts; NULL for a text
 * UTF-8 cannot hold (a lone surrogate), with the error cleared. */
static const char *utf8_at(PyObject *text, Py_ssize_t pos, Py_ssize_t *size, Py_ssize_t *at)
{
    Py_ssize_t i, chars;
    const char *s = PyUnicode_AsUTF8AndSize(text, size);
    if (s == NULL) {
        PyErr_Clear();
        return NULL;
    }
    for (i = 0, chars = 0; i < *size && chars < pos; i++)
        if (((unsigned char)s[i] & 0xC0) != 0x80)
            chars++;
    while (i < *size && ((unsigned char)s[i] & 0xC0) == 0x80)
        i++;
    *at = i;
    return s;
}

#define STACK_TOKENS 128

static PyObject *tokens(PyObject *self, PyObject *args)
{
    PyObject *text, *list = NULL, *item = NULL, *kind, *value;
    Py_ssize_t pos, integer_digits, fraction_digits, size, at, count, t;
    Token stack[STACK_TOKENS], *found = stack;
    const char *s;
    (void)self;
    if (!PyArg_ParseTuple(args, "Unnn", &text, &pos, &integer_digits, &fraction_digits))
        return NULL;
    s = utf8_at(text, pos, &size, &at);
    if (s == NULL)  /* a lone surrogate: the Python tokenizer reads it */
        Py_RETURN_NOTIMPLEMENTED;
    if (size - at + 1 > STACK_TOKENS && (found = PyMem_New(Token, size - at + 1)) == NULL)
        return PyErr_NoMemory();
    count = scan(s, size, at, pos, integer_digits, fraction_digits, found);
    if (count < 0) {
        if (found != stack)
            PyMem_Free(found);
        Py_RETURN_NONE;
    }
    list = PyList_New(count);
    if (list == NULL)
        goto error;
    for (t = 0; t < count; t++) {
        Token *token = &found[t];
        if (token->kind >= 0) {
            kind = value = operator_text[token->kind];
            Py_INCREF(value);
        } else {
            kind = token->kind == T_NUMBER ? kind_number : token->kind == T_STRING ? kind_string
                 : token->kind == T_LETTERS ? kind_letters : empty;
            if (token->kind == T_END) {
                value = empty;
                Py_INCREF(value);
            } else {
                value = PyUnicode_DecodeUTF8(s + token->start, token->stop - token->start, NULL);
                if (value == NULL)
                    goto error;
            }
        }
        item = Py_BuildValue("(ONnn)", kind, value, token->col, token->end);
        if (item == NULL)
            goto error;
        PyList_SetItem(list, t, item);  /* steals the reference */
    }
    if (found != stack)
        PyMem_Free(found);
    return list;
error:
    Py_XDECREF(list);
    if (found != stack)
        PyMem_Free(found);
    return NULL;
}

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

static PyObject *expr(Parser *p, int min_level, Py_ssize_t *start, Py_ssize_t *end);

/* ']' expected: consumed, its end column returned; 0 (given up) otherwise. */
static Py_ssize_t expect(Parser *p, int kind)
{
    Token *token = at(p, p->i);
    if (token->kind != kind) {
        p->gave_up = 1;
        return 0;
    }
    p->i++;
    return token->end;
}

#define OP_BRACKET 12
#define OP_CLOSE 13
#define OP_HASH 14
#define OP_ASSIGN 15
#define OP_MINUS 6
#define OP_PLUS 7
#define OP_SLASH 9

static PyObject *param(Parser *p, Py_ssize_t *start, Py_ssize_t *end)
{
    static const int names[] = {F_INDEX, F_SPAN};
    Token *token;
    PyObject *values[2];
    Py_ssize_t col = at(p, p->i)->col, inner_start, last;
    p->i++;
    token = at(p, p->i);
    if (token->kind == OP_HASH) {
        values[0] = param(p, &inner_start, &last);
    } else if (token->kind == OP_BRACKET) {
        p->i++;
        values[0] = expr(p, 1, &inner_start, &last);
        if (values[0] == NULL)
            return NULL;
        last = expect(p, OP_CLOSE);
        if (!last) {
            Py_DECREF(values[0]);
            return NULL;
        }
    } else if (token->kind == T_NUMBER) {
        p->i++;
        last = token->end;
        values[0] = number(p, token, 1.0, token->col, token->end);
    } else {
        return give_up(p);
    }
    if (values[0] == NULL)
        return NULL;
    values[1] = span(p, col, last);
    *start = col;
    *end = last;
    return node(PARAM, 2, names, values);
}

static PyObject *operand(Parser *p, Py_ssize_t *start, Py_ssize_t *end)
{
    Token *token = at(p, p->i);
    Py_ssize_t col = token->col, inner_start, last;
    int function;
    PyObject *inner, *values[4];
    if (token->kind == T_NUMBER) {
        p->i++;
        *start = col;
        *end = token->end;
        return number(p, token, 1.0, col, token->end);
    }
    if (token->kind == OP_HASH)
        return param(p, start, end);
    if (token->kind == OP_MINUS || token->kind == OP_PLUS) {
        static const int unary_names[] = {F_OP, F_OPERAND, F_SPAN};
        int minus = token->kind == OP_MINUS;
        p->i++;
        inner = operand(p, &inner_start, &last);
        if (inner == NULL)
            return NULL;
        *start = col;
        *end = last;
        if (Py_IS_TYPE(inner, (PyTypeObject *)classes[NUMBER])) {  /* a sign folds into a literal */
            static const int names[] = {F_VALUE, F_SPAN};
            PyObject *value = PyObject_GetAttr(inner, fields[F_VALUE]);
            double folded;
            Py_DECREF(inner);
            if (value == NULL)
                return NULL;
            folded = PyFloat_AsDouble(value);
            Py_DECREF(value);
            values[0] = PyFloat_FromDouble(minus ? -folded : folded);
            values[1] = span(p, col, last);
            return node(NUMBER, 2, names, values);
        }
        values[0] = operator_text[token->kind];
        Py_INCREF(values[0]);
        values[1] = inner;
        values[2] = span(p, col, last);
        return node(UNARY, 3, unary_names, values);
    }
    if (token->kind == OP_BRACKET) {
        p->i++;
        inner = expr(p, 1, &inner_start, &last);
        if (inner == NULL)
            return NULL;
        last = expect(p, OP_CLOSE);
        if (!last) {
            Py_DECREF(inner);
            return NULL;
        }
        *start = col;
        *end = last;
        return inner;
    }
    if (token->kind != T_LETTERS || at(p, p->i + 1)->kind != OP_BRACKET)
        return give_up(p);
    function = lookup(p->s + token->start, token->stop - token->start, FUNCTIONS, N_FUNCTIONS);
    if (function < 0)
        return give_up(p);
    {
        static const int names[] = {F_NAME, F_ARGS, F_SPAN};
        PyObject *first, *second = NULL;
        p->i += 2;
        first = expr(p, 1, &inner_start, &last);
        if (first == NULL)
            return NULL;
        last = expect(p, OP_CLOSE);
        if (!last) {
            Py_DECREF(first);
            return NULL;
        }
        /* ATAN[y]/[x] takes two operands; ATAN[x]/2 divides */
        if (strcmp(FUNCTIONS[function], "ATAN") == 0 && at(p, p->i)->kind == OP_SLASH
                && at(p, p->i + 1)->kind == OP_BRACKET) {
            p->i += 2;
            second = expr(p, 1, &inner_start, &last);
            if (second == NULL) {
                Py_DECREF(first);
                return NULL;
            }
            last = expect(p, OP_CLOSE);
            if (!last) {
                Py_DECREF(first);
                Py_DECREF(second);
                return NULL;
            }
        }
        values[0] = function_names[function];
        Py_INCREF(values[0]);
        values[1] = second ? PyTuple_Pack(2, first, second) : PyTuple_Pack(1, first);
        Py_DECREF(first);
        Py_XDECREF(second);
        values[2] = span(p, col, last);
        *start = col;
        *end = last;
        return node(CALL, 3, names, values);
    }
}

/* The binding level of the token at p->i as an operator (0: none) and the text a node keeps. */
static int level_of(Parser *p, PyObject **op, int *compare)
{
    Token *token = at(p, p->i);
    int k;
    *compare = -1;
    if (token->kind >= 0) {
        static const int LEVEL[] = {4, 1, 1, 1, 1, 1, 2, 2, 3, 3, 1, 1, 0, 0, 0, 0};  /* by OPERATORS */
        *op = operator_text[token->kind];
        if (LEVEL[token->kind] == 1)
            *compare = token->kind;
        return LEVEL[token->kind];
    }
    if (token->kind != T_LETTERS)
        return 0;
    {
        Token *after = at(p, p->i + 1);  /* MOD2 is a name, MOD.5 is not */
        if (after->kind == T_NUMBER && after->col == token->end && p->s[after->start] != '.')
            return 0;
    }
    k = lookup(p->s + token->start, token->stop - token->start, WORD_OPERATORS, N_WORD_OPERATORS);
    if (k < 0)
        return 0;
    *op = word_operator_text[k];
    if (WORD_LEVEL[k] == 1)
        *compare = 100 + k;
    return WORD_LEVEL[k];
}

static PyObject *compare_text(int compare)
{
    static const int SYMBOL[] = {-1, 1, 2, 2, 4, 5};  /* ** == <> != <= >= -> the OPERATORS entry kept */
    if (compare >= 100)
        return PyUnicode_InternFromString(WORD_COMPARE[compare - 100]);
    if (compare >= 1 && compare <= 5) {
        PyObject *text = operator_text[SYMBOL[compare]];
        Py_INCREF(text);
        return text;
    }
    {  /* '<' or '>' */
        PyObject *text = operator_text[compare];
        Py_INCREF(text);
        return text;
    }
}

static PyObject *expr(Parser *p, int min_level, Py_ssize_t *start, Py_ssize_t *end)
{
    static const int names[] = {F_OP, F_LEFT, F_RIGHT, F_SPAN};
    Py_ssize_t right_start, right_end;
    PyObject *left = operand(p, start, end), *right, *op, *values[4];
    int level, compare;
    while (left != NULL) {
        level = level_of(p, &op, &compare);
        if (level < min_level || level == 0)
            return left;
        p->i++;
        right = expr(p, level + 1, &right_start, &right_end);
        if (right == NULL) {
            Py_DECREF(left);
            return NULL;
        }
        *end = right_end;
        if (level == 1) {
            values[0] = compare_text(compare);
        } else {
            values[0] = op;
            Py_INCREF(op);
        }
        values[1] = left;
        values[2] = right;
        values[3] = span(p, *start, *end);
        left = node(level == 1 ? COMPARE : BINARY, 4, names, values);
    }
    return NULL;
}

/* The Block of the UTF-8 line s[:size]; NULL without an exception where fastparse gives up. */
static PyObject *read_block(const char *s, Py_ssize_t size, PyObject *path, PyObject *line,
                            Py_ssize_t integer_digits, Py_ssize_t fraction_digits)
{
    static const int word_names[] = {F_LETTER, F_VALUE, F_SPAN};
    static const int assign_names[] = {F_TARGET, F_VALUE, F_SPAN};
    static const int block_names[] = {F_WORDS, F_ASSIGNS, F_MESSAGE, F_LINE_NUMBER, F_BLOCK_DELETE, F_SPAN};
    PyObject *words = NULL, *assigns = NULL, *result = NULL, *values[6];
    Py_ssize_t count, first_col, last_end = 0, start, end;
    Token stack[STACK_TOKENS], *found = stack;
    Parser p;
    int block_delete;
    p.s = s;
    p.path = path;
    p.line = line;
    if (size + 1 > STACK_TOKENS && (found = PyMem_New(Token, size + 1)) == NULL)
        return PyErr_NoMemory();
    count = scan(p.s, size, 0, 0, integer_digits, fraction_digits, found);
    if (count < 2)  /* nothing to read, or no token covers a character */
        goto done;
    p.tokens = found;
    p.count = count;
    p.i = 0;
    p.gave_up = 0;
    words = PyList_New(0);
    assigns = PyList_New(0);
    if (words == NULL || assigns == NULL)
        goto done;
    first_col = found[0].col;
    block_delete = found[0].kind == OP_SLASH;
    if (block_delete)
        p.i = 1;
    for (;;) {
        Token *token = at(&p, p.i);
        PyObject *made;
        if (token->kind == OP_HASH) {
            PyObject *target = param(&p, &start, &end), *value;
            if (target == NULL)
                goto done;
            if (!expect(&p, OP_ASSIGN) || at(&p, p.i)->kind == OP_ASSIGN) {
                p.gave_up = 1;
                Py_DECREF(target);
                goto done;
            }
            value = expr(&p, 1, &start, &end);
            if (value == NULL) {
                Py_DECREF(target);
                goto done;
            }
            values[0] = target;
            values[1] = value;
            values[2] = span(&p, token->col, end);
            made = node(ASSIGN, 3, assign_names, values);
            if (made == NULL || PyList_Append(assigns, made) < 0) {
                Py_XDECREF(made);
                goto done;
            }
            Py_DECREF(made);
            last_end = end;
        } else if (token->kind == T_LETTERS) {
            Py_ssize_t length = token->stop - token->start, col = token->col;
            char letter = (char)(p.s[token->start] & ~0x20);
            PyObject *value;
            if (length == 1) {
                p.i++;
            } else if (lookup(p.s + token->start + 1, length - 1, FUNCTIONS, N_FUNCTIONS) >= 0
                       && lookup(p.s + token->start, length, FUNCTIONS, N_FUNCTIONS) < 0) {
                token->start += 1;  /* XSIN[1]: the word X, then SIN */
                token->col += 1;
            } else {  /* ASIN[ (the function wins), MOD, GX: the grammar's */
                p.gave_up = 1;
                goto done;
            }
            value = operand(&p, &start, &end);
            if (value == NULL)
                goto done;
            values[0] = letters[letter - 'A'];
            Py_INCREF(values[0]);
            values[1] = value;
            values[2] = span(&p, col, end);
            made = node(WORD, 3, word_names, values);
            if (made == NULL || PyList_Append(words, made) < 0) {
                Py_XDECREF(made);
                goto done;
            }
            Py_DECREF(made);
            last_end = end;
        } else if (token->kind == T_END) {
            break;
        } else {
            p.gave_up = 1;
            goto done;
        }
    }
    if (PyList_Size(words) == 0 && PyList_Size(assigns) == 0) {
        p.gave_up = 1;
        goto done;
    }
    {
        PyObject *line_number = Py_None, *word_tuple;
        Py_ssize_t skip = 0;
        Py_INCREF(Py_None);
        if (PyList_Size(words) > 0) {
            PyObject *first = PyList_GetItem(words, 0);
            PyObject *letter = PyObject_GetAttr(first, fields[F_LETTER]);
            PyObject *value = letter ? PyObject_GetAttr(first, fields[F_VALUE]) : NULL;
            if (value == NULL) {
                Py_XDECREF(letter);
                Py_DECREF(Py_None);
                goto done;
            }
            if (letter == letters['N' - 'A'] && Py_IS_TYPE(value, (PyTypeObject *)classes[NUMBER])) {
                PyObject *number_value = PyObject_GetAttr(value, fields[F_VALUE]);
                Py_DECREF(Py_None);
                line_number = number_value ? PyLong_FromDouble(PyFloat_AsDouble(number_value)) : NULL;
                Py_XDECREF(number_value);
                skip = 1;
            }
            Py_DECREF(letter);
            Py_DECREF(value);
            if (line_number == NULL)
                goto done;
        }
        word_tuple = PyList_GetSlice(words, skip, PyList_Size(words));
        values[0] = word_tuple ? PyList_AsTuple(word_tuple) : NULL;
        Py_XDECREF(word_tuple);
        values[1] = PyList_AsTuple(assigns);
        values[2] = Py_None;
        Py_INCREF(Py_None);
        values[3] = line_number;
        values[4] = PyBool_FromLong(block_delete);
        values[5] = span(&p, first_col, last_end);
        result = node(BLOCK, 6, block_names, values);
    }
done:
    Py_XDECREF(words);
    Py_XDECREF(assigns);
    if (found != stack)
        PyMem_Free(found);
    return result;
}

static int ready(void)
{
    if (classes[0] != NULL)
        return 1;
    PyErr_SetString(PyExc_RuntimeError, "_lexer.setup() was not called");
    return 0;
}

static PyObject *block(PyObject *self, PyObject *args)
{
    PyObject *text, *path, *line, *result;
    Py_ssize_t integer_digits, fraction_digits, size, at_byte;
    const char *s;
    (void)self;
    if (!ready() || !PyArg_ParseTuple(args, "UOOnn", &text, &path, &line, &integer_digits, &fraction_digits))
        return NULL;
    s = utf8_at(text, 0, &size, &at_byte);
    if (s == NULL)
        Py_RETURN_NONE;
    result = read_block(s, size, path, line, integer_digits, fraction_digits);
    if (result == NULL && !PyErr_Occurred())
        Py_RETURN_NONE;
    return result;
}

/* The condition of an If/While head whose keyword ends at byte ``at_byte`` (code point ``pos``) of the
 * UTF-8 line s[:size], exactly as fastparse._Line.condition reads it, with its end column and stray
 * ']' count; NULL without an exception where that method gives up. */
static PyObject *read_condition(const char *s, Py_ssize_t size, Py_ssize_t at_byte, Py_ssize_t pos,
                                PyObject *path, PyObject *line, int is_if, Py_ssize_t integer_digits,
                                Py_ssize_t fraction_digits, Py_ssize_t *end, Py_ssize_t *extra)
{
    static const char *const THEN[] = {"THEN"};
    PyObject *cond = NULL;
    Py_ssize_t count, start;
    Token stack[STACK_TOKENS], *found = stack;
    Parser p;
    Token *then;
    *extra = 0;
    if (size - at_byte + 1 > STACK_TOKENS && (found = PyMem_New(Token, size - at_byte + 1)) == NULL)
        return PyErr_NoMemory();
    count = scan(s, size, at_byte, pos, integer_digits, fraction_digits, found);
    if (count < 1)
        goto fail;
    p.s = s;
    p.path = path;
    p.line = line;
    p.tokens = found;
    p.count = count;
    p.i = 0;
    p.gave_up = 0;
    if (!expect(&p, OP_BRACKET))
        goto fail;
    cond = expr(&p, 1, &start, end);
    if (cond == NULL || !(*end = expect(&p, OP_CLOSE)))
        goto fail;
    while (at(&p, p.i)->kind == OP_CLOSE) {
        *end = expect(&p, OP_CLOSE);
        (*extra)++;
    }
    then = at(&p, p.i);
    if (is_if && then->kind == T_LETTERS) {
        if (lookup(p.s + then->start, then->stop - then->start, THEN, 1) < 0)
            goto fail;
        *end = expect(&p, T_LETTERS);
    }
    if (at(&p, p.i)->kind != T_END)
        goto fail;
    if (found != stack)
        PyMem_Free(found);
    return cond;
fail:
    Py_XDECREF(cond);
    if (found != stack)
        PyMem_Free(found);
    return NULL;
}

/* condition(text, pos, path, line, is_if, integer_digits, fraction_digits): the condition of an
 * If/While head whose keyword ends before ``pos``, as (cond, end column, stray ']' count), exactly
 * as fastparse._Line.condition reads it; None where that method gives up or this one does not try. */
static PyObject *condition(PyObject *self, PyObject *args)
{
    PyObject *text, *path, *line, *cond, *result;
    Py_ssize_t pos, integer_digits, fraction_digits, size, at_byte, end, extra;
    int is_if;
    const char *s;
    (void)self;
    if (!ready() || !PyArg_ParseTuple(args, "UnOOpnn", &text, &pos, &path, &line, &is_if, &integer_digits,
                                      &fraction_digits))
        return NULL;
    s = utf8_at(text, pos, &size, &at_byte);
    if (s == NULL)
        Py_RETURN_NONE;
    cond = read_condition(s, size, at_byte, pos, path, line, is_if, integer_digits, fraction_digits, &end, &extra);
    if (cond == NULL) {
        if (PyErr_Occurred())
            return NULL;
        Py_RETURN_NONE;
    }
    result = Py_BuildValue("(Onn)", cond, end, extra);
    Py_DECREF(cond);
    return result;
}

/* ------------------------------------------------------------------------------------------
 * statement(text, path, line, integer_digits, fraction_digits): what fastparse.parse_fast makes of a
 * line without '(' (the caller checks that, and the input limits): None for a blank or comment line,
 * the Block of words and assignments (as block() above), the Open/Close of a Sub/If/While head or
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
    p.s = s;
    p.path = path;
    p.line = line;
    p.tokens = found;
    p.count = count;
    p.i = 0;
    p.gave_up = 0;
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
        if (item == NULL || PyList_Append(items, item) < 0) {
            Py_XDECREF(item);
            goto done;
        }
        Py_DECREF(item);
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
 * is longer than ``shortest_problem`` code points or holds a '(' (line_parser.parse_line asks the
 * compiled reader about the other lines only). */
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
            } else if (memchr(s, '(', (size_t)size) == NULL) {
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
 * field) without the Python-level call of that __init__. */
static PyObject *new_node(PyObject *self, PyObject *args)
{
    PyObject *cls, *values, *names, *made;
    Py_ssize_t k, count;
    (void)self;
    if (!PyArg_ParseTuple(args, "O!O!", &PyType_Type, &cls, &PyTuple_Type, &values))
        return NULL;
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
        if (pair == NULL || PyList_Append(out, pair) < 0) {
            Py_XDECREF(pair);
            return -1;
        }
        Py_DECREF(pair);
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
    if (pair == NULL || PyList_Append(out, pair) < 0) {
        Py_XDECREF(pair);
        return -1;
    }
    Py_DECREF(pair);
    return 0;
}

/* Append (param, literal index, scope) to ``uses`` for every pair of ``pairs``. */
static int uses_into(PyObject *uses, PyObject *pairs, PyObject *scope)
{
    Py_ssize_t i, count = PyList_Size(pairs);
    for (i = 0; i < count; i++) {
        PyObject *pair = PyList_GetItem(pairs, i);
        PyObject *use = PyTuple_Pack(3, PyTuple_GetItem(pair, 0), PyTuple_GetItem(pair, 1), scope);
        if (use == NULL || PyList_Append(uses, use) < 0) {
            Py_XDECREF(use);
            return -1;
        }
        Py_DECREF(use);
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
            PyObject *literal = literal_of(target, literal_index), *use;
            use = literal ? PyTuple_Pack(3, target, literal, scope) : NULL;
            Py_XDECREF(literal);
            failed = use == NULL || PyList_Append(targets, use) < 0;
            Py_XDECREF(use);
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
    PyObject *pair = PyTuple_Pack(2, first, second);
    int failed = pair == NULL || PyList_Append(list, pair) < 0;
    Py_XDECREF(pair);
    return failed ? -1 : 0;
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

/* An If or a While: its condition's reads, then its branches or body (an If that reads #5380 with
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
        reads_simulation = PyObject_RichCompareBool(PyTuple_GetItem(PyList_GetItem(pairs, i), 1), sv->simulation, Py_EQ);
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

static PyMethodDef methods[] = {
    {"tokens", tokens, METH_VARARGS,
     "tokens(text, pos, integer_digits, fraction_digits): the fast path's tokens, None to give up."},
    {"block", block, METH_VARARGS,
     "block(text, path, line, integer_digits, fraction_digits): the Block of a word line, None to give up."},
    {"condition", condition, METH_VARARGS,
     "condition(text, pos, path, line, is_if, integer_digits, fraction_digits): (cond, end, extra), None to give up."},
    {"statement", statement, METH_VARARGS,
     "statement(text, path, line, integer_digits, fraction_digits): the node of a line, None if blank, "
     "the give-up marker to give up."},
    {"block_facts", block_facts, METH_VARARGS,
     "block_facts(code_key, literal_index, block, scope, uses, targets): (g, m, coded, reads) as "
     "lint.facts.block_facts."},
    {"expr_reads", expr_reads, METH_VARARGS,
     "expr_reads(literal_index, expr): the (param, literal index) pairs of lint.facts.expr_reads."},
    {"statements", statements, METH_VARARGS,
     "statements(lines, path, first_line, shortest_problem, integer_digits, fraction_digits): statement() of "
     "each short line without '(', the give-up marker for the others."},
    {"survey", survey, METH_VARARGS,
     "survey(code_key, literal_index, scope_class, simulation_branches, other_reads, codes_class, end_keys, "
     "simulation, into, body, scope): lint.facts._Survey.visit(body, scope) on into."},
    {"new", new_node, METH_VARARGS,
     "new(cls, values): a frozen dataclass node with these field values, as its __init__ makes it."},
    {"setup", setup, METH_VARARGS,
     "setup(nodes_module[, blocks_module, give_up, keywords]): the classes the readers make."},
    {NULL, NULL, 0, NULL},
};

static struct PyModuleDef module = {
    PyModuleDef_HEAD_INIT, "_lexer", "The optional compiled tokenizer (see syntax/fastparse.py).", -1, methods,
    NULL, NULL, NULL, NULL,
};

PyMODINIT_FUNC PyInit__lexer(void)
{
    size_t k;
    kind_number = PyUnicode_InternFromString("n");
    kind_string = PyUnicode_InternFromString("s");
    kind_letters = PyUnicode_InternFromString("i");
    empty = PyUnicode_InternFromString("");
    if (kind_number == NULL || kind_string == NULL || kind_letters == NULL || empty == NULL)
        return NULL;
    for (k = 0; k < N_OPERATORS; k++) {
        operator_text[k] = PyUnicode_InternFromString(OPERATORS[k]);
        if (operator_text[k] == NULL)
            return NULL;
    }
    for (k = 0; k < N_FIELDS; k++)
        if ((fields[k] = PyUnicode_InternFromString(FIELD_NAMES[k])) == NULL)
            return NULL;
    for (k = 0; k < N_FUNCTIONS; k++)
        if ((function_names[k] = PyUnicode_InternFromString(FUNCTIONS[k])) == NULL)
            return NULL;
    for (k = 0; k < N_WORD_OPERATORS; k++)
        if ((word_operator_text[k] = PyUnicode_InternFromString(WORD_OPERATORS[k])) == NULL)
            return NULL;
    for (k = 0; k < N_HANDLED; k++)
        if ((handled_text[k] = PyUnicode_InternFromString(HANDLED_TEXT[k])) == NULL)
            return NULL;
    for (k = 0; k < 26; k++) {
        char name[2] = {(char)('A' + k), '\0'};
        if ((letters[k] = PyUnicode_InternFromString(name)) == NULL)
            return NULL;
    }
    return PyModule_Create(&module);
}
