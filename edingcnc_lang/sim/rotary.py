"""A mill with a rotary axis cutting a bar: ``simulate_cylinder``.

The bar turns with A about X (along X from X0 to X0 + LENGTH, its axis through work Y0 Z0), or
with B about Y where the ini shows B and hides A (along Y from Y0, its axis through work X0 Z0).
A point of the bar at its own angle θ (degrees) stands at θ + A in the machine, measured about X
from +Y towards +Z (for B: about Y from -X towards +Z, both right-handed); so the tool, pointing
down -Z, works at machine angle 90°.  The tool's pose is the machine's joints (the motion stage's
inverse kinematics of each move, so a plug-in or a ``KIN`` mapping that moves other motors than
the job names is honoured), less the work offset and tool length in force as the move arrives.
Each move is sampled so that neither the linear joints move more than a slice nor the rotary one
more than an angle cell between samples (indexed and simultaneous 4-axis moves alike), and at each
sample every part of the tool (``rotary_stamp.py``: the cutter with its shape, the shank and the
holder) is stamped into the bar: along the ray from the axis through each (slice, angle) cell it
covers an interval of radii, which ``RoundStock.cut`` takes as it takes a lathe insert's.
"""
from __future__ import annotations

import math
import time
from array import array
from collections.abc import Callable, Sequence
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from edingcnc_lang.canon import Batch, Move, Pose
from edingcnc_lang.config.machine_config import MachineConfig
from edingcnc_lang.errors import EcncError, Location
from edingcnc_lang.machine import tables as t
from edingcnc_lang.runner import Run, RunOptions, RunResult
from edingcnc_lang.sim.simulator import SimOutcome, SimulatorBase
from edingcnc_lang.sim.findings import CutFinding, merged
from edingcnc_lang.sim.job import CUTTING_KINDS, chords, drive
from edingcnc_lang.sim.round_stock import EPS, RoundStock
from edingcnc_lang.sim.stock import StockError
from edingcnc_lang.sim.rotary_stamp import CUT, HOLDER, RAPID, SHANK, SPINDLE_OFF, extent, parts_of, stamps
from edingcnc_lang.sim.tools import Tool, ini_tool
from edingcnc_lang.sim.turning import CHUNK

KIND_OF_CODE = {RAPID: "rapid_into_stock", SPINDLE_OFF: "spindle_off", SHANK: "shank", HOLDER: "holder"}


@dataclass(frozen=True)
class RotaryAxis:
    """The rotary axis the bar turns with: ``A`` (about X, the bar along X) or ``B`` (about Y)."""

    letter: str = "A"

    def __post_init__(self) -> None:
        if self.letter not in ("A", "B"):
            raise ValueError(f"the bar turns with A (about X) or B (about Y), not {self.letter!r}")

    @property
    def joint(self) -> int:
        """Its index among X Y Z A B C."""
        return 4 if self.letter == "B" else 3

    def frame(self, row: Sequence[float], off: Sequence[float]) -> tuple[float, float, float, float]:
        """Joints (machine X Y Z A B C) as a pose in the bar's frame: axial, p, q of the tip, angle."""
        if self.letter == "B":
            return row[1] - off[1], off[0] - row[0], row[2] - off[2], row[4] - off[4]
        return row[0] - off[0], row[1] - off[1], row[2] - off[2], row[3] - off[3]

    def frames(self, rows: np.ndarray, off: Sequence[float]) -> np.ndarray:
        """``frame`` of many rows of joints at once (N x 6 -> N x 4), the very same numbers."""
        if self.letter == "B":
            return np.column_stack((rows[:, 1] - off[1], off[0] - rows[:, 0], rows[:, 2] - off[2], rows[:, 4] - off[4]))
        return np.column_stack((rows[:, 0] - off[0], rows[:, 1] - off[1], rows[:, 2] - off[2], rows[:, 3] - off[3]))

    def work(self, pose: Sequence[float]) -> tuple[float, float, float]:
        """The work X Y Z of a pose of the bar's frame (a finding's position)."""
        axial, p, q = float(pose[0]), float(pose[1]), float(pose[2])
        return (-p, axial, q) if self.letter == "B" else (axial, p, q)


