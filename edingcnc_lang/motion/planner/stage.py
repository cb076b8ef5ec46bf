"""The planner stage: times every move as the controller's look-ahead would run it, then hands it on.

It sits behind the motion stage (so it sees the joints and the kinematics' speed limits) and in
front of the output sinks (trace, samples, callbacks), which get each move with its time.  Moves
are collected as plain values and planned a window at a time with numpy; the machine keeps
``LOOKAHEAD`` moves in hand that it could still stop within, as a real look-ahead buffer does.
Exact stop (G61/G61.1), rapids, probing, homing and the events in ``STOPPING_EVENTS`` stop the
machine.  See docs/planner.md for the model and the decisions.
"""
from __future__ import annotations

import math
from array import array
from collections import deque
from collections.abc import Callable, Iterator, Sequence
from itertools import chain
from typing import TYPE_CHECKING, Any, Protocol

from edingcnc_lang import speedups
from edingcnc_lang.canon import Batch, Event, Move, Pose
from edingcnc_lang.events import (DialogEvent, DwellEvent, EndEvent, ExecEvent, OperatorWaitEvent, OverrideEvent,
                                  PathControlEvent, PauseEvent, SpindleEvent, ToolChangeEvent)
from edingcnc_lang.config.machine_config import MachineConfig
from edingcnc_lang.motion.planner.angles import turns_beyond
from edingcnc_lang.motion.planner.estimate import Estimate
from edingcnc_lang.motion.sinks import Timing
from edingcnc_lang.motion.planner.limits_report import LimitsReport
from edingcnc_lang.motion.planner.overrides import Overrides
from edingcnc_lang.motion.planner.runs import Runs

if TYPE_CHECKING:
    import numpy as np

    from edingcnc_lang.motion.arc_table import ArcTable
    from edingcnc_lang.motion.stage import AxisLimits, PlainLimits, Samples

# Move kinds as small integers (the window keeps one per move).
RAPID, LINEAR, ARC, PROBE, HOME = range(5)
KIND_CODES = {"rapid": RAPID, "linear": LINEAR, "arc": ARC, "probe": PROBE, "home": HOME}
STRAIGHT = -1  # a move of the fast path: rapid if its feed is 0, else linear

WINDOW = 4096      # moves planned in one numpy pass
LOOKAHEAD = 256    # moves the machine keeps in hand beyond what it commits to (it can stop within them)
# Events the machine stops for: it waits for a dwell, a tool change, a pause or the end, the spindle
# to reach its speed, an external program or an operator's answer.
STOPPING_EVENTS = (DwellEvent, ToolChangeEvent, PauseEvent, EndEvent, SpindleEvent, ExecEvent, DialogEvent,
                   OperatorWaitEvent)


# A window of straight moves and arcs planned in C (csrc/speedups_plan.c), on the compiled core: None on the Python one
_PLAN_WINDOW = speedups.compiled("plan_window")

# What a move runs under: exact stop, G64 P, the feed override, the limits of rapids and of the rest, G64 R S D.
State = tuple[bool, float, float, int, int, tuple[float, float, float]]


class TimedSink(Protocol):
    """What the planner feeds: output sinks that get every move with its time."""

    def move(self, move: Move, joints: Pose, samples: Samples | None, timing: Timing) -> None: ...

    def write_batch(self, batch: Batch, times: Sequence[float], speeds: Sequence[float]) -> None: ...

    def event(self, event: Event) -> None: ...

    def close(self) -> None: ...


