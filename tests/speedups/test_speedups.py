"""The compiled core does exactly what the Python reference does (skipped where it is not built).

The whole suite runs on whichever core is active; these tests put both side by side on the
same inputs: the check pass's scan, the bulk path's targets and arcs, an arc's frame, a batch's bounds and
the trace rows, byte for byte.
``ECNC_PURE_PYTHON=1`` must select the Python core in a fresh process.
"""
from __future__ import annotations

import math
import os
import random
import subprocess
import sys
from pathlib import Path

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from edingcnc_lang import RunOptions, run_file
from edingcnc_lang.canon import Arc
from edingcnc_lang.kinematics.trajectory import arc_frame, arc_frame_rows
from edingcnc_lang.machine import plain_runs
from edingcnc_lang.machine.plain_runs import NO_MOTION, plain_moves
from edingcnc_lang.syntax.input_limits import INTEGER_DIGITS, MAX_GCODE_LINE, MAX_NUMBER_DIGITS
from edingcnc_lang.motion.reach import column_bounds
from edingcnc_lang.motion.sinks import trace_rows
from edingcnc_lang.syntax.parser import non_plain_lines
from tests.arc_lines import assert_arc_reader_is_the_general_paths

pytestmark = pytest.mark.slow  # the whole module (pyproject's slow marker)

compiled = pytest.importorskip("edingcnc_lang._speedups", reason="the compiled core is not built here")

numbers = st.one_of(st.integers(-999, 999).map(str), st.floats(-1000, 1000).map(lambda v: f"{v:.4f}"),
                    st.sampled_from([".5", "-.25", "+3", "7.", "0", "00012.500", "1" * 40, "-0"]))
words = st.tuples(st.sampled_from("GXYZABCFNMSgxyzf"), st.sampled_from(["", " ", "\t"]), numbers)
# ( ) comments the plain path skips, and the ones it must leave to the parser (messages, unclosed,
# a control or non-ASCII character after the '(')
comments = st.sampled_from(["", "", "", "(note)", " (a;b) ", "(T1 D=6)", "(msg)", "( MSG, hi)", "(msg1)", "(msg_x)",
                            "(\tmsg x)", "(note", "(é)", "(x é)", "(\x0bmsg)", "( \u00a0msg)", "(()", "(msg",
                            "(\udc80)", "(x \ud800 y)"])  # a lone surrogate: a line read with surrogateescape
lines = st.builds(lambda ws, lead, tail: lead + " ".join(f"{c}{a}{gap}{v}" for c, (a, gap, v) in ws) + tail,
                  st.lists(st.tuples(comments, words), max_size=6), st.sampled_from(["", " ", "\t", "(c) "]),
                  st.sampled_from(["", " ; cut X5", ";", " (note)", "(msg hi)", " (unclosed", "#1=2", "\r",
                                   " ;\udcff", "\ud800", "X\udc801", " \udfff"]))


@settings(max_examples=300, deadline=None)
@given(st.lists(lines, min_size=1, max_size=12))
def test_the_check_scan_is_the_same(chunk: list[str]) -> None:
    assert compiled.non_plain_lines(MAX_GCODE_LINE, INTEGER_DIGITS, MAX_NUMBER_DIGITS, chunk) == non_plain_lines(chunk)


@settings(max_examples=300, deadline=None)
@given(st.lists(lines, min_size=1, max_size=12), st.sampled_from([1.0, 25.4]), st.booleans(),
       st.sampled_from([NO_MOTION, 0, 10]), st.sampled_from([0.0, 500.0]), st.integers(0, 15))
def test_the_targets_of_plain_lines_are_the_same(chunk: list[str], scale: float, incremental: bool, motion: int,
                                                 feed: float, room: int) -> None:
    numbered = tuple((number, text) for number, text in enumerate(chunk, 7) if not non_plain_lines([text]))
    pos, offset = [1.5, -2.0, 0.25, 0.0, 90.0, 0.0], [10.0, 0.1, -3.0, 0.0, 0.0, 45.0]
    args = (numbered, 0, pos, offset, scale, incremental, motion, feed, room)
    assert compiled.plain_moves(*args) == plain_moves(*args)


