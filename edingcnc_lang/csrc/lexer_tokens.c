/* Part of _lexer.c (one translation unit: included there, in this order). The tokenizer: tokens() and the scanner the readers share. */

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