class Planner:
    """One run's planner: ``move``/``move_batch``/``event`` in program order, ``close`` at the end."""

    needs_limits = True  # every move comes with the limits it runs against

    def __init__(self, config: MachineConfig, sinks: Sequence[TimedSink], overrides: Overrides, *, tool: int = 0,
                 joints_of: Callable[[np.ndarray], np.ndarray] | None = None, want_samples: bool = False) -> None:
        self.config = config
        self.sinks = list(sinks)
        self.overrides = overrides
        self.tool = tool
        self.joints_of = joints_of
        self.want_samples = want_samples
        self.estimate = Estimate()
        self.limits = LimitsReport(config)
        self.time = 0.0
        self.exact_stop = not config.g64_active
        self.tolerance = config.g64_p
        # G64 R, S (degrees) and D (mm) as the job programmed them (manual pp. 37-40); NaN R: none yet
        self.laf: tuple[float, float, float] = (math.nan, math.nan, 0.0)
        self._limit_sets: list[tuple[tuple[float, ...], tuple[float, ...]]] = []  # (velocity, acceleration)
        self._limit_index: dict[tuple[tuple[float, ...], tuple[float, ...]], int] = {}
        self._states: list[State] = []
        self._state_index: dict[State, int] = {}
        self._start2 = 0.0
        self._origin: Pose = (0.0,) * 6  # where the first collected move starts
        self._clear()

    # ------------------------------------------------------------------ input
    def move(self, move: Move, joints: Pose, samples: Samples | None,
             limits: AxisLimits | PlainLimits | None,
             cap: float = math.inf, accel_cap: float = math.inf) -> None:
        """One move with the limits it runs against; ``cap`` and ``accel_cap`` are the path speed (mm/s) and
        acceleration (mm/s^2) the kinematics' joints allow."""
        assert limits is not None  # needs_limits: the motion stage passes them to a planner that asks
        if self._ends and move.start != self._ends[-1]:
            self.flush()  # the position jumped (a kinematics switch): nothing to blend
        if not self._ends:
            self._origin = move.start
        if move.arc is not None:
            from edingcnc_lang.motion.arc_table import ArcTable

            self._arc_tables.append(ArcTable.of(move.start, [move.end], [move.arc]).shifted(len(self._ends)))
        limit = self._limit_id(limits)
        self._ends.append(move.end)
        self._feed.append(move.feed)
        self._kind.add(KIND_CODES[move.kind])
        self._cap.add(cap)
        self._accel_cap.add(accel_cap)
        self._state.add(self._state_id(limit, limit, self._feed_factor(move.sync)))
        # only the extremes of a move's samples count (for the limits report): a window of long moves holds
        # two rows per move, never their millions of samples
        self._joints.append(None if samples is None else self.limits.joint_extremes(samples.joints))
        self._sampled += samples is not None
        self._queue.append(("move", move, joints))
        self._after_add()

    def move_batch(self, batch: Batch, limits: dict[str, PlainLimits] | None, arcs: ArcTable | None = None) -> None:
        """Moves in bulk whose joints are their positions (the interpreter's fast path).

        Per move only the end and the feed are kept (a straight move is a rapid if its feed is 0),
        and the arcs' frames (``arcs``, the motion stage's table of them, else made here); the rest is
        the same for the whole batch, as it is for a single ``move``.
        """
        assert limits is not None  # needs_limits, as in move()
        if self._ends and batch.start != self._ends[-1]:
            self.flush()
        if not self._ends:
            self._origin = batch.start
        count = len(batch)
        self._kind.add(STRAIGHT, count)  # the arcs among them are marked from their table when planned
        if batch.arcs is not None:
            if arcs is None:
                from edingcnc_lang.motion.arc_table import ArcTable

                arcs = ArcTable.of(batch.start, batch.ends, batch.arcs)
            self._arc_tables.append(arcs.shifted(len(self._ends)))
        self._ends.extend(batch.ends)
        self._feed.extend(batch.feeds)
        self._cap.add(math.inf, count)
        self._accel_cap.add(math.inf, count)
        state = self._state_id(self._limit_id(limits["rapid"]), self._limit_id(limits["linear"]),
                               self._feed_factor(batch.sync))
        self._state.add(state, count)
        self._joints.extend([None] * count)
        self._queue.append(("batch", batch))
        self._after_add()

    def _feed_factor(self, sync: float) -> float:
        """The feed override a move runs under: a spindle-synchronised cut (G33, G76) follows the spindle, not it."""
        return 1.0 if sync > 0.0 else self.overrides.feed_factor

    def event(self, event: Event) -> None:
        if isinstance(event, OverrideEvent):
            self.overrides.apply(event)
        elif isinstance(event, PathControlEvent):
            self.exact_stop = event.mode != "G64"
            self.tolerance = event.p
            if event.r is not None or ((event.s is not None or event.d is not None) and not math.isnan(self.laf[0])):
                angle, second, deviation = self.laf
                self.laf = (angle if event.r is None else event.r, second if event.s is None else event.s,
                            deviation if event.d is None else event.d)
        if isinstance(event, STOPPING_EVENTS):
            self.flush()
            self._emit_event(event)
            return
        if self._queue:
            self._queue.append(("event", event))
        else:
            self._emit_event(event)

    def flush(self) -> None:
        """Plan and hand on everything collected; the machine comes to rest at the end of it."""
        if self._ends:
            self._commit(len(self._ends))
        for item in self._queue:
            self._emit_event(item[1])
        self._queue.clear()
        self._start2 = 0.0

    def close(self) -> None:
        try:
            self.flush()
        finally:
            for sink in self.sinks:
                sink.close()

    # ------------------------------------------------------------------ planning
    def _clear(self) -> None:
        self._origin = (0.0,) * 6
        # one entry per collected move
        self._ends: list[Pose] = []
        self._feed: list[float] = []    # mm/min as programmed (0 for rapids)
        self._kind = Runs()             # a KIND_CODES value, or STRAIGHT: rapid if the feed is 0, else linear
        self._cap = Runs()              # the speed the kinematics' joints allow
        self._accel_cap = Runs()        # the path acceleration they allow
        self._state = Runs()            # index into self._states
        self._joints: list[Any] = []    # the extremes of the joints sampled along the move ((2, 6)), None where
        #                                 they are the position
        self._sampled = 0               # how many of them are not None
        self._arc_tables: list[ArcTable] = []  # the frames of the arcs among them, in order
        self._queue: deque[tuple[Any, ...]] = deque()

    def _limit_id(self, limits: AxisLimits | PlainLimits) -> int:
        """The index of a set of limits in a small table (kept as plain floats: the C planner reads them too)."""
        key = (tuple(map(float, limits.velocity)), tuple(map(float, limits.acceleration)))
        index = self._limit_index.get(key)
        if index is None:
            index = self._limit_index[key] = len(self._limit_sets)
            self._limit_sets.append(key)
        return index

    def _state_id(self, rapid_limits: int, other_limits: int, feed_factor: float) -> int:
        """The index of the machine state a move runs in: path control, tolerance, feed override, limits,
        the programmed look-ahead angles.

        It changes rarely, so moves keep an index into a small table instead of six values each.
        """
        state = (self.exact_stop, self.tolerance, feed_factor, rapid_limits, other_limits, self.laf)
        index = self._state_index.get(state)
        if index is None:
            index = self._state_index[state] = len(self._states)
            self._states.append(state)
        return index

    def _after_add(self) -> None:
        # Windows of WINDOW moves planned with LOOKAHEAD more, however the moves came (one by one or
        # in batches of any size): the times of a job never depend on how its reader cut it.
        while len(self._ends) >= WINDOW + LOOKAHEAD:
            self._commit(WINDOW, WINDOW + LOOKAHEAD)

    def _commit(self, count: int, horizon: int | None = None) -> None:
        """Plan the first ``horizon`` collected moves (default: all), then commit the first ``count`` of them
        (all: the machine stops after them).

        numpy and the model load here, with the first move: a job that does not move never needs them, and
        on the compiled core a window the C planner takes (``_in_c``) never does.
        """
        if self._in_c():
            self._commit_in_c(count, horizon)
            return
        import numpy as np

        from edingcnc_lang.motion.planner.junctions import corner_speeds2
        from edingcnc_lang.motion.planner.profile import plan_nodes, profiles
        from edingcnc_lang.motion.planner.samples import time_true_samples
        from edingcnc_lang.motion.planner.segments import segments

        n = len(self._ends) if horizon is None else horizon
        ends = np.fromiter(chain.from_iterable(self._ends[:n]), float, 6 * n).reshape(n, 6).T.copy()  # columns
        starts = np.empty_like(ends)
        starts[:, 0], starts[:, 1:] = self._origin, ends[:, :-1]
        feed = np.fromiter(self._feed, float, n)
        kind, state = self._kind.array(np.int64)[:n], self._state.array(np.int64)[:n]
        arcs = self._window_arcs().before(n)
        kind = np.where(kind == STRAIGHT, np.where(feed > 0.0, LINEAR, RAPID), kind)
        kind[arcs.index] = ARC
        exact_mode, tolerance, factor, rapid_limits, other_limits = (np.array(column) for column in
                                                                     list(zip(*self._states))[:5])
        laf = np.array([state_row[5] for state_row in self._states]).reshape(-1, 3).T
        limit = np.where(kind == RAPID, rapid_limits[state], other_limits[state])
        exact = exact_mode[state] | (kind == RAPID) | (kind == PROBE) | (kind == HOME)
        fastest = (kind == RAPID) | (kind == HOME)
        speed = np.minimum(self._cap.array(float)[:n], np.where(fastest, np.inf, feed * factor[state] / 60.0))
        cfg = self.config
        if (limit == limit[0]).all():  # the usual case: one set of limits for the whole window
            vlim, alim = (np.array(column) for column in self._limit_sets[int(limit[0])])
        else:
            vlim = np.array([v for v, _ in self._limit_sets])[limit].T
            alim = np.array([a for _, a in self._limit_sets])[limit].T
        seg = segments(starts, ends, speed, vlim, alim, arcs, cfg.laf_arcfeed_factor, cfg.min_circle_segment_size)
        moving = np.flatnonzero(seg.length > 0.0)  # moves of zero length take no time and do not stop the machine
        exact = exact[moving]
        all_accel = np.minimum(seg.accel, self._accel_cap.array(float)[:n])
        length, vmax, accel = seg.length[moving], seg.vmax[moving], all_accel[moving]
        before, after = moving[:-1], moving[1:]
        corner = corner_speeds2(seg.tangent_out[:, before], seg.tangent_in[:, after], seg.length[before],
                                seg.length[after], np.minimum(all_accel[before], all_accel[after]),
                                tolerance[state[after]], cfg.laf_angle,
                                None if np.isnan(laf[0]).all() else (laf[0, state[after]], laf[1, state[after]],
                                                                     laf[2, state[after]]))
        with np.errstate(over="ignore"):  # a speed limit past 1e154 squares to inf: no limit, as it is
            corner = np.where(exact[:-1] | exact[1:], 0.0, np.minimum(corner, np.minimum(vmax[:-1], vmax[1:]) ** 2))
        first = 0.0 if len(exact) and exact[0] else self._start2
        node2 = plan_nodes(length, accel, np.concatenate(([first], corner, [0.0]))[:len(moving) + 1], first)
        planned = profiles(length, vmax, accel, node2)
        duration, peak = np.zeros(n), np.zeros(n)
        duration[moving], peak[moving] = planned.duration, planned.peak
        done = int(np.searchsorted(moving, count))  # moving moves among the committed ones
        self._start2 = float(node2[done]) if count < n else 0.0
        t_end = self.time + np.cumsum(duration[:count])
        self._account(kind[:count], duration[:count], seg.xyz_length[:count])
        self.limits.add(starts[:, :count], ends[:, :count], arcs.before(count),
                        self._joints[:count] if self._sampled else None)
        samples = None
        if self.want_samples and self.joints_of is not None:
            samples = time_true_samples(starts[:, :count], ends[:, :count], arcs, moving[:done], planned, t_end,
                                        duration[:count], cfg.interpolation_time, self.joints_of)
        self._hand_on(count, t_end.tolist(), peak[:count].tolist(), samples)

    def _in_c(self) -> bool:
        """Whether the C planner takes this window: straight moves and arcs, each timed against the limits of
        its state (no joints' caps, no samples wanted or kept) and no G64 R programmed."""
        return (_PLAN_WINDOW is not None and not self._sampled and not self.want_samples
                and all(cap == math.inf for cap in chain(self._cap.values, self._accel_cap.values))
                and all(math.isnan(self._states[state][5][0]) for state in self._state.values))

    def _commit_in_c(self, count: int, horizon: int | None) -> None:
        """``_commit`` of a window of straight moves and arcs, in C: the same numbers to the bit (tests/planner).

        The arcs' frames go to C as the bytes of their table's rows; their extremes (the limits report)
        are the table's own (numpy is loaded anyway where there are arcs)."""
        n = len(self._ends) if horizon is None else horizon
        cfg = self.config
        rows, share, arcs = b"", 0.0, None
        if self._arc_tables:
            from edingcnc_lang.motion.planner.segments import curvature_share

            arcs = self._window_arcs().before(n)
            rows, share = arcs.rows.tobytes(), curvature_share(cfg.laf_arcfeed_factor)
        t_end, peak, self._start2, rapid_seconds, feed_seconds, rapid_distance, feed_distance, low, high = \
            _PLAN_WINDOW(self._origin, self._ends, self._feed, n, count, (self._kind.values, self._kind.counts),
                           (self._state.values, self._state.counts), self._states, self._limit_sets,
                           turns_beyond(180.0 - cfg.laf_angle), self._start2, self.time, rows, share,
                           cfg.min_circle_segment_size)
        self.estimate.add_moves(self.tool, rapid_seconds, feed_seconds, rapid_distance, feed_distance, count)
        if low is not None:
            self.limits.add_extremes(low, high, None if arcs is None else arcs.before(count), self._ends)
        speeds = array("d")  # (as bytes: the trace never reads them, so they need not become floats)
        speeds.frombytes(peak)
        self._hand_on(count, t_end, speeds, None)

    def _window_arcs(self) -> ArcTable:
        """The collected moves' arcs as one table, kept joined for the windows after this one."""
        from edingcnc_lang.motion.arc_table import ArcTable

        arcs = ArcTable.joined(self._arc_tables)
        self._arc_tables = [arcs] if len(arcs) else []
        return arcs

    def _hand_on(self, count: int, t_end: list[float], speeds: Sequence[float],
                 samples: Iterator[Samples | None] | None) -> None:
        """Hand the first ``count`` planned moves to the sinks with their end times, then forget them."""
        self._emit(count, t_end, speeds, samples)
        if count:
            self.time = t_end[-1]
        self._drop(count)

    def _account(self, kinds: np.ndarray, duration: np.ndarray, distance: np.ndarray) -> None:
        rapid = (kinds == RAPID) | (kinds == HOME)
        self.estimate.add_moves(self.tool, _in_order(duration[rapid]), _in_order(duration[~rapid]),
                                _in_order(distance[rapid]), _in_order(distance[~rapid]), len(kinds))

    def _drop(self, count: int) -> None:
        """Forget the first ``count`` collected moves (already committed)."""
        if count:
            self._origin = self._ends[count - 1]
        for values in (self._ends, self._feed, self._joints):
            del values[:count]
        for runs in (self._kind, self._cap, self._accel_cap, self._state):
            runs.drop(count)
        if self._sampled:
            self._sampled = sum(j is not None for j in self._joints)
        self._arc_tables = [left for table in self._arc_tables if len(left := table.after(count))]

    # ------------------------------------------------------------------ output
    def _emit(self, count: int, ends: list[float], speeds: Sequence[float],
              samples: Iterator[Samples | None] | None) -> None:
        """Hand the first ``count`` collected moves (their end times and peak speeds), and the events between
        them, to the sinks."""
        index = 0
        queue = self._queue
        while queue and index < count:
            item = queue[0]
            if item[0] == "event":
                self._emit_event(item[1])
            elif item[0] == "move":
                timing = Timing(ends[index - 1] if index else self.time, ends[index], speeds[index])
                sampled = next(samples) if samples is not None else None
                for sink in self.sinks:
                    sink.move(item[1], item[2], sampled, timing)
                index += 1
            else:  # a batch never has samples: the motion stage sends moves one by one when samples are wanted
                batch = item[1]
                take = min(len(batch), count - index)
                times = [ends[index - 1] if index else self.time, *ends[index:index + take]]
                for sink in self.sinks:
                    sink.write_batch(batch.head(take), times, speeds[index:index + take])
                if samples is not None:  # keep the samples in step with the moves
                    for _ in range(take):
                        next(samples, None)
                index += take
                if take < len(batch):
                    queue[0] = ("batch", batch.tail(take))
                    break
            queue.popleft()

    def _emit_event(self, event: Event) -> None:
        if isinstance(event, DwellEvent):
            self.estimate.add_dwell(self.tool, event.seconds)
            self.time += event.seconds
        elif isinstance(event, ToolChangeEvent):
            self.tool = event.tool
        elif isinstance(event, OperatorWaitEvent):
            knob = self.overrides.feed_percent if event.override == "feed" else 100.0
            self.estimate.add_note(f"{event.path}:{event.line}: M{event.m} P0 waits for the operator to turn the "
                                   f"{event.override} override knob (not timed); the run goes on at {knob:g} %")
        for sink in self.sinks:
            sink.event(event)


def _in_order(values: np.ndarray) -> float:
    """The sum of ``values`` added one after the other (numpy's ``sum`` adds in pairs, which the C planner's
    window would have to copy block for block)."""
    return float(values.cumsum()[-1]) if len(values) else 0.0
