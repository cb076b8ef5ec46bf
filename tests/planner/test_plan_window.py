"""The compiled planner of straight moves (csrc/speedups_plan.c) times every window exactly as the numpy
reference (``Planner._commit``) does: the same bits in every move's times and speed, the estimate, the
limits report and the speed the next window starts from.

Random windows of rapids, feeds, probing and homing moves (and now and then an arc, whose window numpy plans) (zero-length moves, duplicate points, 90 and
180 degree corners, collinear runs, rotary-only moves), exact stop on and off, G64 P, the feed override,
several limit sets, moves one by one and in batches, with small windows so that windows are committed in
part (``LOOKAHEAD``) and start from the speed the last one left; each job runs once with the C planner
and once with the reference.  The corner model's exact cases are pinned below.
"""
from __future__ import annotations

import dataclasses
import math
from collections.abc import Sequence
from typing import Any

import numpy as np
import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from edingcnc_lang import speedups
from edingcnc_lang.canon import Arc, Batch, Event, Move, Pose
from edingcnc_lang.config.machine_config import MachineConfig
from edingcnc_lang.events import DwellEvent, OverrideEvent, PathControlEvent
from edingcnc_lang.motion.planner import stage as planner_stage
from edingcnc_lang.motion.planner.angles import turns_beyond
from edingcnc_lang.motion.planner.junctions import corner_speeds2
from edingcnc_lang.motion.planner.overrides import Overrides
from edingcnc_lang.motion.planner.stage import Planner
from edingcnc_lang.motion.sinks import Timing
from edingcnc_lang.motion.stage import AxisLimits, PlainLimits

PLAN_WINDOW = speedups.compiled("plan_window")
needs_c = pytest.mark.skipif(PLAN_WINDOW is None, reason="the compiled core is not built (or the Python one runs)")

coordinates = st.one_of(st.sampled_from([0.0, 1.0, 2.0, -3.0, 0.5, 10.0, 1e-3]),
                        st.floats(-50, 50, allow_nan=False, allow_subnormal=False))
poses = st.one_of(
    st.tuples(coordinates, coordinates, st.sampled_from([0.0, 0.0, -1.0, 2.5])).map(lambda p: (*p, 0.0, 0.0, 0.0)),
    st.tuples(coordinates, coordinates, coordinates, st.sampled_from([0.0, 0.0, 90.0, 45.5])).map(
        lambda p: (*p, 0.0, 0.0)))
feeds = st.sampled_from([100.0, 600.0, 1500.0, 60000.0, 0.5, 3000.0, 20000.0])
limit_values = st.tuples(*[st.sampled_from([50.0, 100.0, 250.0, 1000.0, math.inf, 0.0])] * 6)  # (0: NaN shares)
# accelerations low against the speeds: corners and short moves bind the speed (the passes matter)
accel_values = st.tuples(*[st.sampled_from([2.0, 20.0, 200.0, 1000.0, 1e9])] * 6)
plain_limits = st.builds(PlainLimits, limit_values, accel_values)
operations = st.one_of(
    st.tuples(st.just("move"), st.sampled_from(["linear"] * 6 + ["rapid"] * 3 + ["probe", "home"]), poses, feeds,
              st.integers(0, 1)),
    st.tuples(st.just("batch"), st.lists(st.tuples(poses, st.sampled_from([0.0, 0.0, 100.0, 600.0, 2000.0])),
                                         min_size=1, max_size=12)),
    st.tuples(st.just("batch"), st.lists(st.tuples(poses, st.just(12000.0)), min_size=1, max_size=12)),
    st.tuples(st.just("g64"), st.sampled_from([0.0, 0.0, 0.01, 0.1, 2.0])),
    st.tuples(st.just("g61")),
    st.tuples(st.just("override"), st.sampled_from([None, 50.0, 120.0, -1.0])),
    st.tuples(st.just("dwell")),
    # a half circle in XY: its window goes to numpy on both sides, and the next starts from its speed
    st.tuples(st.just("arc"), st.sampled_from([0.5, 2.0, 5.0]), st.sampled_from([1, -1])))


class Recorder:
    """A sink that keeps what the planner hands on, every float as its bits (repr)."""

    def __init__(self) -> None:
        self.rows: list[Any] = []

    def move(self, move: Move, joints: Pose, samples: object, timing: Timing) -> None:
        self.rows.append(("move", move.line, repr(timing.start), repr(timing.end), repr(timing.speed)))

    def write_batch(self, batch: Batch, times: Sequence[float], speeds: Sequence[float]) -> None:
        self.rows.append(("batch", tuple(batch.lines), tuple(map(repr, times)), tuple(map(repr, speeds))))

    def event(self, event: Event) -> None:
        self.rows.append(("event", event.kind))

    def close(self) -> None:
        self.rows.append(("close",))


