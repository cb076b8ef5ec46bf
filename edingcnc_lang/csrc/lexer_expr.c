/* Part of _lexer.c (one translation unit: included there, in this order). Expressions, the Block of a word line (block()) and the condition of an If/While head. */

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
#define LINE_NUMBER_DIGITS 5  /* input_limits.LINE_NUMBER_DIGITS (manual 3.4.1) */

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
    if (size + 1 > STACK_TOKENS && (found = PyMem_New(Token, size + 1)) == NULL)
        return PyErr_NoMemory();
    count = scan(s, size, 0, 0, integer_digits, fraction_digits, found);
    if (count < 2)  /* nothing to read, or no token covers a character */
        goto done;
    parser_start(&p, s, path, line, found, count);
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
            if (append_new(assigns, made) < 0)
                goto done;
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
            if (letter == 'N' && PyList_Size(words) == 0 && end - start > LINE_NUMBER_DIGITS) {
                Py_DECREF(value);  /* a line number of more than five digits: the grammar's */
                p.gave_up = 1;
                goto done;
            }
            values[0] = letters[letter - 'A'];
            Py_INCREF(values[0]);
            values[1] = value;
            values[2] = span(&p, col, end);
            made = node(WORD, 3, word_names, values);
            if (append_new(words, made) < 0)
                goto done;
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
    parser_start(&p, s, path, line, found, count);
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