def rotary_axis(config: MachineConfig) -> RotaryAxis:
    """B about Y when the ini shows B and hides A (``[KINEMATICS] aVisible``/``bVisible``, the
    joints' ``visible``), else A about X."""
    def shown(letter: str, joint: int) -> bool:
        try:
            visible = float(config.kinematics_settings.get(f"{letter}visible", "1")) != 0.0
        except ValueError:  # not a number: the setting says nothing
            visible = True
        return config.joints[joint].visible and visible

    return RotaryAxis("B" if shown("b", 4) and not shown("a", 3) else "A")


@dataclass
class CylinderResult(SimOutcome[RoundStock]):
    """The cut bar, the findings and what the run left; ``error`` when the job stopped early."""

    run: RunResult | None = None
    error: EcncError | None = None
    axis: str = "A"  # the rotary axis the bar turned with: A (along X) or B (along Y)
    tips: np.ndarray | None = None  # with ``tips=True``: (moves, 2) axial position and bar angle of each move's end


class CylinderSimulator(SimulatorBase[RoundStock]):
    """The ``on_move``/``on_batch``/``on_event`` callbacks stamping a mill's tool into a bar on its rotary axis."""

    def __init__(self, stock: RoundStock, run: Run, tools: dict[int, Tool] | None, first_tool: int,
                 axis: RotaryAxis | None = None) -> None:
        super().__init__(stock, 4)  # axial, p, q of the tool tip and the bar's angle, per sample
        self.run = run
        self.axis = axis or rotary_axis(run.config)
        self.table = tools
        self.tool = self._tool(first_tool)
        self.used: dict[int, Tool] = {}
        self.found: list[CutFinding] = []
        self.last: tuple[float, ...] | None = None  # the pose the queue ends at
        self.steps = (stock.angle_step(), stock.resolution)  # the most a sample may turn and move
        self.tips: array[float] | None = None  # with tips: axial position, bar angle of each move's end

    def _tool(self, number: int) -> Tool:
        if self.table is not None and number in self.table:
            return self.table[number]
        return ini_tool(self.run.config, number)

    def change_tool(self, number: int) -> None:
        self.last = None
        self.tool = self._tool(number)

    def on_move(self, move: Move, _joints: Pose) -> None:
        index = self.record(move)
        if move.kind not in CUTTING_KINDS:
            if self.tips is not None:  # a probe move: the tool stays where the last move left it
                self.tips.extend(self.tips[-2:] if len(self.tips) else (math.nan, math.nan))
            return
        self._queue_move(move, index)

    def _queue_move(self, move: Move, index: int) -> None:
        """Queue the samples of a cutting move (the ``index``-th) in the bar's frame; cut once the queue is full."""
        off = self.run.interpreter.offset()  # Z holds the tool length: the tip's Z
        code = RAPID if move.kind in ("rapid", "home") else CUT if self.spindle_on else SPINDLE_OFF
        rows: list[Sequence[float]]
        if move.arc is None:
            rows = [move.start, move.end]
        else:
            points = chords(move, self.stock.resolution / 4.0).tolist()
            count = len(points) - 1
            rows = [(*p, *(s + (e - s) * k / count for s, e in zip(move.start[3:], move.end[3:])))
                    for k, p in enumerate(points)]
        if not self.run.motion.joints_are_position:  # the kinematics' joints along the move, finely
            dense = [*rows[0], *self._fill([(*r[:3], r[self.axis.joint]) for r in rows], rows)]
            try:
                rows = self.run.motion.joints_at(np.array(dense).reshape(-1, 6)).tolist()
            except EcncError as err:  # a pose between the machine's own samples it cannot reach
                err.location = err.location or Location(move.path, move.line)
                raise
        poses = [self.axis.frame(r, off) for r in rows]
        samples = self._fill(poses, poses) if self.last == poses[0] else [*poses[0], *self._fill(poses, poses)]
        self.last = poses[-1]
        if self.tips is not None:
            self.tips.extend((self.last[0], bar_angle(self.last)))
        self.queue.add(samples, index, code)
        if self.queue.full:
            self.flush()

    def on_batch(self, batch: Batch) -> None:
        """A batch's moves, as ``on_move`` takes them one by one: the straight moves' samples and codes as
        arrays, queued in pieces that fill the queue exactly when ``on_move``'s would (what is cut at once
        decides the findings), its arcs a move at a time.  The viewer's frames and tips, and kinematics whose
        joints are not the position, take the batch a move at a time."""
        if self.on_snapshot is not None or self.tips is not None or not self.run.motion.joints_are_position:
            super().on_batch(batch)
            return
        first = self.record_batch(batch)
        count = len(batch)
        if not count:
            return
        off = self.run.interpreter.offset()
        poses = self.axis.frames(np.array([batch.start, *batch.ends], dtype=float), off)
        code = np.array([RAPID if kind == "rapid" else CUT if self.spindle_on else SPINDLE_OFF
                         for kind in batch.kinds], dtype=np.int8)
        for begin, stop in self.straight_runs(batch):
            if begin < stop:
                self._queue_straight(poses[begin:stop + 1], first + begin, code[begin:stop])
            if stop < count:  # an arc
                self._queue_move(batch.move(stop, batch.ends[stop - 1] if stop else batch.start), first + stop)

    def _queue_straight(self, poses: np.ndarray, first: int, codes: np.ndarray) -> None:
        """Queue straight moves ``first``, ``first + 1``, ... from ``poses[k]`` to ``poses[k + 1]`` (the bar's
        frame) with ``codes``: ``_fill``'s samples, computed as arrays, cut each time the queue is full."""
        turn, step = self.steps
        delta = poses[1:] - poses[:-1]
        reach = np.sqrt(np.sum(delta[:, :3] * delta[:, :3], axis=1)) / step
        near = np.abs(reach - np.round(reach)) <= 1e-9 * np.maximum(reach, 1.0)
        for k in np.flatnonzero(near).tolist():  # where math.dist's last bit could decide a ceiling
            reach[k] = math.dist(poses[k, :3].tolist(), poses[k + 1, :3].tolist()) / step
        counts = np.maximum(np.ceil(np.maximum(np.abs(delta[:, 3]) / turn, reach)), 1.0).astype(np.int64)
        move = np.repeat(np.arange(len(counts)), counts)
        j = np.arange(len(move)) - np.repeat(np.cumsum(counts) - counts, counts) + 1
        rows = poses[move] + delta[move] * (j / counts[move])[:, None]
        single = np.repeat(counts == 1, counts)
        rows[single] = poses[1:][counts == 1]
        if tuple(poses[0].tolist()) != self.last:  # not where the queue ends: the first move's start too
            rows, move, counts = np.vstack((poses[:1], rows)), np.r_[0, move], counts.copy()
            counts[0] += 1
        self.last = tuple(poses[-1].tolist())
        self.queue_moves(rows, first + move, np.repeat(codes, counts), np.cumsum(counts))

    def _fill(self, keys: Sequence[Sequence[float]], rows: Sequence[Sequence[float]]) -> list[float]:
        """``rows`` after the first, flat, with samples between where the ``keys`` (three lengths and an
        angle) move more than a slice or an angle cell."""
        out: list[float] = []
        turn, move = self.steps
        for k in range(1, len(rows)):
            p, q = keys[k - 1], keys[k]
            n = max(1, math.ceil(max(abs(q[3] - p[3]) / turn, math.dist(p[:3], q[:3]) / move)))
            a, b = rows[k - 1], rows[k]
            if n == 1:
                out.extend(b)
                continue
            for j in range(1, n + 1):
                f = j / n
                out.extend([u + (v - u) * f for u, v in zip(a, b)])
        return out

    def flush(self) -> None:
        """Stamp what is queued with the tool in the spindle now: in each pose its parts from the
        outside in, each cell's cuts in the tool's order."""
        if not len(self.queue):
            return
        poses, moves, codes = self.queue.take()
        tool = self.tool
        parts, counts = [], []
        for part in parts_of(tool):  # the parts that reach the bar in this batch
            count = extent(self.stock, poses, part)[4]
            if count.any():
                parts.append(part)
                counts.append(count)
        if not parts:  # all above the bar
            return
        ends = np.cumsum(np.sum(counts, axis=0))
        self.used[tool.number] = tool
        start = 0
        while start < len(poses):  # chunks of bounded work, in the tool's order
            stop = max(int(np.searchsorted(ends, ends[start] + CHUNK, side="right")), start + 1)
            chunk = [part for part, count in zip(parts, counts) if count[start:stop].any()]
            if not chunk:  # these poses are all above the bar
                start = stop
                continue
            pieces = [stamps(self.stock, poses[start:stop], part.radius, part) for part in chunk]
            code = np.concatenate([codes[start:stop][p[0]] if part.code == CUT else
                                   np.full(len(p[0]), part.code, np.int8) for part, p in zip(chunk, pieces)])
            if len(chunk) == 1:
                sample, cell, low, high = pieces[0]
            else:  # pose by pose, the outer part first
                sample, cell, low, high = (np.concatenate([p[k] for p in pieces]) for k in range(4))
                rank = np.repeat(np.arange(len(chunk)), [len(p[0]) for p in pieces])
                order = np.lexsort((rank, sample))
                sample, cell, low, high, code = sample[order], cell[order], low[order], high[order], code[order]
            if len(cell):
                depth = self.stock.cut(cell, low, high, open_top=False)
                self._found(start + sample, depth, code, poses, moves, tool.number)
            start = stop

    def _found(self, at: np.ndarray, depth: np.ndarray, code: np.ndarray, poses: np.ndarray, moves: np.ndarray,
               tool: int) -> None:
        """The deepest cut that should not have been, per move and kind."""
        bad = np.flatnonzero((depth > EPS) & (code != CUT))
        if not len(bad):
            return
        at, depth, code = at[bad], depth[bad], code[bad]
        move = moves[at]
        order = np.lexsort((at, -depth, code, move))
        first = order[np.r_[True, (np.diff(move[order]) != 0) | (np.diff(code[order]) != 0)]]
        for k in first.tolist():
            index = int(move[k])
            pose = poses[at[k]]
            self.found.append(CutFinding(KIND_OF_CODE[int(code[k])], *self.source(index),
                                         self.axis.work(pose), float(depth[k]), tool, index, bar_angle(pose)))

    def notes(self) -> list[str]:
        return [f"T{n} has no flute_length: its shank and holder are not checked" if tool.shape != "insert" else
                f"T{n} is a lathe insert: simulated as a flat end mill of its diameter on the rotary axis"
                for n, tool in sorted(self.used.items()) if tool.flute_length is None or tool.shape == "insert"]


