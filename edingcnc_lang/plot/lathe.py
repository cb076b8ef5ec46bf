"""A turning job as the lathe hand reads it: the part's half section in the ZX plane, in work
coordinates (Z0 at the work zero), X labelled as a diameter on a diameter lathe.

A lathe's machine path is not the part: every tool has its own X and Z offset, so the same
diameter is cut at a different cross-slide position by each tool.  So a plot's run on a lathe
watches the work offset (G5x + G92 + the tool's G43 offsets) in force as each move reaches the
motion stage, and the picture draws every move through the offset it ran with.  ``plot --joints``
keeps the machine's view (the motors).
"""
from __future__ import annotations

from dataclasses import replace
from typing import TYPE_CHECKING, ClassVar

import numpy as np

from edingcnc_lang.canon import Arc, Batch, Canon, Move
from edingcnc_lang.events import Event
from edingcnc_lang.records import record
from edingcnc_lang.config.machine_config import MachineConfig
from edingcnc_lang.machine.state import MachineState
from edingcnc_lang.pipeline.base import Stage
from edingcnc_lang.runner import Run

if TYPE_CHECKING:
    from edingcnc_lang.plot.toolpath import Toolpath

@record(frozen=True, slots=True)
class WorkOffsetEvent(Event):
    """The plot run's own event (never in ``ecnc run``'s): the work offset (x, y, z) the moves after it
    are made under."""

    kind: ClassVar[str] = "work_offset"
    offset: tuple[float, float, float]


class OffsetWatch(Stage):
    """In front of the motion stage of a plot's run: before a move made under another work offset
    than the one before, an event with the new offset (events reach the recorder in order with the
    moves).  The stages in front hold no move across an offset change: G43, G92 and G10 are refused
    under cutter compensation."""

    def __init__(self, next_canon: Canon, config: MachineConfig, machine: MachineState) -> None:
        super().__init__(next_canon, config)
        self.machine = machine
        self.sent: tuple[float, ...] | None = None

    def _tell(self, path: str, line: int) -> None:
        x, y, z = self.machine.offset()[:3]
        offset = (x, y, z)
        if offset != self.sent:
            self.sent = offset
            self.next.event(WorkOffsetEvent(path, line, offset))

    def move(self, move: Move) -> None:
        self._tell(move.path, move.line)
        self.next.move(move)

    def move_batch(self, batch: Batch) -> None:
        if len(batch.lines):
            self._tell(batch.path, int(batch.lines[0]))
        self.next.move_batch(batch)


def watch_offsets(run: Run) -> None:
    """Put an ``OffsetWatch`` between the run's last stage and its motion stage."""
    last = run.pipeline.stages[-1]
    last.next = OffsetWatch(last.next, run.config, run.interpreter)


def in_work(path: Toolpath) -> Toolpath:
    """A lathe's path (one with ``offsets``) in work coordinates, any other as it is."""
    return part_view(path) if path.offsets is not None else path


def part_view(path: Toolpath) -> Toolpath:
    """``path`` in work coordinates: each move less the offset it ran with (X a radius; the
    picture labels it as a diameter on a diameter lathe), the work zero at 0, no machine box."""
    assert path.offsets is not None
    shift = np.zeros((len(path), 6))
    shift[:, :3] = path.offsets
    arcs = {i: _arc_shifted(arc, path.offsets[i]) for i, arc in path.arcs.items()}
    return replace(path, starts=path.starts - shift, ends=path.ends - shift, arcs=arcs,
                   work_zero=(0.0, 0.0, 0.0), limits=None, offsets=None, part=True)


def _arc_shifted(arc: Arc, offset: np.ndarray) -> Arc:
    axes = ["XYZ".index(a) for a in arc.plane]
    center = (arc.center[0] - float(offset[axes[0]]), arc.center[1] - float(offset[axes[1]]))
    return Arc(center, arc.plane, arc.turn, arc.full_turns)
