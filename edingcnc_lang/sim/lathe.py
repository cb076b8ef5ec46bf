"""A lathe job cutting a bar: ``simulate_bar``, the round-stock counterpart of ``job.simulate``.

Each move's controlled point (the imaginary tool tip the offsets were measured to) is taken in the
bar's frame: machine X less the work offset is the radius (machine X is a radius on this lathe,
whatever the programming mode), machine Z less the offset the axial position.  The nose's centre is
that point less ``tip_shift(orientation, nose radius)``; the nose swept along the move is cut into
the bar while the spindle turns it (``turning.spans``).  Findings: material removed by a rapid or
with the spindle stopped, and with ``--chuck`` the tool reaching into the chuck.
"""
from __future__ import annotations

import time
from collections.abc import Callable
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from edingcnc_lang.canon import Move, Pose
from edingcnc_lang.config.machine_config import MachineConfig
from edingcnc_lang.errors import EcncError
from edingcnc_lang.machine import tables as t
from edingcnc_lang.pipeline.comp_geometry import tip_shift
from edingcnc_lang.runner import Run, RunOptions, RunResult
from edingcnc_lang.sim.simulator import SimOutcome, SimulatorBase
from edingcnc_lang.sim.findings import CutFinding, merged
from edingcnc_lang.sim.insert import INSIDE, holder_ranges, holder_reach, holder_spans, insert_shape, insert_spans
from edingcnc_lang.sim.job import CUTTING_KINDS, chords, drive
from edingcnc_lang.sim.round_stock import EPS, RoundStock
from edingcnc_lang.sim.stock import StockError
from edingcnc_lang.sim.tools import Tool
from edingcnc_lang.sim.turning import CHUNK, ranges_over, reaching, spans

KIND_OF_CODE = {1: "rapid_into_stock", 2: "spindle_off", 3: "holder"}
CUT, RAPID, SPINDLE_OFF, HOLDER = 0, 1, 2, 3


@dataclass
class BarResult(SimOutcome[RoundStock]):
    """The cut bar, the findings and what the run left; ``error`` when the job stopped early."""

    diameter_mode: bool
    chuck: float | None = None  # the axial position of the chuck's face
    run: RunResult | None = None
    error: EcncError | None = None


def insert_of(config: MachineConfig, number: int, table: dict[int, Tool] | None) -> Tool:
    """Tool ``number`` as an insert: from the tools file, else the ini's nose (diameter / 2) and orientation."""
    if table is not None and number in table:
        return table[number]
    entry = config.tools.get(number)
    if entry is None:
        return Tool(number, shape="insert", diameter=0.0, nose_radius=0.0, orientation=0, source="default")
    return Tool(number, shape="insert", diameter=entry.diameter, nose_radius=max(entry.diameter, 0.0) / 2.0,
                orientation=entry.orientation)


