"""The compiled tokenizer (``_lexer.c``) gives exactly the tokens of the Python one, or gives up where
it gives up, and its block reader builds exactly the Blocks of ``fastparse._Line.block``; the Python
functions are the reference.

Lines are built from the pieces the fast path meets (numbers near the digit limits, strings,
comments, operators, letters) and from arbitrary text (other characters, non-ASCII, lone
surrogates, newlines), read from a random start.
"""
from __future__ import annotations

import os
from pathlib import Path
import random
import subprocess
import sys

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from edingcnc_lang.syntax import blocks, fastparse, nodes
from edingcnc_lang.syntax.input_limits import MAX_NUMBER_DIGITS
from edingcnc_lang.syntax.plain_words import INTEGER_DIGITS
from edingcnc_lang.syntax.printer import expr_text, stmt_lines

from .test_fastparse import _respace, comments, lines
from .test_properties import blocks as block_nodes, exprs, plain_lines

pytestmark = pytest.mark.slow  # the whole module (pyproject's slow marker)

lexer = pytest.importorskip("edingcnc_lang._lexer", reason="the compiled tokenizer is not built")
lexer.setup(nodes, blocks, fastparse.GIVE_UP, fastparse._KEYWORDS - fastparse._HANDLED)  # as fastparse does (also under ECNC_PURE_PYTHON=1)


def _python(text: str, pos: int) -> object:
    try:
        return fastparse._tokens_python(text, pos)
    except fastparse._GiveUp:
        return None


def _same(text: str, pos: int = 0) -> None:
    compiled = lexer.tokens(text, pos, INTEGER_DIGITS, MAX_NUMBER_DIGITS)
    if compiled is NotImplemented:  # not UTF-8: the wrapper hands it to the Python tokenizer
        with pytest.raises(UnicodeEncodeError):
            text.encode()
        return
    assert compiled == _python(text, pos), (text, pos)


def _digits(count: int) -> str:
    return "".join(str(i % 10) for i in range(count))


numbers = st.one_of(
    st.from_regex(r"[0-9]{1,4}(\.[0-9]{0,3})?|\.[0-9]{1,3}", fullmatch=True),
    st.sampled_from([INTEGER_DIGITS - 1, INTEGER_DIGITS, INTEGER_DIGITS + 1]).map(_digits),
    st.sampled_from([MAX_NUMBER_DIGITS - 1, MAX_NUMBER_DIGITS, MAX_NUMBER_DIGITS + 1])
      .map(lambda count: "1." + _digits(count)),
    st.sampled_from([MAX_NUMBER_DIGITS, MAX_NUMBER_DIGITS + 1]).map(lambda count: "." + _digits(count)),
)
pieces = st.one_of(
    numbers,
    st.sampled_from(["**", "==", "<>", "!=", "<=", ">=", "-", "+", "*", "/", "<", ">", "[", "]", "#", "=",
                     "!", ".", " ", "\t", "  ", "(", ")", ",", "_", "\r", "\n", "é", '"']),
    st.from_regex(r"[A-Za-z]{1,6}", fullmatch=True),
    st.from_regex(r'"[^"\n]{0,6}"', fullmatch=True),
    st.from_regex(r";[^\n]{0,8}", fullmatch=True),
    st.text(max_size=3),
)


@given(st.lists(pieces, max_size=14).map("".join), st.integers(0, 20))
def test_the_compiled_tokenizer_gives_the_python_tokens(text: str, pos: int) -> None:
    _same(text, min(pos, len(text)))


@given(st.text(max_size=30), st.integers(0, 40))
def test_any_text(text: str, pos: int) -> None:
    _same(text, min(pos, len(text)))


