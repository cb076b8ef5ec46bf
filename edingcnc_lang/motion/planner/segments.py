"""What each move of a window allows: its length, its direction at both ends, its speed and acceleration limits.

The stage collects moves as plain Python values (cheap per move); ``segments`` turns a window of
them into arrays.  A move's path speed is limited by every axis it moves: an axis that does a
fraction f of the path's length runs at f times the path speed, so the path may run at most
``limit / f`` (the same for acceleration).  The feed applies to the XYZ path; a move of the
rotary axes only is measured in degrees.  The arcs of a window are computed together too.
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from edingcnc_lang.kinematics.trajectory import CURVATURE_SHARE
from edingcnc_lang.motion.arc_table import ArcTable

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


def curvature_share(arc_accel_factor: float) -> float:
    """The share of the in-plane acceleration an arc may spend on turning (lafArcfeedFactor raises it)."""
    return min(CURVATURE_SHARE * arc_accel_factor, MAX_CURVATURE_SHARE)


def segments(start: np.ndarray, end: np.ndarray, speed: np.ndarray, vlim: np.ndarray, alim: np.ndarray,
             arcs: ArcTable, arc_accel_factor: float, min_arc_length: float) -> Segments:
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
    # summed axis by axis in order (numpy's sum over the axes may pair them otherwise): the C planner's order
    linear2, rotary2 = square[0] + square[1] + square[2], square[3] + square[4] + square[5]
    linear = np.sqrt(linear2)
    length = np.where(linear2 > 0.0, linear, np.sqrt(rotary2))
    span = np.abs(delta)
    with np.errstate(invalid="ignore", divide="ignore"):
        tangent_in = delta / np.sqrt(linear2 + rotary2)
        # min over the axes of limit / fraction (fraction = span / length), as length / max(span / limit)
        vmax = length / np.max(span / vlim, axis=0)
        accel = length / np.max(span / alim, axis=0)
    tangent_out = tangent_in.copy() if len(arcs) else tangent_in
    speed = speed.copy()
    xyz_length = linear.copy() if len(arcs) else linear
    if len(arcs):
        _arcs(start, end, arcs, vlim, alim, length, xyz_length, tangent_in, tangent_out, vmax, accel, speed,
              arc_accel_factor, min_arc_length)
    return Segments(length, xyz_length, tangent_in, tangent_out, np.minimum(vmax, speed), accel)


def _arcs(start: np.ndarray, end: np.ndarray, arcs: ArcTable, vlim: np.ndarray, alim: np.ndarray,
          length: np.ndarray, xyz_length: np.ndarray, tangent_in: np.ndarray, tangent_out: np.ndarray,
          vmax: np.ndarray, accel: np.ndarray, speed: np.ndarray, arc_accel_factor: float,
          min_arc_length: float) -> None:
    """The arcs' entries of a window's arrays (in place), all arcs at once: a CAM job has many.

    An arc's path runs along its circle (helical: with the normal axis) and its tangents turn with
    it; each in-plane axis carries the whole arc speed somewhere on it.
    """
    index, u, v = arcs.index, arcs.column("u"), arcs.column("v")
    r0, r1, angle, sweep, linear = (arcs.column(name) for name in ("r0", "r1", "start_angle", "sweep", "linear"))
    delta = end[:, index] - start[:, index]
    columns = np.arange(len(index))
    in_plane = np.abs(sweep) * (r0 + r1) / 2.0
    arc_len = np.where(linear > 0.0, linear, np.sqrt((delta[3:] * delta[3:]).sum(axis=0)))
    with np.errstate(invalid="ignore", divide="ignore"):
        fraction = np.where(arc_len > 0.0, np.abs(delta) / arc_len, 0.0)
        fraction[u, columns] = fraction[v, columns] = np.where(arc_len > 0.0, in_plane / arc_len, 0.0)
    length[index], xyz_length[index] = arc_len, linear
    for tangents, at, radius in ((tangent_in, angle, r0), (tangent_out, angle + sweep, r1)):
        tangent = delta.copy()
        tangent[u, columns], tangent[v, columns] = -np.sin(at) * sweep * radius, np.cos(at) * sweep * radius
        norm = np.sqrt((tangent * tangent).sum(axis=0))
        tangents[:, index] = np.where(norm > 0.0, tangent / np.where(norm > 0.0, norm, 1.0), tangent)
    row_v = vlim[:, index] if vlim.shape[1] > 1 else vlim[:, [0]]
    row_a = alim[:, index] if alim.shape[1] > 1 else alim[:, [0]]
    with np.errstate(divide="ignore", invalid="ignore"):  # (a limit of 0: NaN shares, as for straight moves)
        vmax[index], accel[index] = 1.0 / np.max(fraction / row_v, axis=0), 1.0 / np.max(fraction / row_a, axis=0)
    radius = (r0 + r1) / 2.0
    turning = (arc_len >= min_arc_length) & (radius > 0.0)
    if turning.any():
        at, radius = index[turning], radius[turning]
        chosen = columns[turning]
        plane_accel = np.minimum(row_a[u[turning], chosen if row_a.shape[1] > 1 else 0],
                                 row_a[v[turning], chosen if row_a.shape[1] > 1 else 0])
        centripetal = plane_accel * curvature_share(arc_accel_factor)
        speed[at] = np.minimum(np.minimum(speed[at], vmax[at]), np.sqrt(centripetal * radius))
        # speeding up along the arc gets what the circle leaves of the in-plane acceleration
        accel[at] = np.minimum(accel[at], plane_accel - speed[at] ** 2 / radius)
