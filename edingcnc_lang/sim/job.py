"""Run a job and cut its moves into the stock: the simulation as one call, ``simulate``.

The moves come through the embedding API (``RunOptions(on_move=..., on_event=...)``, unplanned, so
each arrives as the interpreter makes it); each is turned into the path of the tool's tip in the
frame of the stock (the job's first work offset, less the tool length in force), arcs cut into
chords no further than a quarter cell from the circle, and queued.  The queue is swept into the
height field a batch at a time (``sweep.sweep``); a tool change sweeps it first.  The spindle's
state comes from the ``spindle`` events (M3/M4 on, M5 off), the tool in the spindle from
``tool_change`` events.
"""
from __future__ import annotations

import math
import time
from dataclasses import dataclass, replace
from collections.abc import Callable
from typing import Any
from pathlib import Path

import numpy as np

from edingcnc_lang.machine import tables as t
from edingcnc_lang.canon import Batch, Event, Move, Pose
from edingcnc_lang.config.machine_config import MachineConfig
from edingcnc_lang.errors import EcncError
from edingcnc_lang.kinematics.sampling import arc_points
from edingcnc_lang.kinematics.trajectory import geometry_of
from edingcnc_lang.runner import Run, RunOptions, RunResult
from edingcnc_lang.sim.simulator import SimOutcome, SimulatorBase
from edingcnc_lang.sim.findings import CutFinding, merged
from edingcnc_lang.sim.stock import Stock
from edingcnc_lang.sim.sweep import CODE_KINDS, EPS, NONE, PLUNGE, RAPID, SPINDLE_OFF, Hits, Segments, sweep
from edingcnc_lang.sim.tools import Tool, ini_tool

PLUNGE_SHARE = 0.5      # a flat tool may plunge this many diameters into the material at once
OUTSIDE = 99            # finding code of a move below the stock's bottom (found here, not in the sweep)
CUTTING_KINDS = frozenset({"rapid", "linear", "arc", "home"})  # probe moves touch, they do not cut


@dataclass
class SimResult(SimOutcome[Stock]):
    """The cut stock, the findings and what the run left; ``error`` when the job stopped early."""

    run: RunResult | None = None
    error: EcncError | None = None
    frame: tuple[float, float, float] = (0.0, 0.0, 0.0)  # machine coordinates of the stock's origin

    @property
    def shank_checked(self) -> bool:
        return all(t.flute_length is not None for t in self.tools.values())


