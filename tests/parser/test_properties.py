"""Property tests: print/parse round trips and the fast path's equivalence with the grammar."""
from __future__ import annotations

import re

import pytest
from hypothesis import assume, example, given, settings
from hypothesis import strategies as st

from edingcnc_lang.syntax import nodes as n
from edingcnc_lang.syntax.input_limits import MAX_GCODE_LINE
from edingcnc_lang.syntax.parser import is_fast_line, parse_line, parse_line_grammar, parse_text
from edingcnc_lang.syntax.printer import program_text
from edingcnc_lang.syntax.serialize import to_data

pytestmark = pytest.mark.slow  # the whole module (pyproject's slow marker)

numbers = st.one_of(
    st.integers(min_value=-99999, max_value=99999).map(float),
    st.floats(min_value=-1e5, max_value=1e5, allow_nan=False, allow_infinity=False),
).map(n.Number)
params = st.integers(min_value=1, max_value=5999).map(lambda i: n.Param(n.Number(float(i))))


def _expr_tree(children: st.SearchStrategy) -> st.SearchStrategy:
    return st.one_of(
        st.builds(n.Binary, st.sampled_from(["**", "*", "/", "MOD", "+", "-", "OR", "XOR", "AND"]),
                  children, children),
        st.builds(n.Compare, st.sampled_from(["==", "<>", "<", ">", "<=", ">="]), children, children),
        st.builds(n.Unary, st.just("-"), children),
        st.builds(n.Call, st.sampled_from(["ABS", "SIN", "COS", "SQRT", "FIX", "FUP", "ROUND"]),
                  children.map(lambda c: (c,))),
        st.builds(lambda y, x: n.Call("ATAN", (y, x)), children, children),
        children.map(n.Param),
    )


exprs = st.recursive(st.one_of(numbers, params), _expr_tree, max_leaves=8)
letters = st.sampled_from("ABCDEFGHIJKLMPQRSTUVWXYZ")
words = st.builds(n.Word, letters, exprs)
assigns = st.builds(n.Assign, params, exprs)
blocks = st.builds(lambda w, a, d: n.Block(tuple(w), tuple(a), None, None, d),
                   st.lists(words, min_size=1, max_size=5), st.lists(assigns, max_size=2), st.booleans())
texts = st.text(alphabet=st.characters(blacklist_characters='"\n\r', blacklist_categories=("Cs",)), max_size=12)
messages = st.builds(n.Message, st.sampled_from(["msg", "warnmsg", "errmsg", "logmsg"]),
                     st.lists(st.one_of(texts, params, exprs), max_size=4).map(tuple))
simple = st.one_of(blocks, messages, st.builds(n.GoSub, st.from_regex(r"[a-z0-9_]{1,10}", fullmatch=True)),
                   st.builds(n.Home, st.sampled_from("XYZABC"), st.booleans()),
                   st.builds(n.Kin, st.sampled_from(["ON", "OFF", "Y2A", "Z2ZC"])))


def _nest(children: st.SearchStrategy) -> st.SearchStrategy:
    bodies = st.lists(children, max_size=3).map(tuple)
    return st.one_of(
        st.builds(lambda c, t, e, h: n.If(c, t, e if h else (), h), exprs, bodies, bodies, st.booleans()),
        st.builds(n.While, exprs, bodies),
    )


statements = st.recursive(simple, _nest, max_leaves=10)
subs = st.builds(n.Sub, st.from_regex(r"[A-Za-z0-9_]{1,12}", fullmatch=True),
                 st.lists(statements, max_size=4).map(tuple))
programs = st.builds(lambda body: n.Program("<gen>", tuple(body)),
                     st.lists(st.one_of(statements, subs), min_size=1, max_size=6))


@settings(max_examples=60, deadline=None)
@given(programs)
@example(parse_text("A0 A SIN[0] X ATAN[1]/[2]\n", "<gen>"))  # a call glued to its word letter read as ASIN
def test_print_parse_print_is_stable(program: n.Program) -> None:
    printed = program_text(program)
    # a tiny number written out in full can make a G-code line longer than the manual's 256 (E114)
    assume(all(len(line) <= MAX_GCODE_LINE for line in printed.splitlines()))
    first = parse_text(printed, "<gen>")  # the printed text always parses
    text = program_text(first)
    again = parse_text(text, "<gen>")
    assert again == first
    assert program_text(again) == text


def test_round_trip_keeps_a_known_program() -> None:
    source = "Sub a\n  If [#1 > [2 * 3]]\n    G1 X[#1 + 1] F100\n  Else\n    msg \"x\" #2\n  EndIf\nEndSub\n"
    program = parse_text(source)
    assert program_text(program) == source


spaces = st.sampled_from(["", " ", "  ", "\t"])
plain_numbers = st.from_regex(r"[+-]?([0-9]{1,5}(\.[0-9]{0,5})?|\.[0-9]{1,5})", fullmatch=True)  # ASCII: "٠" is no digit
# an N of six digits or more is no plain word: the parser refuses it as a line number (manual 3.4.1)
LONG_LINE_NUMBER = re.compile(r"[Nn][ \t]*[+-]?[0-9]{6}")
plain_words = st.tuples(st.sampled_from("GMXYZABCIJKFSTPQRNgmxyz"), spaces, plain_numbers, spaces).map("".join)
gaps = st.sampled_from(["", "", "(note)", "(T1 D=6 ;x) ", "(msg1)", "( msg_2)", "(a(b)"])  # comments the grammar drops
plain_lines = st.tuples(gaps, spaces, st.lists(st.tuples(plain_words, gaps).map("".join), min_size=1, max_size=7)
                        .map("".join), st.sampled_from(["", ";", "; comment", " ;x", "; ring 8 mm G1 X2", "(end)"])
                        ).map("".join).filter(lambda line: not LONG_LINE_NUMBER.search(line))


@settings(max_examples=400, deadline=None)
@given(plain_lines)
def test_fast_path_builds_what_the_grammar_builds(line: str) -> None:
    assert is_fast_line(line)
    assert to_data(parse_line(line, "f", 3)) == to_data(parse_line_grammar(line, "f", 3))


@settings(max_examples=200, deadline=None)
@given(st.lists(st.sampled_from(["", " ", "\t", "(note)", "( MSG: no )", "(msg)", ";", "; c", "(a;b)", "x"]),
                max_size=5).map("".join))
def test_comment_only_lines_agree_with_the_grammar(line: str) -> None:
    try:
        expected = to_data(parse_line_grammar(line, "f", 1))
    except Exception:  # the grammar rejects it: the fast path must not accept it either
        with pytest.raises(Exception):
            parse_line(line, "f", 1)
        return
    assert to_data(parse_line(line, "f", 1)) == expected


def test_fast_path_declines_lines_it_does_not_understand() -> None:
    for line in ["G1 X[1]", "#1=2", "G0 X1 (msg c)", "G0 X1 (MSG)", "G0 X1 (c", "G0 X1 ( \u00a0msg)", "G0 (é) X1",
                 "msg \"a\"", "Sub a1", "/G0 X1", "G0 X1+2", "G0 X(c)1"]:
        assert not is_fast_line(line)
