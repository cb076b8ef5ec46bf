"""What each move of a window allows: its length, its direction at both ends, its speed and acceleration limits.

The stage collects moves as plain Python values (cheap per move); ``segments`` turns a window of
them into arrays.  A move's path speed is limited by every axis it moves: an axis that does a
fraction f of the path's length runs at f times the path speed, so the path may run at most
``limit / f`` (the same for acceleration).  The feed applies to the XYZ path; a move of the
rotary axes only is measured in degrees.  Arcs (few per job) get their geometry one by one.
"""
from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from edingcnc_lang.kinematics.trajectory import CURVATURE_SHARE, Geometry

MAX_CURVATURE_SHARE = 0.95  # lafArcfeedFactor may raise the turn's share, never to all of it


@dataclass(frozen=True)
class Segments:
    """A window of n moves as arrays: path length, unit directions at both ends, limits.

    Poses are columns, (6, n): numpy reduces over the six axes far faster that way round.
    """

    length: np.ndarray       # (n,) mm, or degrees for moves of the rotary axes only
    xyz_length: np.ndarray   # (n,) mm along XYZ (0 for rotary-only moves): what distances add up
    tangent_in: np.ndarray   # (6, n) unit direction at the start (undefined for moves of zero length)
    tangent_out: np.ndarray  # (6, n) unit direction at the end
    vmax: np.ndarray         # (n,) path speed limit, units/s
    accel: np.ndarray        # (n,) path acceleration limit, units/s^2


def _unit(vector: np.ndarray) -> np.ndarray:
    norm = float(np.linalg.norm(vector))
    return vector / norm if norm > 0.0 else vector


def _arc(start: np.ndarray, end: np.ndarray, geometry: Geometry
         ) -> tuple[float, float, np.ndarray, np.ndarray, np.ndarray, float, tuple[int, int]]:
    """Path and XYZ lengths, per-axis fractions, start and end tangents (unscaled), mean radius and
    in-plane axes of one arc."""
    frame = geometry.arc_frame()
    u, v, sweep = frame.u, frame.v, frame.sweep
    delta = end - start
    in_plane = abs(sweep) * (frame.r0 + frame.r1) / 2.0
    length = frame.linear if frame.linear > 0.0 else float(np.linalg.norm(delta[3:]))
    fraction = np.abs(delta) / length if length > 0.0 else np.zeros(6)
    if length > 0.0:
        fraction[u] = fraction[v] = in_plane / length  # each in-plane axis carries the whole arc speed somewhere
    tangents = []
    for angle, radius in ((frame.start_angle, frame.r0), (frame.start_angle + sweep, frame.r1)):
        tangent = delta.copy()
        tangent[u], tangent[v] = -math.sin(angle) * sweep * radius, math.cos(angle) * sweep * radius
        tangents.append(tangent)
    return length, frame.linear, fraction, tangents[0], tangents[1], (frame.r0 + frame.r1) / 2.0, (u, v)


def segments(start: np.ndarray, end: np.ndarray, speed: np.ndarray, vlim: np.ndarray, alim: np.ndarray,
             arcs: dict[int, Geometry], arc_accel_factor: float, min_arc_length: float) -> Segments:
    """Arrays for a window of n moves from ``start`` to ``end`` (columns, (6, n)).

    ``speed`` is each move's own speed limit (the programmed feed with its override, a plug-in's or
    the joints' limit; inf for rapids); ``vlim``/``alim`` (6, n) the axis limits each move runs
    against, or (6,) when they are the same for all.  Arcs also keep v^2 / r within the in-plane
    acceleration's ``CURVATURE_SHARE`` (times ``arc_accel_factor``) and speed up with what is left,
    except arcs shorter than ``min_arc_length``, which the controller runs as one straight chord.
    """
    vlim = vlim if vlim.ndim == 2 else vlim[:, None]
    alim = alim if alim.ndim == 2 else alim[:, None]
    delta = end - start
    square = delta * delta
    linear2, rotary2 = square[:3].sum(axis=0), square[3:].sum(axis=0)
    linear = np.sqrt(linear2)
    length = np.where(linear2 > 0.0, linear, np.sqrt(rotary2))
    span = np.abs(delta)
    with np.errstate(invalid="ignore", divide="ignore"):
        tangent_in = delta / np.sqrt(linear2 + rotary2)
        # min over the axes of limit / fraction (fraction = span / length), as length / max(span / limit)
        vmax = length / np.max(span / vlim, axis=0)
        accel = length / np.max(span / alim, axis=0)
    tangent_out = tangent_in.copy() if arcs else tangent_in
    speed = speed.copy()
    xyz_length = linear.copy() if arcs else linear
    for index, geometry in arcs.items():
        arc_len, linear_len, fraction, t_in, t_out, radius, (u, v) = _arc(start[:, index], end[:, index], geometry)
        length[index], xyz_length[index] = arc_len, linear_len
        tangent_in[:, index], tangent_out[:, index] = _unit(t_in), _unit(t_out)
        row_v, row_a = vlim[:, index if vlim.shape[1] > 1 else 0], alim[:, index if alim.shape[1] > 1 else 0]
        with np.errstate(divide="ignore"):
            vmax[index], accel[index] = 1.0 / np.max(fraction / row_v), 1.0 / np.max(fraction / row_a)
        if arc_len >= min_arc_length and radius > 0.0:
            in_plane = min(row_a[u], row_a[v])
            centripetal = in_plane * min(CURVATURE_SHARE * arc_accel_factor, MAX_CURVATURE_SHARE)
            speed[index] = min(speed[index], vmax[index], math.sqrt(centripetal * radius))
            # speeding up along the arc gets what the circle leaves of the in-plane acceleration
            accel[index] = min(accel[index], in_plane - speed[index] ** 2 / radius)
    return Segments(length, xyz_length, tangent_in, tangent_out, np.minimum(vmax, speed), accel)
