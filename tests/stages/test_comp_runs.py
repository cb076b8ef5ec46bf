"""Runs of corners under cutter compensation (pipeline/comp_runs.py) give the moves of one move at a time.

``comp_lines`` (Python, and C on the compiled core) compensates a run of straight moves in one loop;
the stage's own code takes every other move.  The compiled loop is held to the Python one on the
same inputs, bit for bit, and whole jobs (arcs in the contour, G41/G42 with D words from a tool
table, G41.1/G42.1, direction changes, folds and reversals the stage refuses, G40 exits, plunges
and rapids) give the same trace, result, moves and events in batches as one move at a time, with
either loop; and the same trace bytes on both cores.
"""
from __future__ import annotations

import math
import os
import subprocess
import sys
from collections.abc import Iterable, Sequence
from pathlib import Path
from random import Random

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st
from stage_helpers import COMPILED, LOOPS, NOT_BUILT

from edingcnc_lang.canon import PLANES, Arc, Pose
from edingcnc_lang.machine.interpreter import Interpreter
from edingcnc_lang.pipeline import comp_runs
from edingcnc_lang.pipeline.comp_geometry import LEFT, RIGHT
from tests.core_outcome import traced_run

TOOLS = Path(__file__).resolve().parents[1] / "golden" / "linuxcnc" / "tools.ini"


def _walk(rng: Random, count: int, axes: tuple[int, int, int]) -> list[Pose]:
    """Ends of a random contour in the plane of ``axes``: straight on, gentle and sharp turns both ways, folds
    back, steps without motion in the plane (a plunge), coordinates that need every bit."""
    first, second, normal = axes
    heading, x, y, depth, ends = rng.uniform(-3, 3), rng.uniform(-50, 50), rng.uniform(-50, 50), 0.0, []
    for _ in range(count):
        roll = rng.random()
        heading += (rng.uniform(-0.04, 0.04) if roll < 0.4 else rng.uniform(-1.3, 1.3) if roll < 0.85
                    else rng.choice([math.pi, -math.pi, 2.9, 0.0, 1e-12]))
        length = rng.choice([rng.uniform(0.3, 9.0), rng.uniform(0.3, 9.0), 0.0, 1e-10])
        x, y = x + length * math.cos(heading), y + length * math.sin(heading)
        depth = depth if rng.random() < 0.9 else rng.uniform(-3, 0)
        end = [0.0, 0.0, 0.0, rng.choice([0.0, 15.0]), 0.0, 0.0]
        end[first], end[second], end[normal] = x, y, depth
        ends.append(tuple(end))
    return ends


@pytest.mark.skipif(COMPILED is None, reason=NOT_BUILT)
@settings(max_examples=400, deadline=None)
@given(seed=st.integers(0, 2**32), count=st.integers(1, 40), plane=st.sampled_from(sorted(PLANES)),
       side=st.sampled_from([LEFT, RIGHT]), radius=st.sampled_from([0.2, 1.0, 3.0, 1e-10, 5e-10]),
       start=st.integers(0, 5), jitter=st.sampled_from([0.0, 0.0, 1e-3, 1.0]))
def test_the_compiled_run_of_corners_is_the_python_one(seed: int, count: int, plane: str, side: int, radius: float,
                                                       start: int, jitter: float) -> None:
    """Any ends and any held move (one as the stage would hold it, or shifted): the same count, points, moves
    (corners among them) and state to the last bit; each run is continued past the move it stopped before."""
    rng = Random(seed)
    axes = PLANES[plane]
    ends = _walk(rng, count, axes)
    columns = ([rng.choice(["linear", "linear", "rapid"]) for _ in ends], list(range(7, 7 + count)), ends,
               [rng.choice([0.0, 250.0, 1200.5]) for _ in ends])
    index = min(start, count - 1)
    sx, sy = rng.uniform(-50, 50), rng.uniform(-50, 50)
    heading = rng.uniform(-math.pi, math.pi)
    dx, dy = math.cos(heading), math.sin(heading)
    cx, cy = sx - side * radius * dy + rng.uniform(-jitter, jitter), sy + side * radius * dx
    state = (sx, sy, cx, cy, dx * 3, dy * 3, cx - dx * 3, cy - dy * 3, rng.choice([0.0, -1.0]))
    runs = 0
    while index < count:
        args = (columns, index, count, (*axes, plane), side, radius, state, rng.random() < 0.3, Arc)
        made = COMPILED.comp_lines(*args)
        assert repr(made) == repr(comp_runs.comp_lines(*args))
        taken, _held, (kinds, lines, ends_made, feeds, arcs), state = made
        assert len(kinds) == len(lines) == len(ends_made) == len(feeds) >= taken - 1
        assert arcs is None or len(arcs) == len(kinds)
        runs += 1
        index += taken + 1  # past the move the stage would take itself
        if index < count:  # as the stage leaves it after that move: held at its end, a radius to the side
            sx, sy = ends[index - 1][axes[0]], ends[index - 1][axes[1]]
            state = (sx, sy, sx + radius, sy, 0.0, 1.0, sx + radius, sy - 1.0, ends[index - 1][axes[2]])
    assert runs >= 1


