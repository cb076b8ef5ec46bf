"""The planner's numpy model alone, against closed-form answers: trapezoids, passes, corners."""
from __future__ import annotations

import math

import numpy as np
import pytest
from hypothesis import given
from hypothesis import strategies as st

from edingcnc_lang.motion.planner.junctions import corner_speeds2
from edingcnc_lang.motion.planner.profile import distance_at, plan_nodes, profiles


def rest_to_rest(length: float, speed: float, accel: float) -> float:
    """One move from rest to rest: trapezoid when it is long enough to reach ``speed``, else triangle."""
    return length / speed + speed / accel if length >= speed * speed / accel else 2.0 * math.sqrt(length / accel)


def chain_time(length: list[float], vmax: list[float], accel: list[float], cap2: list[float]) -> float:
    """Duration of a chain; node caps are first limited by the moves on both sides, as the stage does."""
    v2 = np.array(vmax) ** 2
    caps = np.minimum(np.array(cap2), np.minimum(np.append(v2, np.inf), np.insert(v2, 0, np.inf)))
    node2 = plan_nodes(np.array(length), np.array(accel), caps, caps[0])
    return float(profiles(np.array(length), np.array(vmax), np.array(accel), node2).duration.sum())


@pytest.mark.parametrize(("length", "speed", "accel"), [
    (100.0, 50.0, 500.0),    # long: L/v + v/a = 2.1 s
    (1.0, 50.0, 500.0),      # short: never reaches 50 mm/s, 2 sqrt(L/a)
    (5.0, 50.0, 500.0),      # exactly v^2/a: the two formulas agree
])
def test_single_move_from_rest_to_rest(length: float, speed: float, accel: float) -> None:
    assert chain_time([length], [speed], [accel], [0.0, 0.0]) == pytest.approx(rest_to_rest(length, speed, accel))


def test_collinear_moves_do_not_stop() -> None:
    # ten 10 mm moves that may be passed at full speed are one 100 mm move
    time = chain_time([10.0] * 10, [50.0] * 10, [500.0] * 10, [0.0] + [math.inf] * 9 + [0.0])
    assert time == pytest.approx(rest_to_rest(100.0, 50.0, 500.0))


def test_exact_stop_polygon_is_the_sum_of_its_sides() -> None:
    sides = [30.0, 40.0, 50.0]
    time = chain_time(sides, [20.0] * 3, [100.0] * 3, [0.0] * 4)
    assert time == pytest.approx(sum(rest_to_rest(side, 20.0, 100.0) for side in sides))


def test_backward_pass_slows_down_in_time_for_a_stop() -> None:
    # a long fast move, then a stop: the node before the short last move is limited by sqrt(2 a L)
    node2 = plan_nodes(np.array([100.0, 0.5]), np.array([100.0, 100.0]), np.array([0.0, np.inf, 0.0]), 0.0)
    assert node2[1] == pytest.approx(2 * 100.0 * 0.5)
    assert node2[2] == 0.0


def test_forward_pass_limits_what_can_be_reached() -> None:
    node2 = plan_nodes(np.array([0.5, 100.0]), np.array([100.0, 100.0]), np.array([0.0, np.inf, 0.0]), 0.0)
    assert node2[1] == pytest.approx(2 * 100.0 * 0.5)


def test_distance_at_follows_the_three_phases() -> None:
    p = profiles(np.array([100.0]), np.array([50.0]), np.array([500.0]), np.array([0.0, 0.0]))
    t_accel, total = 0.1, 2.1
    dist, speed, acc = distance_at(p, np.zeros(4, dtype=int), np.array([0.05, t_accel, 1.0, total]))
    np.testing.assert_allclose(dist, [0.5 * 500 * 0.05 ** 2, 2.5, 2.5 + 50 * 0.9, 100.0])
    np.testing.assert_allclose(speed, [25.0, 50.0, 50.0, 0.0], atol=1e-9)
    np.testing.assert_allclose(acc, [500.0, 0.0, 0.0, -500.0])


def test_right_angle_corner_speed_within_a_tolerance() -> None:
    x, y = np.array([[1.0, 0, 0, 0, 0, 0]]).T, np.array([[0.0, 1, 0, 0, 0, 0]]).T  # directions as columns
    tolerance = 0.01
    half = math.pi / 4
    radius = tolerance * math.cos(half) / (1 - math.cos(half))
    speed2 = corner_speeds2(x, y, np.array([100.0]), np.array([100.0]), np.array([1000.0]), np.array([tolerance]), 5.0)
    assert speed2[0] == pytest.approx(1000.0 * radius)


def test_corner_without_tolerance_is_limited_by_the_room_on_the_moves() -> None:
    x, y = np.array([[1.0, 0, 0, 0, 0, 0]]).T, np.array([[0.0, 1, 0, 0, 0, 0]]).T  # directions as columns
    speed2 = corner_speeds2(x, y, np.array([2.0]), np.array([100.0]), np.array([1000.0]), np.array([0.0]), 5.0)
    assert speed2[0] == pytest.approx(1000.0 * 1.0)  # blend in half the shorter move: R = 1 / tan(45 deg)


def test_straight_on_is_not_a_corner_and_a_reversal_is_a_stop() -> None:
    x = np.array([[1.0, 0, 0, 0, 0, 0]] * 3).T
    after = np.array([[1.0, 0, 0, 0, 0, 0], [-1.0, 0, 0, 0, 0, 0],
                      [-math.cos(math.radians(4)), math.sin(math.radians(4)), 0, 0, 0, 0]]).T
    speed2 = corner_speeds2(x, after, np.full(3, 10.0), np.full(3, 10.0), np.full(3, 1000.0), np.full(3, 0.01), 5.0)
    assert speed2[0] == math.inf
    assert speed2[1] == 0.0 and speed2[2] == 0.0  # 4 degrees between the moves is below lafAngle 5


lengths = st.lists(st.floats(0.01, 200.0), min_size=1, max_size=30)


@given(lengths, st.floats(1.0, 500.0), st.floats(10.0, 20000.0), st.data())
def test_blending_is_between_exact_stop_and_the_no_corner_bound(length: list[float], speed: float, accel: float,
                                                               data: st.DataObject) -> None:
    n = len(length)
    corners = data.draw(st.lists(st.floats(0.0, 1e6), min_size=n - 1, max_size=n - 1))
    vmax, acc = [speed] * n, [accel] * n
    exact = chain_time(length, vmax, acc, [0.0] * (n + 1))
    blended = chain_time(length, vmax, acc, [0.0, *corners, 0.0])
    no_corner = rest_to_rest(sum(length), speed, accel)
    assert no_corner * (1 - 1e-9) <= blended <= exact * (1 + 1e-9)


@given(lengths, st.floats(1.0, 500.0), st.floats(10.0, 20000.0), st.data())
def test_planned_nodes_respect_caps_and_acceleration(length: list[float], speed: float, accel: float,
                                                     data: st.DataObject) -> None:
    n = len(length)
    corners = data.draw(st.lists(st.floats(0.0, 1e6), min_size=n - 1, max_size=n - 1))
    cap2 = np.array([0.0, *corners, 0.0])
    node2 = plan_nodes(np.array(length), np.full(n, accel), cap2, 0.0)
    assert (node2 <= cap2).all()
    reach = 2 * accel * np.array(length)
    rounding = 1e-12 * reach.sum()  # the passes work on running sums of the reach
    assert (np.abs(np.diff(node2)) <= reach * (1 + 1e-9) + rounding).all()  # every change of speed is reachable