def bar_angle(pose: Sequence[float]) -> float:
    """The bar's own angle (degrees, 0..360) under the tool tip of a pose in the bar's frame: the
    tip's machine angle about the axis (90: straight above it, as on the axis itself) less A (B)."""
    p, q = float(pose[1]), float(pose[2])
    machine = math.degrees(math.atan2(q, p)) if math.hypot(p, q) > 1e-9 else 90.0
    return (machine - float(pose[3])) % 360.0


def simulate_cylinder(job: str | Path, stock: RoundStock, options: RunOptions | None = None,
                      tools: dict[int, Tool] | None = None, first_tool: int | None = None,
                      name: str | None = None, axis: RotaryAxis | None = None, every: int = 0,
                      on_snapshot: Callable[[int, RoundStock], None] | None = None,
                      tips: bool = False) -> CylinderResult:
    """Run the 4-axis ``job`` and cut the bar on its rotary axis (``axis``, default as the ini has it:
    ``rotary_axis``); a runtime error is kept in ``error``.  ``on_snapshot(move, stock)`` is called
    with the bar as cut before move 0, ``every``, 2 ``every``, ...; ``tips`` keeps where each move
    leaves the tool on the bar (``CylinderResult.tips``): the viewer's frames and marker."""
    started = time.perf_counter()

    def make(run: Run) -> CylinderSimulator:
        if run.config.lathe:
            raise StockError("a bar on a rotary axis is a mill's: the ini is a lathe's (machineType 1 or 2); "
                             "a lathe's bar takes --bar DIAMETER,LENGTH[,Z0]")
        first = int(run.interpreter.params.read(t.TOOL_CURRENT)) if first_tool is None else first_tool
        made = CylinderSimulator(stock, run, tools, first, axis)
        if on_snapshot is not None:
            made.every, made.on_snapshot = max(1, every), on_snapshot
        if tips:
            made.tips = array("f")
        return made

    sim, result, error = drive(job, options, name, make)
    sim.flush()
    ends = None if sim.tips is None else np.frombuffer(sim.tips, np.float32).reshape(-1, 2)
    return CylinderResult(stock, merged(sim.found), dict(sim.used), sim.notes(), time.perf_counter() - started,
                          len(sim.lines), result, error, sim.axis.letter, ends)