@pytest.mark.parametrize("text", [
    "#1 = [#2 * 2.5 + SIN[#3]] ; note", 'msg "é ü" #1 "ok"', "G1 X1.5 Y.5 Z-3.", "If [#1 <> 2] THEN",
    "", "   ", "; only", "#1 = 1 (x)", "a!b", "1..2", "x\ud800", 'msg "\ud800"', "; \ud800", "é", "X1 é",
    "1" * INTEGER_DIGITS + "." + "2" * MAX_NUMBER_DIGITS, "1" * (INTEGER_DIGITS + 1),
    "1." + "2" * (MAX_NUMBER_DIGITS + 1), '"open', "#1 ; a\nb",
])
@pytest.mark.parametrize("pos", [0, 1, 3])
def test_edges(text: str, pos: int) -> None:
    _same(text, min(pos, len(text)))


def test_the_fast_path_takes_the_compiled_tokenizer_unless_told_not_to() -> None:
    """``ECNC_PURE_PYTHON=1`` selects the Python tokenizer, as it selects the Python core."""
    code = "from edingcnc_lang.syntax import fastparse; print(fastparse._COMPILED is not None)"
    env = {k: v for k, v in os.environ.items() if k != "ECNC_PURE_PYTHON"}
    assert subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, env=env,
                          check=True).stdout.strip() == "True"
    assert subprocess.run([sys.executable, "-c", code], capture_output=True, text=True,
                          env={**env, "ECNC_PURE_PYTHON": "1"}, check=True).stdout.strip() == "False"


# ------------------------------------------------------------------ the compiled block reader

def _python_block(line: str) -> object:
    try:
        return fastparse._Line(fastparse._tokens_python(line, 0), "f", 7).block()
    except (fastparse._GiveUp, IndexError):
        return None


def _same_block(line: str) -> object:
    """The compiled reader gives the Python method's Block (spans and node types included, as repr
    shows them), or gives up; it never answers where the Python method gives up."""
    compiled = lexer.block(line, "f", 7, INTEGER_DIGITS, MAX_NUMBER_DIGITS)
    python = _python_block(line)
    if compiled is not None:
        assert python is not None, line
        assert repr(compiled) == repr(python) and compiled == python, line
        assert [type(w.value) for w in compiled.words] == [type(w.value) for w in python.words], line
    return compiled


@settings(max_examples=150, deadline=None)
@given(block_nodes.map(lambda b: stmt_lines(b)[0]), st.sampled_from(["", " ; note", ";x G1 X2", "   ", " ; é"]),
       st.randoms(use_true_random=False))
def test_the_compiled_block_reader_builds_the_python_blocks(line: str, comment: str, rnd: random.Random) -> None:
    for spaced in (line.replace(" ", ""), line, _respace(line, rnd)):
        _same_block(spaced + comment)


@given(st.lists(pieces, max_size=12).map("".join))
def test_the_compiled_block_reader_on_any_pieces(line: str) -> None:
    _same_block(line)


@pytest.mark.parametrize("line", [
    "#1003 = [#1001 * 1.234 + #4000]", "G1 X[#2 * 2.5] Y[SIN[#2 * 10] * #3] F[#4001 + 100]", "N10 G0 X-1.5 y.5",
    "/M3 S[#1*100]", "#1 = [[#2 > 3] and [#3 <> 0]]", "#1=ATAN[1]/[2]", "#1 = ATAN[1]/2", "#1 = -[2]",
    "XSIN[1]", "#1 = [1 EQ 2] + [3 != 4] - [1 le 2]", "#1 = 2 MOD 3 ** 2 / 4 xor 1", "#1 = #[#2 + 1]",
    "#1 = ##2", "G1 X-#1 Y+[1] Z+2", "N1.5 X1", "#1 = 1 ; é", "x[#1 mod 2] ; ü", "G1 X" + "9" * 300 + ".5",
])
def test_the_compiled_block_reader_takes_the_common_lines(line: str) -> None:
    assert _same_block(line) is not None, line


