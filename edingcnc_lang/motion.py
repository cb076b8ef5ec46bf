"""The motion stage: what happens to a move after the interpreter (the canon's machine side).

It turns Cartesian moves into joint positions through the active kinematics,
samples moves at the interpolation rate when the joints need it (kinematics on,
or a samples file asked for), checks joint and Cartesian limits, copies the
kinematics' user output into parameters, and hands each move with its joints
to the output sinks.
"""
from __future__ import annotations

import math
from collections.abc import Callable, Sequence
from dataclasses import dataclass
from typing import Protocol

import numpy as np

from .canon import AXES, PLANES, Event, Move, Pose
from .config import MachineConfig
from .errors import Location, MachineError, PluginError
from .geometry import arc_extremes
from .kinematics import abi
from .kinematics.base import Kinematics, KinematicsDomainError
from .kinematics.builtin import CylinderMapping, TrivialKinematics, bend_knife_correction
from .kinematics.sampling import sample_arc, sample_line

JOINT_NAMES = ("jx", "jy", "jz", "ja", "jb", "jc")
LIMIT_SLACK = 1e-9


class MoveSink(Protocol):
    """Receives every executed move with its joints (and samples when they were computed)."""

    def move(self, move: Move, joints: Pose, samples: "Samples | None") -> None: ...

    def event(self, event: Event) -> None: ...

    def close(self) -> None: ...


@dataclass(frozen=True)
class Samples:
    """One move sampled at the interpolation rate: absolute times, Cartesian poses, joints."""

    t: np.ndarray
    pos: np.ndarray
    joints: np.ndarray


def _located(move: Move) -> Location:
    return Location(move.path, move.line)


