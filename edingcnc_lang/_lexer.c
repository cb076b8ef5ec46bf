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

static int append(PyObject *list, PyObject *kind, PyObject *value, Py_ssize_t col, Py_ssize_t end)
{
    PyObject *token = PyTuple_New(4), *first, *last;
    int failed;
    if (token == NULL)
        return -1;
    first = PyLong_FromSsize_t(col);
    last = PyLong_FromSsize_t(end);
    if (first == NULL || last == NULL) {
        Py_XDECREF(first);
        Py_XDECREF(last);
        Py_DECREF(token);
        return -1;
    }
    Py_INCREF(kind);
    Py_INCREF(value);
    PyTuple_SetItem(token, 0, kind);  /* each steals the reference */
    PyTuple_SetItem(token, 1, value);
    PyTuple_SetItem(token, 2, first);
    PyTuple_SetItem(token, 3, last);
    failed = PyList_Append(list, token);
    Py_DECREF(token);
    return failed;
}

static PyObject *tokens(PyObject *self, PyObject *args)
{
    PyObject *text, *list, *value = NULL;
    Py_ssize_t pos, integer_digits, fraction_digits, size, i, chars, start, start_char, k;
    const char *s;
    (void)self;
    if (!PyArg_ParseTuple(args, "Unnn", &text, &pos, &integer_digits, &fraction_digits))
        return NULL;
    s = PyUnicode_AsUTF8AndSize(text, &size);
    if (s == NULL) {  /* a lone surrogate: the Python tokenizer reads it */
        PyErr_Clear();
        Py_RETURN_NOTIMPLEMENTED;
    }
    /* the byte where code point ``pos`` starts */
    for (i = 0, chars = 0; i < size && chars < pos; i++)
        if (((unsigned char)s[i] & 0xC0) != 0x80)
            chars++;
    while (i < size && ((unsigned char)s[i] & 0xC0) == 0x80)
        i++;
    list = PyList_New(0);
    if (list == NULL)
        return NULL;
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
                goto give_up;
            i++;
            chars += 2;
            value = PyUnicode_DecodeUTF8(s + start, i - start, NULL);
            if (value == NULL || append(list, kind_string, value, start_char + 1, chars + 1) < 0)
                goto error;
            Py_DECREF(value);
            continue;
        }
        if (is_digit(c) || c == '.') {
            Py_ssize_t digits = 0;
            while (i < size && is_digit((unsigned char)s[i])) {
                i++;
                digits++;
            }
            if (digits > integer_digits)
                goto give_up;
            if (i < size && s[i] == '.') {
                Py_ssize_t fraction = 0;
                i++;
                while (i < size && is_digit((unsigned char)s[i])) {
                    i++;
                    fraction++;
                }
                /* more digits than allowed, or a lone '.': no token covers it */
                if (fraction > fraction_digits || (digits == 0 && fraction == 0))
                    goto give_up;
            } else if (digits == 0) {
                goto give_up;
            }
            chars += i - start;
            value = PyUnicode_FromStringAndSize(s + start, i - start);
            if (value == NULL || append(list, kind_number, value, start_char + 1, chars + 1) < 0)
                goto error;
            Py_DECREF(value);
            continue;
        }
        if (is_letter(c)) {
            while (i < size && is_letter((unsigned char)s[i]))
                i++;
            chars += i - start;
            value = PyUnicode_FromStringAndSize(s + start, i - start);
            if (value == NULL || append(list, kind_letters, value, start_char + 1, chars + 1) < 0)
                goto error;
            Py_DECREF(value);
            continue;
        }
        k = operator_at(s + i, size - i);
        if (k < 0)
            goto give_up;
        value = operator_text[k];
        i += (Py_ssize_t)strlen(OPERATORS[k]);
        chars += i - start;
        if (append(list, value, value, start_char + 1, chars + 1) < 0) {
            Py_DECREF(list);
            return NULL;
        }
    }
    if (append(list, empty, empty, chars + 1, chars + 1) < 0) {
        Py_DECREF(list);
        return NULL;
    }
    return list;
give_up:
    Py_DECREF(list);
    Py_RETURN_NONE;
error:
    Py_XDECREF(value);
    Py_DECREF(list);
    return NULL;
}

static PyMethodDef methods[] = {
    {"tokens", tokens, METH_VARARGS,
     "tokens(text, pos, integer_digits, fraction_digits): the fast path's tokens, None to give up."},
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
    return PyModule_Create(&module);
}
