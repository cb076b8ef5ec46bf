"""How fast the machine may pass the corner between two moves (G64), as squared speeds.

The model (docs/planner.md): the corner is rounded by a circular blend tangent to both moves.
Its radius is as large as fits in half of the shorter move and, with a G64 P tolerance, as keeps
the blend within P of the programmed corner: R = P cos(phi/2) / (1 - cos(phi/2)) for a change of
direction phi.  The corner is passed at the speed whose centripetal acceleration on that circle
is the path acceleration: v^2 = a R.  Collinear moves (phi = 0) do not slow down at all.  A
corner sharper than ``lafAngle`` (the angle between the two moves, 180 degrees being straight)
is a full stop, as EdingCNC's look-ahead does.

Once the job programs ``G64 R..`` the manual's own rules apply (pp. 38-40; R, S, D are the
change of direction ``phi`` in degrees and a length): ``phi`` up to R passes at full speed (the
blend above), with no S a larger ``phi`` stops the machine (the standard algorithm), with S the
new algorithm limits the corners between R and S by a virtual circle that deviates D from the
corner and blends the larger ones within P; ``R0`` switches the look-ahead off: every corner stops.
"""
from __future__ import annotations

import math

import numpy as np

from edingcnc_lang.motion.planner.angles import turns_beyond


def dot_columns(a: np.ndarray, b: np.ndarray) -> np.ndarray:
    """The dot products of the columns of ``a`` and ``b`` ((6, k)), summed axis by axis in order (as the C does)."""
    total = a[0] * b[0]
    for axis in range(1, len(a)):
        total = total + a[axis] * b[axis]
    return total


def corner_speeds2(tangent_out: np.ndarray, tangent_in: np.ndarray, length_before: np.ndarray,
                   length_after: np.ndarray, accel: np.ndarray, tolerance: np.ndarray, laf_angle: float,
                   programmed: tuple[np.ndarray, np.ndarray, np.ndarray] | None = None) -> np.ndarray:
    """Squared corner speeds for k corners: the direction leaving the move before and entering the one after
    (unit vectors as columns, (6, k)).

    ``tolerance`` is the G64 P in force for the move after the corner (0 = no tolerance: only the
    room on both moves limits the blend); ``laf_angle`` in degrees.  ``programmed`` are the G64 R, S
    (degrees) and D (mm) in force for each corner (R NaN: none programmed, ``laf_angle`` applies; S
    NaN: the standard algorithm; D 0: the tolerance P instead).  The half angle's cosine and tangent
    come from cos(phi) by the half-angle formulas (sqrt only, see ``angles.turns_beyond``).
    """
    cos_phi = np.clip(dot_columns(tangent_out, tangent_in), -1.0, 1.0)
    cos_half = np.sqrt((1.0 + cos_phi) / 2.0)
    if programmed is not None:
        angle, second, deviation = programmed
        on = ~np.isnan(angle)
        beyond_angle = cos_phi < _per_corner(angle)
        circle = on & ~np.isnan(second) & beyond_angle & ~(cos_phi < _per_corner(second)) & (deviation > 0.0)
        tolerance = np.where(circle, deviation, tolerance)  # the new algorithm's virtual circle (p. 39)
    with np.errstate(divide="ignore", invalid="ignore"):
        tan_half = np.sqrt((1.0 - cos_phi) / (1.0 + cos_phi))
        fit = np.minimum(length_before, length_after) / 2.0 / tan_half
        within = np.where(tolerance > 0.0, tolerance * cos_half / (1.0 - cos_half), np.inf)
        radius = np.minimum(fit, within)
        speed2 = np.where(radius > 0.0, accel * radius, 0.0)
    # the angle between the two moves is 180 degrees - phi; below lafAngle the machine stops
    sharp = cos_phi < turns_beyond(180.0 - laf_angle)
    if programmed is not None:
        standard = np.isnan(second) | (angle == 0.0)  # R0: no look-ahead at all
        stops = on & standard & beyond_angle & (cos_phi < 1.0)  # (phi > 0: straight on never stops)
        sharp = np.where(on, stops, sharp)
    return np.where(sharp | np.isnan(speed2), 0.0, speed2)


def _per_corner(angles: np.ndarray) -> np.ndarray:
    """``turns_beyond`` of each corner's angle (a few distinct values: one ``math`` call each; NaN stays NaN)."""
    distinct, index = np.unique(angles, return_inverse=True)
    return np.array([math.nan if math.isnan(a) else turns_beyond(a) for a in distinct.tolist()])[index.reshape(-1)]
