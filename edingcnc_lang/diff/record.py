"""One run of a job, recorded for comparison: every move as a row of numbers, the events that matter.

``record`` runs the job with a ``Recorder`` among the planner's outputs (``RunOptions.sinks``) and keeps
each move as one row of doubles in a flat ``array``, a batch of straight moves as its rows at once from
the batch's columns (no ``Move`` made per move), then hands out numpy columns.  ``sample`` turns the moves into the dense polyline the alignment walks: every
move's end, arcs in pieces that keep their circle, long lines split every ``LINE_STEP``.
"""
from __future__ import annotations

import math
from array import array
from collections.abc import Sequence
from itertools import chain
from dataclasses import dataclass, field, replace
from pathlib import Path

import numpy as np

from edingcnc_lang import speedups
from edingcnc_lang.canon import Batch, Event, Move, Pose
from edingcnc_lang.events import CoolantEvent, DwellEvent, SpindleEvent, SpindleSpeedEvent, ToolChangeEvent
from edingcnc_lang.kinematics.trajectory import ARC_ROW, arc_frame_rows
from edingcnc_lang.motion.sinks import Timing
from edingcnc_lang.motion.stage import Samples
from edingcnc_lang.runner import Run, RunOptions, RunResult

KINDS = ("rapid", "linear", "arc", "probe", "home")
RAPID_KINDS = (0, 4)
# per move: kind, tool, job line, feed, spindle rpm, start s, end s, start xyzabc, end xyzabc, and for an
# arc its frame as ``trajectory.arc_frame_rows`` gives it (u, v, centre (2), r0, r1, start angle, sweep,
# length; u -1: not an arc)
FRAME = ARC_ROW - 1
ROW = 19 + FRAME
LINE_STEP = 5.0        # mm: a straight move longer than this gets points inside it, so alignment stays local
MAX_CHORDS = 4096      # pieces per arc move at most
ARC_STEP = math.radians(10.0)  # radians: an arc in pieces this long, each measured to its circle
CHUNK = 2048           # moves filled at once: each piece's arrays stay small enough to reuse memory
                       # (a big one is new pages from the system each time, which costs more than the loop)
NO_ARC = (-1.0,) + (0.0,) * (FRAME - 1)

_FRAME_ROWS = speedups.compiled("arc_frame_rows") or arc_frame_rows  # the planner's arc frames


@dataclass
class Recording:
    """What one run did, as numpy columns, plus its events and result."""

    name: str
    kinds: np.ndarray      # (N,) int8 index into KINDS
    tools: np.ndarray      # (N,) int32
    lines: np.ndarray      # (N,) int32 the job line (the calling line for a move made in a sub)
    feeds: np.ndarray      # (N,) mm/min
    spindles: np.ndarray   # (N,) rpm at the end of the move
    times: np.ndarray      # (N, 2) planned start and end, seconds
    starts: np.ndarray     # (N, 6)
    ends: np.ndarray       # (N, 6)
    frames: np.ndarray     # (N, FRAME) the arc moves' frames (column 0, u, is -1 for a straight move)
    # (kind, job line, value, moves before it): tool changes, spindle on/off, coolant, dwell
    events: list[tuple[str, int, float, int]] = field(default_factory=list)
    result: RunResult | None = None

    def __len__(self) -> int:
        return len(self.kinds)

    @property
    def seconds(self) -> float:
        estimate = self.result.estimate if self.result is not None else None
        return estimate.seconds if estimate is not None else 0.0

    def take(self, moves: np.ndarray) -> Recording:
        """The moves ``moves`` (sorted indices) alone, for their path: no events, no result."""
        return Recording(self.name, self.kinds[moves], self.tools[moves], self.lines[moves], self.feeds[moves],
                         self.spindles[moves], self.times[moves], self.starts[moves], self.ends[moves],
                         self.frames[moves])

    def arc_moves(self) -> np.ndarray:
        """The indices of the arc moves."""
        return np.flatnonzero(self.frames[:, 0] >= 0)

    def tool_order(self) -> list[int]:
        """The tools put into the spindle, in order (a tool change to the tool already in is not one)."""
        order: list[int] = []
        for kind, _line, value, _at in self.events:
            if kind == "tool_change" and (not order or order[-1] != int(value)):
                order.append(int(value))
        return order


