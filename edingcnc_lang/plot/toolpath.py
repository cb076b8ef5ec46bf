"""The toolpath of one run, recorded through the embedding API for pictures and the viewer.

``record_job`` runs a job with ``RunOptions(on_timed_move=..., on_event=...)`` and keeps every
move with the tool in the spindle when it ran and the motion planner's timing of it; ``Toolpath`` holds them as numpy columns and turns
them into polylines (arcs sampled finely) for whoever draws them.  A run that stops with a
runtime error still gives the path as far as it got, with the error kept beside it: a picture
of where a macro went wrong is worth having.
"""
from __future__ import annotations

import math
import tempfile
from array import array
from collections.abc import Iterator, Sequence
from dataclasses import dataclass, field, replace
from pathlib import Path

import numpy as np

from edingcnc_lang.canon import Arc, Batch, Event, Move, Pose
from edingcnc_lang.events import ToolChangeEvent
from edingcnc_lang.config.machine_config import MachineConfig, load_config
from edingcnc_lang.errors import EcncError
from edingcnc_lang.kinematics.base import declared_joint_kinds
from edingcnc_lang.kinematics.trajectory import arc_geometry
from edingcnc_lang.motion.sinks import Samples, Timing
from edingcnc_lang.machine.tables import TOOL_CURRENT
from edingcnc_lang.plot.lathe import WorkOffsetEvent, watch_offsets
from edingcnc_lang.runner import Run, RunOptions, RunResult
from edingcnc_lang.syntax.source import iter_file_lines

KINDS = ("rapid", "linear", "arc", "probe", "home")
FEED_KINDS = frozenset({KINDS.index("linear"), KINDS.index("arc"), KINDS.index("probe")})
RAPID_KINDS = frozenset({KINDS.index("rapid"), KINDS.index("home")})
PROBE = KINDS.index("probe")
ARC_STEP = math.radians(3.0)  # 120 chords a turn: 0.014 mm off a 40 mm radius
ROW = 9                       # values the recorder keeps per move (see Recorder.rows)
WIDE = 1e5                    # mm: a limit this far out is "no limit configured" (the defaults are 1e6)
SAMPLE_ROWS = 200_000         # rows of each --samples column a toolpath keeps (every step-th): a joint plot's points


@dataclass(frozen=True)
class Polyline:
    """Consecutive moves drawn alike: their points, and which move each segment belongs to."""

    points: np.ndarray    # (N, 3) machine XYZ
    moves: np.ndarray     # (N - 1,) index of the move each segment belongs to
    kind: int             # index into KINDS of the first move (all moves of a polyline are rapid or all feed)
    tool: int