def _run(ops: list[Any], limit_sets: list[PlainLimits], laf_angle: float, compiled: bool,
         monkeypatch: pytest.MonkeyPatch) -> tuple[Any, ...]:
    """Feed the planner ``ops`` (with the C planner or the reference) and say what came out of it."""
    monkeypatch.setattr(planner_stage, "_PLAN_WINDOW", PLAN_WINDOW if compiled else None)
    calls = []
    if compiled:
        def counted(*args: Any) -> Any:
            calls.append(args[4])
            return PLAN_WINDOW(*args)
        monkeypatch.setattr(planner_stage, "_PLAN_WINDOW", counted)
    config = dataclasses.replace(MachineConfig.default(), laf_angle=laf_angle)
    recorder = Recorder()
    planner = Planner(config, [recorder], Overrides(feed_percent=80.0))
    position: Pose = (0.0,) * 6
    line = 0
    rapid = PlainLimits(tuple(v * 2.0 for v in limit_sets[0].velocity), limit_sets[0].acceleration)
    for op in ops:
        line += 1
        if op[0] == "move":
            _, kind, end, feed, which = op
            limits = limit_sets[which % len(limit_sets)]
            numpy_limits = AxisLimits(np.array(limits.velocity), np.array(limits.acceleration))
            planner.move(Move(kind, "job.nc", line, position, end, 0.0 if kind in ("rapid", "home") else feed), end,
                         None, numpy_limits)
            position = end
        elif op[0] == "batch":
            ends, batch_feeds = [e for e, _ in op[1]], [f for _, f in op[1]]
            batch = Batch("job.nc", position, ["linear" if f else "rapid" for f in batch_feeds],
                          list(range(line, line + len(ends))), ends, batch_feeds)
            planner.move_batch(batch, {"rapid": rapid, "linear": limit_sets[-1]})
            position = ends[-1]
        elif op[0] == "arc":
            radius, turn = op[1], op[2]
            end = (position[0] + 2.0 * radius, *position[1:])
            numpy_limits = AxisLimits(np.full(6, 100.0), np.full(6, 1000.0))
            planner.move(Move("arc", "job.nc", line, position, end, 1200.0, Arc((position[0] + radius, position[1]),
                                                                               "XY", turn)), end, None, numpy_limits)
            position = end
        elif op[0] == "g64":
            planner.event(PathControlEvent("job.nc", line, "G64", op[1]))
        elif op[0] == "g61":
            planner.event(PathControlEvent("job.nc", line, "G61", 0.0))
        elif op[0] == "override":
            planner.event(OverrideEvent("job.nc", line, 50, op[1]))
        else:
            planner.event(DwellEvent("job.nc", line, 0.25))
    planner.close()
    limits = planner.limits
    return (recorder.rows, repr(planner.estimate), repr(planner.time),
            [repr(v) for v in (*limits.axis_low, *limits.axis_high, *limits.joint_low, *limits.joint_high)],
            len(calls) if compiled else None)


@needs_c
@settings(max_examples=300, deadline=None, suppress_health_check=[HealthCheck.function_scoped_fixture])
@given(st.lists(operations, min_size=1, max_size=40), st.lists(plain_limits, min_size=1, max_size=3),
       st.sampled_from([5.0, 0.0, 90.0, 135.0, 180.0, 12.5]), st.sampled_from([(5, 3), (4, 1), (4096, 256)]),
       st.sampled_from([True, False]))
def test_the_c_planner_times_windows_of_straight_moves_as_the_reference(
        monkeypatch: pytest.MonkeyPatch, ops: list[Any], limit_sets: list[PlainLimits], laf_angle: float,
        window: tuple[int, int], exact_start: bool) -> None:
    with monkeypatch.context() as patch:
        patch.setattr(planner_stage, "WINDOW", window[0])
        patch.setattr(planner_stage, "LOOKAHEAD", window[1])
        if exact_start:
            ops = [("g61",), *ops]
        compiled = _run(ops, limit_sets, laf_angle, True, patch)
        reference = _run(ops, limit_sets, laf_angle, False, patch)
    if any(op[0] in ("move", "batch") for op in ops) and not any(op[0] == "arc" for op in ops):
        assert compiled[4]  # the C planner took the windows
    assert compiled[:4] == reference[:4]


