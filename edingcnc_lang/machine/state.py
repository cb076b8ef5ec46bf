"""The interpreter's machine state and the constants its parts share.

``MachineState`` holds what one virtual machine knows (modal state, position, feed,
parameters, the call stack, and one record per part that owns its state, ``parts.py``) and the
few helpers every part needs: errors that name the line, the step budget and handing a move to
the canon.  The parts of the interpreter (control flow, line steps, offsets, motion, ...) are
mixins on top of it, assembled in ``interpreter.py``.
"""
from __future__ import annotations

import math
import operator
from collections.abc import Callable, Iterable, Mapping, Sequence
from dataclasses import dataclass
from functools import reduce
from operator import itemgetter
from pathlib import Path
from contextlib import AbstractContextManager
from typing import TYPE_CHECKING, ClassVar, Literal

from edingcnc_lang.syntax import nodes as n
from edingcnc_lang.machine import tables as t
from edingcnc_lang.canon import AXES, PLANES, Arc, Batch, Canon, Css, Move, Pose
from edingcnc_lang.config.machine_config import MachineConfig
from edingcnc_lang.diagnostics import Diagnostic
from edingcnc_lang.errors import Cancelled, Location, MachineError
from edingcnc_lang.machine.evaluator import Evaluator
from edingcnc_lang.host import Host
from edingcnc_lang.machine.parameters import Parameters
from edingcnc_lang.machine.spindle import SpindleError, clamp_rpm, mean_rpm_points
from edingcnc_lang.machine.observe import MachineView, Observer
from edingcnc_lang.machine.parts import (CallFrame, CycleState, DeviceState, FlowState, JobFiles, MessageLog,
                                         MotionGuards, OffsetState, RotationState, ScalingState, SpindleState,
                                         StepBudget, ZhcState)

if TYPE_CHECKING:
    from edingcnc_lang.machine.geometry import ArcPlan

INCH = t.MM_PER_INCH
MAX_CALL_DEPTH = 64
MIN_PROBE_DISTANCE = 0.254
PROBE_BACK_OFF = 0.254  # mm the probe backs off after it trips (manual 3.6.10.1; the RS274/NGC canon's)
G = t.code_key  # G(38.2) -> 382

AXIS_INDEX = {a: i for i, a in enumerate(AXES)}
AXIS_SET = frozenset(AXES)
LINEAR_AXES = frozenset("XYZ")
UNSUPPORTED_MOTION: frozenset[int] = frozenset()  # every motion code of the tables runs
PAUSE_CODES = frozenset(t.code_key(c) for c in (0, 1))  # M0, M1 (M60 ends the program like M30)
SPINDLE_SELECT = tuple(range(90, 98))  # M90 standard spindle, M91..M97 alternate spindles (#5390 = 0..7)
# M92..M97 -> the [SPINDLE_n] section whose offsets apply (manual 3.7.2: M91..M93 the 2nd..4th spindle;
# the ini's comments name [SPINDLE_3] "Mounted Probe M95" and [SPINDLE_4] "Mounted camera M97");
# M91's offsets are #5391..#5393 (MachineState.spindle_offset).
SPINDLE_SECTION = {92: 2, 93: 3, 95: 3, 97: 4}
ROTARY = (3, 4, 5)

# G codes as integer tenths, computed once (they are compared on every line).
G_0 = G(0)
G_1 = G(1)
G_2 = G(2)
G_3 = G(3)
G_4 = G(4)
G_10 = G(10)
G_17 = G(17)
G_18 = G(18)
G_19 = G(19)
G_20 = G(20)
G_21 = G(21)
G_28 = G(28)
G_30 = G(30)
G_38_2 = G(38.2)
G_40 = G(40)
G_41 = G(41)
G_41_1 = G(41.1)
G_42_1 = G(42.1)
G_43 = G(43)
G_43_1 = G(43.1)
G_49 = G(49)
G_51 = G(51)
G_53 = G(53)
G_54 = G(54)
G_64 = G(64)
G_68 = G(68)
G_69 = G(69)
G_70 = G(70)
G_80 = G(80)
G_90 = G(90)
G_91 = G(91)
G_92 = G(92)
G_92_1 = G(92.1)
G_92_2 = G(92.2)
G_92_3 = G(92.3)
G_93 = G(93)
G_94 = G(94)
G_95 = G(95)
G_96 = G(96)
G_98 = G(98)
G_99 = G(99)

