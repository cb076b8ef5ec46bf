"""The bulk path for plain G0/G1 lines and arcs behaves exactly like the general path.

``run_file`` reads a job in run mode (plain lines in bulk); ``run_string`` parses the same
text into ordinary blocks, which always take the general path.  Generated jobs mix plain
moves with lines that change the state between them (units, distance mode, offsets, feed
mode, motion modes, the spindle, G68, G51, cutter compensation, height compensation), so both
paths have to agree on every hand-over: whole move records, events, parameters (GetJobDistance)
and errors are compared.
"""
from __future__ import annotations

import math
from pathlib import Path

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from edingcnc_lang import EcncError, Event, Move, RunOptions, run_file, run_string
from edingcnc_lang.config.heightmap import HeightMap, ProbeAt
from edingcnc_lang.host import Host
from tests.core_outcome import traced_run

numbers = st.one_of(st.integers(-200, 200).map(str),
                    st.floats(-200, 200, allow_nan=False).map(lambda v: f"{v:.3f}"),
                    st.sampled_from([".5", "-.25", "+3", "7.", "0"]))
axis_words = st.lists(st.tuples(st.sampled_from("XYZABCxyz"), numbers), min_size=0, max_size=4,
                      unique_by=lambda w: w[0].upper())
plain_lines = st.builds(
    lambda g, words, f, n, space, comment: space.join(
        ([f"N{n}"] if n else []) + ([g] if g else []) + [f"{a}{v}" for a, v in words] + ([f"F{f}"] if f else []))
    + comment,
    st.sampled_from(["", "G0", "G1", "G01", "g1", "G2", "G81"]), axis_words,
    st.sampled_from(["", "", "100", "0", "-5", "1200.5"]), st.sampled_from([0, 0, 10]),
    st.sampled_from([" ", ""]), st.sampled_from(["", " ; cut"]))
# arcs: R forms that reach most ends, centre words that rarely fit (errors must agree too), words of
# another plane, R with centre words; the incremental ones always fit under G91
fitting_arcs = st.sampled_from(["G2 X10 Y0 I5 J0", "G3 X-10 Y0 I-5 J0 F300", "X10 Y10 I10", "G2 X0 Y0 Z-1 I5 J0",
                                "G3 X4 Z4 I2 K2", "G2 Y6 Z0 J3 K0 F80", "G2 X20 R10", "G3 X1 Y1 Z1 A5 R-1 (arc)",
                                "G2 X5 Y-5 R300", "G3 Y7 R-300 F40"])
arc_lines = st.one_of(fitting_arcs, fitting_arcs, st.builds(
    lambda g, words, centre, f, n: " ".join(([f"N{n}"] if n else []) + ([g] if g else []) + [f"{a}{v}" for a, v in words]
                                             + centre + ([f"F{f}"] if f else [])),
    st.sampled_from(["G2", "G3", "G02", "g3", ""]), axis_words,
    st.sampled_from([["R300"], ["r-300"], ["R5"], ["R0"], ["I5", "J0"], ["I-5"], ["J5"], ["K5", "I0"], ["J3", "K4"],
                     ["I5", "R300"], []]),
    st.sampled_from(["", "", "100", "0"]), st.sampled_from([0, 10])))
state_lines = st.sampled_from(["G17", "G18", "G19", "G91", "G90", "G20", "G21", "G10 L2 P1 X5 Y-3 Z1", "G92 X0 Y0", "G92.1",
                               "G93", "G94", "G55", "G54", "#1 = [#1 + 1]", "G68 X0 Y0 R30", "G69",
                               "G43 H1", "G49", "(comment)", "M3 S1000", "G80", "G17 G2 X1 Y1 I1 J0 F100",
                               "M4 S2500", "M5", "G51 P2", "G51 X2 Y-1", "G50", "G68 X5 Y5 R-45",
                               "G41.1 D0.5", "G42.1 D1", "G40", "ZHC on", "ZHC off", "GetJobDistance 100",
                               "G1 X1 Y1 F50 M3 S300", "G0 X0 Y0 Z0"])