@needs_c
def test_a_window_committed_in_part_starts_the_next_one_at_speed(monkeypatch: pytest.MonkeyPatch) -> None:
    """A long run of gentle corners under G64: windows of 5 committed 3 at a time carry their end speed on."""
    ends = [(float(k), 0.1 * (k % 2), 0.0, 0.0, 0.0, 0.0) for k in range(1, 40)]
    ops: list[Any] = [("g64", 0.1), ("batch", [(end, 1200.0) for end in ends])]
    limits = [PlainLimits((100.0,) * 6, (1000.0,) * 6)]
    monkeypatch.setattr(planner_stage, "WINDOW", 3)
    monkeypatch.setattr(planner_stage, "LOOKAHEAD", 2)
    compiled = _run(ops, limits, 5.0, True, monkeypatch)
    reference = _run(ops, limits, 5.0, False, monkeypatch)
    assert compiled[4] > 10 and compiled[:4] == reference[:4]
    speeds = [float(s) for row in compiled[0] if row[0] == "batch" for s in row[3]]
    assert len(speeds) == len(ends) and all(s > 0.0 for s in speeds)


def test_windows_the_c_planner_leaves_to_the_reference(monkeypatch: pytest.MonkeyPatch) -> None:
    """A G64 R programmed (the manual's corner rules) or samples wanted: the numpy reference plans them."""
    monkeypatch.setattr(planner_stage, "_PLAN_WINDOW", lambda *args: pytest.fail("the C planner took the window"))
    config = MachineConfig.default()
    planner = Planner(config, [], Overrides())
    planner.event(PathControlEvent("job.nc", 1, "G64", 0.0, r=30.0))
    limits = AxisLimits(np.full(6, 100.0), np.full(6, 1000.0))
    planner.move(Move("linear", "job.nc", 2, (0.0,) * 6, (1.0, 0, 0, 0, 0, 0), 600.0), (1.0, 0, 0, 0, 0, 0), None,
                 limits)
    planner.close()
    sampled = Planner(config, [], Overrides(), want_samples=True)
    sampled.move(Move("linear", "job.nc", 2, (0.0,) * 6, (1.0, 0, 0, 0, 0, 0), 600.0), (1.0, 0, 0, 0, 0, 0), None,
                 limits)
    sampled.close()
    assert planner.estimate.moves == sampled.estimate.moves == 1


# ---------------------------------------------------------------- the corner model's exact cases
def _corner(before: Sequence[float], after: Sequence[float], laf_angle: float = 5.0, tolerance: float = 0.0,
            programmed: tuple[float, float, float] | None = None) -> float:
    columns = [np.array([[*v, 0.0, 0.0, 0.0]]).T for v in (before, after)]
    return float(corner_speeds2(columns[0], columns[1], np.array([10.0]), np.array([10.0]), np.array([1000.0]),
                                np.array([tolerance]), laf_angle,
                                None if programmed is None else tuple(np.array([v]) for v in programmed))[0])


def test_exact_corners_stay_exact() -> None:
    x, y, back = (1.0, 0.0, 0.0), (0.0, 1.0, 0.0), (-1.0, 0.0, 0.0)
    diagonal = (0.6, 0.8, 0.0)  # a unit vector whose dot product with itself is not exactly 1
    assert _corner(x, x) == math.inf and _corner(x, x, tolerance=0.01) == math.inf  # collinear: no corner
    assert _corner(diagonal, diagonal) > 1e15  # as good as straight on
    assert _corner(x, back, laf_angle=0.0) == 0.0  # a reversal stops, whatever lafAngle says
    assert _corner(x, y) == 1000.0 * 5.0  # 90 degrees: tan(45) is exactly 1, R = half the move
    # a corner of exactly lafAngle (90 degrees between the moves) is not below it: it blends
    assert _corner(x, y, laf_angle=90.0) == 5000.0 and _corner(x, y, laf_angle=90.5) == 0.0
    # G64 R90 without S (the standard algorithm): a change of direction of exactly R passes, beyond it stops
    assert _corner(x, y, programmed=(90.0, math.nan, 0.0)) == 5000.0
    assert _corner(x, y, programmed=(89.9, math.nan, 0.0)) == 0.0
    assert _corner(x, x, programmed=(0.0, math.nan, 0.0)) == math.inf  # R0 stops at corners, not straight on
    assert _corner(x, y, programmed=(0.0, math.nan, 0.0)) == 0.0


def test_turns_beyond_is_exact_where_the_cosine_is() -> None:
    assert [turns_beyond(a) for a in (0.0, 60.0, 90.0, 120.0, 180.0, 270.0)] == [1.0, 0.5, 0.0, -0.5, -1.0, -1.0]
    assert turns_beyond(-1.0) == math.inf and turns_beyond(45.0) == math.cos(math.radians(45.0))


