"""How fast the machine may pass the corner between two moves (G64), as squared speeds.

The model (docs/planner.md): the corner is rounded by a circular blend tangent to both moves.
Its radius is as large as fits in half of the shorter move and, with a G64 P tolerance, as keeps
the blend within P of the programmed corner: R = P cos(phi/2) / (1 - cos(phi/2)) for a change of
direction phi.  The corner is passed at the speed whose centripetal acceleration on that circle
is the path acceleration: v^2 = a R.  Collinear moves (phi = 0) do not slow down at all.  A
corner sharper than ``lafAngle`` (the angle between the two moves, 180 degrees being straight)
is a full stop, as EdingCNC's look-ahead does.
"""
from __future__ import annotations

import math

import numpy as np


def corner_speeds2(tangent_out: np.ndarray, tangent_in: np.ndarray, length_before: np.ndarray,
                   length_after: np.ndarray, accel: np.ndarray, tolerance: np.ndarray, laf_angle: float) -> np.ndarray:
    """Squared corner speeds for k corners: the direction leaving the move before and entering the one after
    (unit vectors as columns, (6, k)).

    ``tolerance`` is the G64 P in force for the move after the corner (0 = no tolerance: only the
    room on both moves limits the blend); ``laf_angle`` in degrees.
    """
    cos_phi = np.clip((tangent_out * tangent_in).sum(axis=0), -1.0, 1.0)
    half = np.arccos(cos_phi) / 2.0
    cos_half = np.cos(half)
    with np.errstate(divide="ignore", invalid="ignore"):
        fit = np.minimum(length_before, length_after) / 2.0 / np.tan(half)
        within = np.where(tolerance > 0.0, tolerance * cos_half / (1.0 - cos_half), np.inf)
        radius = np.minimum(fit, within)
        speed2 = np.where(radius > 0.0, accel * radius, 0.0)
    # the angle between the two moves is pi - phi; below lafAngle the machine stops
    sharp = (math.pi - 2.0 * half) < math.radians(laf_angle)
    return np.where(sharp | np.isnan(speed2), 0.0, speed2)
