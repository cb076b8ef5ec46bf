"""The compiled core and the pure-Python core run arc and compensation jobs to the same bytes.

The pure-Python path is the reference: random jobs of R and I/J arcs in every plane (most of them
fitting, some refused, in runs long enough for the bulk path's readers), straight lines, feeds, G91,
inch, offsets and cutter compensation (G41.1/G42.1 with straight runs and arcs) run here on the core
this process has and in a worker process on the Python core (``tests/core_outcome.py``); the traces,
events, results and errors must be equal.
"""
from __future__ import annotations

from collections.abc import Callable
from pathlib import Path

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from tests.core_outcome import outcome


PLANE_WORDS = {"G17": ("X", "Y", "I", "J"), "G18": ("Z", "X", "K", "I"), "G19": ("Y", "Z", "J", "K")}
steps = st.floats(-20, 20, allow_nan=False).filter(lambda v: abs(v) > 0.01)
bends = st.one_of(st.floats(-3, 3, allow_nan=False), st.sampled_from([0.0, 0.5, -0.5]))


def _ij_arc(g: str, plane: str, du: float, dv: float, k: float, drift: float) -> str:
    """An incremental arc by (du, dv) whose centre is on the chord's perpendicular (k: how far along it),
    ``drift`` moving the centre off it (beyond the radius tolerance: refused)."""
    a, b, i, j = PLANE_WORDS[plane]
    return f"{g} {a}{du:.4f} {b}{dv:.4f} {i}{du / 2 - k * dv + drift:.4f} {j}{dv / 2 + k * du:.4f}"


def _r_arc(g: str, plane: str, du: float, dv: float, factor: float, long_way: bool) -> str:
    """An incremental R arc by (du, dv), its radius ``factor`` times half the chord (below 1: no circle)."""
    a, b, _, _ = PLANE_WORDS[plane]
    radius = factor * (du * du + dv * dv) ** 0.5 / 2
    return f"{g} {a}{du:.4f} {b}{dv:.4f} R{-radius if long_way else radius:.4f}"


def _arc_lines(plane: str) -> st.SearchStrategy[str]:
    g = st.sampled_from(["G2", "G3", "G02", "g3"] * 10 + [""])  # none: the motion in force (refused after a G1)
    ij = st.builds(_ij_arc, g, st.just(plane), steps, steps, bends, st.sampled_from([0.0] * 30 + [0.0005, 0.5]))
    r = st.builds(_r_arc, g, st.just(plane), steps, steps, st.sampled_from([1.0, 1.2, 3.0, 50.0] * 8 + [0.99]),
                  st.booleans())
    feed = st.sampled_from([""] * 40 + [" F300", " F1200.5"] * 5 + [" F0"])
    return st.builds(str.__add__, st.one_of(ij, r), feed)


straight = st.builds(lambda g, dx, dy, dz: f"{g} X{dx:.3f} Y{dy:.3f}" + (f" Z{dz:.3f}" if dz else ""),
                     st.sampled_from(["G1"] * 8 + ["G0"] * 2 + [""]), steps, steps, st.sampled_from([0.0, 0.0, -0.5, 1.0]))
state = st.sampled_from(["G20", "G21", "G10 L2 P1 X5 Y-3 Z1", "G55", "G54", "F800", "GetJobDistance 100",
                         "M3 S1000", "G1 F50", "G64 P0.1"])


@st.composite
def jobs(draw: st.DrawFn) -> str:
    """A job in G91 (every arc fits wherever the last one ended) in runs of one plane, those in XY often
    compensated (the tool on either side)."""
    lines = ["G21 G91 G94 F600", "G0 X0.1 Y0.2 Z0.3"]
    for _ in range(draw(st.integers(1, 4))):
        plane = draw(st.sampled_from(sorted(PLANE_WORDS)))
        comp = draw(st.sampled_from(["", "G41.1 D2", "G42.1 D0.5"])) if plane == "G17" else ""
        lines += [plane, comp, "G1 X1 Y1" if comp else ""]
        lines += draw(st.lists(st.one_of(_arc_lines(plane), _arc_lines(plane), _arc_lines(plane), straight, state),
                               min_size=1, max_size=40))
        lines.append("G40" if comp else "")
    return "\n".join([*lines, "G40", "G90 G0 X0 Y0", "M30"]) + "\n"


@pytest.mark.slow
@settings(max_examples=120, deadline=None)
@given(jobs())
def test_both_cores_run_arc_and_compensation_jobs_alike(python_core: Callable[[Path], str], tmp_path_factory:
                                                        pytest.TempPathFactory, source: str) -> None:
    job = tmp_path_factory.mktemp("cores") / "job.nc"
    job.write_text(source)
    compiled = outcome(job)
    assert compiled == python_core(job)


def test_a_long_arc_job_runs_alike_on_both_cores(python_core: Callable[[Path], str], tmp_path: Path) -> None:
    """Runs of thousands of arcs (the readers' runs, the planner's windows, the limits report's extremes)
    under compensation, R and I/J in turn."""
    lines = ["G21 G17 G90 G94 F600", "G0 X-5 Y0", "G41.1 D1", "G1 X0 Y0"]
    for k in range(6000):
        x = 2.0 * (k + 1)
        lines.append(f"G{2 + k % 2} X{x:.4f} Y0 " + (f"R{1.0 if k % 3 else -1.5}" if k % 4 < 2 else "I1.0 J0"))
    job = tmp_path / "long.nc"
    job.write_text("\n".join([*lines, "G40", "G0 X0 Y0", "M30"]) + "\n")
    compiled = outcome(job)
    assert compiled.count(",arc,") > 5000 and compiled == python_core(job)