jobs = st.lists(st.one_of(plain_lines, plain_lines, plain_lines, arc_lines, arc_lines, state_lines), min_size=1,
                max_size=30)
# a 2 x 2 height map probed on a tilted surface, so "ZHC on" has a table to follow
ZHC_HEADER = "ZHCINIT 100 2 2\n" + "".join(
    f"G0 Z5\nG0 X{x} Y{y}\nG38.2 Z-20 F500\nZHCADDPOINT\n" for y in (0, 100) for x in (0, 100)) + "G0 Z5\nG0 X0 Y0\n"
SURFACE = ProbeAt(HeightMap((0.0, 100.0), (0.0, 100.0), ((0.0, 0.4), (0.2, 0.6))))


def _outcome(run) -> tuple:  # type: ignore[no-untyped-def]
    records: list[Move | Event] = []
    options = RunOptions(on_move=lambda move, _joints: records.append(move), on_event=records.append,
                         host=Host(probe=SURFACE))
    try:
        result = run(options)
    except EcncError as err:
        return ("error", err.format(), records)
    return ("ok", result.machine, result.modal, result.variables, result.spindle, records)


@pytest.mark.slow
@settings(max_examples=150, deadline=None, suppress_health_check=[HealthCheck.function_scoped_fixture])
@given(jobs, st.booleans())
def test_bulk_and_general_paths_agree(tmp_path: Path, lines: list[str], zhc: bool) -> None:
    text = (ZHC_HEADER if zhc else "") + "\n".join([*lines, "GetJobDistance 101"]) + "\n"
    job = tmp_path / "job.nc"
    job.write_text(text)
    # the callback sink takes moves one by one, and the trace writer in bulk: check both ways
    bulk = _outcome(lambda options: run_file(job, options))
    general = _outcome(lambda options: run_string(text, options, path=str(job)))
    assert bulk == general


def _contour(side: str, plane: str) -> str:
    """A compensated arc of a circle in 120 segments, counter-clockwise (straight on, then corners of
    0.09 rad: inside on the left, outside on the right), with a plunge and a rapid in it."""
    a, b = {"G17": "XY", "G18": "ZX", "G19": "YZ"}[plane]
    angles = [k * 0.01 for k in range(60)] + [0.6 + k * 0.09 for k in range(60)]
    lines = [f"{plane} G0 {a}45 {b}-20", f"{side} D2", f"G1 {a}30 {b}0 F800"]
    for k, angle in enumerate(angles):
        lines.append(f"{a}{30 * math.cos(angle):.4f} {b}{30 * math.sin(angle):.4f}")
        if k == 70:
            lines.append("G1 Z-1" if plane == "G17" else "G1 Y-1" if plane == "G18" else "G1 X-1")
        if k == 90:
            lines.append("G0")
    lines += ["G40", f"G1 {a}0 {b}0", "M30"]
    return "\n".join(lines) + "\n"


ARCS = ("G1 X0 Y0 F100\nG2 X10 Y0 I5 J0\nG1 X20\nG3 X30 Y0 R5\nX40 Y0 R-5\nG2 X40 Y0 I-5 J0 Z-2\n"
        "G18 G2 X50 Z-2 I5 K0\nG19 G3 Y10 Z-2 J5 K0 F50\nG17 G91 G2 X10 I5\nG1 Y2\nG90 G0 X0 Y0\n")


REFUSED_IN_A_BATCH = "G1 X1 F100\nG2 X11 I5\nG18\nG1 X2\nZ1\nG2 X12 Z1 I5 K0\nG1 X0\n"  # the XZ arc: refused


@pytest.mark.slow
@pytest.mark.parametrize("source", [ARCS, "M3 S900\nG68 X1 Y1 R30\n" + ARCS, "G51 P2\n" + ARCS,
                                    "G68 X1 Y1 R30\n" + REFUSED_IN_A_BATCH, "G51 P2\n" + REFUSED_IN_A_BATCH,
                                    "G1 X1 F100\nG0 Y2\nX3\n", "G91 G1 X1 F50\nX1\nY-2\n", "G20 G1 X1 F10\n",
                                    "M3 S900\nG68 X1 Y1 R30\nG1 X1 F100\nY2\nG51 P2\nX3 Y3\n",
                                    _contour("G41.1", "G17"), _contour("G42.1", "G17"), _contour("G41.1", "G18"),
                                    "G20\n" + _contour("G42.1", "G19")])