@dataclass
class Toolpath:
    """Every move of a run in execution order, machine coordinates in mm and degrees."""

    job: str
    kinds: np.ndarray        # (N,) int8, index into KINDS
    tools: np.ndarray        # (N,) int32, the tool in the spindle
    lines: np.ndarray        # (N,) int32, source line of the move
    callers: np.ndarray      # (N,) int32, a move made in a sub: the job line that called it (else 0)
    files: np.ndarray        # (N,) int16, index into ``paths``
    paths: tuple[str, ...]
    feeds: np.ndarray        # (N,) mm/min, 0 for rapids
    starts: np.ndarray       # (N, 6)
    ends: np.ndarray         # (N, 6)
    joints: np.ndarray       # (N, 6) joints at the end of each move
    arcs: dict[int, Arc]     # move index -> its circle
    work_zero: tuple[float, float, float]
    limits: tuple[np.ndarray, np.ndarray] | None  # lower and upper XYZ of the machine, when configured
    times: np.ndarray        # (N, 2) planned start and end of each move, seconds from the job's start
    speeds: np.ndarray       # (N,) the planner's top speed of each move, mm/min (deg/min for rotary-only moves)
    seconds: float           # the planner's time estimate of the whole job (as far as it ran)
    result: RunResult | None = None
    error: EcncError | None = None
    joint_names: tuple[str, ...] = ()
    joint_kinds: tuple[str, ...] | None = None  # "linear"/"rotary" per joint, as the plug-in declares them
    kinematics: str = "trivial"
    samples: dict[str, np.ndarray] | None = None  # the run's --samples columns, when asked for (every step-th
    #                                               row, at most SAMPLE_ROWS)
    sample_spread: dict[str, float] | None = None  # each of those columns' max - min over every row
    copies: dict[str, str] = field(default_factory=dict)  # a name in ``paths`` -> the file to read its text from
    # a lathe's run: the work offset (machine - work, XYZ) each move ran with (plot/lathe.py); None elsewhere
    offsets: np.ndarray | None = None
    part: bool = False          # in work coordinates (plot/lathe.part_view), not the machine's
    x_diameter: bool = False    # the machine programs X as a diameter: the lathe view labels X so
    # bounds() by feed_only, worked out once: the picture asks twice and samples every arc each time
    # (not an __init__ field, so ``replace`` gives a new path an empty one)
    _bounds: dict[bool, tuple[np.ndarray, np.ndarray] | None] = field(default_factory=dict, init=False,
                                                                      repr=False, compare=False)

    def __len__(self) -> int:
        return len(self.kinds)

    def move_points(self, index: int, arc_step: float = ARC_STEP) -> np.ndarray:
        """The XYZ points of one move: its two ends, or an arc sampled every ``arc_step`` radians."""
        start, end = self.starts[index], self.ends[index]
        arc = self.arcs.get(index)
        if arc is None:
            return np.vstack((start[:3], end[:3]))
        geometry = arc_geometry(tuple(start), tuple(end), arc)
        assert geometry.center is not None
        first, second = (geometry.normal + 1) % 3, (geometry.normal + 2) % 3
        c1, c2 = geometry.center[first], geometry.center[second]
        radius = max(math.hypot(start[first] - c1, start[second] - c2), 1e-9)
        swept = abs(geometry.frame.sweep)
        chords = max(2, math.ceil(swept / arc_step))
        length = math.hypot(swept * radius, end[geometry.normal] - start[geometry.normal])
        if length <= 0.0:
            return np.vstack((start[:3], end[:3]))
        _t, pts = geometry.sample(1.0, length / chords)
        return np.vstack((start[:3], pts[:, :3]))

    def polylines(self, key: np.ndarray | None = None, arc_step: float = ARC_STEP) -> Iterator[Polyline]:
        """Runs of consecutive moves with the same drawing style, as one polyline each.

        A run ends where rapid meets feed, where ``key`` (default: the tool) changes, or where a
        move does not start at the previous end (a kinematics switch).
        """
        key = self.tools if key is None else key
        rapid = np.isin(self.kinds, list(RAPID_KINDS))
        count = len(self)
        if not count:
            return
        breaks = np.ones(count, dtype=bool)
        if count > 1:
            joined = np.all(np.abs(self.starts[1:, :3] - self.ends[:-1, :3]) < 1e-9, axis=1)
            breaks[1:] = (rapid[1:] != rapid[:-1]) | (key[1:] != key[:-1]) | ~joined
        starts = np.flatnonzero(breaks)
        for first, stop in zip(starts, [*starts[1:], count]):
            pieces: list[np.ndarray] = [self.starts[first:first + 1, :3]]
            owners: list[np.ndarray] = []
            plain_from = first
            for index in [i for i in range(first, stop) if i in self.arcs] + [stop]:
                if index > plain_from:  # straight moves: their end points
                    pieces.append(self.ends[plain_from:index, :3])
                    owners.append(np.arange(plain_from, index))
                if index < stop:
                    points = self.move_points(index, arc_step)[1:]
                    pieces.append(points)
                    owners.append(np.full(len(points), index))
                plain_from = index + 1
            yield Polyline(np.vstack(pieces), np.concatenate(owners), int(self.kinds[first]), int(self.tools[first]))

    def part_moves(self) -> np.ndarray:
        """Which moves cut the part: the feed moves (G1, arcs) that are not measuring.

        Probing (G38.2) is measuring, and so is every move of a sub call that probes: the tool
        change that drives to a tool setter at the far end of the table, a probing macro.  Without
        this an 80 x 50 part next to a tool setter was labelled 470 x 160.  A job with no such
        moves falls back to every feed move, then to every move.
        """
        cutting = np.isin(self.kinds, list(FEED_KINDS - {PROBE}))
        probing = np.unique(self.callers[(self.kinds == PROBE) & (self.callers > 0)])
        chosen = cutting & ~((self.callers > 0) & np.isin(self.callers, probing))
        for fallback in (np.isin(self.kinds, list(FEED_KINDS)), np.ones(len(self), dtype=bool)):
            if chosen.any():
                break
            chosen = fallback
        return chosen

    def bounds(self, feed_only: bool = True) -> tuple[np.ndarray, np.ndarray] | None:
        """Lower and upper XYZ of the part (``part_moves``), or of the whole path."""
        if feed_only not in self._bounds:
            self._bounds[feed_only] = self._work_out_bounds(feed_only)
        return self._bounds[feed_only]

    def _work_out_bounds(self, feed_only: bool) -> tuple[np.ndarray, np.ndarray] | None:
        if not len(self):
            return None
        chosen = self.part_moves() if feed_only else np.ones(len(self), dtype=bool)
        indices = np.flatnonzero(chosen)
        points = [self.starts[indices, :3], self.ends[indices, :3]]
        ends = np.vstack(points)
        lower, upper = ends.min(axis=0).tolist(), ends.max(axis=0).tolist()
        for i in (int(i) for i in indices if i in self.arcs):
            box = _interior_box(self.starts[i].tolist(), self.ends[i].tolist(), self.arcs[i])
            if box is None or any(map(float.__lt__, box[0], lower)) or any(map(float.__gt__, box[1], upper)):
                points.append(self.move_points(i))  # it may reach past the ends: its points count
        stacked = np.vstack(points)
        return stacked.min(axis=0), stacked.max(axis=0)

    def source_lines(self, moves: np.ndarray | None = None, context: int = 3,
                     limit: int = 2_000) -> dict[str, dict[int, str]]:
        """The text of the source lines that made ``moves`` (default: all), with ``context`` lines
        around each, cut at ``limit`` characters."""
        chosen_moves = slice(None) if moves is None else moves
        wanted: dict[int, set[int]] = {}
        for file_index, line in set(zip(self.files[chosen_moves].tolist(), self.lines[chosen_moves].tolist())):
            wanted.setdefault(file_index, set()).update(range(line - context, line + context + 1))
        texts: dict[str, dict[int, str]] = {}
        for file_index, numbers in wanted.items():
            path = self.paths[file_index]
            chosen: dict[int, str] = {}
            try:
                for number, text in enumerate(iter_file_lines(self.copies.get(path, path)), start=1):
                    if number in numbers:
                        chosen[number] = text[:limit]
            except OSError:
                continue  # "<string>" or a file gone since the run: no text to show
            texts[path] = chosen
        return texts

    def select_lines(self, first: int, last: int) -> Toolpath:
        """Only the moves made by job lines ``first``..``last`` (moves inside subs count with their caller)."""
        caller = _caller_lines(self)
        keep = (caller >= first) & (caller <= last)
        indices = np.flatnonzero(keep)
        renumber = {int(old): new for new, old in enumerate(indices)}
        return replace(self, kinds=self.kinds[keep], tools=self.tools[keep], lines=self.lines[keep],
                       callers=self.callers[keep],
                       files=self.files[keep], feeds=self.feeds[keep], starts=self.starts[keep],
                       ends=self.ends[keep], joints=self.joints[keep],
                       arcs={renumber[i]: arc for i, arc in self.arcs.items() if i in renumber},
                       times=self.times[keep], speeds=self.speeds[keep])