def test_the_compiled_arcs_of_plain_lines_are_the_same() -> None:
    """The compiled arcs of plain lines against the general path's reading (tests/arc_lines.py)."""
    assert_arc_reader_is_the_general_paths(compiled.plain_arcs)


coordinates = st.one_of(st.floats(-1e4, 1e4), st.sampled_from([0.0, -0.0, 5.0, -5.0, 1e-9]))


@settings(max_examples=400, deadline=None)
@given(st.tuples(*[coordinates] * 6), st.tuples(*[coordinates] * 6), st.tuples(*[coordinates] * 3),
       st.integers(0, 2), st.sampled_from([1, -1, 2, -3]), st.sampled_from([-1.0, 1e-12, 1e-6, math.inf]))
def test_the_frame_of_an_arc_is_the_same(start: tuple[float, ...], end: tuple[float, ...],
                                         center: tuple[float, ...], normal: int, turns: int, epsilon: float) -> None:
    """The circle of an arc as the planner reads it: radii, angles, sweep and length to the last bit."""
    frame = arc_frame(start, end, center, normal, turns, epsilon)
    assert repr(compiled.arc_frame(start, end, center, normal, turns, epsilon)) == repr(tuple(frame))


def test_the_frame_of_an_arc_whose_ends_are_its_centre_is_the_same() -> None:
    """Zero radii and ends on the centre: atan2 of signed zeros, as CPython's own atan2 reads them."""
    for start, end in (((0.0,) * 6, (0.0,) * 6), ((-0.0,) * 6, (0.0, -0.0, 1.0, 0.0, 0.0, 0.0))):
        for turns in (1, -1):
            expected = tuple(arc_frame(start, end, (0.0, -0.0, 0.0), 2, turns, 1e-12))
            assert repr(compiled.arc_frame(start, end, (0.0, -0.0, 0.0), 2, turns, 1e-12)) == repr(expected)


arcs = st.builds(Arc, st.tuples(coordinates, coordinates), st.sampled_from(["XY", "XZ", "YZ"]),
                 st.sampled_from([1, -1]), st.sampled_from([0, 0, 1, 3]))


@settings(max_examples=300, deadline=None)
@given(st.tuples(*[coordinates] * 6), st.lists(st.tuples(st.tuples(*[coordinates] * 6), st.none() | arcs), max_size=8))
def test_the_frames_of_a_batchs_arcs_are_the_same(start: tuple[float, ...],
                                                  moves: list[tuple[tuple[float, ...], Arc | None]]) -> None:
    """A batch's arcs as the motion stage and the planner read them (straight moves between them, every plane,
    full circles and more turns): each the frame the arc's own ``arc_frame`` gives, to the last bit."""
    ends, arcs_of = [end for end, _ in moves], [arc for _, arc in moves]
    rows = arc_frame_rows(start, ends, arcs_of)
    assert repr(compiled.arc_frame_rows(start, ends, arcs_of)) == repr(rows)
    assert len(rows) == 10 * sum(arc is not None for arc in arcs_of)
    with pytest.raises(ValueError):
        compiled.arc_frame_rows(start, [start], [Arc((0.0, 0.0), "XW", 1)])


@pytest.mark.parametrize("chunk", [
    ["M3", "G1 X1", "G1 X2"], ["G1 X1", "G1 X2", "M5"], ["M3", "M4", "G1 X1", "(msg hi)", "#1=2", "G0 Y1"],
    ["G1 X1"], ["G1X1Y2 (note) ; tail", "x 1.5 Y 2", "G1 X1.2.3", "G1 X" + "1" * 301],
    ["G1 X" + "1" * INTEGER_DIGITS, "G1 X" + "1" * (INTEGER_DIGITS + 1), "G1 X1 ;\udc80", "G1 X\ud8001"]])