@pytest.mark.parametrize("line", ["#1 == 2", "GX1", "ASIN[1]", "#1 = MOD2", "G1 X", "G0 X1+2", "é X1",
                                  "#1 = [1", "N", "/", "", "G1 X\ud800"])
def test_the_compiled_block_reader_gives_up_where_python_does(line: str) -> None:
    assert _python_block(line) is None
    assert lexer.block(line, "f", 7, INTEGER_DIGITS, MAX_NUMBER_DIGITS) is None


# ------------------------------------------------------------------ the compiled condition reader

def _same_condition(line: str) -> object:
    """``If``/``While`` heads: the compiled reader gives the condition, end column and stray ']' count
    of ``_Line.condition``, or gives up; never an answer where the Python method gives up."""
    head = fastparse._HEAD.match(line)
    assert head is not None
    kind, start, pos = head.group(1).capitalize(), head.start(1) + 1, head.end()
    compiled = lexer.condition(line, pos, "f", 7, kind == "If", INTEGER_DIGITS, MAX_NUMBER_DIGITS)
    try:
        python = fastparse._Line(fastparse._tokens_python(line, pos), "f", 7).condition(kind, start)
    except (fastparse._GiveUp, IndexError):
        python = None
    if compiled is not None:
        assert python is not None, line
        cond, end, extra = compiled
        assert (repr(cond), end, extra) == (repr(python.cond), python.span.end_col, python.extra), line
    return compiled


@settings(max_examples=100, deadline=None)
@given(exprs.map(expr_text), st.sampled_from(["If ", "IF", "while ", "WHILE"]),
       st.sampled_from(["", "]", "]]", " THEN", " then ; x", "] Then", " ELSE", " X1", " é", " ; é"]))
def test_the_compiled_condition_reader_reads_the_python_conditions(cond: str, keyword: str, tail: str) -> None:
    _same_condition(f"{keyword}[{cond}]{tail}")
    _same_condition(f"{keyword}[{cond.replace(' ', '')}]{tail}")


@pytest.mark.parametrize("line", ["If [[#5380 == 0] and [#5397 == 0]]", "While [#1 < 10]", "IF [#1] THEN",
                                  "If [#1 > 2]] ; stray", "while [[#1 <> 1] or [#2 ge 3]]"])
def test_the_compiled_condition_reader_takes_the_common_heads(line: str) -> None:
    assert _same_condition(line) is not None, line


@pytest.mark.parametrize("line", ["If [1] AND [2]", "While [#1] then", "If #1", "If [#1", "If [1] THEN X",
                                  "If [1] é"])
def test_the_compiled_condition_reader_gives_up_where_python_does(line: str) -> None:
    assert _same_condition(line) is None


@settings(max_examples=300, deadline=None)
@given(plain_lines)
def test_the_compiled_block_reader_builds_the_plain_line_blocks(line: str) -> None:
    """Plain word lines (``line_parser._fast_block``, the regular-expression path) read the same."""
    from edingcnc_lang.syntax.line_parser import _fast_block

    compiled = lexer.block(line, "f", 3, INTEGER_DIGITS, MAX_NUMBER_DIGITS)
    if "(" in line:  # a ( ) comment among the words: the compiled reader leaves it to _fast_block
        assert compiled is None, line
        return
    assert compiled is not None, line
    assert repr(compiled) == repr(_fast_block(line, "f", 3)), line


def test_no_keyword_line_reads_as_words() -> None:
    """``parse_line`` lets the compiled reader try short lines first: it must give up on every line
    that starts with a keyword (none is a letter and a function name, like XSIN)."""
    for keyword in fastparse._KEYWORDS:
        for line in (keyword, f"{keyword} [1]", f"{keyword} X1", f"{keyword.upper()}[#1] = 2", f"{keyword}1"):
            assert lexer.block(line, "f", 1, INTEGER_DIGITS, MAX_NUMBER_DIGITS) is None, line


