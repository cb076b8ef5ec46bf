"""Runs of hole lines read in bulk drill exactly what the general path drills, on both cores.

``run_file`` reads a job in run mode: a run of lines that only name the next hole under a canned
cycle goes through ``canned.CannedCycles._steady_holes`` (``hole_runs.hole_moves``, or its compiled
twin); ``run_string`` parses the same text into ordinary blocks, which always take the general path,
one hole at a time.  Random drilling jobs (every cycle, G98/G99, G90/G91, inch, the three planes, work
offsets, L repeats, sticky words changed, G68, G51 and offsets changed between holes, the step budget
running out, a limit refusing a hole) must give the same moves, events, state and errors each way,
and the compiled reader the same moves as the Python reference, to the bit.
"""
from __future__ import annotations

from pathlib import Path

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from edingcnc_lang import EcncError, Event, Move, RunOptions, run_file, run_string
from edingcnc_lang.machine import canned
from edingcnc_lang.machine.hole_runs import hole_moves
from edingcnc_lang.syntax.plain_words import is_fast_line

coordinates = st.one_of(st.integers(-300, 300).map(str), st.floats(-300, 300, allow_nan=False).map(lambda v: f"{v:.3f}"),
                        st.sampled_from([".5", "-.25", "+3", "7.", "0", "-0", "12.3456789", "0.1", "0.2"]))
# a hole line: the plane's two axes (one or both, either order, any case and spacing), an N word first at times;
# now and then a line that is not quite one (a comment, a word of another letter, an axis twice, N after a word)
hole_lines = st.builds(
    lambda n, words, gap, tail: (f"N{n}{gap}" if n else "") + gap.join(f"{a}{v}" for a, v in words) + tail,
    st.sampled_from([0, 0, 0, 7, 12345]),
    st.lists(st.tuples(st.sampled_from("XXYYZxyz"), coordinates), min_size=1, max_size=2,
             unique_by=lambda w: w[0].upper()),
    st.sampled_from([" ", "", "\t", "  "]),
    st.sampled_from([""] * 12 + [" (hole)", " ; drill", " N5", " X1", " F200", " L2", " R1", " Z-1", " M8"]))
CYCLES = {"G81": "G81", "G82": "G82 P0.2", "G83": "G83 Q1.5", "G73": "G73 Q0.7", "G85": "G85", "G86": "G86 P0.1",
          "G89": "G89 P0.1", "G84": "G84", "G74": "G74", "G88": "G88 P0.1", "G87": "G87 I1 J0.5 K-1"}
between = st.sampled_from(["M8", "#1 = [#1 + 1]", "G68 X0 Y0 R30", "G69", "G51 P2", "G50", "G10 L2 P1 X5 Y-3 Z1",
                           "G10 L2 P1 X0.1 Y0.2 Z0.3", "G55", "G54", "Z-3 R1", "R4", "R-0.3", "X5 Y5 L3", "G99", "G98",
                           "G91", "G90", "G80", "G81 X1 Y1", "G0 Z20", "G1 Z-1 F100", "G43 H1", "G49", "F250",
                           "G20", "G21", "S500", "M5", "M3 S900", "GetJobDistance 100"])
jobs = st.builds(
    lambda header, cycle, plane, modes, start, r, holes: "\n".join(
        [header, plane, modes, "S1200 M3", start, f"{modes} {CYCLES[cycle]} X1 Y1 Z-2 {r} F300", *holes,
         "G80", "#100 = #5001", "#101 = #5002", "#102 = #5003", "GetJobDistance 101", "M30"]) + "\n",
    st.sampled_from(["G21", "G20", "G21 G10 L2 P1 X10.1 Y-20.3 Z3.7", "G21 G10 L2 P1 X0.1 Y0.7 Z0.3 A0.1",
                     "G21 G92 X3 Y4 Z1"]),
    st.sampled_from(sorted(CYCLES)),
    st.sampled_from(["G17", "G17", "G18", "G19"]),
    st.sampled_from(["G90 G98", "G90 G99", "G91 G98", "G91 G99"]),
    st.sampled_from(["G0 X0 Y0 Z10", "G0 X0 Y0 Z-1", "G0 X0 Y0 Z0.3"]),
    st.sampled_from(["R2", "R-0.5", "R0"]),  # (under G91 G99: each hole half a millimetre deeper)
    st.lists(st.one_of(hole_lines, hole_lines, hole_lines, hole_lines, between), min_size=1, max_size=40))