def test_the_check_scan_at_the_ends_of_a_chunk(chunk: list[str]) -> None:
    """Other lines first, last and one after another: each run of plain lines ends where the scan resumes."""
    assert compiled.non_plain_lines(MAX_GCODE_LINE, INTEGER_DIGITS, MAX_NUMBER_DIGITS, chunk) == non_plain_lines(chunk)


@pytest.mark.parametrize("texts", [
    ["N10 G1 X1 Y2 F100", "n12 g0 z5", "N14 X3 G1", "N16 X4 N18"],    # N words; another order; N twice
    ["G1 X1 F100", "G01 Y2", "G1.0 Z-0", "F-0 X1", "G0 X-0 F0", "G1 X1"],  # G1.0, F-0, a G1 after F0
    ["Y1 X2 Z3 C4 B5 A6 F7 G1", "X1 X2"], ["G1 X1 ; G2", "G2 X1 Y1 I1 J0"], ["G1 Z1 F-5", "G1 Z2"],
    ["G0 X-0 F0", "F-0 G0 Y1", "Z2", "G1 X1"]])  # rapids with no feed, then a G1 without one
def test_the_targets_of_edge_lines_are_the_same(texts: list[str]) -> None:
    numbered = tuple(enumerate(texts, 3))
    for scale, incremental, motion in [(1.0, False, NO_MOTION), (25.4, True, 10), (1.0, False, 0)]:
        args = (numbered, 0, [1.5, -2.0, 0.25, -0.0, 90.0, 0.0], [10.0, 0.1, -3.0, 0.0, -0.0, 45.0],
                scale, incremental, motion, 250.0, len(texts))
        assert compiled.plain_moves(*args) == plain_moves(*args)


# Runs of lines of one shape, long enough for plain_moves to read them in bulk (plain_runs.SHAPE_LEAST), and
# the lines that end such a run: another shape, another G text, an F that stops the run, a comment.
SHAPES = ["G1 X{} Y{} Z{}", "N{} G1 X{} Y{}", "n{} g0 x{} y{} z{} a{} b{} c{}", "X{} Y{}", "G01 X {} Z{} F{}",
          "G1 X{}\tY{} F{}", " G0 Z{} ", "G91 G1 X{} Y{}"]
ENDINGS = ["G1 X1.0 Y2", "G1.0 X1 Y1 Z1", "G0 X1 Y2 Z3", "G1 X1 Y2 Z3 F0", "G1 X1 Y2 F-1", "G1 X1 Y2 (c)",
           "G1 X1 Y2 ; c", "G2 X1 Y1 I1 J0", "M5", "X1 Y2 Z3 A4"]
shape_numbers = st.one_of(st.integers(-99, 999).map(str), st.floats(-500, 500).map(lambda v: f"{v:.3f}"),
                          st.sampled_from(["-0", "0", ".5", "7.", "+2", "0.000"]))


@settings(max_examples=150, deadline=None)
@given(st.lists(st.tuples(st.sampled_from(SHAPES), st.integers(1, 90), st.sampled_from(ENDINGS + [""])),
                min_size=1, max_size=4),
       st.lists(shape_numbers, min_size=7, max_size=7), st.data(), st.sampled_from([1.0, 25.4]), st.booleans(),
       st.sampled_from([NO_MOTION, 0, 10]), st.sampled_from([0.0, 500.0]), st.integers(0, 400))