# ---------------------------------------------------------------- windows with arcs
PLANES = {"XY": (0, 1, 2), "XZ": (0, 2, 1), "YZ": (1, 2, 0)}  # in-plane axes in the plane's order, the normal
radii = st.sampled_from([0.0, 1e-3, 0.02, 0.5, 2.0, 5.0, 37.5])
arc_operations = st.one_of(
    # an arc: plane, radius, start angle from the centre, angle to the end (0: full turns), normal travel,
    # turn, full turns, feed, a limit set; now and then its end off the circle (a spiral: r0 != r1)
    st.tuples(st.just("arc"), st.sampled_from(sorted(PLANES)), radii, st.floats(-math.pi, math.pi),
              st.sampled_from([0.3, 1.0, math.pi / 2, math.pi, 3.0, 6.2, -0.7, -2.5, 0.0]),
              st.sampled_from([0.0, 0.0, 0.0, 1.5, -0.25]), st.sampled_from([1, -1]), st.sampled_from([1, 1, 2]),
              feeds, st.integers(0, 2), st.sampled_from([1.0, 1.0, 1.0002])),
    st.tuples(st.just("straight"), poses, feeds),
    st.tuples(st.just("g64"), st.sampled_from([0.0, 0.01, 0.1])),
    st.tuples(st.just("g61")),
    st.tuples(st.just("override"), st.sampled_from([None, 50.0, 150.0])))


def _arc(position: Pose, op: tuple[Any, ...]) -> tuple[Pose, Arc]:
    """An arc ``op`` from ``position``: its end and its circle."""
    _, plane, radius, angle, turn_by, travel, turn, turns, _, _, spiral = op
    u, v, normal = PLANES[plane]
    centre = (position[u] - radius * math.cos(angle), position[v] - radius * math.sin(angle))
    end = list(position)
    if turn_by:
        end[u] = centre[0] + radius * spiral * math.cos(angle + turn_by)
        end[v] = centre[1] + radius * spiral * math.sin(angle + turn_by)
    end[normal] += travel
    return tuple(end), Arc(centre, plane, turn, 0 if turn_by else turns)  # type: ignore[return-value]


def _run_arcs(ops: list[Any], limit_sets: list[PlainLimits], config: MachineConfig, batched: bool,
              compiled: bool, monkeypatch: pytest.MonkeyPatch) -> tuple[Any, ...]:
    """Feed the planner arcs and straight moves (one by one, or the runs of them in batches)."""
    calls: list[int] = []

    def counted(*args: Any) -> Any:
        calls.append(args[4])
        return PLAN_WINDOW(*args)
    monkeypatch.setattr(planner_stage, "_PLAN_WINDOW", counted if compiled else None)
    recorder = Recorder()
    planner = Planner(config, [recorder], Overrides(feed_percent=90.0))
    position: Pose = (0.0,) * 6
    pending: list[tuple[Pose, float, Arc | None, int]] = []

    def send() -> None:
        if pending:
            start = planner._ends[-1] if planner._ends else (0.0,) * 6
            lines = [line for *_, line in pending]
            batch = Batch("job.nc", start, ["arc" if a else "linear" for _, _, a, _ in pending], lines,
                          [e for e, _, _, _ in pending], [f for _, f, _, _ in pending],
                          arcs=[a for _, _, a, _ in pending])
            planner.move_batch(batch, {"rapid": limit_sets[0], "linear": limit_sets[-1]})
            pending.clear()

    for line, op in enumerate(ops, 1):
        if op[0] in ("arc", "straight"):
            end, arc = _arc(position, op) if op[0] == "arc" else (op[1], None)
            feed = op[-3] if op[0] == "arc" else op[2]
            if batched:
                pending.append((end, feed, arc, line))
            else:
                limits = limit_sets[(op[-2] if op[0] == "arc" else 0) % len(limit_sets)]
                numpy_limits = AxisLimits(np.array(limits.velocity), np.array(limits.acceleration))
                planner.move(Move("arc" if arc else "linear", "job.nc", line, position, end, feed, arc), end, None,
                             numpy_limits)
            position = end
            continue
        send()
        if op[0] == "g64":
            planner.event(PathControlEvent("job.nc", line, "G64", op[1]))
        elif op[0] == "g61":
            planner.event(PathControlEvent("job.nc", line, "G61", 0.0))
        else:
            planner.event(OverrideEvent("job.nc", line, 50, op[1]))
    send()
    planner.close()
    limits = planner.limits
    return (recorder.rows, repr(planner.estimate), repr(planner.time),
            [repr(v) for v in (*limits.axis_low, *limits.axis_high, *limits.joint_low, *limits.joint_high)],
            len(calls))