PARSE_FILES = """
import sys
from pathlib import Path
from edingcnc_lang.syntax.parser import StatementReader
from edingcnc_lang.syntax.source import iter_file_lines
for name in sorted(p for folder in sys.argv[1:] for p in Path(folder).rglob("*")
                   if p.suffix.lower() in (".cnc", ".nc", ".ngc", ".tap")):
    reader = StatementReader(iter_file_lines(name), str(name), tolerant=True)
    print(name, repr(tuple(reader)), repr(reader.diagnostics), repr(reader.warnings))
"""


def test_both_cores_read_the_shipped_files_alike() -> None:
    """Every statement of the examples, the packaged macros and the parser's test files, spans and
    findings included, is the same on the compiled reader and on the pure-Python one."""
    root = Path(__file__).resolve().parent.parent.parent
    folders = [str(root / f) for f in ("examples", "stdlib", "tests/parser", "tests/lint/cases", "tests/corpus")]
    env = {k: v for k, v in os.environ.items() if k != "ECNC_PURE_PYTHON"}

    def read(pure: bool) -> str:
        return subprocess.run([sys.executable, "-c", PARSE_FILES, *folders], capture_output=True, text=True,
                              check=True, env={**env, "ECNC_PURE_PYTHON": "1"} if pure else env).stdout

    compiled = read(False)
    assert compiled.count("\n") > 50  # the files were really read
    assert compiled == read(True)


# ------------------------------------------------------------------ the compiled statement reader

def _python_statement(line: str) -> object:
    """``parse_fast`` on the Python tokenizer and methods alone (the reference)."""
    saved = fastparse._COMPILED, fastparse._COMPILED_BLOCK, fastparse._COMPILED_CONDITION
    fastparse._COMPILED = fastparse._COMPILED_BLOCK = fastparse._COMPILED_CONDITION = None
    try:
        return fastparse.parse_fast(line, "f", 7)
    finally:
        fastparse._COMPILED, fastparse._COMPILED_BLOCK, fastparse._COMPILED_CONDITION = saved


def _same_statement(line: str) -> object:
    """The compiled statement reader gives ``parse_fast``'s node (spans, node and item types included),
    None for a blank line, or gives up; never an answer where ``parse_fast`` gives up.  The caller
    (``line_parser.parse_line``) hands it only lines without '('."""
    compiled = lexer.statement(line, "f", 7, INTEGER_DIGITS, MAX_NUMBER_DIGITS)
    if compiled is fastparse.GIVE_UP:
        return compiled
    python = _python_statement(line)
    assert python is not fastparse.GIVE_UP, line
    assert type(compiled) is type(python) and repr(compiled) == repr(python) and compiled == python, line
    if isinstance(python, (nodes.Message, nodes.Dialog)):
        assert [type(item) for item in compiled.items] == [type(item) for item in python.items], line
    if isinstance(python, blocks.Open):
        assert vars(compiled) == vars(python), line
    return compiled


@settings(max_examples=200, deadline=None)
@given(lines, comments, st.randoms(use_true_random=False))
def test_the_compiled_statement_reader_builds_the_python_nodes(line: str, comment: str, rnd: random.Random) -> None:
    for spaced in (line, _respace(line, rnd)):
        if not fastparse.paren_before_comment(spaced + comment):
            _same_statement(spaced + comment)


@given(st.lists(st.one_of(pieces, st.sampled_from(["msg ", "dlgmsg", "If ", "while", "EndIf", "else", "Sub ",
                                                  "gosub ", "logfile ", "home ", "kin", "_", "1"])),
                max_size=10).map("".join))
def test_the_compiled_statement_reader_on_any_pieces(line: str) -> None:
    if not fastparse.paren_before_comment(line):
        _same_statement(line)


