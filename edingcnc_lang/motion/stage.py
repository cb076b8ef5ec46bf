"""The motion stage: what happens to a move after the interpreter (the canon's machine side).

It owns the joints.  It switches kinematics (``KIN``, homing, the bend knife), samples each move
at the interpolation rate when the joints are not simply the position (at the programmed feed,
slowed where a joint's velocity or acceleration limit needs it; rapids and homing as fast as the
limits allow), evaluates the inverse kinematics once per move on all samples, checks joint and
Cartesian limits, copies the kinematics' user output into parameters, and hands each move with
its joints, the limits it runs against and the speed the joints allow to the planner
(``planner/``), which times it and feeds the output sinks.
See docs/kinematics.md ("Running jobs") for the rules.

numpy is imported by the sampling methods and for the limits a sampled move is timed against (a move whose
joints are its position gets ``PlainLimits``, plain floats): while the
joints are simply the position (no kinematics, trivial kinematics, no bend knife), no samples are
written and nothing reads time (the planner is ``planner.untimed``), a run never loads it.
"""
from __future__ import annotations

import math
import operator
from collections.abc import Callable, Sequence
from edingcnc_lang.records import record
from functools import cached_property
from typing import TYPE_CHECKING, Any, Protocol, TypeVar

from edingcnc_lang import speedups
from edingcnc_lang.machine import tables as t
from edingcnc_lang.canon import AXES, Batch, Event, Move, Pose
from edingcnc_lang.events import DwellEvent
from edingcnc_lang.config.machine_config import MachineConfig
from edingcnc_lang.errors import EcncError, Location, MachineError, PluginError
from edingcnc_lang.kinematics import abi
from edingcnc_lang.kinematics.base import PLUGIN_FAILURES, Kinematics, KinematicsDomainError, as_pose, checked_rows
from edingcnc_lang.kinematics.builtin import (
    MAPPINGS,
    CylinderMapping,
    TrivialKinematics,
    bend_knife_correction,
)
from edingcnc_lang.kinematics.trajectory import CURVATURE_SHARE, Dynamics, dynamics, geometry_of
from edingcnc_lang.motion.reach import batch_arcs_beyond, beyond, column_bounds, table_beyond

_T = TypeVar("_T")

if TYPE_CHECKING:
    import numpy as np

    from edingcnc_lang.motion.arc_table import ArcTable

LIMIT_SLACK = 1e-9          # mm or degrees beyond a position limit that still counts as on it
DYNAMICS_SLACK = 1.01       # 1 % over maxVelocity before it is an error
SWITCH_TOLERANCE = 1e-6     # a joint that would have to jump further than this at a switch is an error
CRAWL_ACCELERATION_SHARE = 1e-3  # of the joints' acceleration: where the path leaves them none
PLAN_PASSES = 4             # rapids: re-sample at most this often to reach the fastest allowed speed
_COLUMN_BOUNDS = speedups.compiled("column_bounds") or column_bounds  # the bounds of a batch, on the core that runs


class PlannerStage(Protocol):
    """The next stage: takes every executed move with its joints and limits, and the events."""

    # False: the stage does not time moves (``planner.untimed``), so they need no limits (nor numpy)
    needs_limits: bool

    def move(self, move: Move, joints: Pose, samples: Samples | None, limits: AxisLimits | PlainLimits | None,
             cap: float = math.inf, accel_cap: float = math.inf) -> None: ...

    def move_batch(self, batch: Batch, limits: dict[str, PlainLimits] | None, arcs: ArcTable | None = None) -> None: ...

    def event(self, event: Event) -> None: ...

    def flush(self) -> None: ...

    def close(self) -> None: ...

    @property
    def overrides(self) -> Any: ...


@record(frozen=True)
class Samples:
    """One move sampled at the interpolation rate: times from the job start, Cartesian poses, joints;
    the planner's time-true samples also carry the path speed (units/s) and acceleration (units/s^2)."""

    t: np.ndarray
    pos: np.ndarray
    joints: np.ndarray
    speed: np.ndarray | None = None
    accel: np.ndarray | None = None


@record(frozen=True)
class AxisLimits:
    """Velocity (units/s) and acceleration (units/s^2) limits of the six axes a move is timed against."""

    velocity: np.ndarray
    acceleration: np.ndarray


