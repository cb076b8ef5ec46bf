"""Time-true samples: where the machine is every ``interpolationTime`` along the planned profile.

Samples fall on the global grid t = k * dt from the job start (so a move that starts between two
ticks has its first sample at the next tick), plus the end point of every move the machine stops
after, so that rests and exact-stop corners are in the file.  Each sample carries the path speed
and acceleration of the profile there.
"""
from __future__ import annotations

import math
from collections.abc import Callable, Iterator
from typing import TYPE_CHECKING

import numpy as np

from edingcnc_lang.kinematics.sampling import arc_points
from edingcnc_lang.kinematics.trajectory import Geometry
from edingcnc_lang.motion.planner.profile import Profiles, distance_at

if TYPE_CHECKING:
    from edingcnc_lang.motion.arc_table import ArcTable
    from edingcnc_lang.motion.stage import Samples

_GRID_SLACK = 1e-9  # a tick this close (in dt) to a move's end counts as on it


def time_true_samples(starts: np.ndarray, ends: np.ndarray, arcs: ArcTable, moving: np.ndarray,
                      planned: Profiles, t_end: np.ndarray, duration: np.ndarray, dt: float,
                      joints_of: Callable[[np.ndarray], np.ndarray]) -> Iterator[Samples | None]:
    """Samples of committed moves ``0..len(t_end)-1`` (``starts``/``ends`` as columns), in order, None for
    moves that take no time.  They are made one move at a time as the sinks take them, so a window of
    long moves (eight 50-minute moves are millions of samples) is never held whole.

    ``moving[k]`` is the move whose profile is ``planned``'s entry k (moves of zero length have none).
    """
    from edingcnc_lang.motion.stage import Samples

    profile_of = {index: k for k, index in enumerate(moving.tolist())}
    arc_of = {index: k for k, index in enumerate(arcs.index.tolist())}
    for index in range(len(t_end)):
        k = profile_of.get(index)
        if k is None:
            yield None
            continue
        stop_after = planned.v1[k] == 0.0
        t1 = float(t_end[index])
        t0 = t1 - float(duration[index])
        first = math.floor(t0 / dt + _GRID_SLACK) + 1
        last = math.floor(t1 / dt + _GRID_SLACK)
        times = np.arange(first, last + 1, dtype=float) * dt
        if stop_after and (not len(times) or times[-1] < t1 - _GRID_SLACK * dt):
            times = np.append(times, t1)
        if not len(times):
            yield None
            continue
        tau = np.minimum(times - t0, float(duration[index]))
        dist, speed, accel = distance_at(planned, np.full(len(times), k), tau)
        length = planned.length[k]
        fraction = np.where(times >= t1, 1.0, dist / length if length > 0.0 else 1.0)  # the end point exactly
        start, end, arc = tuple(starts[:, index].tolist()), tuple(ends[:, index].tolist()), arc_of.get(index)
        pos = Geometry(start, end).points_at(fraction) if arc is None else \
            arc_points(start, end, arcs.frame(arc), fraction)
        yield Samples(times, pos, joints_of(pos), speed=speed, accel=accel)