def test_bulk_trace_matches_the_general_trace(tmp_path: Path, source: str) -> None:
    """The same rows and the same error either way (G68 and G51 P2 refuse the XZ arc: Z is not scaled)."""
    job = tmp_path / "job.nc"
    job.write_text(source)
    bulk, general = tmp_path / "bulk.csv", tmp_path / "general.csv"

    def traced(run, trace: Path) -> tuple[str, str | None]:  # type: ignore[no-untyped-def]
        try:
            run(RunOptions(trace=trace))
        except EcncError as err:
            return trace.read_text(), err.format()
        return trace.read_text(), None

    made = traced(lambda options: run_file(job, options), bulk)
    assert made == traced(lambda options: run_string(source, options, path=str(job)), general)
    if source.endswith(ARCS):
        assert made[0].count(",arc,") == (7 if source == ARCS else 4)
    if source.endswith(REFUSED_IN_A_BATCH):  # the moves of the batch before the refused arc are written
        assert made[0].count("\n") == 5 and made[1] is not None and ":7:1: error: an arc" in made[1]
        assert "XZ plane" in made[1]


@pytest.mark.slow
def test_a_long_job_is_timed_the_same_in_batches_and_one_by_one(tmp_path: Path) -> None:
    """The planner commits fixed windows of moves, however the moves arrive: the ``t`` column of a
    job longer than several windows is the same to the last bit from the bulk path (batches cut
    where the reader's blocks and chunks end) and from the general path (one move at a time)."""
    rng = __import__("random").Random(4)
    source = "G21 G90 F1500\n" + "".join(
        f"G1 X{rng.uniform(0, 300):.3f} Y{rng.uniform(0, 200):.3f} Z{rng.uniform(-5, 0):.3f}\n"
        for _ in range(10_000)) + "M30\n"
    job = tmp_path / "job.nc"
    job.write_text(source)
    bulk, general = tmp_path / "bulk.csv", tmp_path / "general.csv"
    with pytest.MonkeyPatch.context() as patch:  # chunks that do not divide the runs or the windows
        patch.setattr("edingcnc_lang.syntax.parser.CHUNK_LINES", 1234)
        run_file(job, RunOptions(trace=bulk))
    run_string(source, RunOptions(trace=general), path=str(job))
    assert bulk.read_text() == general.read_text()


def test_an_arc_in_a_batch_is_refused_where_it_bulges_past_a_limit(tmp_path: Path) -> None:
    """Both ends of the arc are inside Y 0..5, its top (Y 10) is not: the moves before it are written,
    and the error names its line, as one move at a time."""
    (tmp_path / "cnc.ini").write_text("[JOINT_1]\nnegativeLimit = -1\npositiveLimit = 5\n")
    source = "G0 X0 Y0\nG1 X1 F200\nG2 X21 Y0 I10 J0\nG1 X0\n"
    job = tmp_path / "job.nc"
    job.write_text(source)
    results = []
    for run, trace in ((lambda o: run_file(job, o), tmp_path / "bulk.csv"),
                       (lambda o: run_string(source, o, path=str(job)), tmp_path / "general.csv")):
        with pytest.raises(EcncError) as caught:
            run(RunOptions(ini=tmp_path / "cnc.ini", trace=trace))
        results.append((trace.read_text(), caught.value.format()))
    assert results[0] == results[1]
    assert ":3:" in results[0][1] and "joint Y would reach 10.0000" in results[0][1]
    assert results[0][0].count("\n") == 3  # the header and the two moves before the arc
    for plan in (False, True):  # checked from the arcs' table when planned, one by one when not
        with pytest.raises(EcncError) as caught:
            run_file(job, RunOptions(ini=tmp_path / "cnc.ini", plan=plan))
        assert caught.value.format() == results[0][1]
    # the other way round the same circle stays below the limit: many such arcs in a batch all run
    # arcs whose circles cross Y 5 but that sweep their lower halves (down to Y -0.5): all run
    job.write_text("G0 X0 Y2.5\nG1 X1 F200\n" + "G3 X7 Y2.5 I3 J0\nG2 X1 Y2.5 I-3 J0\n" * 50)
    limits = run_file(job, RunOptions(ini=tmp_path / "cnc.ini")).limits["joints"]["y"]
    assert (limits["min"], limits["max"]) == (pytest.approx(-0.5), pytest.approx(2.5))


