"""The Python core's reader of runs of arc lines (``machine/plain_arcs.py``) reads them as the general path does.

``plain_arcs`` inlines the general path's ``_target``, ``center_from_radius``, ``check_radius``, ``sweep`` and
``path_length``: on the lines of tests/arc_lines.py in every plane, distance mode, unit and offset, and on
random arcs, it must give the very records ``arc_run`` over ``BulkPath._arc_of_words`` gives, or stop where it
stops.  (tests/speedups/test_speedups.py holds the compiled one to the same.)
"""
from __future__ import annotations

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from edingcnc_lang import RunOptions
from edingcnc_lang.machine import bulk
from edingcnc_lang.machine.plain_arcs import ARC_ORDER, plain_arcs
from edingcnc_lang.machine.plain_runs import usual_order
from edingcnc_lang.runner import Run
from edingcnc_lang.syntax.plain_words import FAST_NUMBER, is_fast_line
from tests.arc_lines import assert_arc_reader_is_the_general_paths


def test_the_python_arcs_of_plain_lines_are_the_general_paths() -> None:
    assert_arc_reader_is_the_general_paths(plain_arcs)


def test_the_arc_order_reads_a_plain_line_as_fast_number_does() -> None:
    """ARC_ORDER reads a number as any run of digits and points: on plain lines the same words as FAST_NUMBER."""
    strict = usual_order(FAST_NUMBER, "", "GXYZABCIJKRF")
    texts = ["G2 X1.5 Y2.5 I0.5 J-0.25", "N12 G03 X1 Y2 Z-1 R5. F300", "G2 X1 Y2 I1 J1 ; G3", "X1 I1 G2",
             "G2 X1 Y2 K1", "g2 x 1.5 i .5", "G2 X1.2.3 I1", "N1 G2 X1 A2 B3 C4 I5 J6 K7 R8 F9"]
    for text in texts:
        found, expected = ARC_ORDER.match(text), strict.match(text)
        assert is_fast_line(text) == (text != "G2 X1.2.3 I1")
        if is_fast_line(text):
            assert (found and found.groups()) == (expected and expected.groups()), text
    assert ARC_ORDER.match(texts[1]).groups() == ("03", "1", "2", "-1", None, None, None, None, None, None, "5.", "300")


ends = st.tuples(st.floats(-50, 50).map(lambda v: round(v, 4)), st.floats(-50, 50).map(lambda v: round(v, 4)))
arc_words = st.one_of(
    st.builds(lambda e, r: f"X{e[0]} Y{e[1]} R{r}", ends, st.floats(-60, 60).map(lambda v: round(v, 3))),
    st.builds(lambda e, c: f"X{e[0]} Y{e[1]} I{c[0]} J{c[1]}", ends, ends))


@settings(max_examples=300, deadline=None)
@given(st.lists(st.tuples(st.sampled_from(["G2 ", "G3 ", ""]), arc_words, st.sampled_from(["", " Z-1", " F100"])),
                min_size=1, max_size=8), st.sampled_from(["G17 G90 G21", "G17 G91 G20", "G18 G90 G21"]))
def test_random_runs_of_arcs_are_the_general_paths(words: list[tuple[str, str, str]], state: str) -> None:
    """Random R and I/J arcs (most of them impossible, some nearly so) as runs, from a moving start."""
    run = Run(RunOptions())
    run.execute_text(state + "\n", "job.nc")
    interp = run.interpreter
    lines = tuple(enumerate((g + w + z for g, w, z in words), 3))
    pose = (1.25, -3.5, 0.5, 0.0, 0.0, 0.0)
    with pytest.MonkeyPatch.context() as monkeypatch:
        monkeypatch.setattr(bulk, "_PLAIN_ARCS", plain_arcs)
        read = interp._arc_reader()
        for motion in (20, 30):
            taken = read(lines, 0, pose, motion, 300.0, len(lines))
            assert taken == bulk.arc_run(interp._arc_of_words, lines, 0, pose, motion, 300.0, len(lines)), lines


def _run_of_arcs(count: int, form: str) -> list[str]:
    """``count`` half circles along X, G3 and G2 in turn, in R or I/J form (one shape, as a job's long runs)."""
    words = "R-1.0" if form == "R" else "I1.0 J0"
    return [f"G{3 - k % 2} X{2.0 * (k + 1):.4f} Y0 {words}" for k in range(count)]


def test_runs_of_one_shape_are_read_as_the_lines_are_one_by_one() -> None:
    """Long runs of one shape (read as columns) give the general path's arcs, and stop where it stops: at a
    line of another shape, at an arc it refuses, at another motion, at the end of the room."""
    run = Run(RunOptions())
    run.execute_text("G17 G90 G21\n", "job.nc")
    interp = run.interpreter
    pose = (0.0, 0.0, -1.0, 0.0, 0.0, 0.0)
    cases = []
    for form in ("R", "IJ"):
        lines = _run_of_arcs(80, form)
        cases.append(lines)
        for at, other in ((40, "G3 X81 Y0 R0.1"), (17, "G3 X36 Y0 Z-2 R-1"), (50, "g02 x102 y0 r-1.0"),
                          (30, "G1 X62 Y0"), (64, "G2 X130 Y0 I1 J0 ; note"), (20, "G3 X42 Y0 R-1 (é)"),
                          (33, "G2 X68.0000 Y0 I1.0 J0.0"), (45, "G3.5 X92 Y0 R-1.0")):
            cases.append(lines[:at] + [other] + lines[at + 1:])
    with pytest.MonkeyPatch.context() as monkeypatch:
        monkeypatch.setattr(bulk, "_PLAIN_ARCS", plain_arcs)
        read = interp._arc_reader()
        for texts in cases:
            numbered = tuple(enumerate(texts, 4))
            for first in (0, 1, 25):
                for room in (len(texts), 30):
                    taken = read(numbered, first, pose, 20, 300.0, room)
                    assert taken == bulk.arc_run(interp._arc_of_words, numbered, first, pose, 20, 300.0, room), texts
    assert len(read(tuple(enumerate(cases[0])), 0, pose, 20, 300.0, 80)[3]) == 80
