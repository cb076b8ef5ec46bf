"""Spindle speed on a lathe: constant surface speed (G96) and feed per revolution (G95).

Pure arithmetic, no interpreter state: the interpreter says what is in force and where a move
runs, this module says how fast the spindle turns there and how long a move that advances a
fixed distance per revolution takes.  Lengths are mm, speeds rpm, surface speed mm/min.
"""
from __future__ import annotations

import math
from collections.abc import Sequence

from edingcnc_lang.canon import Css  # the G96 record a move carries

M_PER_MIN = 1000.0    # G96 S in G21: metres per minute
FT_PER_MIN = 304.8    # G96 S in G20: feet per minute


class SpindleError(ValueError):
    """A spindle speed that cannot be had (the message is for the user)."""


Speed = float | Css  # what is in force: a fixed rpm (G97) or constant surface speed (G96)


def rpm_at(speed: Speed, x: float) -> float:
    """The spindle speed at machine X ``x``."""
    return speed.rpm(x) if isinstance(speed, Css) else speed


def clamp_rpm(rpm: float, max_rpm: float, min_rpm: float) -> float:
    """A G97 speed within the machine's limits (0 = no limit); 0 stays 0 (spindle stopped)."""
    if rpm <= 0.0:
        return 0.0
    if max_rpm > 0.0:
        rpm = min(rpm, max_rpm)
    return max(rpm, min_rpm)


def speed_clamp_message(asked: float, rpm: float, max_rpm: float) -> str:
    """What a G97 S outside the machine's range turns at (the run's and lint's G521)."""
    limit = "spindleNmax" if rpm == max_rpm and asked > rpm else "spindleNmin"
    return (f"S{asked:g}: the spindle turns at {rpm:g} rpm, the machine's {limit} (cnc.ini), "
            f"not the {asked:g} rpm written")


def css_limits(d_word: float | None, machine_max: float, machine_min: float) -> tuple[float, float]:
    """The G96 clamp: the lower of D and the machine's maximum, and the machine's minimum."""
    if d_word is not None and d_word < 0:
        raise SpindleError(f"G96 D{d_word:g}: the maximum spindle speed must not be negative")
    limits = [v for v in (d_word or 0.0, machine_max) if v > 0.0]
    return (min(limits) if limits else 0.0), machine_min


def _breaks(x0: float, x1: float, css: Css) -> list[float]:
    """Fractions of a straight move where 1/rpm changes slope: the centre and the clamps."""
    points = {0.0, 1.0}
    if x1 == x0:
        return sorted(points)
    radii = [0.0]
    radii += [css.surface / (2.0 * math.pi * css.max_rpm)] if css.max_rpm > 0.0 else []
    radii += [css.surface / (2.0 * math.pi * css.min_rpm)] if css.min_rpm > 0.0 else []
    for radius in radii:
        for target in (css.axis_x - radius, css.axis_x + radius):
            f = (target - x0) / (x1 - x0)
            if 0.0 < f < 1.0:
                points.add(f)
    return sorted(points)


def mean_rpm_straight(speed: Speed, x0: float, x1: float) -> float:
    """The speed that makes a per-revolution move from X ``x0`` to ``x1`` take its true time.

    A move advancing a fixed distance per revolution takes length * mean(1/rpm) / feed; under
    constant surface speed 1/rpm is piecewise linear in the distance travelled (linear in the
    radius, clamped), so the trapezoid rule between its break points is exact.
    """
    if not isinstance(speed, Css):
        return speed
    points = _breaks(x0, x1, speed)
    if any(speed.minutes_per_rev(x0 + (x1 - x0) * f) == 0.0 for f in points):
        raise SpindleError("G96 reaches the turning centre with no maximum spindle speed "
                           "(give D on the G96 line or set spindleNmax in cnc.ini)")
    total = sum((b - a) * (speed.minutes_per_rev(x0 + (x1 - x0) * a)
                           + speed.minutes_per_rev(x0 + (x1 - x0) * b)) / 2.0
                for a, b in zip(points, points[1:]))
    return 1.0 / total if total > 0.0 else speed.rpm(x0)


def mean_rpm_points(speed: Speed, xs: Sequence[float]) -> float:
    """As ``mean_rpm_straight`` for a curved move given by equally spaced points' X values."""
    if not isinstance(speed, Css):
        return speed
    legs = [mean_rpm_straight(speed, a, b) for a, b in zip(xs, xs[1:])]
    return len(legs) / sum(1.0 / rpm for rpm in legs) if legs else speed.rpm(xs[0])