def _outcome(run) -> tuple:  # type: ignore[no-untyped-def]
    records: list[Move | Event] = []
    try:
        result = run(lambda move, _joints: records.append(move), records.append)
    except EcncError as err:
        return ("error", err.format(), records)
    return ("ok", result.machine, result.modal, result.variables, result.spindle, records)


def _both_ways(job: Path, text: str, **options: object) -> tuple[tuple, tuple]:  # type: ignore[type-arg]
    bulk = _outcome(lambda on_move, on_event: run_file(job, RunOptions(on_move=on_move, on_event=on_event, **options)))
    general = _outcome(lambda on_move, on_event: run_string(text, RunOptions(on_move=on_move, on_event=on_event,
                                                                             **options), path=str(job)))
    return bulk, general


@pytest.mark.slow
@settings(max_examples=150, deadline=None, suppress_health_check=[HealthCheck.function_scoped_fixture])
@given(jobs, st.sampled_from([None, None, 40, 120, 333]), st.booleans())
def test_holes_in_bulk_are_the_general_paths_holes(tmp_path: Path, monkeypatch: pytest.MonkeyPatch, text: str,
                                                   max_steps: int | None, python_reader: bool) -> None:
    if python_reader:  # the Python reference on the compiled core too (the run is the same on either core)
        monkeypatch.setattr(canned, "_HOLE_MOVES", hole_moves)
    job = tmp_path / "holes.nc"
    job.write_text(text)
    (tmp_path / "cnc.ini").write_text("[JOINT_0]\nnegativeLimit = -150\npositiveLimit = 150\n")
    bulk, general = _both_ways(job, text, max_steps=max_steps, ini=tmp_path / "cnc.ini")
    assert repr(bulk) == repr(general)  # (repr: to the bit, -0.0 not 0.0)


