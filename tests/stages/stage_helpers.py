"""A canon that records what reaches it, to test stages alone."""
from __future__ import annotations

from importlib import import_module
from typing import Any

import pytest

from edingcnc_lang.canon import Batch, Event, Move, Pose
from edingcnc_lang.pipeline import comp_runs

try:  # the compiled core, also where ECNC_PURE_PYTHON=1 runs the suite on the Python one
    COMPILED: Any = import_module("edingcnc_lang._speedups")
except ImportError:
    COMPILED = None
NOT_BUILT = "the compiled core is not built here"
# compensation's loop over a run of corners: the Python one and the compiled one (pipeline/comp_runs.py)
LOOPS = [pytest.param(comp_runs.comp_lines, id="python"),
         pytest.param(getattr(COMPILED, "comp_lines", None), id="compiled",
                      marks=pytest.mark.skipif(COMPILED is None, reason=NOT_BUILT))]

ZERO: Pose = (0.0,) * 6


def pose(x: float = 0.0, y: float = 0.0, z: float = 0.0) -> Pose:
    return (x, y, z, 0.0, 0.0, 0.0)


def line(x0: float, y0: float, x1: float, y1: float, number: int = 1, feed: float = 100.0) -> Move:
    return Move("linear", "job.nc", number, pose(x0, y0), pose(x1, y1), feed)


def batch(start: Pose, *items: tuple[str, int, Pose, float], path: str = "job.nc") -> Batch:
    """A batch of straight moves from (kind, line, end, feed) items."""
    kinds, lines, ends, feeds = (list(column) for column in zip(*items)) if items else ([], [], [], [])
    return Batch(path, start, kinds, lines, ends, feeds)  # type: ignore[arg-type]


class Recorder:
    """Records moves, bulk batches, events and kinematics calls as tuples, in arrival order."""

    def __init__(self) -> None:
        self.log: list[tuple[object, ...]] = []

    def move(self, move: Move) -> None:
        self.log.append(("move", move))

    def move_batch(self, batch: Batch) -> None:
        self.log.append(("batch", batch))

    def event(self, event: Event) -> None:
        self.log.append(("event", event.kind))

    def kinematics(self, mode: str, args: tuple[float, ...], pos: Pose, path: str, line: int) -> Pose:
        self.log.append(("kinematics", mode))
        return pos

    def moves(self) -> list[Move]:
        moves: list[Move] = []
        for entry in self.log:
            if entry[0] == "move":
                moves.append(entry[1])  # type: ignore[arg-type]
            elif entry[0] == "batch":
                moves.extend(entry[1].moves())  # type: ignore[attr-defined]
        return moves
