"""The check pass's scan in Python (``parser.non_plain_lines``): the other lines of a chunk, wherever they stand.

It runs on every core (tests/speedups/test_speedups.py puts it beside the compiled one where that is built).
"""
from __future__ import annotations

from edingcnc_lang.syntax.input_limits import MAX_LINE_LENGTH
from edingcnc_lang.syntax.parser import non_plain_lines


def test_other_lines_first_last_and_in_a_row_are_found() -> None:
    chunk = ["M3 S1000", "G1 X1 Y2", "N5 G0 Z1 (note) ; tail", "(msg hi)", "#1=2", "g1x1y2", "X1.2.3", "",
             "G1 X" + "1" * 301, "G2 X1 Y1 I1 J0"]
    # M3 S1000 and G2 ... are plain word lines too: "plain" is the word grammar, not the motion
    assert non_plain_lines(chunk) == [3, 4, 6, 7, 8]
    assert non_plain_lines(["#1=2"]) == [0]
    assert non_plain_lines(["G1 X1"]) == []


def test_a_chunk_with_a_line_past_the_length_limit() -> None:
    assert non_plain_lines(["G1 X1", "G1 X" + "1" * MAX_LINE_LENGTH, "(msg)", "G0 Y2"]) == [1, 2]
