"""The pure-Python core's fast readers and writers read and write exactly what their plain forms do.

``plain_runs.USUAL_ORDER`` reads a number as any run of digits and points, possessively from Python 3.11
on: on the plain lines it is given (the check pass's FAST_LINE) it must take the same lines and the same
words as the pattern with FAST_NUMBER, backtracking included.  ``sinks.trace_rows`` writes a column of few
values once a value: its rows must be those a move at a time writes (``TraceWriter.move``), -0.0 and NaN too.
"""
from __future__ import annotations

import math
import re

from hypothesis import given, settings
from hypothesis import strategies as st

from edingcnc_lang.machine import plain_runs
from edingcnc_lang.machine.plain_runs import G_0, G_1, USUAL_ORDER, usual_order
from edingcnc_lang.motion.sinks import SIX_REPR, trace_rows
from edingcnc_lang.syntax.plain_words import FAST_NUMBER, is_fast_line, plain_words, word_matches

numbers = st.one_of(st.integers(-999, 99999).map(str), st.floats(-1000, 1000).map(lambda v: f"{v:.4f}"),
                    st.sampled_from([".5", "-.25", "+3", "7.", "0", "00012.500", "1" * 40, "-0", "1.2.3", ".", "1..",
                                     "1" * 301, "0." + "1" * 401, "+-1"]))
words = st.tuples(st.sampled_from("GXYZABCFNIJRMgxyzfn"), st.sampled_from(["", " ", "\t"]), numbers)
lines = st.builds(lambda lead, ws, gap, tail: lead + gap.join(f"{c}{a}{v}" for c, a, v in ws) + tail,
                  st.sampled_from(["", " ", "\t "]), st.lists(words, max_size=7), st.sampled_from([" ", "", "  "]),
                  st.sampled_from(["", " ", " ; cut X5", ";", " (note)", "\r", "\t"]))
# the usual order's reference: FAST_NUMBER, nothing possessive (the pattern as Python 3.10 runs it, and as it was)
STRICT = usual_order(FAST_NUMBER, "")
SIMPLE = usual_order("[0-9.]+", "")


@settings(max_examples=1000, deadline=None)
@given(lines)
def test_the_usual_order_reads_a_plain_line_as_fast_number_does(text: str) -> None:
    if not is_fast_line(text):
        return  # (the bulk path is given plain lines only)
    strict = STRICT.match(text)
    expected = strict and strict.groups()
    for pattern in (USUAL_ORDER, SIMPLE):
        found = pattern.match(text)
        assert (found and found.groups()) == expected, (text, pattern.pattern)


def test_the_usual_order_on_lines_cam_output_writes() -> None:
    """The lines of a CAM pass (N words, arcs that must be refused quickly) and the ones around them."""
    texts = ["N10 G1 X0.0114 Y6.8164", "N12 G2 X1.5 Y2.5 I0.5 J-0.25", "N14 G0 Z5.", "N15 X1 Y2", "N16 G1 Z-1. F300",
             "G1 X1 Y2 ; G2", "g01 x 1.5 y-2 z+.5 a1 b2 c3 f100", "X1 G1", "N1 N2 X1", "G1 X1 X2", "  ", ""]
    for text in texts:
        assert is_fast_line(text) or not text.strip()
        strict = STRICT.match(text)
        found = USUAL_ORDER.match(text)
        assert (found and found.groups()) == (strict and strict.groups()), text
    assert USUAL_ORDER.match(texts[0]).groups() == ("1", "0.0114", "6.8164", None, None, None, None, None)
    assert USUAL_ORDER.match(texts[1]) is None


def test_the_g_texts_looked_up_are_the_motions_their_numbers_give() -> None:
    for text, motion in plain_runs._MOTION_OF.items():
        assert motion == (G_0 if float(text) == 0.0 else G_1) and float(text) in (0.0, 1.0), text