def test_the_targets_of_runs_of_one_shape_are_the_same(runs: list[tuple[str, int, str]], first: list[str],
                                                       data: st.DataObject, scale: float, incremental: bool,
                                                       motion: int, feed: float, room: int) -> None:
    """Long runs of lines of one shape (read in bulk by the Python core), cut by the budget or by another line."""
    texts: list[str] = []
    for shape, count, ending in runs:
        for k in range(count):
            values = first if k % 7 else data.draw(st.lists(shape_numbers, min_size=7, max_size=7))
            texts.append(shape.format(*values))
        if ending:
            texts.append(ending)
    numbered = tuple((number, text) for number, text in enumerate(texts, 5) if not non_plain_lines([text]))
    start = data.draw(st.integers(0, min(3, len(numbered))))
    args = (numbered, start, [1.5, -2.0, 0.25, -0.0, 90.0, 0.0], [10.0, 0.1, -3.0, 0.0, -0.0, 45.0],
            scale, incremental, motion, feed, room)
    assert repr(compiled.plain_moves(*args)) == repr(_looking_plain_moves(*args))  # -0.0 too


@pytest.mark.parametrize("shape", SHAPES)
def test_every_ending_of_a_run_of_one_shape(shape: str) -> None:
    """Each line that ends a run, after 40 lines of each shape and before 20 more, both ways of counting."""
    rng = random.Random(shape)
    for ending in ENDINGS:
        texts = [shape.format(*(f"{rng.uniform(-50, 50):.{rng.randint(0, 4)}f}" for _ in range(7))) for _ in range(60)]
        texts.insert(40, ending)
        for scale, incremental, motion in [(1.0, False, 10), (25.4, True, 0), (1.0, False, NO_MOTION)]:
            args = (tuple(enumerate(texts, 2)), 0, [1.5, -2.0, 0.25, -0.0, 90.0, 0.0], [10.0, 0.1, -3.0, 0.0, -0.0, 45.0],
                    scale, incremental, motion, 250.0, 100)
            assert repr(compiled.plain_moves(*args)) == repr(_looking_plain_moves(*args)), (shape, ending)


def test_a_run_of_one_shape_is_read_in_bulk(monkeypatch: pytest.MonkeyPatch) -> None:
    """The case above does reach the bulk reader: the 200 lines after the first in one go."""
    taken: list[int] = []
    real = plain_runs._same_shape
    monkeypatch.setattr(plain_runs, "_same_shape", lambda *args: taken.append(real(*args)) or taken[-1])
    numbered = tuple((number, f"G1 X{number * 0.001:.3f} Y-{number}.5 Z-0") for number in range(3, 204))
    args = (numbered, 0, [0.0] * 6, [0.0, 0.0, 0.0, 0.0, -0.0, 0.0], 1.0, False, 10, 100.0, 500)
    assert repr(compiled.plain_moves(*args)) == repr(_looking_plain_moves(*args))
    assert taken == [200]


def _looking_plain_moves(*args: object) -> object:
    """``plain_moves`` looking for runs of one shape at every chance (as after a look that found one)."""
    plain_runs._looks.found(True)
    return plain_moves(*args)  # type: ignore[arg-type]


