"""Angles of corners as the planner compares them: through the dot product of the two directions.

Pure Python (no numpy): the compiled planner of straight moves gets its threshold from here too.
"""
from __future__ import annotations

import math

# cos of the angles whose cosine is exact (a corner of exactly 90 or 60 degrees compares as such)
_EXACT_COS = {0.0: 1.0, 60.0: 0.5, 90.0: 0.0, 120.0: -0.5, 180.0: -1.0}


def turns_beyond(angle: float) -> float:
    """The cosine c such that a change of direction is larger than ``angle`` degrees exactly when the dot
    product of the two (unit) directions is below c.

    Angles are compared through that dot product, not through ``arccos`` of it: only +, -, *, / and
    sqrt (correctly rounded everywhere) then decide a corner, so every CPU and the compiled planner
    (csrc/speedups_plan.c) agree to the bit; cosines that are exact in binary stay exact.
    """
    if angle < 0.0:
        return math.inf  # every change of direction, none included, is larger
    if angle >= 180.0:
        return -1.0      # none is
    exact = _EXACT_COS.get(angle)
    return math.cos(math.radians(angle)) if exact is None else exact