def _rows_one_at_a_time(lines: list[int], kinds: list[str], ends: list[tuple[float, ...]], name: str,
                        times: list[float]) -> str:
    """What TraceWriter.move writes for each move (its joints are its end)."""
    return "".join(f"{line},{kind},{SIX_REPR % end},{SIX_REPR % end},{name},{time!r}\n"
                   for line, kind, end, time in zip(lines, kinds, ends, times[1:]))


COLUMNS = [
    [5.0, 1.0, -2.0, 5.0] * 40,  # a hole's levels: few values, written once each
    [0.0, -0.0] * 80,  # zeros of both signs among few values: each its own repr
    [-0.0, 1.5] * 80, [1.5, -0.0] * 80, [0.0] * 100 + [-0.0], [math.nan, 1.0] * 50,
    [math.inf, -math.inf, 1e22] * 40, [0.1 + 0.2, 0.3] * 60, [float(i) for i in range(160)],  # all distinct
    [float(i // 4) for i in range(160)], [1.0] * 64 + [float(i) for i in range(100)],  # repeats, then not
]


def test_trace_rows_of_columns_of_few_values_are_the_moves_rows() -> None:
    for column in COLUMNS:
        count = len(column)
        for axis in range(6):
            ends = [tuple(column[row] if k == axis else (float(row % 3) if k < 3 else 0.0) for k in range(6))
                    for row in range(count)]
            args = (list(range(count)), ["rapid", "linear"] * (count // 2) + ["rapid"] * (count % 2), ends, "job.nc",
                    [0.0, *(row * 0.1 for row in range(1, count + 1))])
            assert trace_rows(*args) == _rows_one_at_a_time(*args), (column[:4], axis)


@settings(max_examples=300, deadline=None)
@given(st.lists(st.tuples(*[st.sampled_from([0.0, -0.0, 1.0, 2.5, -7.125, 1e-7, math.nan, 3.0])] * 6),
                min_size=1, max_size=150),
       st.sampled_from(["job.nc", "100%.nc", '"a,b"']))
def test_trace_rows_of_any_few_values_are_the_moves_rows(ends: list[tuple[float, ...]], name: str) -> None:
    count = len(ends)
    args = (list(range(count)), ["linear"] * count, ends, name, [float(i) for i in range(count + 1)])
    assert trace_rows(*args) == _rows_one_at_a_time(*args)


def test_trace_rows_stop_at_the_shortest_column_when_every_coordinate_is_the_same() -> None:
    ends = [(1.0, 2.0, 3.0, 0.0, 0.0, 0.0)] * 2
    assert trace_rows([1, 2, 3, 4], ["rapid"] * 4, ends, "job.nc", [0.0, 1.0, 2.0, 3.0, 4.0]) == \
        "1,rapid,1.0,2.0,3.0,0.0,0.0,0.0,1.0,2.0,3.0,0.0,0.0,0.0,job.nc,1.0\n" \
        "2,rapid,1.0,2.0,3.0,0.0,0.0,0.0,1.0,2.0,3.0,0.0,0.0,0.0,job.nc,2.0\n"


STRICT_WORDS = re.compile(rf"([A-Za-z])[ \t]*([+-]?{FAST_NUMBER})")


@settings(max_examples=1000, deadline=None)
@given(lines)
def test_the_words_of_a_plain_line_are_those_fast_number_reads(text: str) -> None:
    if not is_fast_line(text) or "(" in text:
        return  # (a line with a comment is read token by token)
    semicolon = text.find(";")
    expected = STRICT_WORDS.findall(text, 0, semicolon if semicolon >= 0 else len(text))
    assert plain_words(text) == expected
    assert [(m.group(1), m.group(2), m.span()) for m in word_matches(text)] == \
        [(m.group(1), m.group(2), m.span())
         for m in STRICT_WORDS.finditer(text, 0, semicolon if semicolon >= 0 else len(text))]
