"""Calling a plug-in pose by pose, so one bad pose is recorded instead of ending the check.

Every call's outcome is a status: reached, out of reach (KinematicsDomainError), another exception,
non-finite numbers returned, or (given the ini's joint limits) joints the machine cannot take.  Scalar calls are used on purpose: a batch call stops at its first
unreachable sample, and a proof needs the answer for every sample.
"""
from __future__ import annotations

from collections.abc import Callable, Sequence
from dataclasses import dataclass, field
from enum import IntEnum

import numpy as np

from edingcnc_lang.canon import AXES
from edingcnc_lang.kinematics.base import PLUGIN_FAILURES, KinematicsDomainError, Pose


class Status(IntEnum):
    OK = 0
    UNREACHABLE = 1
    RAISED = 2
    NON_FINITE = 3
    JOINT_LIMIT = 4  # the plug-in reaches it, but a joint would be beyond its [JOINT_n] limits


JOINT_SLACK = 1e-9  # mm or degrees beyond a joint limit that still counts as on it (as a run counts)


@dataclass
class Outcome:
    """(N, 6) values (NaN where the call gave none), a status per row, the first message per status."""

    values: np.ndarray
    status: np.ndarray
    messages: dict[int, str] = field(default_factory=dict)

    @property
    def ok(self) -> np.ndarray:
        return self.status == Status.OK

    def first(self, status: Status) -> int | None:
        hits = np.flatnonzero(self.status == status)
        return int(hits[0]) if len(hits) else None


def call_each(fn: Callable[[Pose], Pose], rows: np.ndarray,
              joint_limits: Sequence[tuple[float, float]] | None = None) -> Outcome:
    """``fn`` on every row of ``rows``; each exception is recorded, never raised.

    With ``joint_limits`` (an inverse's output, the ini's ``[JOINT_n]`` limits) a row whose joints
    fall outside them is JOINT_LIMIT: a run refuses such a pose, so it is not reachable there.
    """
    values = np.full((len(rows), 6), np.nan)
    status = np.zeros(len(rows), dtype=np.int8)
    messages: dict[int, str] = {}
    for i, row in enumerate(rows):
        pose = (float(row[0]), float(row[1]), float(row[2]), float(row[3]), float(row[4]), float(row[5]))
        try:
            out = np.asarray(fn(pose), dtype=float)
        except KinematicsDomainError as err:
            status[i] = Status.UNREACHABLE
            messages.setdefault(Status.UNREACHABLE, err.message)
            continue
        except PLUGIN_FAILURES as err:  # the plug-in is under test: any failure is a finding, not a crash
            status[i] = Status.RAISED
            messages.setdefault(Status.RAISED, f"{type(err).__name__}: {err}")
            continue
        if out.shape != (6,):
            status[i] = Status.RAISED
            messages.setdefault(Status.RAISED, f"returned {out.size} values instead of 6")
            continue
        values[i] = out
        if not np.isfinite(out).all():
            status[i] = Status.NON_FINITE
        elif joint_limits is not None:
            beyond = _beyond(out, joint_limits)
            if beyond is not None:
                status[i] = Status.JOINT_LIMIT
                messages.setdefault(Status.JOINT_LIMIT, beyond)
    return Outcome(values, status, messages)


def _beyond(joints: np.ndarray, limits: Sequence[tuple[float, float]]) -> str | None:
    """What the first joint outside its limits would be, as a run says it; None if all are inside."""
    for axis, (value, (low, high)) in enumerate(zip(joints, limits)):
        if not low - JOINT_SLACK <= value <= high + JOINT_SLACK:
            return (f"joint {AXES[axis]} would be at {value:.4f}, outside its limits [{low:g}, {high:g}] "
                    f"([JOINT_{axis}])")
    return None
