"""Arc geometry: centres from R or IJK words, radius checks, sweep angles.

Pure functions on in-plane coordinates (a1, a2) where a1 x a2 points along the
plane's normal, so "counter-clockwise" means the same in G17, G18 and G19.
"""
from __future__ import annotations

import math
from collections.abc import Sequence
from typing import NamedTuple

from edingcnc_lang.canon import Arc
from edingcnc_lang.machine.tables import MM_PER_INCH

# A start/end radius difference up to this much is accepted, whatever the radius: the manual's 0.002 mm
# (3.6.3, p. 20; LinuxCNC also accepts 0.1 % of the radius, the controller does not), and LinuxCNC's
# TOLERANCE_INCH in G20, so a CAM post that prints inches to four decimals passes here as it does there.
RADIUS_TOLERANCE_MM = 0.002
RADIUS_TOLERANCE_INCH = 0.0002
TINY = 1e-12


class ArcError(ValueError):
    """Arc words that describe no circle; the message is for the user, ``center`` the centre when it is known."""

    def __init__(self, message: str, center: tuple[float, float] | None = None) -> None:
        super().__init__(message)
        self.center = center


class ArcPlan(NamedTuple):
    """An arc as a line's words describe it: its record, its centre (in-plane), swept angle and path length."""

    arc: Arc
    center: tuple[float, float]
    angle: float
    length: float


def radius_tolerance(inch: bool) -> float:
    """The absolute radius tolerance in mm for a program in inches (G20) or millimetres."""
    return RADIUS_TOLERANCE_INCH * MM_PER_INCH if inch else RADIUS_TOLERANCE_MM


def center_from_radius(start: tuple[float, float], end: tuple[float, float], radius: float,
                       clockwise: bool, tolerance: float = RADIUS_TOLERANCE_MM) -> tuple[float, float]:
    """Centre of the arc through start and end with signed radius R (R < 0: more than 180 degrees)."""
    (s1, s2), (e1, e2) = start, end
    if math.hypot(e1 - s1, e2 - s2) < TINY:
        raise ArcError("an R-form arc needs an end point different from its start point")
    abs_r = abs(radius)
    mid1, mid2 = (s1 + e1) / 2.0, (s2 + e2) / 2.0
    half = math.hypot(mid1 - e1, mid2 - e2)
    if half - abs_r > tolerance:
        raise ArcError(f"R{radius:g} is too small to reach the end point: the chord is {2 * half:.4f} mm long")
    if abs_r == 0.0:  # ends closer than the tolerance: R0 still describes no circle
        raise ArcError(f"R{radius:g} is no radius: an R-form arc needs R other than 0")
    if half / abs_r > 1.0 - TINY:
        half = abs_r
    theta = math.atan2(e2 - s2, e1 - s1) + (-math.pi / 2 if (clockwise == (radius > 0)) else math.pi / 2)
    offset = abs_r * math.cos(math.asin(half / abs_r))
    return mid1 + offset * math.cos(theta), mid2 + offset * math.sin(theta)


def check_radius(start: tuple[float, float], center: tuple[float, float],
                 end: tuple[float, float], tolerance: float = RADIUS_TOLERANCE_MM) -> tuple[float, float]:
    """Both radii of an IJK arc; raises ArcError when they differ beyond the tolerance."""
    r1 = math.hypot(start[0] - center[0], start[1] - center[1])
    r2 = math.hypot(end[0] - center[0], end[1] - center[1])
    if r1 < TINY:
        raise ArcError("the arc centre lies on its start point (radius 0)")
    if abs(r1 - r2) > tolerance:
        raise ArcError(f"start and end are not on one circle: start radius {r1:.4f}, end radius {r2:.4f}")
    return r1, r2


def sweep(start: tuple[float, float], center: tuple[float, float], end: tuple[float, float],
          clockwise: bool, full_circle_epsilon: float, r_form: bool = False,
          tolerance: float = RADIUS_TOLERANCE_MM) -> tuple[float, int]:
    """Swept angle in radians (always > 0) and whether the arc is a full circle (1) or not (0).

    Only an I/J arc whose ends meet (within ``tolerance``, the program's precision) is a full
    circle, when it sweeps less than ``full_circle_epsilon``; an R arc (its ends always differ) and
    an arc whose ends differ sweep what they sweep, however little (``G2 X10 R10000000``).
    """
    a0 = math.atan2(start[1] - center[1], start[0] - center[0])
    a1 = math.atan2(end[1] - center[1], end[0] - center[0])
    delta = (a0 - a1) if clockwise else (a1 - a0)
    delta %= 2 * math.pi
    ends_meet = math.dist(start, end) <= tolerance
    if delta == 0.0 or (not r_form and ends_meet and delta < full_circle_epsilon):
        return 2 * math.pi, 1
    return delta, 0


def circle_within(center: tuple[float, float], radius: float, axes: tuple[int, int],
                  low: Sequence[float], high: Sequence[float]) -> bool:
    """Whether the whole circle (in the plane of ``axes``) lies within ``low``..``high``: then no point
    of an arc on it, its extremes included, can be outside (rounding is monotonic, so the extremes
    ``arc_extremes`` computes lie within centre +- radius too)."""
    (cu, cv), (u, v) = center, axes
    return low[u] <= cu - radius and cu + radius <= high[u] and low[v] <= cv - radius and cv + radius <= high[v]


def arc_extremes(center: tuple[float, float], radius: float, start_angle: float, sweep_angle: float,
                 clockwise: bool) -> list[tuple[float, float]]:
    """In-plane points where the arc reaches its extremes along each axis (for exact limit checks)."""
    points = []
    direction = -1.0 if clockwise else 1.0
    for k in range(4):
        quadrant = k * math.pi / 2
        rel = (direction * (quadrant - start_angle)) % (2 * math.pi)
        if rel <= sweep_angle + 1e-12:
            points.append((center[0] + radius * math.cos(quadrant), center[1] + radius * math.sin(quadrant)))
    return points


def scale_about(pose: Sequence[float], center: Sequence[float], factors: Sequence[float]) -> tuple[float, ...]:
    """``pose`` with X, Y, Z scaled by ``factors`` about ``center`` (rotary axes unchanged)."""
    return tuple(c + f * (p - c) for p, f, c in zip(pose[:3], factors, center)) + tuple(pose[3:])


# The two axes a rotation in each plane turns, ordered so that a positive angle is counter-clockwise
# seen from the plane's positive normal (right-handed): XY about Z, YZ about X, XZ about Y (Z to X).
TURNED_AXES = {"XY": (0, 1), "YZ": (1, 2), "XZ": (2, 0)}


def rotate_about(pose: Sequence[float], pivot: Sequence[float], degrees: float, plane: str = "XY") -> tuple[float, ...]:
    """``pose`` turned by ``degrees`` in ``plane`` (counter-clockwise seen from the plane's positive
    normal axis) about the line through ``pivot`` along that normal; ``pivot`` may be (x, y) for XY."""
    c, s = math.cos(math.radians(degrees)), math.sin(math.radians(degrees))
    a, b = TURNED_AXES[plane]
    da, db = pose[a] - pivot[a], pose[b] - pivot[b]
    turned = list(pose)
    turned[a], turned[b] = pivot[a] + c * da - s * db, pivot[b] + s * da + c * db
    return tuple(turned)
