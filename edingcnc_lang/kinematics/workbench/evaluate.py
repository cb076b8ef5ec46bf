"""Calling a plug-in pose by pose, so one bad pose is recorded instead of ending the check.

Every call's outcome is a status: reached, out of reach (KinematicsDomainError), another exception,
or non-finite numbers returned.  Scalar calls are used on purpose: a batch call stops at its first
unreachable sample, and a proof needs the answer for every sample.
"""
from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass, field
from enum import IntEnum

import numpy as np

from edingcnc_lang.kinematics.base import PLUGIN_FAILURES, KinematicsDomainError, Pose


class Status(IntEnum):
    OK = 0
    UNREACHABLE = 1
    RAISED = 2
    NON_FINITE = 3


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


def call_each(fn: Callable[[Pose], Pose], rows: np.ndarray) -> Outcome:
    """``fn`` on every row of ``rows``; each exception is recorded, never raised."""
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
    return Outcome(values, status, messages)
