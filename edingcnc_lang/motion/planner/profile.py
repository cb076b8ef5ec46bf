"""Velocity profiles along a chain of moves: the look-ahead passes and trapezoidal timing.

Everything here works on whole windows of moves at once (numpy arrays, no Python loop per
move).  A chain of n moves has n + 1 nodes: node i is where move i starts, node n where the
last one ends.  Speeds at nodes are handled squared (v^2), in which the distance needed to
speed up or slow down is linear: from v0 to v1 at acceleration a takes (v1^2 - v0^2) / 2a.
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np


def plan_nodes(length: np.ndarray, accel: np.ndarray, cap2: np.ndarray, start2: float) -> np.ndarray:
    """Squared speeds at the n + 1 nodes of a chain of n moves.

    ``cap2`` holds the squared speed allowed at each node (the corner speed, never above the speed
    limits of the moves on either side; 0 where the machine must stop; the last node is 0 so that
    the machine can always stop at the end of what it has seen); ``start2`` is the squared speed already reached at node 0.  The backward pass makes
    every node slow enough to stop in time, w_i = min(cap_i, w_{i+1} + 2 a_i L_i); the forward pass
    makes it reachable, u_{i+1} = min(w_{i+1}, u_i + 2 a_i L_i).  With D_i the running sum of
    2 a L, both recurrences are running minima of offset sequences, which numpy does in one call.
    """
    reach = np.concatenate(([0.0], np.cumsum(2.0 * accel * length)))
    backward = np.minimum.accumulate((cap2 + reach)[::-1])[::-1] - reach
    backward[0] = min(float(backward[0]), start2)
    forward = np.minimum.accumulate(backward - reach) + reach
    # the offsets cost a few ulps of the running sum: keep caps (stops above all) exact
    return np.clip(forward, 0.0, np.maximum(cap2, 0.0))


@dataclass(frozen=True)
class Profiles:
    """Trapezoidal (or triangular) speed profiles of a chain of moves, one entry per move.

    Each move speeds up from ``v0`` to ``peak`` at ``accel``, cruises, and slows down to ``v1``;
    ``t_accel``, ``t_cruise`` and ``t_decel`` are the durations of the three phases.
    """

    length: np.ndarray
    v0: np.ndarray
    v1: np.ndarray
    peak: np.ndarray
    accel: np.ndarray
    t_accel: np.ndarray
    t_cruise: np.ndarray
    t_decel: np.ndarray

    @property
    def duration(self) -> np.ndarray:
        return self.t_accel + self.t_cruise + self.t_decel


def profiles(length: np.ndarray, vmax: np.ndarray, accel: np.ndarray, node2: np.ndarray) -> Profiles:
    """Profiles of moves given their lengths, speed limits, accelerations and squared node speeds.

    The peak is the lower of the move's limit and the speed where speeding up from v0 meets
    slowing down to v1: v_p^2 = (v0^2 + v1^2) / 2 + a L.  A move from rest to rest thus takes
    L/v + v/a when it is long enough to reach v, and 2 sqrt(L/a) when it is not.
    """
    v0_2, v1_2 = node2[:-1], node2[1:]
    with np.errstate(invalid="ignore", divide="ignore", over="ignore"):
        peak2 = np.minimum(vmax * vmax, 0.5 * (v0_2 + v1_2) + accel * length)
        peak2 = np.maximum(peak2, np.maximum(v0_2, v1_2))  # rounding: never below the ends
        peak, v0, v1 = np.sqrt(peak2), np.sqrt(v0_2), np.sqrt(v1_2)
        finite_accel = np.isfinite(accel)
        t_accel = np.where(finite_accel, (peak - v0) / accel, 0.0)
        t_decel = np.where(finite_accel, (peak - v1) / accel, 0.0)
        ramps = np.where(finite_accel, (2.0 * peak2 - v0_2 - v1_2) / (2.0 * accel), 0.0)
        cruise = np.maximum(length - ramps, 0.0)
        # a feed below about 1e-161 mm/min squares to 0: the move crawls at that feed all the way
        # (it took 0 s), and a time past the doubles is the largest one
        crawl = np.minimum(length / vmax, np.finfo(float).max)
        t_cruise = np.where(peak > 0.0, cruise / peak, np.where(vmax > 0.0, crawl, 0.0))
    moving = length > 0.0
    zero = np.zeros_like(length)
    return Profiles(length, v0, v1, peak, accel, np.where(moving, t_accel, zero),
                    np.where(moving & np.isfinite(t_cruise), t_cruise, zero), np.where(moving, t_decel, zero))


def distance_at(p: Profiles, index: np.ndarray, tau: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Distance along, speed and acceleration of move ``index[k]`` at ``tau[k]`` seconds after its start."""
    v0, peak, a = p.v0[index], p.peak[index], p.accel[index]
    t1, t2 = p.t_accel[index], p.t_accel[index] + p.t_cruise[index]
    with np.errstate(invalid="ignore"):
        a_fin = np.where(np.isfinite(a), a, 0.0)
        d1 = v0 * t1 + 0.5 * a_fin * t1 * t1
        d2 = d1 + peak * (t2 - t1)
        in_accel, in_cruise = tau < t1, tau < t2
        after = tau - t2
        dist = np.where(in_accel, v0 * tau + 0.5 * a_fin * tau * tau,
                        np.where(in_cruise, d1 + peak * (tau - t1), d2 + peak * after - 0.5 * a_fin * after * after))
        speed = np.where(in_accel, v0 + a_fin * tau, np.where(in_cruise, peak, peak - a_fin * after))
        acc = np.where(in_accel, a_fin, np.where(in_cruise, 0.0, -a_fin))
    length = p.length[index]
    return np.clip(dist, 0.0, length), np.maximum(speed, 0.0), acc