class BarSimulator(SimulatorBase[RoundStock]):
    """The ``on_move``/``on_event`` callbacks cutting a bar (``drive`` feeds them)."""

    def __init__(self, stock: RoundStock, run: Run, tools: dict[int, Tool] | None, first_tool: int,
                 chuck: float | None) -> None:
        super().__init__(stock, 4)  # z0 r0 z1 r1 of the controlled point
        self.config = run.config
        self.interp = run.interpreter
        self.table = tools
        self.chuck = chuck
        self.tool = insert_of(self.config, first_tool, tools)
        self.used: dict[int, Tool] = {}
        self.found: list[CutFinding] = []
        self.chord = stock.resolution / 4.0
        self.scale = 2.0 if self.config.diameter_mode else 1.0  # a radius as the job writes X

    def change_tool(self, number: int) -> None:
        self.tool = insert_of(self.config, number, self.table)

    def on_move(self, move: Move, _joints: Pose) -> None:
        index = self.record(move)
        if move.kind not in CUTTING_KINDS:
            return
        off = self.interp.offset()
        code = RAPID if move.kind in ("rapid", "home") else CUT if self.spindle_on else SPINDLE_OFF
        if move.arc is None:
            points = np.array([[move.start[2], move.start[0]], [move.end[2], move.end[0]]])
        else:
            points = chords(move, self.chord)[:, [2, 0]]
        points = points - (off[2], off[0])
        self.queue.add(np.hstack((points[:-1], points[1:])).ravel().tolist(), index, code)
        if self.queue.full:
            self.flush()

    def flush(self) -> None:
        """Cut what is queued with the insert in the turret now."""
        if not len(self.queue):
            return
        ends, moves, codes = self.queue.take()
        tool = self.used[self.tool.number] = self.tool
        nose = tool.nose_radius or 0.0
        dx, dz = tip_shift(tool.orientation or 0, nose)
        centre = ends - (dz, dx, dz, dx)  # the nose's centre: the controlled point less the tip's shift
        a, b = centre[:, :2], centre[:, 2:]
        shape = insert_shape(tool)
        reach = shape.z_extent if shape is not None else (-nose, nose)
        below = -shape.r_low if shape is not None else nose  # how far the insert reaches below its path
        if self.chuck is not None:
            self._chuck(a, b, reach[0], moves, tool.number)
        holder = shape.holder if shape is not None else None
        # an inside insert's edge short of the bore's wall in a slice cuts nothing there, rather than the wall
        open_top = shape is None or tool.orientation not in INSIDE
        z_low, z_high = np.minimum(a[:, 0], b[:, 0]), np.maximum(a[:, 0], b[:, 0])
        first, last = ranges_over(self.stock, z_low + reach[0], z_high + reach[1])
        counts = np.maximum(last - first + 1, 0)
        if holder is not None:
            h_first, h_last = holder_ranges(self.stock, a, b, holder)
            counts = counts + np.maximum(h_last - h_first + 1, 0)
        ends_at = np.cumsum(counts)
        start = 0
        while start < len(moves):  # chunks of bounded work, in the tool's order
            stop = max(int(np.searchsorted(ends_at, ends_at[start] + CHUNK, side="right")), start + 1)
            part = np.arange(start, stop)
            cut = part[reaching(self.stock, a[part], b[part], below, first[part], last[part])]
            if shape is None:
                seg, cell, low, high = spans(self.stock, a[cut], b[cut], nose, first[cut], last[cut])
            else:
                seg, cell, low, high = insert_spans(self.stock, a[cut], b[cut], shape, first[cut], last[cut])
            seg, code = cut[seg], codes[cut[seg]]
            if shape is not None and holder is not None:  # each stroke's holder before its insert: the holder meets what is there
                near = part[reaching(self.stock, a[part], b[part], -holder_reach(holder)[2], h_first[part],
                                     h_last[part])]
                h_seg, h_cell, h_lo, h_hi = holder_spans(self.stock, a[near], b[near], shape, open_top)
                seg, cell, low, high = (np.concatenate(pair) for pair in
                                        ((seg, near[h_seg]), (cell, h_cell), (low, h_lo), (high, h_hi)))
                code = np.concatenate((code, np.full(len(h_seg), HOLDER, dtype=code.dtype)))
                order = np.lexsort((code != HOLDER, seg))
                seg, cell, low, high, code = seg[order], cell[order], low[order], high[order], code[order]
            if len(seg):
                depth = self.stock.cut(cell, low, high, open_top=open_top)
                self._hits(moves[seg], code, cell, depth, low, tool.number)
            start = stop

    def _hits(self, moves: np.ndarray, codes: np.ndarray, cell: np.ndarray, depth: np.ndarray, low: np.ndarray,
              tool: int) -> None:
        """Findings of the cut entries (each with its move and code) that removed material they should not have."""
        bad = np.flatnonzero((depth > EPS) & (codes != CUT))
        centres = self.stock.centres()
        for k in bad.tolist():
            where = (max(float(low[k]), 0.0) * self.scale, 0.0, float(centres[cell[k]]))
            self._add(KIND_OF_CODE[int(codes[k])], int(moves[k]), where, float(depth[k]), tool)

    def _chuck(self, a: np.ndarray, b: np.ndarray, reach: float, moves: np.ndarray, tool: int) -> None:
        """The insert (``reach``: its lowest Z offset from the path) past the chuck's face (towards
        the bar's far end) meets the chuck."""
        assert self.chuck is not None
        deepest = np.minimum(a[:, 0], b[:, 0]) + reach
        for s in np.flatnonzero(deepest < self.chuck - EPS).tolist():
            point = a[s] if a[s, 0] <= b[s, 0] else b[s]
            self._add("chuck", int(moves[s]), (float(point[1]) * self.scale, 0.0, float(deepest[s])),
                      float(self.chuck - deepest[s]), tool)

    def _add(self, kind: str, move: int, where: tuple[float, float, float], depth: float, tool: int) -> None:
        self.found.append(CutFinding(kind, *self.source(move), where, depth, tool, move))

    def notes(self) -> list[str]:
        """What the report should say about the inserts that cut: those simulated as a point, and
        those whose edges have no direction (orientation 0 or 9: the nose alone)."""
        notes = [f"T{n} has no nose radius (no --tools entry, no ini diameter): simulated as a sharp point"
                 for n, tool in sorted(self.used.items()) if not tool.nose_radius]
        return notes + [f"T{n}'s insert_angle needs an orientation from 1 to 8 to point its edges: "
                        "simulated as its nose" for n, tool in sorted(self.used.items())
                        if tool.insert_angle is not None and not 1 <= (tool.orientation or 0) <= 8]


def simulate_bar(job: str | Path, stock: RoundStock, options: RunOptions | None = None,
                 tools: dict[int, Tool] | None = None, first_tool: int | None = None,
                 name: str | None = None, chuck: float | None = None, every: int = 0,
                 on_snapshot: Callable[[int, RoundStock], None] | None = None) -> BarResult:
    """Run the lathe ``job`` and turn the bar with it; ``chuck`` is the axial position of the chuck's
    face (the bar gripped beyond it).  A runtime error is kept in ``BarResult.error``.
    ``on_snapshot(move, stock)`` is called with the bar as cut before move 0, ``every``, 2 ``every``,
    ... (the viewer's frames)."""
    started = time.perf_counter()

    def make(run: Run) -> BarSimulator:
        if not run.config.lathe:
            raise StockError("a bar turns on a lathe: the ini is a mill's (machineType = 1 or 2 is a lathe); "
                             "a mill's rotary axis takes --stock cylinder:DIAMETER,LENGTH[,X0]")
        first = int(run.interpreter.params.read(t.TOOL_CURRENT)) if first_tool is None else first_tool
        made = BarSimulator(stock, run, tools, first, chuck)
        if on_snapshot is not None:
            made.every, made.on_snapshot = max(1, every), on_snapshot
        return made

    sim, result, error = drive(job, options, name, make)
    sim.flush()
    return BarResult(stock, merged(sim.found), dict(sim.used), sim.notes(), time.perf_counter() - started,
                     len(sim.lines), sim.config.diameter_mode, chuck, result, error)
