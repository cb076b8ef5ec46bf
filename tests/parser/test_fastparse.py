"""The hand-written fast parser builds exactly what the Lark grammar builds, spans included.

Lines come from printing generated statements (so every construct and operator appears),
with random spacing, case and comments mixed in; the fast parser may give up on a line,
but whenever it answers, its answer must equal the grammar's.
"""
from __future__ import annotations

import random
import re

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from edingcnc_lang.syntax.fastparse import GIVE_UP, parse_fast
from edingcnc_lang.syntax.parser import _LineError, parse_line_grammar
from edingcnc_lang.syntax.printer import stmt_lines
from edingcnc_lang.syntax.serialize import to_data

from .test_properties import blocks, exprs, messages, simple

_TOKEN_GAP = re.compile(r" ")


def _respace(text: str, rnd: random.Random) -> str:
    """Drop or widen the spaces between tokens, as hand-written files do (one choice per gap)."""
    return _TOKEN_GAP.sub(lambda _m: rnd.choice(["", " ", "  ", "\t"]), text)


def _grammar(line: str) -> object:
    try:
        return to_data(parse_line_grammar(line, "f", 7))
    except _LineError:
        return "error"


def _check(line: str) -> bool:
    fast = parse_fast(line, "f", 7)
    if fast is GIVE_UP:
        return False
    assert to_data(fast) == _grammar(line), line
    return True


heads = st.one_of(
    exprs.map(lambda e: f"If [{_plain(e)}]"), exprs.map(lambda e: f"IF [{_plain(e)}] THEN"),
    exprs.map(lambda e: f"while [{_plain(e)}]"), exprs.map(lambda e: f"If [{_plain(e)}]]"),
    st.sampled_from(["Else", "ENDIF", "endwhile", "EndSub", "Sub 1st_sub", "GoSub change_tool", "gosub X"]),
)


def _plain(expr) -> str:  # type: ignore[no-untyped-def]
    from edingcnc_lang.syntax.printer import expr_text
    return expr_text(expr)


others = st.one_of(
    st.builds(lambda a, t: f"{'homeTandem' if t else 'home'} {a}", st.sampled_from("xyzabcXC"), st.booleans()),
    st.builds(lambda items: "dlgmsg " + " ".join(items),
              st.lists(st.one_of(st.from_regex(r'"[a-z (;]{0,8}"', fullmatch=True),
                                 st.integers(1, 6000).map(str), st.just("#27")), max_size=5)),
    st.builds(lambda name, mode: f"logfile {name}{mode}",
              st.sampled_from(['"log.txt"', "probe.txt", '"a;b (1).txt"', "x", "C:\\temp\\l.txt"]),
              st.sampled_from(["", " 0", " 1", " [1]", " -1"])),
    st.builds(lambda name, state: f"{name} {state}", st.sampled_from(["TCAGuard", "zhc", "tanknife", "LaserEngrave"]),
              st.sampled_from(["on", "OFF", "Off ", "x", "on1", "onx"])),
    st.builds(lambda name, args: f"{name}{args}",
              st.sampled_from(["ZHCINIT", "zhcaddpoint", "ZHCS", "modbus", "GetToolInfo", "exec", "ZHCcheck"]),
              st.sampled_from(["", " ", " [#4104] [#4100] [#4101] ", " 20", " s1 f5 a22 v1", " num 5025",
                               " table.txt", ' "a b.txt"', " -#1 [2 * 3]", " [1]x", " 1 %d", " ]", "\t2\t"])),
)
lines = st.one_of(others, blocks.map(lambda b: stmt_lines(b)[0]), messages.map(lambda m: stmt_lines(m)[0]), heads,
                  simple.map(lambda s: stmt_lines(s)[0]))
comments = st.sampled_from(["", " ; note", ";x G1 X2", "   ", "\t; feed (mm/min)", ' ;; "(x" (', "\t\t;(msg x)"])


@pytest.mark.slow
@settings(max_examples=150, deadline=None)
@given(lines, comments, st.randoms(use_true_random=False))
def test_fast_parser_agrees_with_the_grammar(line: str, comment: str, rnd: random.Random) -> None:
    """Each generated line is checked three ways: every gap closed, as printed, and each gap drawn
    at random (drawing the gaps from one Random, not one hypothesis draw per gap, and three lines
    per example: generating the statements is what costs, not checking them)."""
    for spaced in (line.replace(" ", ""), line, _respace(line, rnd)):
        _check(spaced + comment)


def test_fast_parser_handles_the_common_lines() -> None:
    handled = ["#1 = [#1 + 1]", "G1 X[#1 * 2] Y-[#2] F[#4105]", "If [[#5380 == 0] and [#5397 == 0]]",
               "While [#1 < 10]", "msg \"T\"#5011\" ok\"", "EndIf", "Else", "Sub home_x ; homes X",
               "GoSub change_tool", "X[ATAN[1]/[2]] Y[SQRT[4]]", "/G0 X[1]", "N10 #3 = 6 G1 X#3",
               "home z", "homeTandem x", 'dlgmsg "Setup" "width" 27', 'logfile "probe.txt" 1',
               'errmsg "probe (T1) not found"', "#4504 = 50\t; feed (mm/min)", "\tIF [#5397 == 0]\t; off (0= off)",
               "TCAGuard off ;allow", "ZHC on", "ZHCINIT [#4104] [#4100] [#4101] ", "ZHCADDPOINT",
               "modbus s1 f2 a23 n1 u723 ;; status (x)", "GetToolInfo num 5025", "ZHCS zHeightCompTable.txt"]
    for line in handled:
        assert _check(line), line


def test_fast_parser_gives_up_on_what_it_does_not_cover() -> None:
    for line in ["G0 X1 (comment)", "kin on", "tanknife maybe", "ZHCx on", "ZHCS(a)", "G0 X1+2", "If [1] AND [2]",
                 "#1 == 2", "msg \"open", "Sub a b", "KIN ON", "G1 X"]:
        assert parse_fast(line, "f", 1) is GIVE_UP, line


def test_spans_have_every_field() -> None:
    """The fast parser builds spans with tuple.__new__ (no field check): they must stay complete."""
    from edingcnc_lang.syntax.nodes import Block, Span

    block = parse_fast("G1 X[#1 * -2] Y[SIN[30]]", "f", 4)
    assert isinstance(block, Block)
    spans = [block.span, *(w.span for w in block.words), *(w.value.span for w in block.words)]
    assert all(len(span) == len(Span._fields) and span.path == "f" and span.line == 4 for span in spans)
