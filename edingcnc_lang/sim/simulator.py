"""What the three simulators (the box's height field, the lathe's bar, the bar on a rotary axis)
share as a run's ``on_move``/``on_event`` callbacks: the spindle's state (a cut with it stopped is a
finding), a tool change cutting what is queued with the tool that made it, the file and line of
every move (findings name them), and the snapshot hook ``ecnc view`` plays its frames from.
"""
from __future__ import annotations

from array import array
from collections.abc import Callable, Iterator
from dataclasses import dataclass
from typing import Generic, TypeVar

import numpy as np

from edingcnc_lang.canon import Batch, Event, Move, Pose
from edingcnc_lang.events import SpindleEvent, ToolChangeEvent
from edingcnc_lang.sim.findings import CutFinding
from edingcnc_lang.sim.queue import MoveQueue
from edingcnc_lang.sim.tools import Tool

StockT = TypeVar("StockT")


@dataclass
class SimOutcome(Generic[StockT]):
    """What every simulation gives (``SimResult``, ``BarResult``, ``CylinderResult`` add their own):
    the cut stock, the findings, the tools that cut, notes for the report, the seconds it took and
    the moves it heard."""

    stock: StockT
    findings: list[CutFinding]
    tools: dict[int, Tool]
    notes: list[str]
    seconds: float
    moves: int


class SimulatorBase(Generic[StockT]):
    """The shared part of a simulator; a simulator adds its tools (``change_tool``) and its cut (``flush``)."""

    def __init__(self, stock: StockT, width: int) -> None:
        self.stock = stock
        self.spindle_on = False
        self.queue = MoveQueue(width)  # the numbers of ``width`` a row of the simulator's cut reads
        self.lines = array("i")  # the line of each move, in program order
        self.files = array("h")  # the file of each move, an index into ``paths``
        self.paths: dict[str, int] = {}
        self.every = 0  # with ``on_snapshot``: cut and call it before every ``every``-th move
        self.on_snapshot: Callable[[int, StockT], None] | None = None

    def flush(self) -> None:
        """Cut what is queued."""
        raise NotImplementedError

    def change_tool(self, number: int) -> None:
        """Tool ``number`` is in the spindle now (what is queued is cut already)."""
        raise NotImplementedError

    def on_move(self, move: Move, joints: Pose) -> None:
        """Queue a move's cut (cutting what is queued once the queue is full)."""
        raise NotImplementedError

    def on_batch(self, batch: Batch) -> None:
        """A batch's moves: one ``on_move`` each, unless the simulator has a batch form of its own."""
        for move in batch.moves():
            self.on_move(move, move.end)

    @staticmethod
    def straight_runs(batch: Batch) -> Iterator[tuple[int, int]]:
        """A batch as (begin, stop): moves begin..stop-1 straight (maybe none), then move ``stop`` an arc
        (when ``stop`` is less than the batch's length), in order: what a batch form queues as arrays and
        what it hands to its ``on_move`` form."""
        begin = 0
        if batch.arcs is not None:
            for stop, arc in enumerate(batch.arcs):
                if arc is not None:
                    yield begin, stop
                    begin = stop + 1
        yield begin, len(batch)

    def queue_moves(self, rows: np.ndarray, moves: np.ndarray, codes: np.ndarray, ends: np.ndarray) -> None:
        """Queue the rows of consecutive moves (each row's move and code; move k's rows end at ``ends[k]``),
        cutting each time the queue is full: in the pieces ``on_move`` a move at a time would fill it with
        (what is cut at once decides the findings)."""
        done = 0  # moves queued
        while done < len(ends):
            taken = int(ends[done - 1]) if done else 0
            stop = min(max(int(np.searchsorted(ends, taken + self.queue.room, side="left")) + 1, done + 1), len(ends))
            upto = int(ends[stop - 1])
            self.queue.add_rows(rows[taken:upto], moves[taken:upto], codes[taken:upto])
            done = stop
            if self.queue.full:
                self.flush()

    def on_event(self, event: Event) -> None:
        if isinstance(event, SpindleEvent):
            self.spindle_on = event.m in (3, 4)
        elif isinstance(event, ToolChangeEvent):
            self.flush()
            self.change_tool(event.tool)

    def record(self, move: Move) -> int:
        """Note ``move``'s file and line (after a snapshot, when one is due); its index, in program order."""
        index = len(self.lines)
        if self.on_snapshot is not None and index % self.every == 0:
            self.flush()
            self.on_snapshot(index, self.stock)
        self.lines.append(move.line)
        self.files.append(self.paths.setdefault(move.path, len(self.paths)))
        return index

    def record_batch(self, batch: Batch) -> int:
        """Note the file and line of each of ``batch``'s moves, as ``record`` notes a move's (without snapshots:
        a simulator with ``on_snapshot`` takes a batch a move at a time); the index of its first move."""
        index = len(self.lines)
        self.lines.extend(batch.lines)
        self.files.extend([self.paths.setdefault(batch.path, len(self.paths))] * len(batch))
        return index

    def source(self, index: int) -> tuple[str, int]:
        """The file and line of the move at ``index``."""
        return list(self.paths)[self.files[index]], self.lines[index]
