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
 * A second extension beside _speedups.c, built the same way (optional, stable ABI).  One translation
 * unit in parts, a part per job (csrc/lexer_*.c), included below in order: their helpers stay static,
 * private to the extension, and the compiler sees the whole as before.
 */
#define PY_SSIZE_T_CLEAN
#define Py_LIMITED_API 0x030A0000
#include <Python.h>
#include <math.h>

#include "csrc/common.c"
#include "csrc/lexer_tokens.c"
#include "csrc/lexer_nodes.c"
#include "csrc/lexer_expr.c"
#include "csrc/lexer_statements.c"
#include "csrc/lexer_blocks.c"
#include "csrc/lexer_facts.c"
#include "csrc/lexer_survey.c"

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
    {"assemble", assemble, METH_VARARGS,
     "assemble(results, k, lines, offset, stack, frame_class, max_depth): statements()'s results from k on "
     "added to the open blocks as StatementReader._fit adds them; (where it stopped, a finished block or None)."},
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
    if (intern_all(operator_text, OPERATORS, N_OPERATORS) < 0 || intern_all(fields, FIELD_NAMES, N_FIELDS) < 0
        || intern_all(function_names, FUNCTIONS, N_FUNCTIONS) < 0
        || intern_all(word_operator_text, WORD_OPERATORS, N_WORD_OPERATORS) < 0
        || intern_all(handled_text, HANDLED_TEXT, N_HANDLED) < 0)
        return NULL;
    for (k = 0; k < 26; k++) {
        char name[2] = {(char)('A' + k), '\0'};
        if ((letters[k] = PyUnicode_InternFromString(name)) == NULL)
            return NULL;
    }
    return PyModule_Create(&module);
}
