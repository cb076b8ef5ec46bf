"""The state each part of the interpreter owns: one record per concern, held by ``MachineState``
as one attribute (``machine.files``, ``machine.devices``, ``machine.offsets``, ``machine.scaling``,
``machine.zhc``, ``machine.messages``, ``machine.cycle``, ``machine.spindle``, ``machine.rotation``,
``machine.guards``).

A part's fields are declared here and nowhere else, each with its meaning; the part's module is the
one that changes them (named in each record's docstring), others only read them.  The records have
slots, so a misspelt field is an error where it is written, and mypy checks every read.
``tests/interpreter/test_machine_state.py`` holds the rule: every attribute of a machine is declared
once, in ``MachineState.__init__`` or in one of these records.
"""
from __future__ import annotations

from dataclasses import dataclass, field
from pathlib import Path
from typing import NamedTuple, Protocol, TextIO

from collections.abc import Sequence

from edingcnc_lang.canon import Canon, Pose
from edingcnc_lang.config.heightmap import ZhcTable
from edingcnc_lang.errors import MachineError
from edingcnc_lang.events import MessageEvent
from edingcnc_lang.machine.geometry import scale_about
from edingcnc_lang.machine.job_files import OpenMode, job_file, open_job_file
from edingcnc_lang.machine.parameters import Parameters
from edingcnc_lang.syntax import nodes as n


class PartMachine(Protocol):
    """What every composed part (``devices.py``, ``zhc_commands.py``) uses of the machine, read-only:
    the parameters, the canon, where the run is and errors naming it; each part's own protocol adds
    its record and the few other things it needs."""

    @property
    def params(self) -> Parameters: ...
    @property
    def canon(self) -> Canon: ...
    @property
    def path(self) -> str: ...
    @property
    def line(self) -> int: ...
    def fail(self, message: str, span: n.Span | None = None) -> MachineError: ...


@dataclass(slots=True)
class JobFiles:
    """The files a job names itself (logfile, ZHCS, ZHCL; ``job_files.py`` has the rules): where they
    are and what the job may not touch.  Set by the runner (``own``, ``kept``) and the debugger
    (``log_dir``, ``MachineView.move_files``); ``messages.py`` and ``zhc_commands.py`` open files through it."""

    log_dir: Path | None = None  # --log-dir; None: the folder of the job file running
    own: frozenset[tuple[int, int]] = frozenset()  # the run's files (job, macro files, ini, outputs) as (device,
    #                                                inode): never the job's to write
    kept: dict[Path, str] | None = None  # a run that only looks (plot, view, sim, diff): what the job writes, by file

    def named(self, raw: str, job: str) -> Path:
        """The file ``raw`` names in the log folder of the job file ``job`` runs from (ValueError: no file name)."""
        return job_file(self.log_dir or Path(job).resolve().parent, raw)

    def open(self, path: Path, mode: OpenMode) -> TextIO:
        """``path`` opened safely (OSError with a reason fit for the user), or in memory in a run that only looks."""
        return open_job_file(path, mode, self.own, self.kept)


@dataclass(slots=True)
class DeviceState:
    """The machine's outputs and attached devices (``devices.py``; coolant, outputs and PWM by ``steps.py``'s
    M7..M9, M26/M27 P, M54..M57 steps): what ``M57`` reads back and what M30 switches off."""

    coolant: set[int] = field(default_factory=set)         # 7 mist, 8 flood (M7/M8; M9 clears)
    outputs: dict[int, bool] = field(default_factory=dict)  # AUX outputs as M54/M55 and M26/M27 P set them
    pwm: dict[int, float] = field(default_factory=dict)     # PWM outputs (M54 E Q): duty in per mille
    heaters: dict[str, float] = field(default_factory=dict)  # 3D printing (M104, M140, M106, ...): temperatures, fan
    spindle_selected: int = 90      # M90 (the standard spindle) .. M97; its offsets: MachineState.spindle_offset
    resolution_factor: float = 1.0  # M100 P: the axis resolution factor (3D printing, manual 3.7.12)

    def output_on(self, port: int, spindle: int) -> bool:
        """What ``M57 P<port>`` reads (manual 3.7.8, pp. 64-65), the spindle turning ``spindle`` (M3, M4 or M5):
        AUX1..n as M54/M55 (and M26/M27 P) set them, 51 machine on and 52 drive enable (on while a job runs),
        61 flood (M8), 62 mist (M7), 63 the spindle (tool) on, 64 its direction output (on under M3: "M3 ...
        TOOLDIR = ein", p. 62)."""
        machine = {51: True, 52: True, 61: 8 in self.coolant, 62: 7 in self.coolant, 63: spindle != 5, 64: spindle == 3}
        return machine[port] if port in machine else bool(self.outputs.get(port))