class MotionStage:
    """The canon implementation that owns the joints; one per run."""

    def __init__(self, config: MachineConfig, kinematics: Kinematics | None, sinks: Sequence[MoveSink],
                 write_param: Callable[[int, float], None], *, sample_always: bool = False) -> None:
        self.config = config
        self.plugin = kinematics or TrivialKinematics({})
        self.sinks = list(sinks)
        self.write_param = write_param
        self.sample_always = sample_always
        self.active: Kinematics | None = None  # None: kinematics off, joints = position
        self.tanknife = False
        self.joints: list[float] = [0.0] * 6
        self.time = 0.0
        self.moves = 0
        self._lower = np.array([j.negative_limit for j in config.joints])
        self._upper = np.array([j.positive_limit for j in config.joints])
        self._vmax = np.array([max(j.max_velocity, 1e-9) for j in config.joints])
        self._plugin_call(lambda: self.plugin.control(abi.OPEN, [0.0] * 12), None)

    # ---------------------------------------------------------------- canon
    def move(self, move: Move) -> None:
        self.moves += 1
        kin = self.active
        samples = None
        if kin is None and not self.sample_always and not self._bend_active():
            self._check_exact(move)
            joints = move.end
        else:
            samples = self._sample(move, kin)
            joints = tuple(float(v) for v in samples.joints[-1])  # type: ignore[assignment]
            self._check_samples(move, samples)
        self.joints = list(joints)
        if kin is not None:
            self._user_output(kin)
        for sink in self.sinks:
            sink.move(move, joints, samples)  # type: ignore[arg-type]

    def event(self, event: Event) -> None:
        for sink in self.sinks:
            sink.event(event)

    def kinematics(self, mode: str, args: tuple[float, ...], pos: Pose, path: str, line: int) -> Pose:
        where = Location(path, line)
        if mode == "ON":
            data = list(pos) + [0.0] * 6
            self._control(abi.ON, data, where)
            self.active = self.plugin
            new = self._plugin_call(lambda: self.plugin.forward(tuple(self.joints)), where)  # type: ignore[arg-type]
            self._user_output(self.plugin)
            return tuple(float(v) for v in new)  # type: ignore[return-value]
        if mode == "OFF":
            if self.active is self.plugin:
                self._control(abi.OFF, [0.0] * 12, where)
            self.active = None
            return tuple(self.joints)  # type: ignore[return-value]
        if mode == "CTRL":
            control_id = int(args[0])
            data = [*args[1:], *[0.0] * (13 - len(args))]
            self._control(control_id, data, where)
            return pos
        if mode.startswith("TANKNIFE"):
            self.tanknife = mode == "TANKNIFE_ON"
            return pos
        zero_x, zero_y = args[0], args[1]
        wrapped_x = mode in ("X2A", "X2XA")
        self.active = self._plugin_call(
            lambda: CylinderMapping(mode, self.config.kinematics_settings, zero_x if wrapped_x else zero_y,
                                    self.joints[2]), where)
        return pos

    def close(self) -> None:
        self._plugin_call(lambda: self.plugin.control(abi.CLOSE, [0.0] * 12), None)
        for sink in self.sinks:
            sink.close()

    # ---------------------------------------------------------------- helpers
    def _bend_active(self) -> bool:
        return self.tanknife and self.config.tanknife.bending_angle != 0.0

    def _control(self, control_id: int, data: list[float], where: Location) -> None:
        result = self._plugin_call(lambda: self.plugin.control(control_id, data), where)
        if result != 0:
            raise MachineError(f"kinematics {self.plugin.name}: control {control_id} returned {result}", where)

    def _plugin_call(self, call: Callable[[], object], where: Location | None) -> object:
        """Run plug-in code; its exceptions become a clear error naming the plug-in (exit 70)."""
        try:
            return call()
        except MachineError as err:
            if err.location is None:
                err.location = where
            raise
        except Exception as err:  # a user plug-in may raise anything
            raise PluginError(f"kinematics plug-in {self.plugin.name} failed: {type(err).__name__}: {err}",
                              where) from None

    def _user_output(self, kin: Kinematics) -> None:
        start, count = self.config.user_output_start, self.config.user_output_count
        if start <= 0 or count <= 0:
            return
        values = list(self._plugin_call(kin.user_output, None))[:count]  # type: ignore[call-overload]
        values += [0.0] * (count - len(values))
        for offset, value in enumerate(values):
            self.write_param(start + offset, float(value))

    def _feed_mm_s(self, move: Move) -> float:
        if move.feed > 0:
            return move.feed / 60.0
        delta = np.abs(np.subtract(move.end, move.start))
        duration = float(np.max(delta / self._vmax)) * (1.0 / max(self.config.g0_velocity_factor, 1e-9))
        length = math.dist(move.start[:3], move.end[:3]) or float(np.linalg.norm(delta[3:]))
        return length / duration if duration > 0 else 1.0

    def _sample(self, move: Move, kin: Kinematics | None) -> Samples:
        dt = self.config.interpolation_time
        feed = self._feed_mm_s(move)
        if move.arc is not None:
            first, second, normal = PLANES[move.arc.plane]
            center = list(move.start[:3])
            named = move.arc.center
            c1, c2 = (named[1], named[0]) if move.arc.plane == "XZ" else named
            center[first], center[second] = c1, c2
            t, pos = sample_arc(move.start, move.end, center, normal, move.arc.turn, feed, dt)
        else:
            t, pos = sample_line(move.start, move.end, feed, dt)
        if kin is None:
            joints = pos.copy()
        else:
            try:
                joints = np.asarray(self._plugin_call(lambda: kin.inverse_many(pos), _located(move)))
            except KinematicsDomainError as err:
                bad = pos[err.sample or 0]
                raise MachineError(f"position ({', '.join(f'{v:.4f}' for v in bad[:3])}) cannot be reached "
                                   f"by {kin.name}: {err.message}", _located(move)) from None
        if self._bend_active():
            knife = self.config.tanknife
            jx, jy = bend_knife_correction(joints[:, 0], joints[:, 1], pos[:, 2], pos[:, 5],
                                           knife.bending_angle, knife.z_hi, knife.z_lo)
            joints[:, 0], joints[:, 1] = jx, jy
        start = self.time
        self.time += float(t[-1])
        return Samples(t + start, pos, joints)

    def _limit_error(self, move: Move, axis: int, value: float) -> MachineError:
        joint = self.config.joints[axis]
        low, high = joint.negative_limit, joint.positive_limit
        return MachineError(f"joint {AXES[axis]} would reach {value:.4f}, outside its limits "
                            f"[{low:g}, {high:g}] ([JOINT_{axis}] in the ini)", _located(move))

    def _check_exact(self, move: Move) -> None:
        """Trivial kinematics: the end point and an arc's extremes bound the whole move."""
        points = [move.end]
        if move.arc is not None:
            first, second, _ = PLANES[move.arc.plane]
            named = move.arc.center
            center = (named[1], named[0]) if move.arc.plane == "XZ" else named
            s = (move.start[first], move.start[second])
            radius = math.hypot(s[0] - center[0], s[1] - center[1])
            start_angle = math.atan2(s[1] - center[1], s[0] - center[0])
            end_angle = math.atan2(move.end[second] - center[1], move.end[first] - center[0])
            clockwise = move.arc.turn < 0
            sweep = ((start_angle - end_angle) if clockwise else (end_angle - start_angle)) % (2 * math.pi)
            if move.arc.full_turns or sweep < 1e-12:
                sweep = 2 * math.pi
            for p1, p2 in arc_extremes(center, radius, start_angle, sweep, clockwise):
                point = list(move.end)
                point[first], point[second] = p1, p2
                points.append(tuple(point))  # type: ignore[arg-type]
        for point in points:
            for axis, value in enumerate(point):
                if value < self._lower[axis] - LIMIT_SLACK or value > self._upper[axis] + LIMIT_SLACK:
                    raise self._limit_error(move, axis, value)

    def _check_cartesian(self, move: Move, pos: np.ndarray) -> None:
        """With kinematics on, [KINEMATICS] limits bound the Cartesian position."""
        low = np.array(self.config.cartesian_negative_limits)
        high = np.array(self.config.cartesian_positive_limits)
        outside = (pos < low - LIMIT_SLACK) | (pos > high + LIMIT_SLACK)
        if outside.any():
            row, axis = np.argwhere(outside)[0]
            raise MachineError(f"{AXES[axis]} would reach {pos[row, axis]:.4f}, outside the Cartesian limits "
                               f"[{low[axis]:g}, {high[axis]:g}] of [KINEMATICS]", _located(move))

    def _check_samples(self, move: Move, samples: Samples) -> None:
        joints = samples.joints
        if self.active is not None:
            self._check_cartesian(move, samples.pos)
        low = joints < self._lower - LIMIT_SLACK
        high = joints > self._upper + LIMIT_SLACK
        if low.any() or high.any():
            row, axis = np.argwhere(low | high)[0]
            raise self._limit_error(move, int(axis), float(joints[row, axis]))
        if len(joints) > 2:
            dt = np.diff(samples.t)[1:, None]
            speed = np.abs(np.diff(joints[1:], axis=0)) / np.where(dt > 0, dt, np.inf)
            over = speed > self._vmax * 1.01 + 1e-9
            if over.any():
                row, axis = np.argwhere(over)[0]
                raise MachineError(f"joint {AXES[axis]} would move at {speed[row, axis]:.1f} units/s, above its "
                                   f"maxVelocity {self._vmax[axis]:g} ([JOINT_{axis}])", _located(move))