def test_trace_rows_are_the_same_bytes() -> None:
    values = [0.0, -0.0, 1e-4, 9.99e-5, 0.1 + 0.2, 1 / 3, 40.309, -1000.001, 999999999.999999, 1e9, 2.5e-7,
              123456.789012, 1e22, 5e-324, math.inf, -math.inf, math.nan, 25.4 * 12.345, 7.0, 1]
    ends = [tuple(values[(i + k) % len(values)] for k in range(6)) for i in range(len(values))]
    times = [0.0, *values]
    count = len(ends)
    args = (list(range(count)), ["linear", "rapid"] * (count // 2), ends, '"a,b"', times)
    assert compiled.trace_rows(*args) == trace_rows(*args)


@pytest.mark.parametrize("column", [[0.0] * 5, [-0.0] * 5, [0.0, 0.0, -0.0, 0.0, 0.0], [-0.0, 0.0, 0.0, 0.0, 0.0],
                                    [5.0] * 5, [5.0, 5.0, 5.0, 5.0, 5.000000000000001], [math.nan] * 5,
                                    [math.inf] * 5, [1e22] * 5, [0.1 + 0.2] * 4 + [0.3]])
def test_trace_rows_of_constant_columns(column: list[float]) -> None:
    """A column that is the same in every row is written once (the Python core): to the bit, -0.0 is not 0.0."""
    for axis in range(6):
        ends = [tuple(column[row] if k == axis else float(row * k) for k in range(6)) for row in range(5)]
        for same in (ends, [tuple(column[row] for _ in range(6)) for row in range(5)]):
            args = (list(range(5)), ["rapid"] * 5, same, "job.nc", [0.0, 1.0, 2.0, 3.0, 4.0, 5.0])
            assert compiled.trace_rows(*args) == trace_rows(*args)
    assert compiled.trace_rows([], [], [], "job.nc", [0.0]) == trace_rows([], [], [], "job.nc", [0.0]) == ""


@settings(max_examples=200, deadline=None)
@given(st.integers(0, 4), st.integers(0, 4), st.integers(0, 4), st.integers(0, 5),
       st.sampled_from(["job.nc", "j\udcffb.nc", "\ud800", '"a,b"']), st.sampled_from(["linear", "r\udc80pid"]))
def test_trace_rows_of_short_and_surrogate_inputs_are_the_same(lines: int, kinds: int, ends: int, times: int,
                                                                name: str, kind: str) -> None:
    """Columns of unequal length (zip stops at the shortest) and a file name or kind with a lone surrogate
    (a path read with surrogateescape): the same text, never an error only one core raises."""
    args = (list(range(lines)), [kind] * kinds, [(float(i), 0.5, -0.0, 0.0, 0.0, 1e22) for i in range(ends)],
            name, [0.0, *map(float, range(times))][:times])
    assert compiled.trace_rows(*args) == trace_rows(*args)


@settings(max_examples=200, deadline=None)
@given(st.lists(st.tuples(*[st.floats(allow_nan=False, width=64)] * 7), min_size=1, max_size=20))
def test_any_double_is_written_as_repr_writes_it(rows: list[tuple[float, ...]]) -> None:
    ends, times = [row[:6] for row in rows], [0.0, *(row[6] for row in rows)]
    args = (list(range(len(rows))), ["linear"] * len(rows), ends, "job.nc", times)
    assert compiled.trace_rows(*args) == trace_rows(*args)


def _doubles_near_decimals(count: int) -> list[float]:
    """Doubles of the kinds a trace holds, and their hard neighbours: short decimals, the next double
    either side of one, long sums, dyadic fractions, powers of two, the edges of the fixed notation."""
    rng = random.Random(22)
    values = [1e-4, math.nextafter(1e-4, 0), 2.0 ** 49, math.nextafter(2.0 ** 49, 0), 1e16, 0.1, 0.3]
    for _ in range(count):
        short = round(rng.uniform(-1e4, 1e4), rng.randint(0, 9))
        values += [short, math.nextafter(short, math.inf), math.nextafter(short, -math.inf),
                   sum(rng.random() for _ in range(3)) * 10 ** rng.randint(-5, 15),
                   rng.randint(-2 ** 53, 2 ** 53) / 2 ** rng.randint(0, 70), 2.0 ** rng.randint(-16, 52)]
    return values


@settings(max_examples=200, deadline=None)
@given(st.lists(st.tuples(*[st.one_of(st.floats(), st.sampled_from([0.0, -0.0, 1.5]))] * 6), min_size=1, max_size=12))
def test_the_bounds_of_a_batch_are_the_same(ends: list[tuple[float, ...]]) -> None:
    """The limit check's bounds: NaN, infinities and signed zeros found as min() and max() find them."""
    assert repr(compiled.column_bounds(ends)) == repr(column_bounds(ends))


def test_doubles_in_fixed_notation_are_written_as_repr_writes_them() -> None:
    """The compiled core finds the shortest text itself for 1e-4 <= |v| < 2**49 (the fallback is
    Python's routine): checked against repr() on 60,000 doubles, the hard cases included."""
    values = _doubles_near_decimals(10_000)
    ends = [(v, -v, 0.0, -0.0, v, v) for v in values]
    lines = [1, 0, 2 ** 40, -7, True, 2 ** 70] * (len(values) // 6) + [3] * (len(values) % 6)
    args = (lines, ["linear"] * len(values), ends, "job.nc", [0.0, *values])
    assert compiled.trace_rows(*args) == trace_rows(*args)


def _run(job: Path, trace: Path, pure: bool) -> str:
    env = {**os.environ, "ECNC_PURE_PYTHON": "1" if pure else "0"}
    code = ("import sys; from edingcnc_lang import speedups; from edingcnc_lang.cli import entry; "
            "print(speedups.CORE, file=sys.stderr); sys.argv = ['ecnc', 'run', sys.argv[1], '--trace', sys.argv[2]]; "
            "entry()")
    done = subprocess.run([sys.executable, "-c", code, str(job), str(trace)], env=env, capture_output=True, text=True)
    assert done.returncode == 0, done.stderr
    return done.stderr.split()[0]


def test_both_cores_write_the_same_trace(tmp_path: Path) -> None:
    job = tmp_path / "job.nc"
    # straight moves, then a CAM pass's arcs (N words, CRLF, I/J and R arcs among G1 moves, G18 arcs), holes drilled
    # by G81 and G83 (lines of holes in batches, pecks), then inch G91
    arcs = "".join(f"N{i} G{2 + i % 2} X{2 + 5 * i + 2} Y0 I1 J0\r\nN{i} G1 X{2 + 5 * i + 3}\r\n"
                   f"G2 X{2 + 5 * i + 5} R1 F800\r\n" for i in range(300))
    job.write_text("G21 G90 F1000\nM3 S800\n" + "".join(f"G1 X{i * 0.37:.3f} Y{-i * 1.1:.2f} Z{i % 7 * -0.5}\n"
                                                          for i in range(3000))
                   + "G0 X0 Y0 Z0\nG1 X2 F600\n" + arcs + "G18 G2 X1506 Z0 I2 K0\nG17 G1\n"
                   + "G0 Z5\nG98 G81 X10 Y10 Z-2.25 R1 F300\n" + "".join(f"X{10 + i * 1.5} Y{i % 9}\n" for i in range(40))
                   + "G83 X5 Y5 Z-6.5 Q1.2 R1\nG80\nG0 Z5\n"
                   + "G20 G91\n" + "".join(f"X0.01 Y{i % 3}.5\n" for i in range(500)) + "G0 Z1\nM30\n")
    pure, fast = tmp_path / "pure.csv", tmp_path / "fast.csv"
    assert (_run(job, pure, pure=True), _run(job, fast, pure=False)) == ("python", "compiled")
    assert pure.read_bytes() == fast.read_bytes()
    assert fast.read_text().count(",arc,") == 601
    assert fast.read_text().count(",-2.25,") == 2 * 41  # every G81 hole's bottom, in both columns (z, jz)
    in_process = tmp_path / "api.csv"
    run_file(job, RunOptions(trace=in_process))
    assert in_process.read_bytes() == pure.read_bytes()


def test_looks_for_runs_of_one_shape_let_more_chances_pass_after_misses() -> None:
    """The guess of how often to look: 1, 3, 7 ... chances let pass after misses, every chance after a find."""
    looks = plain_runs._Looks()
    passed = []
    for _ in range(4):
        looks.found(False)
        passed.append(looks.skip)
    assert passed == [1, 3, 7, 15]
    for _ in range(10):
        looks.found(False)
    assert looks.skip == plain_runs.MAX_SKIP
    looks.found(True)
    assert looks.skip == 0