PLANE_OF = {G_17: "XY", G_18: "XZ", G_19: "YZ"}
# Axis words that give IJK centre offsets per plane, in the plane's (first, second) order.
CENTER_WORDS = {"XY": ("I", "J"), "XZ": ("K", "I"), "YZ": ("J", "K")}
DEFAULT_MODAL = {"motion": G_0, "plane": G_17, "units": G_21, "cutter_comp": G_40,
                 "length_offset": G_49, "coord_system": G_54, "path_control": G_64,
                 "distance": G_90, "feed_mode": G_94, "return_mode": G_98}


# Dispatch tables of the parts (interpreter.py merges them): functions, not method names, so every
# entry is checked by mypy and seen by dead-code tools.  The methods take the part's own type.
StatementTable = dict[type, Callable[..., None]]      # statement type -> (machine, stmt)
StepTable = dict[str, Callable[..., None]]            # ORDER_OF_EXECUTION name -> (machine, value, words, g, span)
CommandTable = dict[str, Callable[..., None]]         # lower-case command name -> (machine, stmt)
MessageKind = Literal["msg", "warn", "error"]       # what ``message`` says (events.MsgEvent, WarnEvent, ErrorEvent)


class ProgramEnd(Exception):
    """M2/M30 (or the end of the file): stops execution wherever it is."""


def format_value(value: float) -> str:
    """How numbers appear in messages: integers plainly, others with up to 4 decimals; an infinite
    or NaN value (only an embedding program can make one) as ``inf``, ``-inf`` or ``nan``."""
    if not math.isfinite(value):
        return str(value)
    if value == int(value) and abs(value) < 1e15:
        return str(int(value))
    if abs(value) >= 1e15:  # not 309 digits for 1e308
        return f"{value:.6g}"
    return f"{value:.4f}".rstrip("0").rstrip(".")



def enters_box(start: Pose, end: Pose | list[float], low: tuple[float, ...], high: tuple[float, ...]) -> bool:
    """Whether the straight XYZ line from start to end goes into the box from outside (an empty box: never)."""
    if all(a >= b for a, b in zip(low[:3], high[:3])) or all(low[i] <= start[i] <= high[i] for i in range(3)):
        return False  # no area configured, or already inside it (leaving is allowed)
    t0, t1 = 0.0, 1.0
    for axis in range(3):
        a, d = start[axis], end[axis] - start[axis]
        if abs(d) < 1e-12:
            if not low[axis] <= a <= high[axis]:
                return False
            continue
        u0, u1 = sorted(((low[axis] - a) / d, (high[axis] - a) / d))
        t0, t1 = max(t0, u0), min(t1, u1)
        if t0 > t1:
            return False
    return True


_XYZ = itemgetter(slice(0, 3))  # a pose's X Y Z (``travelled``)


def path_length(start: Pose, end: Pose | list[float], arc: Arc | None) -> float:
    """How far the tool travels along a move (mm): the helix of an arc, else the straight XYZ line."""
    if arc is None:
        return xyz_distance(start, end)
    first, second, normal = PLANES[arc.plane]
    cx, cy = (arc.center[1], arc.center[0]) if arc.plane == "XZ" else arc.center
    a0 = math.atan2(start[second] - cy, start[first] - cx)
    a1 = math.atan2(end[second] - cy, end[first] - cx)
    turned = ((a1 - a0) * arc.turn) % (2 * math.pi) + 2 * math.pi * arc.full_turns
    radius = math.hypot(start[first] - cx, start[second] - cy)
    return math.hypot(radius * turned, end[normal] - start[normal])


def xyz_distance(a: list[float] | Pose, b: list[float] | Pose) -> float:
    """Length of a move in XYZ (mm)."""
    return math.dist(a[:3], b[:3])


def fmt_point(point: tuple[float, float]) -> str:
    return ", ".join(f"{v:.4f}" for v in point)