def _interior_box(start: list[float], end: list[float], arc: Arc) -> tuple[list[float], list[float]] | None:
    """A box that holds every point ``Toolpath.move_points`` samples between an arc's two ends, with
    room for rounding; None when that is not worked out simply (the arc is then sampled).

    ``bounds`` has the ends already: an arc whose box is inside them cannot change the bounds, and
    most arcs of a part are (sampling each took 30 µs, most of a 200,000-move picture's bounds).
    The box follows ``sample_arc``: interior fractions ``k dt / linear`` of the sweep, the radius
    between the start's and the end's, the normal axis linear (exact when it does not move)."""
    geometry = arc_geometry(tuple(start), tuple(end), arc)
    frame, normal = geometry.frame, geometry.normal
    (cu, cv), u, v = frame.center, frame.u, frame.v
    swept = abs(frame.sweep)
    assert geometry.center is not None
    radius = max(math.hypot(start[u] - geometry.center[u], start[v] - geometry.center[v]), 1e-9)  # as move_points
    chords = max(2, math.ceil(swept / ARC_STEP))
    length = math.hypot(swept * radius, end[normal] - start[normal])
    if not (length > 0.0 and frame.linear > 0.0 and frame.linear / (length / chords) < chords + 2):
        return None
    dt = length / chords
    last = math.ceil(frame.linear / dt * (1.0 + 1e-12) - 1e-9) - 1  # the last sample before the end
    fractions = (dt / frame.linear, min(1.0, last * dt / frame.linear * (1.0 + 1e-12)))
    angles = sorted(frame.start_angle + frame.sweep * f for f in fractions)
    low_angle, high_angle = angles[0] - 1e-9, angles[1] + 1e-9

    def reaches(phase: float) -> bool:
        """Whether the sampled angles pass ``phase`` (mod a full turn)."""
        return phase + 2.0 * math.pi * math.ceil((low_angle - phase) / (2.0 * math.pi)) <= high_angle

    r_low, r_high = min(frame.r0, frame.r1), max(frame.r0, frame.r1)
    box_low, box_high = end[:3], end[:3]
    for axis, centre, trig, top, bottom in ((u, cu, math.cos, 0.0, math.pi), (v, cv, math.sin, math.pi / 2, -math.pi / 2)):
        high = 1.0 if reaches(top) else max(trig(low_angle), trig(high_angle))
        low = -1.0 if reaches(bottom) else min(trig(low_angle), trig(high_angle))
        slack = 1e-9 * (1.0 + abs(centre) + r_high)
        box_high[axis] = centre + (r_high if high >= 0.0 else r_low) * high + slack
        box_low[axis] = centre + (r_high if low <= 0.0 else r_low) * low - slack
    if start[normal] != end[normal]:
        box_low[normal] = min(start[normal], end[normal]) - 1e-9 * (1.0 + abs(start[normal]) + abs(end[normal]))
        box_high[normal] = max(start[normal], end[normal]) + 1e-9 * (1.0 + abs(start[normal]) + abs(end[normal]))
    return box_low, box_high