@record(frozen=True)
class PlainLimits:
    """``AxisLimits`` as plain floats: those of the moves whose joints are their position (kinematics off,
    nothing sampled), which a planner times without numpy (``Planner`` plans windows of straight ones in C
    on the compiled core)."""

    velocity: tuple[float, ...]
    acceleration: tuple[float, ...]


def _positive(values: Sequence[float]) -> np.ndarray:
    """Limits as an array; a plug-in's answer of 0 or less means "not set" rather than "cannot move"
    (the ini's own limits are checked to be above 0 when it is read, see config/machine_config.py)."""
    import numpy as np

    array = np.asarray(values, dtype=float)
    return np.where(array > 0.0, array, np.inf)


def _plain_positive(value: float) -> float:
    """``_positive`` of one limit, as a Python float."""
    return float(value) if value > 0.0 else math.inf


def _located(move: Move) -> Location:
    return Location(move.path, move.line)


class MotionStage:
    """The canon implementation that owns the joints; one per run."""

    def __init__(self, config: MachineConfig, kinematics: Kinematics | None, planner: PlannerStage,
                 write_param: Callable[[int, float], None], *, sample_always: bool = False) -> None:
        self.config = config
        self.plugin = kinematics or TrivialKinematics({})
        self.planner = planner
        self.write_param = write_param
        self.sample_always = sample_always
        self.active: Kinematics | None = None  # None: kinematics off, joints = position
        self.tanknife = False
        self.knife_z_zero = 0.0                # machine Z of the work zero when tanknife was switched on
        self.joints: Pose = (0.0,) * 6
        self.time = 0.0
        self.moves = 0
        # joint position limits, LIMIT_SLACK included
        self._lower = [j.negative_limit - LIMIT_SLACK for j in config.joints]
        self._upper = [j.positive_limit + LIMIT_SLACK for j in config.joints]
        self._plugin_call(lambda: self.plugin.control(abi.OPEN, [0.0] * abi.CONTROL_DATA_LEN), None)

    @cached_property
    def _joint_limits(self) -> AxisLimits:
        joints = self.config.joints
        return AxisLimits(_positive([j.max_velocity for j in joints]), _positive([j.max_acceleration for j in joints]))

    @cached_property
    def _cartesian_limits(self) -> AxisLimits:
        return AxisLimits(_positive(self.config.cartesian_max_velocity),
                          _positive(self.config.cartesian_max_acceleration))

    # ---------------------------------------------------------------- canon
    def move(self, move: Move) -> None:
        checked = move.kind != "home"  # homing is what puts the joints in their range: not checked
        cap = accel = math.inf
        if self._identity() and not self.sample_always:
            samples = None
            if checked:
                self._check_exact(move)
            joints = move.end
        else:
            start_time = self.time
            samples, speed, accel = self._sample(move)
            cap = math.inf if self._identity() else speed
            joints = as_pose(samples.joints[-1])
            if checked and self._identity():
                self._check_exact(move)
            elif checked:
                self._check_samples(move, samples, start_time)
        if self.active is not None:
            self._user_output(self.active, _located(move))
        limits = None if not self.planner.needs_limits else \
            self._plain_limits_for(move) if samples is None else self._limits_for(move)
        self.planner.move(move, joints, samples, limits, cap, accel)
        self.joints = joints  # counted once the next stage took it (an embedder's callback may stop the run)
        self.moves += 1

    def move_batch(self, batch: Batch) -> None:
        """Moves in bulk; joints = position and no samples make this the cheap case."""
        if not (self._identity() and not self.sample_always and self.active is None):
            batch.each(self.move)
            return
        lower, upper = self._lower, self._upper
        if not batch.lines:
            return
        least, most = _COLUMN_BOUNDS(batch.ends)
        if any(map(operator.lt, least, lower)) or any(map(operator.gt, most, upper)):
            self._first_limit_violation(batch)
        arcs = None
        if batch.arcs is not None and self.planner.needs_limits:  # the planner reads the arcs as one table
            from edingcnc_lang.motion.arc_table import ArcTable

            arcs = ArcTable.of(batch.start, batch.ends, batch.arcs)
        if batch.arcs is not None and (table_beyond(arcs, batch.ends, lower, upper) if arcs is not None else
                                       batch_arcs_beyond(batch.start, batch.ends, batch.arcs, lower, upper)):
            self._first_limit_violation(batch)  # (an untimed run checks them one by one: it never loads numpy)
        self._write_batch(batch, arcs)

    def _first_limit_violation(self, batch: Batch) -> None:
        """Write the moves before the first one out of limits, then raise its error."""
        for count, move in enumerate(batch.moves()):
            try:
                self._check_exact(move)
            except MachineError as err:
                self._write_batch(batch.head(count))
                err.done = count
                raise

    def _write_batch(self, batch: Batch, arcs: ArcTable | None = None) -> None:
        if batch.lines:
            try:
                self.planner.move_batch(batch, self._straight_limits if self.planner.needs_limits else None, arcs)
            except EcncError as err:  # a callback stopped the batch: the moves before it were made
                if err.done:
                    self.moves += err.done
                    self.joints = batch.ends[err.done - 1]
                raise
            self.moves += len(batch)
            self.joints = batch.end

    @cached_property
    def _straight_limits(self) -> dict[str, PlainLimits]:
        """The limits of the fast path's rapids and feed moves (kinematics off: the joints'), as ``_limits_for``
        gives them, worked out without numpy."""
        joints = self.config.joints
        velocity = [_plain_positive(j.max_velocity) for j in joints]
        acceleration = [_plain_positive(j.max_acceleration) for j in joints]
        rapid_v, rapid_a = self._rapid_velocity_factor, self.config.g0_acceleration_factor
        return {"rapid": PlainLimits(tuple(v * rapid_v for v in velocity), tuple(a * rapid_a for a in acceleration)),
                "linear": PlainLimits(tuple(velocity), tuple(acceleration))}

    def event(self, event: Event) -> None:
        if isinstance(event, DwellEvent):
            self.time += event.seconds
        self.planner.event(event)

    def kinematics(self, mode: str, args: tuple[float, ...], pos: Pose, path: str, line: int) -> Pose:
        """``KIN ON|OFF|CTRL|<mapping>`` and ``tanknife on|off``; returns the Cartesian position after it."""
        where = Location(path, line)
        self.planner.flush()  # the machine comes to rest before the kinematics change
        if mode == "ON":
            self._control(abi.ON, [*pos, *[0.0] * 6], where)
            return self._switch(self.plugin, f"KIN ON ({self.plugin.name})", where)
        if mode == "OFF":
            if self.active is self.plugin:
                self._control(abi.OFF, [0.0] * abi.CONTROL_DATA_LEN, where)
            return self._switch(None, "KIN OFF", where)
        if mode == "CTRL":
            self._control(int(args[0]), [*args[1:], *[0.0] * (abi.CONTROL_DATA_LEN + 1 - len(args))], where)
            return self._switch(self.active, f"KIN CTRL {int(args[0])}", where) if self.active else pos
        if mode in ("TANKNIFE_ON", "TANKNIFE_OFF"):
            self.tanknife = mode == "TANKNIFE_ON"
            self.knife_z_zero = args[2] if len(args) > 2 else 0.0
            self._check_no_jump(pos, f"tanknife {'on' if self.tanknife else 'off'}", where)
            return pos
        if mode.upper() in MAPPINGS:
            return self._start_mapping(mode.upper(), args, where)
        raise MachineError(f"unknown kinematics mode {mode!r}", where)

    def close(self) -> None:
        try:
            self._plugin_call(lambda: self.plugin.control(abi.CLOSE, [0.0] * abi.CONTROL_DATA_LEN), None)
        finally:
            self.planner.close()

    # ---------------------------------------------------------------- switching
    def _start_mapping(self, mode: str, args: tuple[float, ...], where: Location) -> Pose:
        """``KIN X2A .. Y2YAZ2ZC``: args are the active work zero's machine X and Y."""
        if self.active is self.plugin:
            self._control(abi.OFF, [0.0] * abi.CONTROL_DATA_LEN, where)
        zero = args[0] if MAPPINGS[mode].wrap == 0 else args[1]
        mapping = self._plugin_call(
            lambda: CylinderMapping(mode, self.config.kinematics_settings, zero, self.joints[2]), where)
        return self._switch(mapping, f"KIN {mode}", where)

    def _switch(self, kin: Kinematics | None, label: str, where: Location) -> Pose:
        """Make ``kin`` active without moving a motor: the position is found from the joints."""
        self.active = kin
        self.write_param(t.KIN_TYPE, float((kin or self.plugin).kin_type()))
        pos = self._forward(self.joints, where)
        self._check_no_jump(pos, label, where)
        if kin is not None:
            self._check_cartesian_start(pos, label, where)
            self._user_output(kin, where)
        return pos

    def _check_cartesian_start(self, pos: Pose, label: str, where: Location) -> None:
        """Kinematics switched on where the tool is outside ``[KINEMATICS]``'s Cartesian limits is an
        error here, naming the pose: else the next move fails, with a message about that move."""
        for axis, value in enumerate(pos):
            low = self.config.cartesian_negative_limits[axis]
            high = self.config.cartesian_positive_limits[axis]
            if not low - SWITCH_TOLERANCE <= value <= high + SWITCH_TOLERANCE:  # (the forward transform rounds)
                from edingcnc_lang.canon import format_pose

                raise MachineError(
                    f"{label} finds the tool at {format_pose(pos, spec='.4f')}: {AXES[axis]} is outside the "
                    f"Cartesian limits [{low:g}, {high:g}] of [KINEMATICS], so no move could start there; "
                    f"bring the joints to a pose inside them before {label.split(' (')[0]} (home the machine, or "
                    f"move with kinematics off), or widen negativeLimit{AXES[axis]}/positiveLimit{AXES[axis]}",
                    where)

    def _forward(self, joints: Pose, where: Location) -> Pose:
        """Cartesian position of ``joints`` under the active kinematics, bend knife correction removed."""
        kin = self.active

        def forward(values: Pose) -> Pose:
            return as_pose(values) if kin is None else self._plugin_call(lambda: as_pose(kin.forward(values)), where)

        pos = forward(joints)
        if not self._bend_active():
            return pos
        import numpy as np

        # the correction depends on Z and C only, which it does not change itself
        return forward(as_pose(np.array(joints) - self._bend_offset(np.array([pos]))[0]))

    def _check_no_jump(self, pos: Pose, label: str, where: Location) -> None:
        """Switching kinematics must not move a motor: the new inverse of ``pos`` must give the current joints."""
        import numpy as np

        joints = self._joints_of(np.array([pos], dtype=float), where)[0]
        jump = np.abs(joints - np.array(self.joints))
        if jump.max() > SWITCH_TOLERANCE:
            axis = int(jump.argmax())
            raise MachineError(f"{label} would make joint {AXES[axis]} jump from {self.joints[axis]:.4f} to "
                               f"{joints[axis]:.4f}; move the machine to where both agree first", where)

    @property
    def joints_are_position(self) -> bool:
        """Whether the joints equal the position now: a simulator may then read a move's path as it is."""
        return self._identity()

    # ---------------------------------------------------------------- helpers
    def _identity(self) -> bool:
        """Joints equal the position: kinematics off or trivial, and no bend knife correction."""
        return (self.active is None or isinstance(self.active, TrivialKinematics)) and not self._bend_active()

    def _bend_active(self) -> bool:
        return self.tanknife and self.config.tanknife.bending_angle != 0.0

    def _control(self, control_id: int, data: list[float], where: Location) -> None:
        result = self._plugin_call(lambda: self.plugin.control(control_id, data), where)
        if result != 0:
            raise MachineError(f"kinematics {self.plugin.name}: control {control_id} returned {result}", where)

    def _plugin_call(self, call: Callable[[], _T], where: Location | None) -> _T:
        """Run plug-in code; its exceptions become a clear error naming the plug-in (exit 70)."""
        try:
            return call()
        except EcncError as err:
            if err.location is None:
                err.location = where
            raise
        except PLUGIN_FAILURES as err:  # noqa: BLE001 - a user plug-in may raise anything
            name = getattr(self.active or self.plugin, "name", "?")
            raise PluginError(f"kinematics plug-in {name} failed: {type(err).__name__}: {err}", where) from None

    def _user_output(self, kin: Kinematics, where: Location) -> None:
        """Copy the kinematics' user output into #start .. #start+n-1 (missing values are 0)."""
        start, count = self.config.user_output_start, self.config.user_output_count
        if start <= 0 or count <= 0:
            return
        values = self._plugin_call(lambda: [float(v) for v in kin.user_output()][:count], where)
        values += [0.0] * (count - len(values))
        for offset, value in enumerate(values):
            self.write_param(start + offset, value)

    def joints_at(self, pos: np.ndarray) -> np.ndarray:
        """Joints of (N, 6) poses under the kinematics now active (the planner's time-true samples)."""
        return self._joints_of(pos, None)

    def _bend_offset(self, pos: np.ndarray) -> np.ndarray:
        """The bend knife's joint XY correction at (N, 6) poses (its Z band is in work coordinates)."""
        import numpy as np

        knife = self.config.tanknife
        offset = np.zeros_like(pos)
        zero = np.zeros(len(pos))
        offset[:, 0], offset[:, 1] = bend_knife_correction(zero, zero, pos[:, 2] - self.knife_z_zero, pos[:, 5],
                                                           knife.bending_angle, knife.z_hi, knife.z_lo)
        return offset

    def _joints_of(self, pos: np.ndarray, where: Location | None) -> np.ndarray:
        """Inverse kinematics of (N, 6) poses in one call, bend correction included; checked for sanity."""
        kin = self.active
        if kin is None:
            joints = pos.copy()
        else:
            try:
                joints = self._plugin_call(lambda: checked_rows(kin.inverse_many(pos), len(pos)), where)
            except KinematicsDomainError as err:
                raise MachineError(f"{err.message} (kinematics {kin.name})", where) from None
        return joints + self._bend_offset(pos) if self._bend_active() else joints

    def _limits_for(self, move: Move) -> AxisLimits:
        """What a move is timed against: joints with kinematics off, [KINEMATICS] (or the plug-in) with them on."""
        if move.kind == "home":
            import numpy as np

            return AxisLimits(np.array(self._home_velocity(move)), self._joint_limits.acceleration)
        limits = self._joint_limits if self._identity() else self._plugin_limits(move) or self._cartesian_limits
        if move.kind == "rapid":
            return AxisLimits(limits.velocity * self._rapid_velocity_factor,
                              limits.acceleration * self.config.g0_acceleration_factor)
        return limits

    def _home_velocity(self, move: Move) -> list[float]:
        """The joints' speeds of a homing move: its feed, else each joint's ``|homeVelocity|``."""
        speed = move.feed / 60.0 if move.feed > 0 else None
        return [float(speed or abs(j.home_velocity) or math.inf) for j in self.config.joints]

    def _plain_limits_for(self, move: Move) -> PlainLimits:
        """``_limits_for`` a move whose joints are its position (kinematics off, nothing sampled), as plain
        floats: the planner times such moves without numpy."""
        if move.kind == "home":
            return PlainLimits(tuple(self._home_velocity(move)), self._straight_limits["linear"].acceleration)
        return self._straight_limits["rapid" if move.kind == "rapid" else "linear"]

    @property
    def _rapid_velocity_factor(self) -> float:
        """Rapids run at the axes' speed times g0VelocityFactor and the rapid override."""
        return self.config.g0_velocity_factor * self.planner.overrides.rapid_factor

    def _plugin_limits(self, move: Move) -> AxisLimits | None:
        """A compiled plug-in's KinematicsInverseMaxFeed(Arc) answer for this move, when it exports one."""
        kin = self.active
        if move.arc is None:
            ask = getattr(kin, "inverse_max_feed", None)
            answer = ask(move.start, move.end) if ask else None
        else:
            ask = getattr(kin, "inverse_max_feed_arc", None)
            geo = geometry_of(move)
            normal = [0.0, 0.0, 0.0]
            normal[geo.normal] = 1.0
            answer = ask(move.start, move.end, geo.center, normal, geo.turns) if ask else None
        return None if answer is None else AxisLimits(_positive(answer[0]), _positive(answer[1]))

    def _sample(self, move: Move) -> tuple[Samples, float, float]:
        """Sample a move at the speed it may run at and evaluate the joints on every sample; return the
        samples, that speed and the path acceleration the joints allow (inf while joints = position).

        Feed moves run at the programmed feed (times the feed override) unless an axis limit
        (Cartesian, or the joints' velocities and accelerations) needs them slower, as the
        controller slows down rather than stops; rapids and homing run as fast as every limit
        allows.  Velocity scales with the path speed and acceleration with its square, so a few
        re-samplings settle the speed.
        """
        import numpy as np

        from edingcnc_lang.kinematics.sampling import TooManySamples

        dt = self.config.interpolation_time
        geo = geometry_of(move)
        limits = self._limits_for(move)
        where = _located(move)
        start, start_joints = np.array(move.start, dtype=float), np.array(self.joints)
        fastest = move.feed <= 0.0 or move.kind == "home"
        joint_timed = not self._identity() and move.kind != "home"
        joint_velocity = self._joint_limits.velocity * (self._rapid_velocity_factor if fastest else 1.0)
        feed = move.feed / 60.0 * (1.0 if move.sync > 0.0 else self.planner.overrides.feed_factor)
        speed = feed if not fastest else geo.chord_speed(limits.velocity)
        joint_dynamics = None
        for attempt in range(PLAN_PASSES + 1):
            try:
                t, pos = geo.sample(speed, dt)
            except TooManySamples as err:
                raise MachineError(str(err), where) from None
            factor = dynamics(0.0, start, t, pos, dt).speed_factor(limits.velocity, limits.acceleration)
            joints = self._joints_of(pos, where) if not self._identity() else pos.copy()
            if joint_timed:
                joint_dynamics = dynamics(0.0, start_joints, t, joints, dt)
                v_ratio, a_ratio = joint_dynamics.ratios(joint_velocity, self._joint_limits.acceleration)
                # the joints' path curvature may use CURVATURE_SHARE of their acceleration
                factor = max(factor, math.sqrt(a_ratio.max() / CURVATURE_SHARE), v_ratio.max())
            done = factor <= 1.0 + 1e-9 and (not fastest or factor >= 0.999 or factor == 0.0)
            if done or attempt == PLAN_PASSES or not math.isfinite(speed / factor):
                break
            speed /= factor
        accel = math.inf
        if joint_dynamics is not None and speed > 0.0:
            # a joint moving g mm per mm of path speeds up g times as hard, with what the curvature leaves
            gain = joint_dynamics.velocity / speed
            room = np.maximum(self._joint_limits.acceleration - joint_dynamics.acceleration, 0.0)
            with np.errstate(divide="ignore", invalid="ignore"):
                accel = float(np.nanmin(np.where(gain > 0.0, room / gain, np.inf)))
            if not accel > 0.0:  # the curvature alone uses all of a joint's acceleration (near a singular
                # pose): the move is timed at a crawl, as the controller would slow to one, never at zero
                accel = CRAWL_ACCELERATION_SHARE * float(np.min(self._joint_limits.acceleration))
        start_time = self.time
        self.time += float(t[-1])
        return Samples(t + start_time, pos, joints), speed, accel

    def _limit_error(self, move: Move, axis: int, value: float) -> MachineError:
        joint = self.config.joints[axis]
        return MachineError(f"joint {AXES[axis]} would reach {value:.4f}, outside its limits "
                            f"[{joint.negative_limit:g}, {joint.positive_limit:g}] ([JOINT_{axis}])", _located(move))

    def _check_exact(self, move: Move) -> None:
        """Joints = position: the end point and an arc's extremes bound the whole move."""
        outside = beyond(move.start, move.end, move.arc, self._lower, self._upper)
        if outside is not None:
            raise self._limit_error(move, *outside)

    def _check_samples(self, move: Move, samples: Samples, start_time: float) -> None:
        """Kinematics on: Cartesian limits, then joint positions, velocities and accelerations."""
        import numpy as np

        where = _located(move)
        if self.active is not None:
            low = np.array(self.config.cartesian_negative_limits)
            high = np.array(self.config.cartesian_positive_limits)
            outside = (samples.pos < low - LIMIT_SLACK) | (samples.pos > high + LIMIT_SLACK)
            if outside.any():
                row, axis = np.argwhere(outside)[0]
                raise MachineError(f"{AXES[axis]} would reach {samples.pos[row, axis]:.4f}, outside the Cartesian "
                                   f"limits [{low[axis]:g}, {high[axis]:g}] of [KINEMATICS]", where)
        joints = samples.joints
        outside = (joints < np.array(self._lower)) | (joints > np.array(self._upper))
        if outside.any():
            row, axis = np.argwhere(outside)[0]
            raise self._limit_error(move, int(axis), float(joints[row, axis]))
        measured = dynamics(start_time, np.array(self.joints), samples.t, joints, self.config.interpolation_time)
        self._check_dynamics(measured, where)

    def _check_dynamics(self, measured: Dynamics, where: Location) -> None:
        """Joint velocities above maxVelocity at the programmed feed are an error.

        Accelerations are not: the planner already slowed the move for them where the path is
        smooth, and at a kink inside a move (the bend knife reaching the edge of its band) the
        sampled velocity steps, which no speed removes and a real controller blends.
        """
        limits = self._joint_limits
        v_ratio, _ = measured.ratios(limits.velocity, limits.acceleration)
        if v_ratio.max() > DYNAMICS_SLACK:
            axis = int(v_ratio.argmax())
            raise MachineError(f"joint {AXES[axis]} would move at {measured.velocity[axis]:.1f} units/s, above its "
                               f"maxVelocity {limits.velocity[axis]:g} ([JOINT_{axis}]); lower the feed", where)