def test_a_long_run_of_holes_is_read_in_bulk(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    """Past its first line a run of G81 holes takes the bulk reader, which drills all the others, and the
    moves, the trace's times and GetJobDistance are the general path's."""
    calls: list[int] = []

    def counted(*args: object) -> object:
        index, numbers, ends = hole_moves(*args)  # type: ignore[arg-type]
        calls.append(index - args[1])  # type: ignore[operator]
        return index, numbers, ends

    monkeypatch.setattr(canned, "_HOLE_MOVES", counted)
    holes = "\n".join(f"X{(k * 37) % 200}.{k % 10} Y{(k * 53) % 150}" for k in range(500))
    text = f"G21 G90 G10 L2 P1 X0.1 Y0.2 Z0.3\nS900 M3\nG0 X0 Y0 Z5\nG99 G81 X1 Y1 Z-2 R1 F300\n{holes}\nG80\nM30\n"
    job = tmp_path / "holes.nc"
    job.write_text(text)
    bulk, general = _both_ways(job, text)
    assert repr(bulk) == repr(general) and sum(calls) == 499  # (the first line: the general path)
    traces = []
    for run, name in ((lambda o: run_file(job, o), "bulk.csv"), (lambda o: run_string(text, o, path=str(job)), "general.csv")):
        run(RunOptions(trace=tmp_path / name))
        traces.append((tmp_path / name).read_text())
    assert traces[0] == traces[1] and traces[0].count(",linear,") == 501


@pytest.mark.parametrize("plane", ["G17", "G18", "G19"])
@pytest.mark.parametrize("modes", ["G90 G98", "G90 G99", "G91 G98", "G91 G99"])
@pytest.mark.parametrize("cycle", ["G73 Q0.6", "G81", "G83 Q0.7", "G85"])
def test_every_straight_cycle_in_every_mode_and_plane(tmp_path: Path, plane: str, modes: str, cycle: str) -> None:
    """Holes of each cycle read in bulk, with work offsets that do not read back exactly, R below the start
    (under G91 G99 each hole half a millimetre deeper: left to the general path) and L repeats."""
    a, b = {"G17": "XY", "G18": "ZX", "G19": "YZ"}[plane]
    holes = "\n".join(f"{a}{k * 1.1:.1f} {b}{k % 7 * 0.3:.1f}" if k % 5 else f"{b}0.1" for k in range(1, 40))
    text = (f"G21 G10 L2 P1 X0.1 Y0.2 Z0.3 A0.1\n{plane}\nS900 M3\nG0 X0 Y0 Z10\n{modes} {cycle} {a}1 {b}1 "
            f"{'XYZ'[({'G17': 2, 'G18': 1, 'G19': 0})[plane]]}-2 R-0.5 F300\n{holes}\n{a}1 L3\n{holes}\nG80\nG90\nM30\n")
    job = tmp_path / "holes.nc"
    job.write_text(text)
    bulk, general = _both_ways(job, text)
    assert repr(bulk) == repr(general) and bulk[0] == "ok"


@pytest.mark.parametrize("cycle", ["G82 P0.5", "G91 G99 G81"])
def test_holes_the_bulk_reader_does_not_model_take_the_general_path(tmp_path: Path, monkeypatch: pytest.MonkeyPatch,
                                                                    cycle: str) -> None:
    """A dwell at each hole (an event between the holes' moves), or G91 G99 (each hole R deeper than the one
    before): every hole on the general path, with the same result."""
    monkeypatch.setattr(canned, "_HOLE_MOVES", lambda *args: pytest.fail("read in bulk"))
    text = f"G21 G90\nS900 M3\nG0 X0 Y0 Z50\n{cycle} X1 Y1 Z-2 R-0.5 F300\n" + "X1 Y2\n" * 20 + "G80\nG90\nM30\n"
    job = tmp_path / "holes.nc"
    job.write_text(text)
    bulk, general = _both_ways(job, text)
    assert repr(bulk) == repr(general) and bulk[0] == "ok"


compiled = getattr(pytest.importorskip("edingcnc_lang.speedups"), "SPEEDUPS", None)


@pytest.mark.slow
@pytest.mark.skipif(compiled is None, reason="the compiled core is not built here (or ECNC_PURE_PYTHON is set)")
@settings(max_examples=400, deadline=None)
@given(st.lists(hole_lines, min_size=1, max_size=30).map(lambda texts: [t for t in texts if is_fast_line(t)]),
       st.integers(0, 3), st.integers(0, 40), st.sampled_from([(0, 1, 2), (2, 0, 1), (1, 2, 0)]),
       st.tuples(*[st.floats(-500, 500, allow_nan=False)] * 6), st.sampled_from([(0.0,) * 6, (0.1, 0.2, 0.3, 0.0, 0.0, 0.0),
                                                                                 (10.1, -20.3, 3.7, 0.1, 0.0, -0.3)]),
       st.sampled_from([1.0, 25.4]), st.booleans(), st.lists(st.floats(-50, 50, allow_nan=False), max_size=7))
def test_the_compiled_reader_gives_the_references_moves(texts: list[str], first: int, stop: int,
                                                         axes: tuple[int, int, int], pos: tuple[float, ...],
                                                         offset: tuple[float, ...], scale: float, incremental: bool,
                                                         levels: list[float]) -> None:
    lines = [(10 + k, text) for k, text in enumerate(texts)]
    stop = min(stop, len(lines))
    args = (lines, first, stop, axes, pos, offset, scale, incremental, levels)
    assert repr(compiled.hole_moves(*args)) == repr(hole_moves(*args))