def _caller_lines(path: Toolpath) -> np.ndarray:
    """For each move, the job line it belongs to: the line that called its sub (GoSub, M code,
    T M6), else its own line in the job; 0 for a move from neither (nothing in the job made it)."""
    job_index = path.paths.index(path.job) if path.job in path.paths else -1
    own = np.where(path.files == job_index, path.lines, 0)
    return np.where(path.callers > 0, path.callers, own)


class Recorder:
    """A sink of the run's planner (``RunOptions.sinks``) that collects its moves with the tool in use: a move
    at a time (``move``) or a batch's columns at once (``write_batch``, the same numbers), and the events."""

    def __init__(self) -> None:
        # flat arrays of doubles, not lists of tuples: a million moves take ~180 MB, not ~750 MB
        self.rows = array("d")    # kind, tool, line, file, feed, start s, end s, speed mm/s, caller per move
        self.poses = array("d")   # start, end and joints per move, six values each
        self.arcs: dict[int, Arc] = {}
        self.paths: dict[str, int] = {}
        self.tool = 0
        self._kind = {kind: i for i, kind in enumerate(KINDS)}
        self.offset = (0.0, 0.0, 0.0)  # a lathe's run: the work offset in force (plot/lathe.py)
        self.offsets = array("d")      # ... and each move's

    def move(self, move: Move, joints: Pose, _samples: Samples | None, timing: Timing) -> None:
        file_index = self.paths.setdefault(move.path, len(self.paths))
        if move.arc is not None:
            self.arcs[len(self.rows) // ROW] = move.arc
        self.rows.extend((self._kind.get(move.kind, 1), self.tool, move.line, file_index, move.feed,
                          timing.start, timing.end, timing.speed, move.caller))
        self.poses.extend(move.start)
        self.poses.extend(move.end)
        self.poses.extend(joints)
        self.offsets.extend(self.offset)

    def write_batch(self, batch: Batch, times: Sequence[float], speeds: Sequence[float]) -> None:
        """A batch's rows from its columns: what ``move`` records for each of its moves (their joints are their
        ends, as the planner hands a batch's moves on one at a time)."""
        count = len(batch)
        if not count:
            return
        first = len(self.rows) // ROW
        table = np.empty((count, ROW))
        kind = self._kind
        table[:, 0] = [kind.get(k, 1) for k in batch.kinds]
        table[:, 1] = self.tool
        table[:, 2] = batch.lines
        table[:, 3] = self.paths.setdefault(batch.path, len(self.paths))
        table[:, 4] = batch.feeds
        clock = np.asarray(times, dtype=float)
        table[:, 5], table[:, 6] = clock[:count], clock[1:count + 1]
        table[:, 7] = speeds[:count]
        table[:, 8] = batch.caller
        ends = np.array(batch.ends, dtype=float).reshape(count, 6)
        poses = np.empty((count, 3, 6))
        poses[0, 0] = batch.start
        poses[1:, 0] = ends[:-1]
        poses[:, 1] = poses[:, 2] = ends
        self.rows.frombytes(table.tobytes())
        self.poses.frombytes(poses.tobytes())
        self.offsets.frombytes(np.tile(np.asarray(self.offset, dtype=float), count).tobytes())
        if batch.arcs is not None:
            self.arcs.update((first + k, arc) for k, arc in enumerate(batch.arcs) if arc is not None)

    def close(self) -> None:
        """(The rows are read by ``toolpath`` when the run has ended.)"""

    def event(self, event: Event) -> None:
        if isinstance(event, ToolChangeEvent):
            self.tool = event.tool
        elif isinstance(event, WorkOffsetEvent):
            self.offset = event.offset

    def toolpath(self, job: str, config: MachineConfig, result: RunResult | None,
                 error: EcncError | None) -> Toolpath:
        table = np.frombuffer(self.rows, dtype=float).reshape(-1, ROW)
        poses = np.frombuffer(self.poses, dtype=float).reshape(-1, 3, 6)
        final: RunResult | None = result or (getattr(error, "result", None) if error else None)
        zero = (final.work_zero[0], final.work_zero[1], final.work_zero[2]) if final is not None else (0.0, 0.0, 0.0)
        return Toolpath(
            job=job, kinds=table[:, 0].astype(np.int8), tools=table[:, 1].astype(np.int32),
            lines=table[:, 2].astype(np.int32), callers=table[:, 8].astype(np.int32),
            files=table[:, 3].astype(np.int16),
            paths=tuple(self.paths), feeds=table[:, 4].copy(), times=table[:, 5:7].copy(),
            speeds=table[:, 7] * 60.0, seconds=final.estimate.seconds if final is not None and final.estimate is not None else 0.0,
            starts=poses[:, 0].copy(), ends=poses[:, 1].copy(), joints=poses[:, 2].copy(), arcs=self.arcs,
            work_zero=zero, limits=machine_limits(config), result=final, error=error,
            joint_names=tuple(j.name for j in config.joints), kinematics=config.kinematics_name or "trivial",
            offsets=np.frombuffer(self.offsets, dtype=float).reshape(-1, 3).copy() if config.lathe else None,
            x_diameter=config.diameter_mode)


def machine_limits(config: MachineConfig) -> tuple[np.ndarray, np.ndarray] | None:
    """The XYZ travel from cnc.ini: the joints' limits on a trivial machine, else ``[KINEMATICS]``'s
    Cartesian limits; None when they are the wide built-in defaults (no ini, or not configured)."""
    lower, upper = (limits[:3] for limits in config.axis_limits())
    if len(lower) < 3 or any(abs(v) >= WIDE for v in (*lower, *upper)):
        return None
    return np.array(lower, dtype=float), np.array(upper, dtype=float)


def record_job(job: str | Path, options: RunOptions | None = None, samples: bool = False,
               name: str | None = None) -> Toolpath:
    """Run ``job`` and return its toolpath; a runtime error is kept in ``Toolpath.error``.

    ``name`` is what messages and the picture call the job (default its path; the CLI names a
    piped job's temporary copy after the pipe).

    Syntax and configuration errors (nothing ran, or the machine could not be built) are raised.
    Callbacks already in ``options`` still receive every move and event.  With ``samples`` the
    trajectory is also sampled at the interpolation rate (the ``--samples`` columns, for joint plots),
    and every step-th sample kept, at most SAMPLE_ROWS per column.
    """
    if samples:
        from edingcnc_lang.motion.samples_file import read_thinned

        with tempfile.TemporaryDirectory(prefix="ecnc-plot-") as folder:
            target = Path(folder) / "samples.npz"
            path = record_job(job, replace(options or RunOptions(), samples=target), name=name)
            if target.exists():  # read back thinned: a long job's samples are gigabytes
                path.samples, path.sample_spread, _ = read_thinned(target, SAMPLE_ROWS)
            return path
    options = options or RunOptions()
    recorder = Recorder()
    config = load_config(options.ini) if options.ini else MachineConfig.default()
    result: RunResult | None = None
    error: EcncError | None = None
    run = Run(replace(options, sinks=(*options.sinks, recorder)))
    recorder.tool = int(run.interpreter.params.read(TOOL_CURRENT))  # the tool the ini's [VARIABLES] left in
    if config.lathe:
        watch_offsets(run)
    try:
        result = run.execute_file(Path(job), name)
    except EcncError as err:
        if getattr(err, "result", None) is None:  # nothing ran: syntax, configuration, plug-in loading
            raise
        error = err
    path = recorder.toolpath(name or str(job), config, result, error)
    path.joint_kinds = declared_joint_kinds(run.kinematics)
    if name is not None:  # a piped job: its lines are read from the copy that ran
        path.copies[name] = str(job)
    return path
