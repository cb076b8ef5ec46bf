"""The stage that stands in for the planner when nothing reads time: moves pass straight through.

A run whose outputs never read a move's time (no ``--json``, trace, samples, events, summary
line or ``on_timed_move``; ``RunOptions(plan=False)``) has nothing to plan for, so it does not
load numpy and the planner's model at all: a three-line job starts as fast as one that only
computes.  The machine-side behaviour is unchanged: override events still set the knobs the
motion stage reads; ``on_move``/``on_event`` are called before this stage (motion/callback_tap.py).
See docs/planner.md ("When the planner runs").
"""
from __future__ import annotations

import math
from typing import TYPE_CHECKING

from edingcnc_lang.canon import Batch, Event, Move, Pose
from edingcnc_lang.events import OverrideEvent
from edingcnc_lang.motion.planner.overrides import Overrides

if TYPE_CHECKING:
    from edingcnc_lang.motion.arc_table import ArcTable
    from edingcnc_lang.motion.stage import AxisLimits, PlainLimits, Samples


class Untimed:
    """Hands every move and event on at once; keeps no estimate and no limits report."""

    needs_limits = False  # the motion stage need not work out what a move is timed against

    def __init__(self, overrides: Overrides) -> None:
        self.overrides = overrides

    def move(self, move: Move, joints: Pose, samples: Samples | None,
             limits: AxisLimits | PlainLimits | None,
             cap: float = math.inf, accel_cap: float = math.inf) -> None:
        """Nothing to time: the embedding program's callbacks heard the move already (motion/callback_tap.py)."""

    def move_batch(self, batch: Batch, limits: dict[str, PlainLimits] | None, arcs: ArcTable | None = None) -> None:
        """As ``move``, for a batch."""

    def event(self, event: Event) -> None:
        if isinstance(event, OverrideEvent):
            self.overrides.apply(event)

    def flush(self) -> None:
        """Nothing is held back."""

    def close(self) -> None:
        """Nothing to close: the output files all read time, so they go with the planner."""
