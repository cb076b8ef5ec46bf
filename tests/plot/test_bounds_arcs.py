"""Issue 42: ``Toolpath.bounds`` samples only the arcs that may reach past the moves' ends, and gives
the very numbers it gave when it sampled every arc (the part box and its size label)."""
from __future__ import annotations

import random
from pathlib import Path

import numpy as np

from edingcnc_lang.plot.toolpath import Toolpath, record_job


def _sampling_every_arc(path: Toolpath, feed_only: bool) -> tuple[np.ndarray, np.ndarray]:
    """The bounds as they were worked out before: the ends and every arc's sampled points."""
    indices = np.flatnonzero(path.part_moves() if feed_only else np.ones(len(path), dtype=bool))
    points = [path.starts[indices, :3], path.ends[indices, :3]]
    points += [path.move_points(int(i)) for i in indices if i in path.arcs]
    stacked = np.vstack(points)
    return stacked.min(axis=0), stacked.max(axis=0)


def _arcs_job(seed: int) -> str:
    """Arcs of every kind: R and I/J, both directions, three planes, helices, full circles, arcs that
    end on the part's edge and arcs that bulge past it, at small and large coordinates."""
    rng = random.Random(seed)
    lines = ["G21 G90 G17", "G0 X0 Y0 Z0", "G1 Z-1 F500"]
    x = y = 0.0
    cz = -1.0
    for k in range(300):
        plane = rng.choice(("G17", "G17", "G18", "G19"))
        scale = rng.choice((1.0, 100.0, 10_000.0))
        nx, ny = x + rng.uniform(-1, 1) * scale, y + rng.uniform(-1, 1) * scale
        z = rng.choice((-1.0, -1.0, rng.uniform(-3, 2)))
        turn = rng.choice(("G2", "G3"))
        if k % 7 == 0:  # a full circle about a centre beside the tool
            lines.append(f"G17 {turn} I{rng.uniform(-2, 2) * scale:.4f} J{rng.uniform(-2, 2) * scale:.4f}")
            continue
        if plane == "G17":
            chord = float(np.hypot(nx - x, ny - y))
            radius = chord / 2.0 * rng.choice((1.0, 1.0001, 1.5, 4.0)) * rng.choice((1, -1))
            lines.append(f"G17 {turn} X{nx:.4f} Y{ny:.4f} Z{z:.4f} R{radius:.4f}")
            x, y = nx, ny
        elif plane == "G18":
            lines.append(f"G18 {turn} X{nx:.4f} Z{z:.4f} I{(nx - x) / 2:.4f} K{(z - cz) / 2:.4f}")
            x = nx
        else:
            lines.append(f"G19 {turn} Y{ny:.4f} Z{z:.4f} J{(ny - y) / 2:.4f} K{(z - cz) / 2:.4f}")
            y = ny
        cz = rng.choice((-1.0, 0.5))
        lines.append(f"G17 G1 Z{cz:.4f}")
    return "\n".join(lines + ["M30", ""])


def test_bounds_are_those_of_every_arc_sampled(tmp_path: Path) -> None:
    for seed in range(4):
        job = tmp_path / f"arcs{seed}.nc"
        job.write_text(_arcs_job(seed), encoding="ascii")
        path = record_job(job)
        assert path.error is None and len(path.arcs) > 200
        for feed_only in (True, False):
            got = path.bounds(feed_only)
            assert got is not None
            want = _sampling_every_arc(path, feed_only)
            assert got[0].tolist() == want[0].tolist() and got[1].tolist() == want[1].tolist()


def test_an_arc_that_bulges_past_its_ends_widens_the_bounds(tmp_path: Path) -> None:
    job = tmp_path / "half.nc"
    job.write_text("G21 G90 G17\nG0 X0 Y0 Z0\nG1 Z-1 F500\nG2 X10 Y0 R5\nM30\n", encoding="ascii")
    lower, upper = record_job(job).bounds() or (None, None)
    assert upper is not None and lower is not None
    assert upper[1] > 4.99 and lower[1] == 0.0  # the top of the half circle, sampled
