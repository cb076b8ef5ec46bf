"""Interpolation of lines, arcs and helices at the interpolation period."""
from __future__ import annotations

import math

import numpy as np
import pytest

from edingcnc_lang.kinematics.sampling import sample_arc, sample_line
from edingcnc_lang.kinematics.trajectory import arc_sweep

DT = 0.005


def test_line_spacing_and_exact_end() -> None:
    start, end = (0.0, 0.0, 0.0, 0.0, 0.0, 0.0), (30.0, 40.0, 0.0, 10.0, 0.0, 0.0)
    t, pts = sample_line(start, end, feed=20.0, dt=DT)            # 50 mm at 20 mm/s: 2.5 s
    assert len(t) == 500 and t[-1] == 2.5
    np.testing.assert_allclose(np.diff(t), DT, rtol=1e-9)
    steps = np.linalg.norm(np.diff(np.vstack([start, pts])[:, :3], axis=0), axis=1)
    np.testing.assert_allclose(steps, 20.0 * DT, rtol=1e-9)
    assert tuple(pts[-1]) == end
    np.testing.assert_allclose(pts[:, 3], pts[:, 0] / 3.0)       # a follows the path linearly


def test_line_with_a_short_last_step() -> None:
    t, pts = sample_line((0,) * 6, (1.0, 0, 0, 0, 0, 0), feed=30.0, dt=DT)
    assert len(t) == 7 and t[-1] == pytest.approx(1.0 / 30.0)
    np.testing.assert_allclose(np.diff(pts[:-1, 0]), 30.0 * DT)
    assert 0.0 < pts[-1, 0] - pts[-2, 0] < 30.0 * DT
    assert pts[-1, 0] == 1.0


def test_zero_length_move_is_its_end_point() -> None:
    t, pts = sample_line((1, 2, 3, 4, 5, 6), (1, 2, 3, 4, 5, 6), feed=10.0, dt=DT)
    assert t.tolist() == [0.0] and pts.tolist() == [[1, 2, 3, 4, 5, 6]]


def test_rotary_only_move_uses_degrees() -> None:
    t, pts = sample_line((0,) * 6, (0, 0, 0, 90.0, 0, 0), feed=45.0, dt=DT)
    assert t[-1] == pytest.approx(2.0) and pts[-1, 3] == 90.0


@pytest.mark.parametrize(("start_angle", "end_angle", "turns", "expected"), [
    (0.0, math.pi / 2, 1, math.pi / 2),
    (0.0, math.pi / 2, -1, -3 * math.pi / 2),
    (1.0, 1.0, 1, 2 * math.pi),
    (1.0, 1.0, -2, -4 * math.pi),
    (0.0, -math.pi / 2, 3, 3 * math.pi / 2 + 4 * math.pi),
])
def test_arc_sweep(start_angle: float, end_angle: float, turns: int, expected: float) -> None:
    assert arc_sweep(start_angle, end_angle, turns) == pytest.approx(expected)


def test_arc_sweep_needs_a_direction() -> None:
    with pytest.raises(ValueError):
        arc_sweep(0.0, 1.0, 0)


@pytest.mark.parametrize("normal", [0, 1, 2])
def test_quarter_arc_points_on_circle(normal: int) -> None:
    """Centre (1, 2, 3), radius 5, counter-clockwise a quarter turn about the normal axis."""
    u, v = (normal + 1) % 3, (normal + 2) % 3
    center = np.array([1.0, 2.0, 3.0])
    start, end = np.zeros(6), np.zeros(6)
    start[:3], end[:3] = center, center
    start[u] += 5.0
    end[v] += 5.0
    t, pts = sample_arc(start, end, center, normal, 1, feed=10.0, dt=DT)
    assert t[-1] == pytest.approx(5.0 * math.pi / 2 / 10.0)
    np.testing.assert_allclose(np.hypot(pts[:, u] - center[u], pts[:, v] - center[v]), 5.0, rtol=1e-12)
    np.testing.assert_allclose(pts[:, normal], center[normal])
    assert np.all(pts[:, v] - center[v] > 0)                        # CCW: through the +v side, never -v
    steps = np.linalg.norm(np.diff(np.vstack([start, pts])[:, :3], axis=0), axis=1)
    np.testing.assert_allclose(steps[:-1], 10.0 * DT, rtol=1e-4)   # chord of the 0.05 mm arc step
    np.testing.assert_array_equal(pts[-1], end)


def test_clockwise_full_helix() -> None:
    """G2 with P2 in XY: two full CW turns of radius 10 while Z sinks 4 mm and C turns 90 degrees."""
    start = np.array([10.0, 0.0, 0.0, 0.0, 0.0, 0.0])
    end = np.array([10.0, 0.0, -4.0, 0.0, 0.0, 90.0])
    t, pts = sample_arc(start, end, (0.0, 0.0, 0.0), 2, -2, feed=50.0, dt=DT)
    length = math.hypot(2 * 2 * math.pi * 10.0, 4.0)
    assert t[-1] == pytest.approx(length / 50.0)
    np.testing.assert_allclose(np.hypot(pts[:, 0], pts[:, 1]), 10.0, rtol=1e-12)
    np.testing.assert_allclose(pts[:, 2], -4.0 * t / t[-1], atol=1e-12)       # z linear in time
    np.testing.assert_allclose(pts[:, 5], 90.0 * t / t[-1], atol=1e-12)
    angle = np.unwrap(np.arctan2(pts[:, 1], pts[:, 0]))
    assert np.all(np.diff(angle) < 0) and angle[-1] == pytest.approx(-4 * math.pi)
    np.testing.assert_array_equal(pts[-1], end)