def _flat(points: Iterable[Sequence[float]]) -> list[float]:
    return [value for point in points for value in point]


def test_a_run_goes_round_outside_corners_and_into_inside_ones() -> None:
    """A square's corners on the left of a counter-clockwise walk are inside ones, on the right outside ones:
    each loop takes the whole square, cutting back or going round each corner (an arc of the tool radius about
    the corner point, or a rapid)."""
    square = [(10.0, 0.0), (10.0, 10.0), (0.0, 10.0), (0.0, 0.0), (10.0, 0.0)]
    ends = [(x, y, -1.0, 0.0, 0.0, 0.0) for x, y in square]
    columns = (["linear", "linear", "rapid", "linear", "linear"], [2, 3, 4, 5, 6], ends, [90.0] * 5)
    for loop in (comp_runs.comp_lines, getattr(COMPILED, "comp_lines", None)):
        if loop is None:
            continue
        inside = loop(columns, 0, 5, (0, 1, 2, "XY"), LEFT, 1.0, (0.0, 0.0, 0.0, 1.0, 1.0, 0.0, -5.0, 1.0, -1.0), False,
                      Arc)
        taken, held, (kinds, lines, made, feeds, arcs), _ = inside
        assert taken == 5 and held == (0.0, 1.0)  # straight on into the square: the held move stays
        assert (kinds, lines, feeds, arcs) == (["linear", "linear", "rapid", "linear"], [2, 3, 4, 5], [90.0] * 4, None)
        assert _flat(pose[:3] for pose in made) == pytest.approx(_flat([(9, 1, -1), (9, 9, -1), (1, 9, -1),
                                                                         (1, 1, -1)]))
        outside = loop(columns, 0, 5, (0, 1, 2, "XY"), RIGHT, 1.0, (0.0, 0.0, 0.0, -1.0, 1.0, 0.0, -5.0, -1.0, -1.0),
                       False, Arc)
        taken, held, (kinds, lines, made, feeds, arcs), _ = outside
        assert taken == 5 and held == (0.0, -1.0)
        assert kinds == ["linear", "arc", "linear", "rapid", "rapid", "arc", "linear", "arc"]
        assert lines == [2, 3, 3, 4, 4, 5, 5, 6] and feeds == [90.0, 90.0, 90.0, 0.0, 90.0, 90.0, 90.0, 90.0]
        assert _flat(pose[:3] for pose in made) == pytest.approx(_flat(
            [(10, -1, -1), (11, 0, -1), (11, 10, -1), (10, 11, -1), (0, 11, -1), (-1, 10, -1), (-1, 0, -1),
             (0, -1, -1)]))
        assert arcs is not None and [arc.center if arc else None for arc in arcs] == [
            None, (10.0, 0.0), None, None, None, (0.0, 10.0), None, (0.0, 0.0)]
        assert {arc.turn for arc in arcs if arc} == {1}  # the tool on the right goes round counter-clockwise


# --------------------------------------------------------------------------- whole jobs
steps = st.tuples(st.sampled_from(["G1", "G1", "G1", "G1", "G0", "G2", "G3", "G2R", "Z", "G40", "G41", "G42",
                                   "G41.1", "G42.1"]),
                  st.sampled_from([0.0, 0.01, -0.02, 0.3, -0.4, 1.2, -1.1, 2.0, math.pi]),
                  st.sampled_from([0.7, 2.0, 5.5, 9.0]))


