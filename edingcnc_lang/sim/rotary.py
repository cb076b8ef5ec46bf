"""A mill with a rotary A axis cutting a bar: ``simulate_cylinder``.

The bar lies along X (from X0 to X0 + LENGTH, its axis through work Y0 Z0) and turns with A.  A
point of the bar at angle θ (its own, degrees) stands at angle θ + A in the machine, measured
about X from +Y towards +Z; so the tool, pointing down -Z, works at machine angle 90°.  Each move
is sampled so that neither X/Y/Z moves more than a cell nor A more than an angle cell between
samples (indexed and simultaneous 4-axis moves alike), and at each sample the tool, a flat end
mill as a vertical cylinder from its tip upwards, is stamped into the bar: along the ray from the
axis through each (slice, angle) cell it covers an interval of radii, which ``RoundStock.cut``
takes as it takes a lathe insert's.  The work offset and tool length are read as each move
arrives; A is taken as the job programs it (a kinematics plug-in that maps axes is not applied).
"""
from __future__ import annotations

import math
import time
from array import array
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from edingcnc_lang.canon import Event, Move, Pose
from edingcnc_lang.errors import EcncError
from edingcnc_lang.events import SpindleEvent, ToolChangeEvent
from edingcnc_lang.machine import tables as t
from edingcnc_lang.runner import Run, RunOptions, RunResult
from edingcnc_lang.sim.queue import MoveQueue
from edingcnc_lang.sim.findings import CutFinding, merged
from edingcnc_lang.sim.job import CUTTING_KINDS, chords, drive
from edingcnc_lang.sim.round_stock import EPS, RoundStock
from edingcnc_lang.sim.tools import Tool, ini_tool
from edingcnc_lang.sim.turning import CHUNK

CUT, RAPID, SPINDLE_OFF = 0, 1, 2
KIND_OF_CODE = {RAPID: "rapid_into_stock", SPINDLE_OFF: "spindle_off"}


@dataclass
class CylinderResult:
    """The cut bar, the findings and what the run left; ``error`` when the job stopped early."""

    stock: RoundStock
    findings: list[CutFinding]
    tools: dict[int, Tool]
    notes: list[str]
    seconds: float
    moves: int
    run: RunResult | None = None
    error: EcncError | None = None


class CylinderSimulator:
    """The ``on_move``/``on_event`` callbacks stamping a mill's tool into a bar on its A axis."""

    def __init__(self, stock: RoundStock, run: Run, tools: dict[int, Tool] | None, first_tool: int) -> None:
        self.stock = stock
        self.run = run
        self.table = tools
        self.tool = self._tool(first_tool)
        self.used: dict[int, Tool] = {}
        self.spindle_on = False
        self.queue = MoveQueue(4)  # x y z a(degrees) of the tool tip per sample
        self.lines = array("i")
        self.files = array("h")
        self.paths: dict[str, int] = {}
        self.found: list[CutFinding] = []
        self.last: tuple[float, ...] | None = None  # the pose the queue ends at

    def _tool(self, number: int) -> Tool:
        if self.table is not None and number in self.table:
            return self.table[number]
        return ini_tool(self.run.config, number)

    def on_event(self, event: Event) -> None:
        if isinstance(event, SpindleEvent):
            self.spindle_on = event.m in (3, 4)
        elif isinstance(event, ToolChangeEvent):
            self.flush()
            self.last = None
            self.tool = self._tool(event.tool)

    def on_move(self, move: Move, _joints: Pose) -> None:
        index = len(self.lines)
        self.lines.append(move.line)
        self.files.append(self.paths.setdefault(move.path, len(self.paths)))
        if move.kind not in CUTTING_KINDS:
            return
        off = self.run.interpreter.offset()  # Z holds the tool length: the tip's Z
        code = RAPID if move.kind in ("rapid", "home") else CUT if self.spindle_on else SPINDLE_OFF
        if move.arc is None:
            points = [move.start[:3], move.end[:3]]
        else:
            points = chords(move, self.stock.resolution / 4.0).tolist()
        count = len(points) - 1
        a0, a1 = move.start[3], move.end[3]
        poses = [(p[0] - off[0], p[1] - off[1], p[2] - off[2], a0 + (a1 - a0) * k / count - off[3])
                 for k, p in enumerate(points)]
        samples: list[float] = []
        if self.last != poses[0]:  # a move starts where the one before ended: its first pose is queued
            samples.extend(poses[0])
        for p, q in zip(poses, poses[1:]):
            steps = max(abs(q[3] - p[3]) / self.stock.angle_step(), math.dist(p[:3], q[:3]) / self.stock.resolution)
            n = max(1, math.ceil(steps))
            for k in range(1, n + 1):
                f = k / n
                samples.extend((p[0] + (q[0] - p[0]) * f, p[1] + (q[1] - p[1]) * f, p[2] + (q[2] - p[2]) * f,
                                p[3] + (q[3] - p[3]) * f))
        self.last = poses[-1]
        self.queue.add(samples, index, code)
        if self.queue.full:
            self.flush()

    def flush(self) -> None:
        """Stamp what is queued with the tool in the spindle now."""
        if not len(self.queue):
            return
        poses, moves, codes = self.queue.take()
        tool = self.used[self.tool.number] = self.tool
        ends = np.cumsum(_extent(self.stock, poses, tool.radius)[4])
        start = 0
        while start < len(poses):  # chunks of bounded work, in the tool's order
            stop = max(int(np.searchsorted(ends, ends[start] + CHUNK, side="right")), start + 1)
            sample, cell, low, high = stamps(self.stock, poses[start:stop], tool.radius)
            if len(cell):
                depth = self.stock.cut(cell, low, high, open_top=False)
                bad = np.flatnonzero((depth > EPS) & (codes[start:stop][sample] != CUT))
                for k in bad.tolist():
                    at = start + int(sample[k])
                    self._add(KIND_OF_CODE[int(codes[at])], int(moves[at]), tuple(poses[at, :3].tolist()),
                              float(depth[k]), tool.number)
            start = stop

    def _add(self, kind: str, move: int, where: tuple[float, ...], depth: float, tool: int) -> None:
        paths = list(self.paths)
        self.found.append(CutFinding(kind, paths[self.files[move]], self.lines[move], where,  # type: ignore[arg-type]
                                     depth, tool, move))

    def notes(self) -> list[str]:
        return [f"T{n} is a {tool.shape} tool: simulated as a flat end mill of its diameter on the rotary axis"
                for n, tool in sorted(self.used.items()) if tool.shape != "flat"]