class Simulator(SimulatorBase[Stock]):
    """The ``on_move``/``on_event`` callbacks of a simulated run; ``attach`` it to the ``Run``."""

    def __init__(self, stock: Stock, config: MachineConfig, tools: dict[int, Tool] | None = None,
                 first_tool: int = 0) -> None:
        super().__init__(stock, 6)  # a segment's two ends: ax ay az bx by bz
        self.config = config
        self.table = tools
        self.ceiling = float(stock.top.max())
        self.known: dict[int, tuple[Tool, str]] = {}  # tool number -> the tool and a note on where it came from
        self.used: dict[int, Tool] = {}  # the tools that swept anything
        self.tool = self._tool(first_tool)
        self.hits: list[tuple[Hits, int]] = []
        self.frame: tuple[float, float, float] | None = None
        self.chord = stock.resolution / 4.0
        self._offset = lambda: (0.0, 0.0, 0.0, 0.0)  # frame x, y, z and the tool length in force

    def attach(self, run: Run) -> None:
        """Read the work offset and the tool length from the run's interpreter as each move arrives."""
        interp = run.interpreter

        def offset() -> tuple[float, float, float, float]:
            off = interp.offset()
            return off[0], off[1], off[2] - interp.offsets.tool_z, interp.offsets.tool_z
        self._offset = offset

    def _tool(self, number: int) -> Tool:
        if number not in self.known:
            note = ""
            if self.table is not None and number in self.table:
                tool = self.table[number]
                if tool.flute_length is None:
                    note = (f"T{number} has no flute_length in the tools file: its shank and holder "
                            "collisions are not checked")
            else:
                tool = ini_tool(self.config, number)
                if self.table is not None:
                    note = (f"T{number} is not in the tools file: the ini's diameter ({tool.diameter:g} mm) "
                            "as a flat end mill, flute length unknown")
                if tool.source == "default":
                    note = (f"T{number} has no diameter in the ini's tool table: simulated as a "
                            f"{tool.diameter:g} mm flat end mill")
            self.known[number] = (tool, note)
        return self.known[number][0]

    @property
    def notes(self) -> list[str]:
        """What the report should say about the tools that cut: those not described as asked."""
        return [self.known[n][1] for n in sorted(self.used) if self.known[n][1]]

    def change_tool(self, number: int) -> None:
        self.tool = self._tool(number)

    def on_move(self, move: Move, _joints: Pose) -> None:
        index = self.record(move)
        if move.kind not in CUTTING_KINDS:
            return
        shift = self._shift()
        self._queue_move(move, index, self._code(move.kind, move.start, move.end), shift)

    def on_batch(self, batch: Batch) -> None:
        """A batch's moves, as ``on_move`` takes them one by one: its straight moves' rows and codes as arrays,
        queued in pieces that fill the queue exactly when ``on_move``'s would (a cut's findings depend on
        what it cuts at once), its arcs a move at a time."""
        if self.on_snapshot is not None:  # the viewer's frames: a cut and a snapshot before every every-th move
            for move in batch.moves():
                self.on_move(move, move.end)
            return
        first = self.record_batch(batch)  # (a batch holds rapids, feed moves and arcs: all of them cut)
        shift = np.array(self._shift())
        count = len(batch)
        ends = np.array(batch.ends, dtype=float)[:, :3]
        starts = np.vstack((np.array(batch.start[:3], dtype=float), ends[:-1]))
        codes = self._codes(np.array([kind == "rapid" for kind in batch.kinds]), starts, ends)
        rows = np.hstack((starts - shift, ends - shift))
        for begin, stop in self.straight_runs(batch):
            self.queue_moves(rows[begin:stop], np.arange(first + begin, first + stop), codes[begin:stop],
                             np.arange(1, stop - begin + 1))  # (a row each)
            if stop < count:  # an arc
                start = batch.ends[stop - 1] if stop else batch.start
                self._queue_move(batch.move(stop, start), first + stop, int(codes[stop]), tuple(shift.tolist()))

    def _shift(self) -> tuple[float, float, float]:
        """Machine coordinates of the stock's origin less the tool length in force: a move's tip in the stock's
        frame is its point less this (the frame is the job's first work offset, set at its first move)."""
        ox, oy, oz, length = self._offset()
        if self.frame is None:
            self.frame = (ox, oy, oz)
        fx, fy, fz = self.frame
        return fx, fy, fz + length

    def _code(self, kind: str, start: Pose, end: Pose) -> int:
        """The finding code a move's cut is checked with: a rapid, a feed with the spindle off, a flat tool's
        plunge (straight down), else none."""
        if kind in ("rapid", "home"):
            return RAPID
        if not self.spindle_on:
            return SPINDLE_OFF
        if self.tool.shape == "flat" and end[2] < start[2] and start[0] == end[0] and start[1] == end[1]:
            return PLUNGE
        return NONE

    def _codes(self, rapid: np.ndarray, starts: np.ndarray, ends: np.ndarray) -> np.ndarray:
        """``_code`` of moves at once: ``rapid`` which are rapids, ``starts`` and ``ends`` their X Y Z."""
        codes = np.full(len(rapid), NONE if self.spindle_on else SPINDLE_OFF, dtype=np.int8)
        if self.spindle_on and self.tool.shape == "flat":
            plunge = (ends[:, 2] < starts[:, 2]) & (starts[:, 0] == ends[:, 0]) & (starts[:, 1] == ends[:, 1])
            codes[plunge] = PLUNGE
        codes[rapid] = RAPID
        return codes

    def _queue_move(self, move: Move, index: int, code: int, shift: tuple[float, float, float]) -> None:
        """Queue a move's rows (a straight move's segment, an arc's chords) in the stock's frame; cut when full."""
        fx, fy, fz = shift
        start, end = move.start, move.end
        if move.arc is None:
            self.queue.add((start[0] - fx, start[1] - fy, start[2] - fz, end[0] - fx, end[1] - fy, end[2] - fz),
                           index, code)
        else:
            points = self._chords(move) - (fx, fy, fz)
            self.queue.add(np.hstack((points[:-1], points[1:])).ravel().tolist(), index, code)
        if self.queue.full:
            self.flush()

    def _chords(self, move: Move) -> np.ndarray:
        return chords(move, self.chord)

    def flush(self) -> None:
        """Sweep what is queued, with the tool in the spindle now."""
        if not len(self.queue):
            return
        rows, moves, codes = self.queue.take()
        segs = Segments(rows[:, :3], rows[:, 3:], moves, codes)
        low = np.minimum(segs.a[:, 2], segs.b[:, 2])
        if not (low < self.ceiling).any():  # all above the material: nothing to cut, nothing to hit
            return
        tool = self.used[self.tool.number] = self.tool
        self.hits.append((sweep(self.stock, tool, segs, PLUNGE_SHARE * tool.diameter, self.ceiling), tool.number))
        # a move that climbs out from below the bottom was told of when it went down there
        below = np.flatnonzero((low < self.stock.bottom - EPS) & (segs.b[:, 2] <= segs.a[:, 2] + EPS))
        if len(below):
            deepest = np.where((segs.a[below, 2] <= segs.b[below, 2])[:, None], segs.a[below], segs.b[below])
            self.hits.append((Hits(segs.move[below], np.full(len(below), OUTSIDE, np.int8),
                                   self.stock.bottom - low[below], deepest), tool.number))

    def findings(self) -> list[CutFinding]:
        """Every hit as a finding, merged (see ``findings.merged``)."""
        found = []
        for hits, tool in self.hits:
            for move, code, depth, where in zip(hits.move.tolist(), hits.code.tolist(), hits.depth.tolist(),
                                                hits.where.tolist()):
                kind = "outside_stock" if code == OUTSIDE else CODE_KINDS[code]
                found.append(CutFinding(kind, *self.source(move), tuple(where),
                                     depth, tool, move))
        return merged(found)