CYCLE_JOB = """G21 G90 G94 G17
S1200 M3
G0 X0 Y0 Z10
G98 G81 X10 Y10 Z-2 R2 F300
X20 Y15 L2
G99 G82 X30 P0.5
G83 X40 Y20 Z-5 Q1.5 R1
G86 X50
G73 X60 Q2
G80
#100 = #5001
G0 X0 Y0
M30
"""


def _batched_and_one_by_one(job: Path, ini: Path, monkeypatch: pytest.MonkeyPatch) -> tuple[str, str, list[object]]:
    """The trace, the result (or the error and the state it left) and the moves and events of ``job``, run with
    batches and then with ``batchable()`` off (one move at a time): they must be the same; the first is returned."""
    from edingcnc_lang.machine.interpreter import Interpreter

    batched = traced_run(job, ini)
    monkeypatch.setattr(Interpreter, "batchable", lambda self: False)
    assert traced_run(job, ini) == batched
    return batched


@pytest.mark.parametrize("z_limit", [-10, -4])
def test_a_canned_cycles_moves_in_one_batch_are_its_moves_one_by_one(tmp_path: Path, monkeypatch: pytest.MonkeyPatch,
                                                                      z_limit: int) -> None:
    """A cycle line's straight moves go to the canon as one batch, handed on before its dwells, spindle stops
    and the next statement: the same moves, events, times, GetJobDistance and state as one move at a time,
    also when a peck deep in the G83 hole is refused below a limit (the state is that after the peck before it)."""
    (tmp_path / "cnc.ini").write_text(f"[JOINT_2]\nnegativeLimit = {z_limit}\n")
    job = tmp_path / "drill.nc"
    job.write_text(CYCLE_JOB)

    batched = _batched_and_one_by_one(job, tmp_path / "cnc.ini", monkeypatch)
    moves = [m for m in batched[2] if isinstance(m, Move)]
    if z_limit == -4:
        assert "drill.nc:7:1: error: joint Z would reach -5.0000" in batched[1] and -4 < moves[-1].end[2] < -2
    else:
        assert "error" not in batched[1] and len(moves) > 40


@pytest.mark.parametrize("x_limit", [300, 150])
def test_lines_of_holes_in_one_batch_are_their_cycles_one_by_one(tmp_path: Path, monkeypatch: pytest.MonkeyPatch,
                                                                 x_limit: int) -> None:
    """A run of lines that only name the next hole (X Y under G81) goes to the canon as one batch, handed on before
    the first other line: the same moves, times, state and GetJobDistance as one cycle at a time, also when a hole
    in the middle of the run is beyond a limit (the error names its line, the state is that before its move)."""
    (tmp_path / "cnc.ini").write_text(f"[JOINT_0]\nnegativeLimit = -1\npositiveLimit = {x_limit}\n")
    holes = "\n".join(f"X{10 + 7 * k} Y{(k * 13) % 50}" for k in range(30))
    job = tmp_path / "holes.nc"
    job.write_text(f"G21 G90 G17\nS800 M3\nG0 X0 Y0 Z10\nG98 G81 X5 Y5 Z-3 R2 F250\n{holes}\nM8\nX3 Y3\n"
                   "G80\n#100 = #5001\nG0 X0 Y0\nM30\n")

    batched = _batched_and_one_by_one(job, tmp_path / "cnc.ini", monkeypatch)
    if x_limit == 150:
        assert "holes.nc:26:1: error: joint X would reach 157.0000" in batched[1]
    else:
        assert "error" not in batched[1] and sum(isinstance(m, Move) for m in batched[2]) > 120