def stamps(stock: RoundStock, poses: np.ndarray, radius: float) -> tuple[np.ndarray, np.ndarray,
                                                                        np.ndarray, np.ndarray]:
    """(sample, cell, low, high): for each tool pose (X, Y, Z of the tip, A degrees) the interval of
    radii its cylinder (radius ``radius``, from the tip upwards) covers on each cell's ray."""
    first, slices, first_angle, spread, per = _extent(stock, poses, radius)
    step = math.radians(stock.angle_step())
    sample = np.repeat(np.arange(len(poses)), per)
    within = np.arange(len(sample)) - np.repeat(np.cumsum(per) - per, per)
    spread_s = spread[sample]
    slice_ = first[sample].astype(np.int64) + within // np.maximum(spread_s, 1)
    angle = (first_angle[sample] + within % np.maximum(spread_s, 1)) % stock.shape[1]
    x, y, z, a = (poses[sample, k] for k in range(4))
    dx = stock.centres()[slice_] - x
    half = np.sqrt(np.maximum(radius * radius - dx * dx, 0.0))
    phi = (angle + 0.5) * step + np.radians(a)
    c, s = np.cos(phi), np.sin(phi)
    with np.errstate(divide="ignore", invalid="ignore"):
        up = s > 1e-12
        down = s < -1e-12
        lo = np.where(up, z / s, np.where(down | (z <= 0), -np.inf, np.inf))
        hi = np.where(down, z / s, np.where(up | (z <= 0), np.inf, -np.inf))
        right, left = c > 1e-12, c < -1e-12
        across = np.abs(y) <= half  # a ray along Z: inside the tool's width or not at all
        side_lo = np.where(right, (y - half) / c, np.where(left, (y + half) / c, np.where(across, -np.inf, np.inf)))
        side_hi = np.where(right, (y + half) / c, np.where(left, (y - half) / c, np.where(across, np.inf, -np.inf)))
    low = np.maximum(lo, side_lo)
    high = np.minimum(hi, side_hi)
    keep = (np.abs(dx) <= radius) & (low < high) & (high >= 0)
    return sample[keep], (slice_ * stock.shape[1] + angle)[keep], low[keep], high[keep]


def _extent(stock: RoundStock, poses: np.ndarray, radius: float) -> tuple[np.ndarray, ...]:
    """Per pose: the first slice and how many, the first angle cell and how many (the machine angles
    the tool can reach: sin(phi) >= z / top for a tip above the axis, all for one below it), and
    their product, the cells to look at."""
    top = float(stock.outer.max())
    reach = poses[:, 2] < top  # a tip above the bar touches nothing
    first = np.clip(np.ceil((poses[:, 0] - radius - stock.start) / stock.resolution - 0.5), 0, stock.shape[0])
    last = np.clip(np.floor((poses[:, 0] + radius - stock.start) / stock.resolution - 0.5), -1, stock.shape[0] - 1)
    slices = np.where(reach, last - first + 1, 0).astype(np.int64).clip(0)
    y, z = poses[:, 1], poses[:, 2]
    rise = np.where(z > 0, np.arcsin(np.clip(z / max(top, 1e-9), -1, 1)), -math.pi / 2)
    # above the axis the tool's bottom corners bound the angles too (the rays reach it between them)
    low = np.where(z > 0, np.maximum(rise, np.arctan2(z, y + radius)), rise)
    high = np.where(z > 0, np.minimum(math.pi - rise, np.arctan2(z, y - radius)), math.pi - rise)
    step = math.radians(stock.angle_step())
    spread = np.where((slices > 0) & (high >= low), np.ceil((high - low) / step).astype(np.int64) + 3, 0)
    spread = np.minimum(spread, stock.shape[1])
    first_angle = np.floor((low - np.radians(poses[:, 3])) / step - 0.5).astype(np.int64) - 1
    return first.astype(np.int64), slices, first_angle, spread, slices * spread


def simulate_cylinder(job: str | Path, stock: RoundStock, options: RunOptions | None = None,
                      tools: dict[int, Tool] | None = None, first_tool: int | None = None,
                      name: str | None = None) -> CylinderResult:
    """Run the 4-axis ``job`` and cut the bar on its A axis; a runtime error is kept in ``error``."""
    started = time.perf_counter()

    def make(run: Run) -> CylinderSimulator:
        first = int(run.interpreter.params.read(t.TOOL_CURRENT)) if first_tool is None else first_tool
        return CylinderSimulator(stock, run, tools, first)

    sim, result, error = drive(job, options, name, make)
    sim.flush()
    return CylinderResult(stock, merged(sim.found), dict(sim.used), sim.notes(), time.perf_counter() - started,
                          len(sim.lines), result, error)