@needs_c
@settings(max_examples=400, deadline=None, suppress_health_check=[HealthCheck.function_scoped_fixture])
@given(st.lists(arc_operations, min_size=1, max_size=30), st.lists(plain_limits, min_size=1, max_size=3),
       st.sampled_from([5.0, 0.0, 90.0, 180.0]), st.sampled_from([0.0, 0.0, 0.05, 1.0]),
       st.sampled_from([1.0, 1.0, 0.5, 3.0]), st.sampled_from([(5, 3), (4, 1), (4096, 256)]), st.booleans(),
       st.sampled_from([("g64", 0.0), ("g64", 0.0), ("g64", 0.05), ("g61",)]))
def test_the_c_planner_times_windows_with_arcs_as_the_reference(
        monkeypatch: pytest.MonkeyPatch, ops: list[Any], limit_sets: list[PlainLimits], laf_angle: float,
        min_circle: float, arc_factor: float, window: tuple[int, int], batched: bool, mode: tuple[Any, ...]) -> None:
    """Arcs in the three planes, helical ones, full circles (one or two turns, helical too), spirals, arcs
    under min_circle_segment_size (one chord) and of zero radius, among straight moves, one by one and in
    batches, under several limit sets and lafArcfeedFactor values."""
    config = dataclasses.replace(MachineConfig.default(), laf_angle=laf_angle, min_circle_segment_size=min_circle,
                                 laf_arcfeed_factor=arc_factor)
    ops = [mode, *ops]  # mostly blending: the arcs' tangents decide the corners
    with monkeypatch.context() as patch:
        patch.setattr(planner_stage, "WINDOW", window[0])
        patch.setattr(planner_stage, "LOOKAHEAD", window[1])
        compiled = _run_arcs(ops, limit_sets, config, batched, True, patch)
        reference = _run_arcs(ops, limit_sets, config, batched, False, patch)
    assert compiled[4] or not any(op[0] in ("arc", "straight") for op in ops)  # the C planner took the windows
    assert compiled[:4] == reference[:4]


@needs_c
def test_an_arc_exactly_min_circle_segment_size_long_turns_on_both(monkeypatch: pytest.MonkeyPatch) -> None:
    """An arc as long as min_circle_segment_size still turns (the centripetal cap applies); just shorter, it
    is a chord: the same on both planners, at the boundary and either side of it."""
    from edingcnc_lang.kinematics.trajectory import arc_frame_rows

    arc_op = ("arc", "XY", 0.02, 0.0, math.pi / 2, 0.0, 1, 1, 60000.0, 0, 1.0)
    end, arc = _arc((0.0,) * 6, arc_op)
    length = arc_frame_rows((0.0,) * 6, [end], [arc])[-1]
    ops = [("g64", 0.0), ("straight", (0.0, 0.0, 0.0, 0.0, 0.0, 0.0), 600.0), arc_op,
           ("straight", (1.0, 1.0, 0.0, 0.0, 0.0, 0.0), 600.0)]
    limits = [PlainLimits((100.0,) * 6, (1000.0,) * 6)]
    times = set()
    for min_circle in (math.nextafter(length, 0.0), length, math.nextafter(length, math.inf)):
        config = dataclasses.replace(MachineConfig.default(), min_circle_segment_size=min_circle)
        compiled = _run_arcs(ops, limits, config, False, True, monkeypatch)
        assert compiled[4] and compiled[:4] == _run_arcs(ops, limits, config, False, False, monkeypatch)[:4]
        times.add(compiled[2])
    assert len(times) == 2  # turning at and under the length, a chord past it


def test_numpy_sine_and_cosine_are_libms() -> None:
    """The C planner's arc tangents call libm's sin and cos where the reference calls numpy's (docs/planner.md):
    on this machine they must agree to the bit (Python's math.sin and math.cos are libm's)."""
    angles = np.random.default_rng(42).uniform(-4.0 * math.pi, 4.0 * math.pi, 20_000)
    angles = np.concatenate((angles, [0.0, -0.0, math.pi, -math.pi, math.pi / 2, 2.5 * math.pi, 1e-300, 1e6]))
    values = angles.tolist()
    assert np.sin(angles).tolist() == [math.sin(a) for a in values]
    assert np.cos(angles).tolist() == [math.cos(a) for a in values]