def _contour_job(items: list[tuple[str, float, float]]) -> str:
    """A compensated contour from (what, turn, length) steps: straight moves, arcs (centre words or R),
    plunges, G40 exits with their exit moves and new starts under G41/G42 (D from the tool table),
    G41.1/G42.1 (D the diameter)."""
    lines = ["G21 G17 G90 G94 F800", "G0 X-20 Y-20 Z0", "G41 D3", "G1 X0 Y0"]
    x = y = heading = 0.0
    for what, turn, length in items:
        heading += turn
        nx, ny = x + length * math.cos(heading), y + length * math.sin(heading)
        if what in ("G40",):
            lines += ["G40", f"G1 X{x + 15:.4f} Y{y:.4f}"]
            x += 15
            continue
        if what in ("G41", "G42", "G41.1", "G42.1"):
            lines += ["G40", f"G0 X{x - 12:.4f} Y{y - 12:.4f}", f"{what} D{3 if '.' not in what else 1.5}"]
        if what == "Z":
            lines.append(f"G1 Z{-turn:.3f}")
            continue
        if what in ("G2", "G3"):  # half a circle over the chord, the centre word relative to the start
            lines.append(f"{what} X{nx:.4f} Y{ny:.4f} I{(nx - x) / 2:.4f} J{(ny - y) / 2:.4f}")
        elif what == "G2R":
            lines.append(f"G3 X{nx:.4f} Y{ny:.4f} R{length:.4f}")
        else:
            lines.append(f"{'G0' if what == 'G0' else 'G1'} X{nx:.4f} Y{ny:.4f}")
        x, y = nx, ny
    return "\n".join(lines + ["G40", f"G1 X{x + 20:.4f} Y{y:.4f}", "M30"]) + "\n"


@pytest.mark.slow
@pytest.mark.parametrize("loop", LOOPS)
@settings(max_examples=60, deadline=None, suppress_health_check=[HealthCheck.function_scoped_fixture])
@given(items=st.lists(steps, min_size=1, max_size=60), long_runs=st.integers(0, 3))
def test_a_compensated_job_in_batches_is_the_job_one_move_at_a_time(tmp_path: Path, monkeypatch: pytest.MonkeyPatch,
                                                                     loop: object, items: list, long_runs: int) -> None:  # type: ignore[type-arg]
    """The trace, the result (or the error and the state it left), the moves and the events: batches through
    the loop, and every move through the stage's own code (``batchable()`` off), are the same."""
    items = [*items[:5], *[("G1", 0.01, 2.0)] * (40 * long_runs), *items[5:]]  # runs long enough to matter
    job = tmp_path / "contour.nc"
    job.write_text(_contour_job(items))
    with monkeypatch.context() as patch:
        patch.setattr(comp_runs, "LINES", loop)
        batched = traced_run(job, TOOLS)
        patch.setattr(Interpreter, "batchable", lambda self: False)
        assert traced_run(job, TOOLS) == batched


SPIRAL = [f"X{40 * math.cos(k / 40) * (1 + k / 3000):.3f} Y{40 * math.sin(k / 40) * (1 + k / 3000):.3f}\n"
          for k in range(1, 1500)]
WHOLE_JOBS = {
    "spiral, tool inside": "G0 X-10 Y0\nG41.1 D2\nG1 X40 Y0 F900\n" + "".join(SPIRAL) + "G40\nG1 X0 Y0\nM30\n",
    "spiral, tool outside": "G0 X-10 Y0\nG42 D3\nG1 X40 Y0 F900\n" + "".join(SPIRAL) + "G40\nG1 X0 Y0\nM30\n",
    "corners of 0.2 rad, outside": "G0 X-10 Y0\nG42.1 D1\nG1 X40 Y0 F900\n" + "".join(
        f"X{40 * math.cos(k / 5):.4f} Y{40 * math.sin(k / 5):.4f}\n" for k in range(1, 300)) + "G40\nG1 X0 Y0\nM2\n",
    "a fold the tool cannot take": "G0 X-10 Y0\nG41.1 D2\nG1 X40 Y0 F500\n" + "".join(SPIRAL[:300])
                                    + "X30 Y30\nX40 Y40\nM2\n",
}


@pytest.mark.slow
@pytest.mark.parametrize("name", sorted(WHOLE_JOBS))
def test_a_compensated_job_traces_the_same_bytes_on_both_cores(tmp_path: Path, name: str) -> None:
    if COMPILED is None:
        pytest.skip(NOT_BUILT)
    job = tmp_path / "job.nc"
    job.write_text(WHOLE_JOBS[name])
    made = []
    for pure in ("1", ""):
        trace = tmp_path / f"trace{pure}.csv"
        env = {**os.environ, "ECNC_PURE_PYTHON": pure}
        done = subprocess.run([sys.executable, "-m", "edingcnc_lang", "run", str(job), "--ini", str(TOOLS),
                               "--trace", str(trace)], capture_output=True, text=True, env=env)
        made.append((done.returncode, done.stderr, trace.read_bytes()))
    assert made[0] == made[1]
    assert made[0][2].count(b"\n") > 250 and ("without gouging" in made[0][1]) == name.startswith("a fold")
