"""Interpolation of one move at the controller's interpolation period.

The interpreter feeds these samples to ``inverse_many``: a straight Cartesian line is a curve in
joint space, so the kinematics must see the path every ``dt`` seconds, not only its ends.

Conventions shared by both functions: the move runs at constant ``feed`` (mm/s along the XYZ
path; degrees/s when only a, b, c move); samples are at t = dt, 2 dt, ... after the move start and
the last sample is the end point exactly (so the start point, which is the previous move's end,
is not repeated); a move of zero length gives just its end point at t = 0.
"""
from __future__ import annotations

import math
from collections.abc import Sequence
import numpy as np

from edingcnc_lang.kinematics.trajectory import ArcFrame, arc_frame
from edingcnc_lang.syntax.input_limits import MAX_MOVE_SAMPLES

# Sample times closer than this fraction of dt to the end are merged into the end point.
_END_SLACK = 1e-9


class TooManySamples(ValueError):
    """A move that would need more than MAX_MOVE_SAMPLES samples (the caller names the job's line)."""


def _times(length: float, feed: float, dt: float) -> np.ndarray:
    """Sample times of a move of ``length`` at ``feed``: every dt, ending exactly at length/feed."""
    if feed <= 0.0 or dt <= 0.0:
        raise ValueError(f"feed and dt must be positive (feed={feed}, dt={dt})")
    if length <= 0.0:
        return np.zeros(1)
    duration = length / feed
    if duration / dt > MAX_MOVE_SAMPLES:
        raise TooManySamples(f"this move takes {duration:.6g} s, {duration / dt:.3g} samples at the interpolation "
                             f"time of {dt:g} s; a move may have at most {MAX_MOVE_SAMPLES:,} (the memory they "
                             "need): raise its feed or split it")
    count = max(1, math.ceil(duration / dt - _END_SLACK))
    t = np.arange(1, count + 1, dtype=float) * dt
    t[-1] = duration
    return t


def _path_length(linear: float, rotary: np.ndarray) -> float:
    """Feed applies to the XYZ path; a rotary-only move is timed in degrees."""
    return linear if linear > 0.0 else float(np.linalg.norm(rotary))


def sample_line(start: Sequence[float], end: Sequence[float], feed: float, dt: float
                ) -> tuple[np.ndarray, np.ndarray]:
    """Samples of a straight move in all six axes: (t of shape (N,), poses of shape (N, 6))."""
    p0, p1 = np.asarray(start, dtype=float), np.asarray(end, dtype=float)
    delta = p1 - p0
    t = _times(_path_length(float(np.linalg.norm(delta[:3])), delta[3:]), feed, dt)
    fraction = t / t[-1] if t[-1] > 0.0 else np.ones(1)
    pts = p0 + fraction[:, None] * delta
    pts[-1] = p1
    return t, pts


def arc_points(start: Sequence[float], end: Sequence[float], frame: ArcFrame, s: np.ndarray) -> np.ndarray:
    """Poses at fractions ``s`` (0..1) of an arc's sweep; s = 1 is the end point exactly."""
    p0, p1 = np.asarray(start, dtype=float), np.asarray(end, dtype=float)
    angle = frame.start_angle + s * frame.sweep
    radius = frame.r0 + s * (frame.r1 - frame.r0)
    pts = p0 + s[:, None] * (p1 - p0)
    pts[:, frame.u] = frame.center[0] + radius * np.cos(angle)
    pts[:, frame.v] = frame.center[1] + radius * np.sin(angle)
    pts[s >= 1.0] = p1
    return pts


def sample_arc(start: Sequence[float], end: Sequence[float], center: Sequence[float], normal: int,
               turns: int, feed: float, dt: float, full_circle_epsilon: float = 1e-12
               ) -> tuple[np.ndarray, np.ndarray]:
    """Samples of an arc or helix about ``center`` in the plane normal to axis ``normal``.

    ``normal`` is 2 for G17 (XY), 1 for G18 (ZX) and 0 for G19 (YZ); the in-plane axes are
    (normal+1, normal+2) mod 3, so positive ``turns`` is counter-clockwise seen from the positive
    normal axis.  The radius blends linearly from the start to the end radius (a slightly
    inconsistent end point still ends exactly); the normal axis and a, b, c move linearly.
    """
    frame = arc_frame(start, end, center, normal, turns, full_circle_epsilon)
    t = _times(_path_length(frame.linear, np.subtract(end[3:], start[3:])), feed, dt)
    s = t / t[-1] if t[-1] > 0.0 else np.ones(1)
    pts = arc_points(start, end, frame, s)
    pts[-1] = np.asarray(end, dtype=float)
    return t, pts
