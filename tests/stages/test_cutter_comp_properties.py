"""Property: round a convex polygon with compensation on, inside or outside, and every move the
tool makes along the contour ends exactly one tool radius from the programmed outline.  (The
last one ends square to the last side at the start corner, as G40 leaves it, so it is left out.)"""
from __future__ import annotations

import math
from pathlib import Path

from hypothesis import given, settings
from hypothesis import strategies as st

from edingcnc_lang.canon import Move
from edingcnc_lang.runner import RunOptions, run_string

EMPTY_MACRO = Path(__file__).parent.parent / "interpreter" / "data" / "empty_macro.cnc"
Point = tuple[float, float]


def _distance_to_segment(p: Point, a: Point, b: Point) -> float:
    ax, ay = b[0] - a[0], b[1] - a[1]
    t = max(0.0, min(1.0, ((p[0] - a[0]) * ax + (p[1] - a[1]) * ay) / (ax * ax + ay * ay)))
    return math.dist(p, (a[0] + t * ax, a[1] + t * ay))


# Convex polygons: n corners on a circle, each shifted from the regular position by up to a fifth
# of the spacing (every corner between 72 and 168 degrees wide).
polygons = st.integers(3, 8).flatmap(
    lambda n: st.lists(st.floats(-0.2, 0.2), min_size=n, max_size=n).map(
        lambda shifts: [2 * math.pi * (k + shift) / len(shifts) for k, shift in enumerate(shifts)]))


@settings(max_examples=60, deadline=None)
@given(polygons, st.floats(20.0, 60.0), st.floats(0.5, 3.0), st.booleans())
def test_the_compensated_contour_keeps_one_radius_from_the_outline(angles: list[float], size: float,
                                                                    radius: float, inside: bool) -> None:
    corners = [(size * math.cos(a), size * math.sin(a)) for a in angles]  # counter-clockwise
    lead = (0.0, 0.0) if inside else (2 * corners[0][0], 2 * corners[0][1])
    lines = ["G21 G17 G90 G94", f"G0 X{lead[0]:.6f} Y{lead[1]:.6f}",
             f"G4{'1' if inside else '2'}.1 D{2 * radius:.6f}"]
    lines += [f"G1 X{x:.6f} Y{y:.6f} F600" for x, y in corners + corners[:1]]
    lines += ["G40", f"G1 X{lead[0]:.6f} Y{lead[1]:.6f}", "M2"]
    moves: list[Move] = []
    run_string("\n".join(lines) + "\n", RunOptions(macro=EMPTY_MACRO, on_move=lambda m, _j: moves.append(m)))
    entry, exit_line = 4, len(corners) + 6
    contour = [m for m in moves if entry < m.line < exit_line][:-1]
    assert contour, "no compensated moves"
    edges = list(zip(corners, corners[1:] + corners[:1]))
    for move in contour:
        end = (move.end[0], move.end[1])
        gap = min(_distance_to_segment(end, a, b) for a, b in edges)
        assert math.isclose(gap, radius, abs_tol=1e-6), (move, gap)
        if move.arc is not None:  # corner arcs go round a corner point at the tool radius
            assert min(math.dist(move.arc.center, c) for c in corners) < 1e-6