@dataclass(slots=True)
class OffsetState:
    """The tool in use and the offsets that are not parameters (``offsets.py``; the tool's by ``steps.py``'s
    T, M6 and G43 steps; ``tool_cursor`` by ``named_commands.py``'s GetToolInfo)."""

    selected_tool: int = 0             # the T word in force (M6 makes it the current tool, #5008)
    tool_z: float = 0.0                # active G43 length
    tool_x: float = 0.0                # active G43 X offset (lathe), a radius
    length_follows_tool: bool = False  # a plain G43 is in force: every M6 applies the new tool's length
    g92_active: bool = False           # G92 offsets (#5211..) apply (G92, G92.3 on; G92.1, G92.2 off)
    cached: list[float] | None = None  # offset() until a parameter it depends on changes (None: recompute)
    tool_cursor: int = 0               # GetToolInfo next: the tool number it gave last


@dataclass(slots=True)
class ScalingState:
    """G51 as programmed (``scaling_words.py``; the ``Scaling`` stage does the geometry of the moves)."""

    factors: tuple[float, float, float] | None = None  # G51 factors x, y, z (None: off)
    center: tuple[float, float] = (0.0, 0.0)           # G51 centre, programmed machine x, y

    def scaled(self, pose: Sequence[float]) -> Sequence[float]:
        """Where the scaling puts a programmed pose (the stage's map, for what the machine reads back)."""
        return pose if self.factors is None else scale_about(pose, (*self.center, 0.0), self.factors)

    def unscaled(self, pose: Sequence[float]) -> Sequence[float]:
        """The programmed pose the scaling puts at ``pose``."""
        return pose if self.factors is None else scale_about(pose, (*self.center, 0.0), [1.0 / f for f in self.factors])


@dataclass(slots=True)
class ZhcState:
    """Z height compensation (``zhc_commands.py``): the table ZHCINIT/ZHCADDPOINT build and ZHCL loads."""

    table: ZhcTable | None = None


@dataclass(slots=True)
class MessageLog:
    """What the job told the operator and its log file (``messages.py``)."""

    events: list[MessageEvent] = field(default_factory=list)  # every msg, warnmsg, errmsg, dlgmsg and logmsg
    log_file: Path | None = None  # where logmsg writes (logfile, else log.txt in the log folder at the first)
    logged: int = 0               # bytes written to log files by this run (input_limits.MAX_LOG_BYTES)

    def move_files(self, scratch: Path, folder: Path) -> None:
        """A log file opened under ``scratch`` is in ``folder`` from here on."""
        if self.log_file is not None and scratch in self.log_file.parents:
            self.log_file = folder / self.log_file.relative_to(scratch)


@dataclass(slots=True)
class PendingMoves:
    """Straight moves a canned cycle makes one by one, held back to go to the canon as one ``Batch``."""

    start: Pose
    kinds: list[str] = field(default_factory=list)
    lines: list[int] = field(default_factory=list)
    ends: list[Pose] = field(default_factory=list)
    feeds: list[float] = field(default_factory=list)

    def append(self, kind: str, line: int, end: Pose, feed: float) -> None:
        self.kinds.append(kind)
        self.lines.append(line)
        self.ends.append(end)
        self.feeds.append(feed)


@dataclass(slots=True)
class CycleState:
    """What the canned cycles keep between lines (``canned.py``; ``bulk.py`` holds and hands on ``pending``)."""

    words: dict[str, float] = field(default_factory=dict)  # sticky R, Z (the drill axis's word), P, Q, and G87's I J K
    initial: float = 0.0                 # drill-axis level where the cycle sequence started (G98 returns there)
    shift: dict[int, float] = field(default_factory=dict)  # G87: the sideways shift past the boring bar, by axis index
    pitch: float = 0.0                   # G84/G74: mm per spindle revolution (0: not a tapping cycle)
    pending: PendingMoves | None = None  # straight moves held back as one batch (bulk.moves_held)