def chords(move: Move, chord: float) -> np.ndarray:
    """The arc's points (X, Y, Z), chords at most ``chord`` from the circle (helices and every plane)."""
    frame = geometry_of(move).frame
    radius = max(frame.r0, frame.r1, 1e-9)
    step = 2.0 * math.acos(max(1.0 - chord / radius, -1.0))
    count = max(2, math.ceil(abs(frame.sweep) / max(step, 1e-6)))
    return arc_points(move.start, move.end, frame, np.linspace(0.0, 1.0, count + 1))[:, :3]


def drive(job: str | Path, options: RunOptions | None, name: str | None,
          make: Callable[[Run], Any]) -> tuple[Any, RunResult | None, EcncError | None]:
    """Run ``job`` with the simulator ``make(run)`` returns fed every move and event first (its
    ``on_move``/``on_event``; callbacks already in ``options`` still get them); a runtime error is
    returned, one before anything ran (syntax, configuration) raised."""
    options = options or RunOptions()
    outer_move, outer_event, outer_batch = options.on_move, options.on_event, options.on_batch
    holder: list[Any] = []

    def on_move(move: Move, joints: Pose) -> None:
        holder[0].on_move(move, joints)
        if outer_move:
            outer_move(move, joints)

    def on_batch(batch: Batch) -> None:
        holder[0].on_batch(batch)
        if outer_batch:
            outer_batch(batch)
        elif outer_move:
            for move in batch.moves():
                outer_move(move, move.end)

    def on_event(event: Event) -> None:
        holder[0].on_event(event)
        if outer_event:
            outer_event(event)

    run = Run(replace(options, on_move=on_move, on_event=on_event, plan=False,
                      on_batch=on_batch if options.on_timed_move is None else None))
    holder.append(make(run))
    result: RunResult | None = None
    error: EcncError | None = None
    try:
        result = run.execute_file(Path(job), name)
    except EcncError as err:
        if getattr(err, "result", None) is None:  # nothing ran: syntax, configuration
            raise
        error = err
    return holder[0], result, error


def simulate(job: str | Path, stock: Stock, options: RunOptions | None = None,
             tools: dict[int, Tool] | None = None, first_tool: int | None = None,
             name: str | None = None, every: int = 0,
             on_snapshot: Callable[[int, Stock], None] | None = None) -> SimResult:
    """Run ``job`` and cut the stock with it; a runtime error is kept in ``SimResult.error``.

    ``tools`` (from ``tools.load_tools``) give the cutters their shapes; without them each tool is
    the ini's diameter as a flat end mill with unknown flute length.  ``first_tool`` is the tool in
    the spindle when the job starts (default: the machine's current tool, #5008).  Callbacks
    already in ``options`` still receive every move and event.  ``on_snapshot(move, stock)`` is
    called with the stock as cut before move 0, ``every``, 2 ``every``, ... (the viewer's frames).
    """
    started = time.perf_counter()

    def make(run: Run) -> Simulator:
        first = int(run.interpreter.params.read(t.TOOL_CURRENT)) if first_tool is None else first_tool
        made = Simulator(stock, run.config, tools, first)
        made.attach(run)
        if on_snapshot is not None:
            made.every, made.on_snapshot = max(1, every), on_snapshot
        return made

    sim, result, error = drive(job, options, name, make)
    sim.flush()
    notes = list(sim.notes)
    if tools is None:
        notes.append("no --tools file: each tool is the ini's diameter as a flat end mill with unknown "
                     "flute length, so shank and holder collisions are not checked")
    return SimResult(stock, sim.findings(), dict(sim.used), notes, time.perf_counter() - started,
                     len(sim.lines), result, error, sim.frame or (0.0, 0.0, 0.0))