class Recorder:
    """The run's timed output (a planner sink): a flat array of doubles per move, a short tuple per
    event that matters."""

    def __init__(self, job: str) -> None:
        self.job = job
        self.rows = array("d")
        self.events: list[tuple[str, int, float, int]] = []
        self.tool = 0
        self.rpm, self.turning = 0.0, False  # the spindle as the events tell it
        self._unplaced: list[int] = []  # events still waiting for their job line
        self._caller = 0  # the job line that called the sub the last move was made in (0: none)
        self._kind = {kind: i for i, kind in enumerate(KINDS)}

    def _line(self, path: str, line: int, caller: int) -> int:
        return caller if caller else (line if path == self.job else 0)

    def _place(self, line: int, caller: int) -> None:
        """A move at job ``line`` (made in a sub if ``caller``): the events waiting for a line get theirs."""
        # events made inside a sub take the job line of the call: the next move's when it is made in a sub
        # too, else that of the sub's last move (the tool change macro's events after its moves)
        placed = line if caller or not self._caller else self._caller
        while self._unplaced:
            kind, _none, value, at = self.events[self._unplaced[-1]]
            self.events[self._unplaced.pop()] = (kind, placed, value, at)
        self._caller = caller

    def move(self, move: Move, joints: Pose, samples: Samples | None, timing: Timing) -> None:
        line = self._line(move.path, move.line, move.caller)
        self._place(line, move.caller)
        # straight moves that came in a bulk batch carry no spindle speed: the events tell it
        rpm = move.spindle or (self.rpm if self.turning else 0.0)
        self.rows.extend((self._kind.get(move.kind, 1), self.tool, line, move.feed, rpm, timing.start, timing.end))
        self.rows.extend(move.start)
        self.rows.extend(move.end)
        # the arc's circle as the planner reads it: one meaning of an arc's frame, not a second derivation
        self.rows.extend(_FRAME_ROWS(move.start, (move.end,), (move.arc,))[1:]
                         if move.arc is not None else NO_ARC)

    def write_batch(self, batch: Batch, times: Sequence[float], speeds: Sequence[float]) -> None:
        """A batch's rows at once from its columns, the same numbers ``move`` records for each of its
        moves, its arcs' frames from one ``arc_frame_rows`` (a batch under constant surface speed, whose
        moves each have their spindle speed: move by move)."""
        count = len(batch)
        if batch.css is not None or not count:
            for move, t0, t1, speed in zip(batch.moves(), times, times[1:], speeds):
                self.move(move, move.end, None, Timing(t0, t1, speed))
            return
        caller = batch.caller
        self._place(self._line(batch.path, batch.lines[0], caller), caller)
        table = np.empty((count, ROW))
        kind = self._kind
        table[:, 0] = [kind.get(k, 1) for k in batch.kinds]
        table[:, 1] = self.tool
        table[:, 2] = caller if caller else (batch.lines if batch.path == self.job else 0)
        table[:, 3] = batch.feeds
        table[:, 4] = batch.spindle or (self.rpm if self.turning else 0.0)
        clock = np.asarray(times, dtype=float)
        table[:, 5], table[:, 6] = clock[:count], clock[1:count + 1]
        ends = np.fromiter(chain.from_iterable(batch.ends), float, count * 6).reshape(count, 6)  # poses, flat
        table[0, 7:13] = batch.start
        table[1:, 7:13] = ends[:-1]
        table[:, 13:19] = ends
        table[:, 19:] = NO_ARC
        if batch.arcs is not None:
            frames = np.asarray(_FRAME_ROWS(batch.start, batch.ends, batch.arcs), dtype=float).reshape(-1, ARC_ROW)
            table[frames[:, 0].astype(np.int64), 19:] = frames[:, 1:]
        self.rows.frombytes(table.tobytes())

    def event(self, event: Event) -> None:
        value: float
        if isinstance(event, ToolChangeEvent):
            self.tool = event.tool
            value = self.tool
        elif isinstance(event, SpindleSpeedEvent):
            self.rpm = event.rpm
            return
        elif isinstance(event, SpindleEvent):
            value = float(event.m)
            self.turning = value != 5.0
            self.rpm = event.rpm or self.rpm
        elif isinstance(event, CoolantEvent):
            value = float(event.m)
        elif isinstance(event, DwellEvent):
            value = event.seconds
        else:
            return
        line = self._line(event.path, event.line, 0)
        if not line:
            self._unplaced.append(len(self.events))
        self.events.append((event.kind, line, value, len(self.rows) // ROW))

    def close(self) -> None:
        """The planner's end of the run: nothing is left to write."""

    def recording(self, name: str, result: RunResult) -> Recording:
        # the float columns are views of the recorded rows, not copies: the rows are all there is
        table = np.frombuffer(self.rows, dtype=float).reshape(-1, ROW)
        return Recording(name=name, kinds=table[:, 0].astype(np.int8), tools=table[:, 1].astype(np.int32),
                         lines=table[:, 2].astype(np.int32), feeds=table[:, 3], spindles=table[:, 4],
                         times=table[:, 5:7], starts=table[:, 7:13], ends=table[:, 13:19], frames=table[:, 19:ROW],
                         events=self.events, result=result)


def record(job: Path, options: RunOptions, name: str | None = None) -> Recording:
    """Run ``job`` (planned, for its time estimate) and record what it did; errors are raised as ``run`` raises them."""
    shown = name or str(job)
    recorder = Recorder(shown)
    run = Run(replace(options, sinks=(*options.sinks, recorder), plan=True))
    result = run.execute_file(job, name)
    return recorder.recording(shown, result)


@dataclass
class PathSamples:
    """A run's path as one polyline whose pieces of arcs remember their circle: points, the move each
    point ends, and for each segment that is a piece of an arc, its circle."""

    points: np.ndarray   # (P, D) machine coordinates (XYZ, and ABC when a run turns them)
    owner: np.ndarray    # (P,) int32 index of the move whose path reaches this point (sorted)
    arc_of: np.ndarray   # (P - 1,) int32 segment -> its arc move, -1 for a straight segment
    centers: np.ndarray  # (N, 3) the centre of each arc move (in its plane; the start's normal coordinate)
    normals: np.ndarray  # (N,) int8 the normal axis of each arc move (0 X, 1 Y, 2 Z), -1 not an arc
    radii: np.ndarray    # (N,)
    jump: np.ndarray     # (P,) bool: a move's start away from the previous end (the segment to it is no path)


def sample(rec: Recording, dims: int = 3, arc_step: float = ARC_STEP, moves: np.ndarray | None = None,
           jumps: np.ndarray | None = None) -> PathSamples:
    """The polyline of ``rec`` (of its moves ``moves`` alone, sorted, numbered 0.. in the result): what
    the alignment compares, so two ways of writing the same path (an arc split in two, a line split in
    three) give points on the same curve.  Arcs are pieces of at most ``arc_step`` radians whose
    distances are measured to the circle, not to the chord.  ``jumps`` says which moves start with a
    point of their own (default: those that start away from the previous move's end, and the first).
    Each point is worked out from its move alone, so a move's points are the same whichever moves are
    sampled with it; filled a chunk of moves at a time, so what it needs besides its result stays small."""
    if moves is None or (len(moves) and moves[-1] - moves[0] == len(moves) - 1):  # a run of moves: views
        rows = slice(None) if moves is None else slice(int(moves[0]), int(moves[-1]) + 1)
        starts, ends, frames = rec.starts[rows, :dims], rec.ends[rows, :dims], rec.frames[rows]
    else:  # only the columns the path needs, not a copy of the whole recording
        starts, ends, frames = rec.starts[moves, :dims], rec.ends[moves, :dims], rec.frames[moves]
    count = len(starts)
    arcs = np.flatnonzero(frames[:, 0] >= 0)
    circle = _circles(frames[arcs], rec.starts[arcs if moves is None else moves[arcs], :3], arcs, arc_step)
    centers = np.zeros((count, 3))
    normals = np.full(count, -1, dtype=np.int8)
    radii = np.zeros(count)
    centers[arcs], normals[arcs], radii[arcs] = circle.center, circle.normal, circle.r0
    if not count:
        return PathSamples(np.zeros((0, dims)), np.zeros(0, dtype=np.int32), np.zeros(0, dtype=np.int32),
                       centers, normals, radii, np.zeros(0, dtype=bool))
    delta = ends - starts
    # at least the middle and the end: a move between two points of the other path that strays between them shows
    pieces = np.maximum(2, np.ceil(np.linalg.norm(delta, axis=1) / LINE_STEP)).astype(np.int64)
    pieces[arcs] = circle.pieces
    if jumps is None:  # a point where a move starts away from the previous end (a kinematics switch, the first move)
        jumps = np.ones(count, dtype=bool)
        jumps[1:] = np.any(np.abs(starts[1:] - ends[:-1]) > 1e-9, axis=1)
    total = int(pieces.sum() + jumps.sum())
    points = np.empty((total, dims))
    owner = np.empty(total, dtype=np.int32)
    firsts = np.cumsum(pieces + jumps) - pieces  # where each move's first point after its start goes
    jump_at = firsts[jumps] - 1
    points[jump_at] = starts[jumps]
    owner[jump_at] = np.flatnonzero(jumps)
    straight = pieces.copy()
    straight[arcs] = 0
    for low in range(0, count, CHUNK):
        high = min(count, low + CHUNK)
        move_of, slot = slots(np.arange(low, high), straight[low:high])
        at = firsts[move_of] + slot
        fraction = (slot + 1) / pieces[move_of]
        points[at] = starts[move_of] + fraction[:, None] * delta[move_of]
        owner[at] = move_of
    arc_of = np.full(max(total - 1, 0), -1, dtype=np.int32)
    for low in range(0, len(arcs), CHUNK // 4):
        high = min(len(arcs), low + CHUNK // 4)
        which, slot = slots(np.arange(low, high), circle.pieces[low:high])
        move_of = arcs[which]
        at = firsts[move_of] + slot
        points[at] = circle.points(which, (slot + 1) / circle.pieces[which], starts, ends)
        owner[at], arc_of[at - 1] = move_of, move_of
    jump = np.zeros(total, dtype=bool)
    jump[jump_at] = True
    return PathSamples(points, owner, arc_of, centers, normals, radii, jump)


def slots(items: np.ndarray, counts: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Each item repeated ``counts`` times, and the repeat's number (0, 1, ...)."""
    repeated = np.repeat(items, counts)
    return repeated, np.arange(len(repeated)) - np.repeat(np.cumsum(counts) - counts, counts)


@dataclass
class _Circles:
    """The arc moves' circles, as columns: in-plane axes, centre, start and end radius, start angle,
    signed sweep and pieces (as ``geometry_of`` and ``trajectory.arc_frame`` read an arc)."""

    u: np.ndarray
    v: np.ndarray
    normal: np.ndarray
    center: np.ndarray   # (K, 3): in-plane centre, the start's normal coordinate
    r0: np.ndarray
    r1: np.ndarray
    angle: np.ndarray
    sweep: np.ndarray
    pieces: np.ndarray
    moves: np.ndarray

    def points(self, which: np.ndarray, fraction: np.ndarray, starts: np.ndarray, ends: np.ndarray) -> np.ndarray:
        """Points at ``fraction`` (0..1 of the sweep) of arcs ``which``: the radius, the normal axis and
        the rotary axes go with the angle; a fraction of 1 is the end exactly."""
        move = self.moves[which]
        start, end = starts[move], ends[move]
        pts = start + fraction[:, None] * (end - start)
        angle = self.angle[which] + fraction * self.sweep[which]
        radius = self.r0[which] + fraction * (self.r1[which] - self.r0[which])
        rows = np.arange(len(which))
        u, v = self.u[which], self.v[which]
        pts[rows, u] = self.center[which, u] + radius * np.cos(angle)
        pts[rows, v] = self.center[which, v] + radius * np.sin(angle)
        last = fraction >= 1.0
        pts[last] = end[last]
        return pts


def _circles(table: np.ndarray, starts: np.ndarray, arcs: np.ndarray, arc_step: float) -> _Circles:
    """The circles of the arc moves ``arcs`` from their recorded frames ``table`` and XYZ ``starts``, each
    in pieces of at most ``arc_step`` radians and ``LINE_STEP`` mm."""
    u, v = table[:, 0].astype(np.int64), table[:, 1].astype(np.int64)
    normal = 3 - u - v
    rows = np.arange(len(arcs))
    center = starts.copy()
    center[rows, u], center[rows, v] = table[:, 2], table[:, 3]
    r0, r1, angle, sweep, length = table[:, 4], table[:, 5], table[:, 6], table[:, 7], table[:, 8]
    pieces = np.clip(np.maximum(np.ceil(np.abs(sweep) / arc_step), np.ceil(length / LINE_STEP)), 2, MAX_CHORDS)
    return _Circles(u, v, normal, center, r0, r1, angle, sweep, pieces.astype(np.int64), arcs)
