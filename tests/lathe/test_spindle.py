"""Constant surface speed and feed per revolution arithmetic (spindle.py)."""
from __future__ import annotations

import math

import pytest
from hypothesis import given
from hypothesis import strategies as st

from edingcnc_lang.machine.spindle import (
    Css,
    SpindleError,
    clamp_rpm,
    css_limits,
    mean_rpm_points,
    mean_rpm_straight,
)


def test_css_follows_the_radius_and_clamps() -> None:
    css = Css(surface=100_000.0, max_rpm=2000.0, min_rpm=100.0, axis_x=0.0)
    assert css.rpm(10.0) == pytest.approx(100_000 / (2 * math.pi * 10))
    assert css.rpm(-10.0) == css.rpm(10.0)
    assert css.rpm(1.0) == 2000.0
    assert css.rpm(1000.0) == 100.0
    assert Css(100_000.0, 0.0, 0.0, 5.0).rpm(5.0) == math.inf


def test_limits_combine_d_and_machine() -> None:
    assert css_limits(2000.0, 3000.0, 50.0) == (2000.0, 50.0)
    assert css_limits(None, 3000.0, 0.0) == (3000.0, 0.0)
    assert css_limits(None, 0.0, 0.0) == (0.0, 0.0)
    with pytest.raises(SpindleError):
        css_limits(-1.0, 0.0, 0.0)
    assert clamp_rpm(5000.0, 3000.0, 0.0) == 3000.0
    assert clamp_rpm(0.0, 3000.0, 100.0) == 0.0


def test_mean_rpm_is_exact_for_a_facing_cut() -> None:
    css = Css(surface=100_000.0, max_rpm=2000.0, min_rpm=0.0, axis_x=0.0)
    # numeric integral of 1/rpm over X 10 -> 0
    n = 200_000
    minutes = sum(1.0 / css.rpm(10.0 - 10.0 * (i + 0.5) / n) for i in range(n)) / n
    assert mean_rpm_straight(css, 10.0, 0.0) == pytest.approx(1.0 / minutes, rel=1e-6)
    assert mean_rpm_straight(1200.0, 10.0, 0.0) == 1200.0
    assert mean_rpm_straight(css, 10.0, 10.0) == pytest.approx(css.rpm(10.0))


def test_centre_without_a_maximum_is_an_error() -> None:
    with pytest.raises(SpindleError, match="no maximum spindle speed"):
        mean_rpm_straight(Css(100_000.0, 0.0, 0.0, 0.0), 10.0, -10.0)


@given(x0=st.floats(-50, 50), x1=st.floats(-50, 50))
def test_mean_lies_between_the_extremes(x0: float, x1: float) -> None:
    css = Css(surface=150_000.0, max_rpm=3000.0, min_rpm=200.0, axis_x=1.0)
    xs = [x0 + (x1 - x0) * i / 50 for i in range(51)]
    mean = mean_rpm_straight(css, x0, x1)
    rpms = [css.rpm(x) for x in xs]
    assert min(rpms) - 1e-6 <= mean <= max(rpms) + 1e-6
    assert mean_rpm_points(css, xs) == pytest.approx(mean, rel=1e-9)