@pytest.mark.parametrize("line", [
    "", "   ", "\t; note", "; é", "EndSub", "  ENDIF ; x", "endwhile", "Else", "Sub user_macro_1",
    "sub 1st ; x", "GoSub change_tool", "If [[#5380 == 0] and [#5397 == 0]]", "IF [#1] THEN", "While [#1 < 10]]",
    'msg "value "#1000" ok"', 'warnmsg "é" #1 "x"', "errmsg", 'logmsg "a" -#2 [1 + 2] SIN[3]',
    'dlgmsg "Setup 0" "Depth" 1000 "Width" 1001', "#1 = [#2 * 2.5]", "G1 X[#2] F100", "N10 G0 X1",
])
def test_the_compiled_statement_reader_takes_the_common_lines(line: str) -> None:
    assert _same_statement(line) is not fastparse.GIVE_UP, line


@pytest.mark.parametrize("line", [
    "home x", 'logfile "a.txt" 1', "kin on", "If [1] AND [2]", "EndIf X1", "Sub", "Sub a b", "GoSub a;\nb",
    'msg "open', "msg ]", "Else\n", " \x0c", "G1 X\ud800", 'msg "\ud800"', "tanknife on", "exec x",
])
def test_the_compiled_statement_reader_gives_up_where_it_should(line: str) -> None:
    assert lexer.statement(line, "f", 7, INTEGER_DIGITS, MAX_NUMBER_DIGITS) is fastparse.GIVE_UP, line


@settings(max_examples=100, deadline=None)
@given(st.lists(st.one_of(lines, st.lists(pieces, max_size=8).map("".join),
                          st.sampled_from(["(x) G1", "G1 X1 (note)", "x" * 101, "#1 = 1" + " " * 95,
                                           "#1 = 2 ; a (b)", 'msg "a;" (b)', '"a ; (b', "G1 X1 ;(msg x)"])),
                max_size=12), st.integers(1, 5000))
def test_the_compiled_lines_reader_reads_each_line_as_the_statement_reader(chunk: list[str], first: int) -> None:
    """``statements`` is ``statement`` of each line short enough for every input limit and without '('
    before its ';' comment,
    and gives up on the others (``parse_line`` asks the compiled reader about no other line)."""
    from edingcnc_lang.syntax.input_limits import SHORTEST_PROBLEM

    found = lexer.statements(chunk, "f", first, SHORTEST_PROBLEM, INTEGER_DIGITS, MAX_NUMBER_DIGITS)
    assert len(found) == len(chunk)
    for number, (line, got) in enumerate(zip(chunk, found), first):
        if len(line) > SHORTEST_PROBLEM or fastparse.paren_before_comment(line):
            assert got is fastparse.GIVE_UP, line
        else:
            want = lexer.statement(line, "f", number, INTEGER_DIGITS, MAX_NUMBER_DIGITS)
            assert got is want if want in (None, fastparse.GIVE_UP) else repr(got) == repr(want), line


def test_new_makes_the_node_the_class_makes() -> None:
    """``_lexer.new`` (the reader's If, While and Sub nodes at end lines) gives what the dataclass's
    own ``__init__`` gives, and refuses a wrong number of values."""
    span, end = nodes.Span("f", 1, 1, 1, 9), nodes.Span("f", 3, 1, 3, 6)
    cond = nodes.Compare("<", nodes.Param(nodes.Number(1.0)), nodes.Number(2.0))
    body = (nodes.GoSub("a", span),)
    for cls, values in ((nodes.If, (cond, body, (), True, 1, span, end)), (nodes.While, (cond, body, 0, span, end)),
                        (nodes.Sub, ("name", body, span, end))):
        made = lexer.new(cls, values)
        want = cls(*values)  # type: ignore[operator]
        assert type(made) is cls and made == want and repr(made) == repr(want)
        assert [getattr(made, f) for f in cls.__match_args__] == list(values)  # type: ignore[attr-defined]
        assert fastparse._construct(cls, values) == want
    with pytest.raises(TypeError):
        lexer.new(nodes.Sub, ("name", body, span))