@dataclass(slots=True)
class SpindleState:
    """The spindle as programmed (``spindle_modes.py``: S, M3/M4/M5, G96/G97; the override by ``steps.py``'s
    M48/M49/M51 and M2/M30; G33's pitch by ``threads.py``; the turns of a G74/G84/G87 cycle by ``canned.py``).
    ``MachineState.css()``, ``rpm_at()`` and ``spindle_along()`` give the speed it turns at."""

    direction: int = 5                 # M3, M4 or M5
    speed: float = 0.0                 # the S word in force: rpm (G97) or surface speed (G96)
    rpm: float = 0.0                   # G97: the speed the spindle turns at, S within the machine's range
    css: tuple[float, float, float] | None = None  # G96: surface mm/min, max and min rpm (None: G97)
    css_max: float = 0.0               # the D word of G96 (0: none)
    sync_pitch: float = 0.0            # K of G33, mm per revolution
    override: float = 100.0            # M51 P..: percent (manual p. 61)
    override_on: bool = True           # M48 on, M49 off, M51 P<0 off

    @property
    def factor(self) -> float:
        """The spindle speed override in force (M48/M49/M51, manual p. 61) as a factor."""
        return self.override / 100.0 if self.override_on else 1.0

    def set_override(self, m: int, p: float | None) -> None:
        """M48 switches the spindle override on at 100 % (there is no spindle knob in a simulation), M49
        off; M51 P.. on at P percent (P0: the knob's 100 %), M51 without P on at the value it had."""
        self.override_on = m != 49
        if m == 48 or (m == 51 and p == 0):
            self.override = 100.0
        elif m == 51 and p is not None:
            self.override = p


class Turn(NamedTuple):
    """G68 in force: the pivot in work coordinates, the angle (degrees, counter-clockwise) and the plane."""

    pivot: tuple[float, float, float]
    angle: float
    plane: str  # "XY", "YZ" or "XZ"


@dataclass(slots=True)
class RotationState:
    """G68 (``offsets.py``: G68/G69, and the pivot the rotation stage is told of as the offsets move it);
    ``moves.py`` (the tangential knife's direction) and ``scaling_words.py`` (G51's centre) read it."""

    turn: Turn | None = None                     # G68 in force (None: G69)
    sent_pivot: tuple[float, ...] | None = None  # the G68 pivot the rotation stage has (None: none sent yet)


@dataclass(slots=True)
class MotionGuards:
    """Switches that change what a move may do or does (``steps.py``'s M26/M27; ``named_commands.py``'s
    TCAGuard, tanknife and KIN): ``MachineState._move`` refuses a move they forbid, ``moves.py`` turns the
    knife, ``threads.py`` takes the Cartesian limits under kinematics, and ``bulk.batchable`` reads them all."""

    clamped: bool = False            # M26: the rotary axes are clamped until M27
    tca_guard: bool = False          # TCAGuard on: moves into the tool-change area are refused
    tanknife: bool = False           # tanknife on: C follows the XY direction of the cut
    kinematics_active: bool = False  # KIN ON or a mapping: the kinematics maps Cartesian moves to the joints


@dataclass
class CallFrame:
    """A sub being run, kept so that errors can show the GoSub chain that led to them."""

    name: str  # lower-case sub name
    path: str
    line: int


@dataclass(slots=True)
class FlowState:
    """The statements' flow (``flow.py``): the subs a job and its macro files define, the subs being
    run (the GoSub chain an error shows, the debugger's call stack) and what ended the run (M2/M30)."""

    subs: dict[str, n.Sub] = field(default_factory=dict)  # by lower-case name
    stack: list[CallFrame] = field(default_factory=list)
    ended_by: str = "end of file"


@dataclass(slots=True)
class StepBudget:
    """The work a run may do (``MachineState.spend``; statements in ``flow.py``, a run of lines in
    ``bulk.py``, holes in ``canned.py``): steps counted against ``limit`` (``--max-steps``)."""

    limit: int | None = None
    steps: int = 0
    cancelled: bool = False  # Run.cancel(): the next step check stops the run

    def cancel(self) -> None:
        """Stop at the next step check (safe from another thread): the budget runs out at once, so
        the hot path checks nothing new."""
        self.cancelled = True
        self.limit = -1

    def room(self) -> int | None:
        """Steps left before the budget runs out (None: no limit)."""
        return None if self.limit is None else self.limit - self.steps
