"""The stage that stands in for the planner when nothing reads time: moves pass straight through.

A run whose outputs never read a move's time (no ``--json``, trace, samples, events, summary
line or ``on_timed_move``; ``RunOptions(plan=False)``) has nothing to plan for, so it does not
load numpy and the planner's model at all: a three-line job starts as fast as one that only
computes.  The machine-side behaviour is unchanged: override events still set the knobs the
motion stage reads, and moves and events reach ``on_move``/``on_event`` in program order.
See docs/planner.md ("When the planner runs").
"""
from __future__ import annotations

import math
from collections.abc import Callable
from typing import TYPE_CHECKING

from edingcnc_lang.canon import Batch, Event, Move, Pose
from edingcnc_lang.events import OverrideEvent
from edingcnc_lang.motion.planner.overrides import Overrides

if TYPE_CHECKING:
    from edingcnc_lang.motion.arc_table import ArcTable
    from edingcnc_lang.motion.stage import AxisLimits, Samples


class Untimed:
    """Hands every move and event on at once; keeps no estimate and no limits report."""

    needs_limits = False  # the motion stage need not work out what a move is timed against

    def __init__(self, overrides: Overrides, on_move: Callable[[Move, Pose], None] | None = None,
                 on_event: Callable[[Event], None] | None = None) -> None:
        self.overrides = overrides
        self.on_move = on_move
        self.on_event = on_event

    def move(self, move: Move, joints: Pose, samples: Samples | None, limits: AxisLimits | None,
             cap: float = math.inf, accel_cap: float = math.inf) -> None:
        if self.on_move:
            self.on_move(move, joints)

    def move_batch(self, batch: Batch, limits: dict[str, AxisLimits] | None, arcs: ArcTable | None = None) -> None:
        if not self.on_move:
            return
        for move in batch.moves():
            self.on_move(move, move.end)

    def event(self, event: Event) -> None:
        if isinstance(event, OverrideEvent):
            self.overrides.apply(event)
        if self.on_event:
            self.on_event(event)

    def flush(self) -> None:
        """Nothing is held back."""

    def close(self) -> None:
        """Nothing to close: the output files all read time, so they go with the planner."""