class MachineState:
    """What one virtual machine knows; create one Interpreter per job run."""

    # Built by interpreter.py from the parts: statement type -> method, and the steps of a line in order.
    _EXECUTE: ClassVar[StatementTable]
    _LINE_STEPS: ClassVar[tuple[tuple[Callable[..., None], str, str], ...]]

    def __init__(self, canon: Canon, config: MachineConfig | None = None, host: Host | None = None, *,
                 max_steps: int | None = None, log_dir: Path | None = None, allow_exec: bool = False,
                 simulation: bool = True, block_delete: bool = False, observer: Observer | None = None) -> None:
        self.canon = canon
        self.observer = observer
        self.view = MachineView(self)  # what the observer is shown
        self.config = config or MachineConfig.default()
        self.host = host or Host()
        self.budget = StepBudget(max_steps)
        self.files = JobFiles(log_dir)  # the files a job names: where they go, which it may not touch
        self.allow_exec = allow_exec
        self.block_delete = block_delete
        self.flow = FlowState()
        self.params = Parameters(self._live_param, self._offsets_changed)
        self.evaluator = Evaluator(self.params)
        self.modal: dict[str, int] = dict(DEFAULT_MODAL)
        if not self.config.g64_active:  # [INTERPRETER] g64Active = 0: the machine starts in exact stop
            self.modal["path_control"] = t.code_key(61)
        self.pos: list[float] = [0.0] * 6  # machine coordinates, mm / degrees
        self.feed = 0.0                    # mm/min (G94), or the raw F in G93/G95
        # the parts' own state, one record each (parts.py declares their fields)
        self.spindle = SpindleState()
        self.devices = DeviceState()
        self.offsets = OffsetState()
        self.scaling = ScalingState()
        self.zhc = ZhcState()
        self.messages = MessageLog()
        self.cycle = CycleState()
        self.rotation = RotationState()
        self.guards = MotionGuards()
        self.job_distance = 0.0            # mm the tool has travelled (GetJobDistance)
        # The tool numbers the loaded job uses (GetToolInfo), asked for only when a macro wants them;
        # the runner sets it, an MDI session has no loaded job.
        self.job_tools: Callable[[], Sequence[int]] = tuple
        # told of each warning a line earns (a limit of the machine changed what it asked for); the
        # runner reports them as it reports load warnings; once per file and line
        self.on_warning: Callable[[Diagnostic], None] | None = None
        self._warned: set[tuple[str, int, str]] = set()
        self.path = "<string>"
        self.line = 0
        self._init_params(simulation)
        if self.config.lathe:
            self.modal["plane"] = G_18

    def _init_params(self, simulation: bool) -> None:
        initial: dict[int, float] = dict(self.config.variables)
        for number, tool in self.config.tools.items():
            initial[t.TOOL_LENGTH + number] = tool.length
            initial[t.TOOL_DIAMETER + number] = tool.diameter
            initial[t.TOOL_X_OFFSET + number] = tool.width
            initial[t.TOOL_X_WEAR + number] = tool.x_delta
            initial[t.TOOL_Z_WEAR + number] = tool.z_delta
            initial[t.TOOL_ORIENTATION + number] = float(tool.orientation)
        for axis, joint in enumerate(self.config.joints):
            initial[t.SOFT_LIMIT_NEG + axis] = joint.negative_limit
            initial[t.SOFT_LIMIT_POS + axis] = joint.positive_limit
            initial[t.HOME_POSITION + axis] = joint.home_position
        alternate = self.config.spindle_offsets[1]  # [SPINDLE_1], the 2nd spindle (M91), else the saved #5391..#5393
        if any(alternate):
            for axis in range(3):
                initial[t.ALT_SPINDLE_OFFSET + axis] = alternate[axis]
        for axis in range(3):  # the tool-change area (manual 3.1: #5131..#5133, #5141..#5143)
            initial[t.TCA_NEGATIVE + axis] = self.config.tca_negative[axis]
            initial[t.TCA_POSITIVE + axis] = self.config.tca_positive[axis]
        initial.setdefault(t.COORD_SYSTEM, 1.0)
        initial[t.SIMULATION] = 1.0 if simulation else 0.0
        initial[t.KIN_TYPE] = 1.0
        self.params.load(initial)
        system = int(self.params.values[t.COORD_SYSTEM])
        self.modal["coord_system"] = t.COORD_SYSTEM_CODES[system - 1] if 1 <= system <= 9 else G_54
        self.params.values[t.COORD_SYSTEM] = float(t.COORD_SYSTEM_CODES.index(self.modal["coord_system"]) + 1)
        self.offsets.g92_active = any(self.params.values[t.G92_OFFSET + i] for i in range(6))

    @property
    def inch(self) -> bool:
        """The program's lengths are inches (G20/G70)."""
        return self.modal["units"] in (G_20, G_70)

    @property
    def scale(self) -> float:
        return INCH if self.inch else 1.0

    def where(self, span: n.Span | None = None) -> Location:
        if span is not None and span.line:
            return Location(span.path, span.line, span.col)
        return Location(self.path, self.line)

    def warn(self, code: str, message: str, span: n.Span | None = None) -> None:
        """A warning at the line (``code`` from codes.py), once per file, line and code."""
        where = self.where(span)
        key = (where.path, where.line or 0, code)
        if self.on_warning is not None and key not in self._warned:
            self._warned.add(key)
            self.on_warning(Diagnostic.make(code, message, where.path, where.line or 0, where.col or 1))

    def fail(self, message: str, span: n.Span | None = None) -> MachineError:
        return MachineError(message, self.where(span))

    def refuse_with_comp(self, what: str, span: n.Span | None) -> None:
        """``what`` is refused while cutter compensation is on (as LinuxCNC does)."""
        if self.modal["cutter_comp"] != G_40:
            raise self.fail(f"{what} is not allowed while cutter compensation (G41/G42) is on; "
                            "turn it off with G40 first", span)

    def cancel(self) -> None:
        """Stop the run at its next statement, loop turn or hole (``Run.cancel``; safe from another thread)."""
        self.budget.cancel()

    def spend(self, steps: int, span: n.Span | None = None) -> None:
        """Count work against the step budget (statements, loop turns, canned-cycle holes and pecks)."""
        budget = self.budget
        budget.steps += steps
        if budget.limit is not None and budget.steps > budget.limit:
            if budget.cancelled:
                raise Cancelled("cancelled by the embedding program", self.where(span))
            raise self.fail(f"step budget of {budget.limit:,} steps exhausted (an endless loop?): statements, "
                            "loop turns and drilled holes count; raise it with --max-steps N "
                            "(RunOptions.max_steps in Python)", span)

    @property
    def diameter_mode(self) -> bool:
        """X words and the work X position are diameters (a lathe with diameterProgramming = 1)."""
        return self.config.diameter_mode

    @property
    def spindle_offset(self) -> tuple[float, float, float]:
        """The selected spindle's offsets (manual 3.7.2): M91's are #5391..#5393 (the ini's [SPINDLE_1] at the
        start; a program may write them), M92..M97 their [SPINDLE_n] sections', M90 none."""
        m = self.devices.spindle_selected
        if m == 91:
            values = self.params.values
            return (values[t.ALT_SPINDLE_OFFSET], values[t.ALT_SPINDLE_OFFSET + 1], values[t.ALT_SPINDLE_OFFSET + 2])
        section = SPINDLE_SECTION.get(m)
        return self.config.spindle_offsets[section] if section is not None else (0.0, 0.0, 0.0)

    def css(self, overridden: bool = True) -> Css | None:
        """Constant surface speed in force (G96), centred on the current work X0; None under G97.
        The spindle override scales the surface speed the spindle keeps (``overridden``)."""
        spindle = self.spindle
        if spindle.css is None:
            return None
        surface, max_rpm, min_rpm = spindle.css
        return Css(surface * (spindle.factor if overridden else 1.0), max_rpm, min_rpm, self.offset()[0])

    def rpm_at(self, x: float, overridden: bool = True) -> float:
        """The spindle speed with the tool at machine X ``x`` (also while it is stopped): the programmed
        one, times the spindle override unless ``overridden`` is False, within the machine's range."""
        css = self.css(overridden)
        return css.rpm(x) if css is not None else self._overridden_rpm() if overridden else self.spindle.rpm

    def _overridden_rpm(self) -> float:
        """The G97 speed the spindle turns at under the spindle override, within the machine's range."""
        spindle = self.spindle
        factor = spindle.factor
        if factor == 1.0:
            return spindle.rpm
        return clamp_rpm(spindle.rpm * factor, self.config.spindle_max_rpm, self.config.spindle_min_rpm)

    def _move(self, kind: str, end: list[float], feed: float = 0.0, arc: Arc | None = None,
              sync: float = 0.0) -> None:
        start = tuple(self.pos)
        guards = self.guards
        if guards.clamped and kind != "home" and any(abs(end[i] - start[i]) > 1e-9 for i in ROTARY):
            raise self.fail("a rotary axis cannot move while it is clamped (M26): release it with M27 first")
        if guards.tca_guard and kind != "home" and \
                enters_box(start, end, self.config.tca_negative, self.config.tca_positive):
            low, high = self.config.tca_negative, self.config.tca_positive
            raise self.fail("the move enters the tool-change area while TCAGuard is on (X "
                            f"{low[0]:g}..{high[0]:g} Y {low[1]:g}..{high[1]:g} Z {low[2]:g}..{high[2]:g}, "
                            "cnc.ini [KINEMATICS] ...TCA): switch it off with TCAGuard off first")
        pending = self.cycle.pending
        if pending is not None:
            if arc is None and not sync and kind != "home":  # a straight move of a canned cycle: into its batch
                pending.append(kind, self.line, tuple(end), feed)
                self.pos = list(end)
                return
            self.flush_pending()  # the moves before this one go first
        rpm, css = self.spindle_along()
        self.canon.move(Move(kind, self.path, self.line, start, tuple(end), feed, arc,
                             css.rpm(end[0]) if css is not None else rpm, css, sync, self.caller()))
        self.job_distance += path_length(start, end, arc)
        self.pos = list(end)  # only a move the machine made changes the position

    def travelled(self, start: Pose | list[float], ends: Sequence[Pose], arc_lengths: Mapping[int, float]) -> None:
        """Count moves from ``start`` through ``ends`` into GetJobDistance, one by one as ``_move`` does: straight,
        or arcs, whose ``path_length`` the bulk path found as it read them (``arc_lengths``, by index)."""
        if len(arc_lengths) == len(ends):  # arcs only (a run of arc lines): their lengths in order
            steps: Iterable[float] = map(arc_lengths.__getitem__, range(len(ends)))
        else:
            points = [start[:3], *map(_XYZ, ends)]
            steps = list(map(math.dist, points, points[1:]))  # xyz_distance of each move
            for index, length in arc_lengths.items():
                steps[index] = length
        self.job_distance = reduce(operator.add, steps, self.job_distance)  # one at a time, in order

    def spindle_along(self) -> tuple[float, Css | None]:
        """The spindle a move made now carries: its speed in rpm (0 while stopped) and, under G96, the
        constant surface speed that gives the speed at any X instead."""
        if self.spindle.direction == 5:
            return 0.0, None
        css = self.css()
        return (0.0, css) if css is not None else (self._overridden_rpm(), None)

    def caller(self) -> int:
        """``Move.caller`` of a move made now: the line of the outermost sub call, 0 at the top level."""
        return self.flow.stack[0].line if self.flow.stack else 0

    def mean_rpm(self, xs: list[float], span: n.Span | None) -> float:
        """The spindle speed that gives a per-revolution move through machine X ``xs`` its true time."""
        css = self.css()
        if css is None:
            return self._overridden_rpm()
        try:
            return mean_rpm_points(css, xs)
        except SpindleError as err:
            raise self.fail(str(err), span) from None

    def _feed_for(self, length: float, words: Mapping[str, float], span: n.Span | None,
                  xs: list[float] | None = None) -> float:
        """The feed (mm/min) of a feed move of ``length`` mm under the active feed mode.

        ``xs`` are machine X values along the move (start to end), for feed per revolution
        under constant surface speed; by default the move is straight from here to here.
        """
        mode = self.modal["feed_mode"]
        if mode == G_93:
            if "F" not in words or words["F"] <= 0:
                raise self.fail("inverse time mode (G93) needs a positive F on every feed move", span)
            return length * words["F"]
        if mode == G_95:
            rpm = self.mean_rpm(xs or [self.pos[0]], span)
            if self.feed > 0 and rpm <= 0:
                raise self.fail("feed per revolution (G95) with no spindle speed: program S first", span)
            rate = self.feed * rpm
        else:
            rate = self.feed
        if rate <= 0:
            raise self.fail("feed rate is 0: program an F word before this feed move (EdingCNC error G1516)",
                            span)
        return rate

    if TYPE_CHECKING:
        # What the parts call on each other.  Each is defined once, in the part named; interpreter.py
        # assembles the parts into one class, and these declarations let mypy check every such call.
        def execute(self, stmt: n.Stmt) -> None: ...                                         # flow.py
        def call_sub(self, name: str, span: n.Span | None = None) -> None: ...              # flow.py
        def _exec_plain_run(self, run: n.PlainRun) -> None: ...                              # bulk.py
        def _exec_plain_lines(self, run: n.PlainRun) -> None: ...                            # bulk.py
        def batchable(self) -> bool: ...                                                     # bulk.py
        def make_batch(self, batch: Batch, arc_lengths: Mapping[int, float], by_line: bool) -> None: ...  # bulk.py
        def moves_held(self) -> AbstractContextManager[None]: ...                            # bulk.py
        def flush_pending(self) -> None: ...                                                 # bulk.py
        def message(self, kind: MessageKind, text: str) -> None: ...  # messages.py
        def move_files(self, scratch: Path, folder: Path) -> None: ...  # messages.py
        def offset(self) -> list[float]: ...                                                 # offsets.py
        def _live_param(self, index: int) -> float: ...                                      # offsets.py
        def _offsets_changed(self) -> None: ...                                              # offsets.py
        def _target(self, words: Mapping[str, float], machine: bool = False,
                    start: Sequence[float] | None = None) -> list[float]: ...                 # offsets.py
        def machine_kept(self) -> AbstractContextManager[None]: ...                          # offsets.py
        def _axis_values(self, words: Mapping[str, float]) -> dict[int, float]: ...          # offsets.py
        def work_position(self, machine: list[float] | None = None) -> list[float]: ...      # offsets.py
        def to_machine(self, work: list[float]) -> list[float]: ...                          # offsets.py
        def machine_frame(self, pose: list[float] | tuple[float, ...]) -> tuple[float, ...]: ...  # offsets.py
        def program_frame(self, pose: list[float] | tuple[float, ...]) -> list[float]: ...   # offsets.py
        def reported_position(self, machine: list[float] | None = None) -> list[float]: ...  # offsets.py
        def _machine_move(self, kind: str, machine: list[float], feed: float = 0.0) -> None: ...  # offsets.py
        def _select_coord_system(self, code: int) -> None: ...                               # offsets.py
        def _rotation(self, code: int, words: Mapping[str, float], span: n.Span) -> None: ...  # offsets.py
        def scaling_off(self) -> None: ...                                                   # scaling.py
        def _motion(self, words: Mapping[str, float], g: Mapping[str, int], non_modal: int | None,
                    span: n.Span) -> None: ...                                               # moves.py
        def arc_plan(self, plane: str, clockwise: bool, start: Sequence[float], end: Sequence[float],
                     words: Mapping[str, float]) -> ArcPlan: ...                            # moves.py
        def _cycle(self, motion: int, words: Mapping[str, float], span: n.Span, new_sequence: bool) -> None: ...  # canned.py
        def hole_run(self, path: str, lines: Sequence[tuple[int, str]], first: int,
                     block: n.PlainBlock) -> int: ...                                        # canned.py
        def _synchronised(self, motion: int, words: Mapping[str, float], span: n.Span) -> None: ...  # threads.py
        def _sync_move(self, end: list[float], pitch: float, span: n.Span | None) -> None: ...  # threads.py
        def _spindle_stop(self) -> None: ...                                                 # spindle_modes.py
        def _step_feed(self, value: float, words: Mapping[str, float], g: Mapping[str, int], span: n.Span) -> None: ...
        def _step_spindle_speed(self, value: float, words: Mapping[str, float], g: Mapping[str, int],
                                span: n.Span) -> None: ...
        def _step_tool_select(self, value: float, words: Mapping[str, float], g: Mapping[str, int],
                              span: n.Span) -> None: ...
