"""The interpreter: executes statements against a virtual machine state.

It evaluates expressions, keeps the modal state, offsets, tools and
parameters, runs subs and control flow, and emits every move and event to a
``Canon``.  It knows nothing of kinematics, traces or files written: those sit
behind the canon.  One Interpreter is one machine; there is no global state.
"""
from __future__ import annotations

import math
import re
from collections.abc import Callable, Iterable, Mapping
from dataclasses import dataclass
from pathlib import Path, PureWindowsPath
from typing import TYPE_CHECKING, Any

from . import nodes as n
from . import tables as t
from .canon import AXES, PLANES, Arc, Canon, Event, Move, Pose
from .config import MachineConfig
from .errors import EcncError, JobAborted, Location, MachineError
from .evaluator import Evaluator, param_index
from .geometry import ArcError, center_from_radius, check_radius, sweep
from .host import DialogAnswer, DialogField, Host
from .params import Parameters
from .parser import plain_block, plain_words

if TYPE_CHECKING:
    from .cycles import Step

INCH = 25.4
MAX_CALL_DEPTH = 64
MAX_DIALOG_FIELDS = 15
MIN_PROBE_DISTANCE = 0.254
G = t.code_key  # G(38.2) -> 382

_NUM = r"([+-]?(?:\d+\.?\d*|\.\d+))[ \t]*"
CAM_LINE = re.compile(r"[ \t]*(?:[Gg][ \t]*" + _NUM + ")?" + "".join(
    f"(?:[{a}{a.lower()}][ \\t]*{_NUM})?" for a in AXES + "F") + r"(?:;.*)?$")
AXIS_INDEX = {a: i for i, a in enumerate(AXES)}
AXIS_SET = frozenset(AXES)
LINEAR_AXES = frozenset("XYZ")
UNSUPPORTED_MOTION = frozenset(t.code_key(c) for c in (33, 33.1, 74, 76, 87))  # threading, back boring
PAUSE_CODES = frozenset(t.code_key(c) for c in (0, 1, 60))  # M0, M1, M60

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
G_98 = G(98)
G_99 = G(99)

PLANE_OF = {G_17: "XY", G_18: "XZ", G_19: "YZ"}
# Axis words that give IJK centre offsets per plane, in the plane's (first, second) order.
CENTER_WORDS = {"XY": ("I", "J"), "XZ": ("K", "I"), "YZ": ("J", "K")}
MOTION_CODES = frozenset(G(c) for c in (0, 1, 2, 3, 38.2)) | t.CANNED_CYCLES
DEFAULT_MODAL = {"motion": G_0, "plane": G_17, "units": G_21, "cutter_comp": G_40,
                 "length_offset": G_49, "coord_system": G_54, "path_control": G_64,
                 "distance": G_90, "feed_mode": G_94, "return_mode": G_98}


class ProgramEnd(Exception):
    """M2/M30 (or the end of the file): stops execution wherever it is."""


@dataclass
class CallFrame:
    """A sub being run, kept so that errors can show the GoSub chain that led to them."""

    name: str  # lower-case sub name
    path: str
    line: int


def format_value(value: float) -> str:
    """How numbers appear in messages: integers plainly, others with up to 4 decimals."""
    if value == int(value) and abs(value) < 1e15:
        return str(int(value))
    return f"{value:.4f}".rstrip("0").rstrip(".")


class Interpreter:
    """Runs EdingCNC statements; create one per job run."""

    def __init__(self, canon: Canon, config: MachineConfig | None = None, host: Host | None = None, *,
                 max_steps: int | None = None, log_dir: Path | None = None, allow_exec: bool = False,
                 simulation: bool = True, block_delete: bool = False) -> None:
        self.canon = canon
        self.config = config or MachineConfig.default()
        self.host = host or Host()
        self.max_steps = max_steps
        self.log_dir = log_dir
        self.allow_exec = allow_exec
        self.block_delete = block_delete
        self.steps = 0
        self.subs: dict[str, n.Sub] = {}
        self.stack: list[CallFrame] = []
        self.params = Parameters(self._live_param, self._offsets_changed)
        self.evaluator = Evaluator(self.params)
        self.modal: dict[str, int] = dict(DEFAULT_MODAL)
        self.pos: list[float] = [0.0] * 6  # machine coordinates, mm / degrees
        self.feed = 0.0                    # mm/min (G94), or the raw F in G93/G95
        self.speed = 0.0
        self.spindle = 5                   # M3, M4 or M5
        self.coolant: set[int] = set()
        self.selected_tool = 0
        self.tool_z = 0.0                  # active G43 length
        self.g92_active = False
        self.rotation: tuple[float, float, float] | None = None  # G68 pivot x, y and angle (deg)
        self.cycle_words: dict[str, float] = {}  # sticky R, Z (drill axis), P, Q of canned cycles
        self.cycle_initial = 0.0                 # drill-axis level where the cycle sequence started
        self.outputs: dict[int, bool] = {}
        self.kinematics_active = False
        self.tanknife = False
        self.ended_by = "end of file"
        self.messages: list[Event] = []
        self.path = "<string>"
        self.line = 0
        self._offset: list[float] | None = None
        self._tool_cursor = 0
        self._log_file: Path | None = None
        self._init_params(simulation)

    # ------------------------------------------------------------------ state
    def _init_params(self, simulation: bool) -> None:
        initial: dict[int, float] = dict(self.config.variables)
        for number, tool in self.config.tools.items():
            initial[t.TOOL_LENGTH + number] = tool.length
            initial[t.TOOL_DIAMETER + number] = tool.diameter
            initial[t.TOOL_X_OFFSET + number] = tool.x_delta
            initial[t.TOOL_ORIENTATION + number] = float(tool.orientation)
        for axis, joint in enumerate(self.config.joints):
            initial[t.SOFT_LIMIT_NEG + axis] = joint.negative_limit
            initial[t.SOFT_LIMIT_POS + axis] = joint.positive_limit
            initial[t.HOME_POSITION + axis] = joint.home_position
        initial.setdefault(t.COORD_SYSTEM, 1.0)
        initial[t.SIMULATION] = 1.0 if simulation else 0.0
        initial[t.KIN_TYPE] = 1.0
        self.params.load(initial)
        system = int(self.params.values[t.COORD_SYSTEM])
        self.modal["coord_system"] = t.COORD_SYSTEM_CODES[system - 1] if 1 <= system <= 9 else G_54
        self.params.values[t.COORD_SYSTEM] = float(t.COORD_SYSTEM_CODES.index(self.modal["coord_system"]) + 1)
        self.g92_active = any(self.params.values[t.G92_OFFSET + i] for i in range(6))

    @property
    def scale(self) -> float:
        return INCH if self.modal["units"] in (G_20, G_70) else 1.0

    def _offsets_changed(self) -> None:
        self._offset = None
        system = self.params.values[t.COORD_SYSTEM]  # a macro may select the system by writing #5220
        if system == int(system) and 1 <= system <= 9:
            self.modal["coord_system"] = t.COORD_SYSTEM_CODES[int(system) - 1]

    def offset(self) -> list[float]:
        """Machine minus work position: G5x + G92 (if active) + tool length on Z (if G43)."""
        if self._offset is None:
            values = self.params.values
            system = int(values[t.COORD_SYSTEM]) if 1 <= values[t.COORD_SYSTEM] <= 9 else 1
            off = [values[t.coord_offset_param(system, i)] for i in range(6)]
            if self.g92_active:
                off = [o + values[t.G92_OFFSET + i] for i, o in enumerate(off)]
            off[2] += self.tool_z
            self._offset = off
        return self._offset

    def to_machine(self, work: list[float]) -> list[float]:
        if self.rotation:
            work = list(work)
            px, py, angle = self.rotation
            c, s = math.cos(math.radians(angle)), math.sin(math.radians(angle))
            dx, dy = work[0] - px, work[1] - py
            work[0], work[1] = px + c * dx - s * dy, py + s * dx + c * dy
        return [w + o for w, o in zip(work, self.offset())]

    def work_position(self, machine: list[float] | None = None) -> list[float]:
        """Work coordinates (mm) of a machine position, in the program's (G68-rotated) frame."""
        work = [m - o for m, o in zip(machine or self.pos, self.offset())]
        if self.rotation:
            px, py, angle = self.rotation
            c, s = math.cos(math.radians(angle)), math.sin(math.radians(angle))
            dx, dy = work[0] - px, work[1] - py
            work[0], work[1] = px + c * dx + s * dy, py - s * dx + c * dy
        return work

    def _live_param(self, index: int) -> float:
        if index >= t.POS_MACHINE:
            return self.pos[index - t.POS_MACHINE]
        return self.work_position()[index - t.POS_WORK]

    def where(self, span: n.Span | None = None) -> Location:
        if span is not None and span.line:
            return Location(span.path, span.line, span.col)
        return Location(self.path, self.line)

    def fail(self, message: str, span: n.Span | None = None) -> MachineError:
        return MachineError(message, self.where(span))

    # ------------------------------------------------------------------ programs
    def define_subs(self, subs: Iterable[n.Sub]) -> None:
        """Register subs (the first definition of a name wins, like a lookup in file order)."""
        for sub in subs:
            self.subs.setdefault(sub.name.lower(), sub)

    def run(self, statements: Iterable[n.Stmt]) -> bool:
        """Execute top-level statements; Sub definitions are skipped. False if M2/M30 ended the run."""
        try:
            for stmt in statements:
                kind = type(stmt)
                if kind is n.PlainRun:  # a chunk of lines, each counted as a statement
                    self._exec_plain_run(stmt)  # type: ignore[arg-type]
                elif kind is not n.Sub:
                    self.execute(stmt)
        except ProgramEnd:
            return False
        return True

    def call_sub(self, name: str, span: n.Span | None = None) -> None:
        """GoSub: run a sub by (case-insensitive) name."""
        sub = self.subs.get(name.lower())
        if sub is None:
            raise self.fail(f"GoSub {name}: no Sub {name} is defined in the job or the macro files", span)
        if len(self.stack) >= MAX_CALL_DEPTH:
            raise self.fail(f"GoSub {name}: calls nested deeper than {MAX_CALL_DEPTH} (endless recursion?)", span)
        frame = CallFrame(sub.name.lower(), self.path, self.line)
        self.stack.append(frame)
        try:
            self.execute_body(sub.body)
        except EcncError as err:
            err.notes = (*err.notes, f"in Sub {sub.name}, called from {frame.path}:{frame.line}")
            raise
        finally:
            self.stack.pop()

    def execute_body(self, body: tuple[n.Stmt, ...]) -> None:
        for stmt in body:
            self.execute(stmt)

    def execute(self, stmt: n.Stmt) -> None:
        span = stmt.span
        self.path, self.line = span.path, span.line
        self.steps += 1
        if self.max_steps is not None and self.steps > self.max_steps:
            self.spend(0, span)  # reports the exhausted budget
        self._EXECUTE[type(stmt)](self, stmt)

    def spend(self, steps: int, span: n.Span | None = None) -> None:
        """Count work against the step budget (statements, loop turns, canned-cycle holes and pecks)."""
        self.steps += steps
        if self.max_steps is not None and self.steps > self.max_steps:
            raise self.fail(f"step budget of {self.max_steps} steps exhausted (an endless loop?); "
                            "raise it with --max-steps", span)

    # ------------------------------------------------------------------ control flow
    def _condition(self, expr: n.Expr) -> bool:
        return self.evaluator.value(expr) != 0.0

    def _exec_if(self, stmt: n.If) -> None:
        self.execute_body(stmt.then if self._condition(stmt.cond) else stmt.orelse)

    def _exec_while(self, stmt: n.While) -> None:
        while self._condition(stmt.cond):
            self.execute_body(stmt.body)
            self.path, self.line = stmt.span.path, stmt.span.line
            self.spend(1, stmt.span)

    def _exec_gosub(self, stmt: n.GoSub) -> None:
        self.call_sub(stmt.name, stmt.span)

    def _exec_sub(self, stmt: n.Sub) -> None:
        raise self.fail(f"Sub {stmt.name} is defined inside a block; subs must be at the top level", stmt.span)

    # ------------------------------------------------------------------ messages and dialogs
    def _text(self, items: tuple[n.MessageItem, ...]) -> str:
        return "".join(item if isinstance(item, str) else format_value(self.evaluator.value(item))
                       for item in items)

    def message(self, kind: str, text: str, data: Mapping[str, object] | None = None) -> None:
        event = Event(kind, self.path, self.line, {"text": text, **(data or {})})
        self.messages.append(event)
        self.canon.event(event)
        if self.host.message:
            self.host.message(kind, text, self.path, self.line)

    def _exec_message(self, stmt: n.Message) -> None:
        text = self._text(stmt.items)
        if stmt.kind == "logmsg":
            self._log(text, stmt.span)
        elif stmt.kind == "errmsg":
            self.message("error", text)
            raise JobAborted(text, Location(self.path, self.line))
        else:
            self.message("warn" if stmt.kind == "warnmsg" else "msg", text)

    def _exec_dialog(self, stmt: n.Dialog) -> None:
        items = stmt.items
        if not items or not isinstance(items[0], str):
            raise self.fail("dlgmsg needs a title string first", stmt.span)
        fields: list[DialogField] = []
        rest = list(items[1:])
        while rest:
            label = rest.pop(0)
            if not isinstance(label, str):
                raise self.fail("dlgmsg expects \"label\" number pairs after the title (EdingCNC error G1167)",
                                label.span)
            if not rest or not isinstance(rest[0], n.Number):
                where = rest[0].span if rest and not isinstance(rest[0], str) else stmt.span
                raise self.fail(f"dlgmsg field \"{label}\" needs a parameter number written without '#' "
                                "(EdingCNC error G1167)", where)
            number = rest.pop(0)
            index = param_index(number.value, number.span)  # type: ignore[union-attr]
            fields.append(DialogField(label, index, self.params.read(index)))
        if len(fields) > MAX_DIALOG_FIELDS:
            raise self.fail(f"dlgmsg has {len(fields)} fields; at most {MAX_DIALOG_FIELDS} fit", stmt.span)
        answer = (self.host.dialog(items[0], fields) if self.host.dialog else None) or DialogAnswer()
        unknown = set(answer.values) - {f.index for f in fields}
        if unknown:
            raise self.fail(f"the answer sets #{min(unknown)}, which is not a field of this dialog", stmt.span)
        if answer.ok:
            for index, value in answer.values.items():
                self.params.write(index, value, self.where(stmt.span))
        self.params.set(t.DIALOG_RESULT, 1.0 if answer.ok else -1.0)
        self.message("dialog", items[0], {"ok": answer.ok,
                                          "fields": {f.label: self.params.read(f.index) for f in fields}})

    def _exec_logfile(self, stmt: n.LogFile) -> None:
        mode = self.evaluator.value(stmt.mode) if stmt.mode is not None else 1.0
        name = PureWindowsPath(stmt.name).name  # never outside the log folder, whatever the path says
        if name in ("", ".", ".."):
            raise self.fail(f"logfile {stmt.name!r} names no file", stmt.span)
        folder = self.log_dir or Path(self.path).resolve().parent
        self._log_file = folder / name
        if mode == 0:
            self._log_file.parent.mkdir(parents=True, exist_ok=True)
            self._log_file.write_text("", encoding="utf-8")

    def _log(self, text: str, span: n.Span) -> None:
        if self._log_file is None:
            self._exec_logfile(n.LogFile("log.txt", None, span))
        assert self._log_file is not None
        self._log_file.parent.mkdir(parents=True, exist_ok=True)
        with open(self._log_file, "a", encoding="utf-8") as handle:
            handle.write(text + "\n")
        self.message("log", text, {"file": str(self._log_file)})

    # ------------------------------------------------------------------ machine commands
    def _exec_home(self, stmt: n.Home) -> None:
        self._kinematics_off()
        axis = AXES.index(stmt.axis)
        end = list(self.pos)
        end[axis] = self.config.joints[axis].home_position
        self._move("home", end)

    def _exec_prepare_delta(self, stmt: n.PrepareLinDeltaHome) -> None:
        self._kinematics_off()
        velocity = self.evaluator.value(stmt.velocity) if stmt.velocity is not None \
            else abs(self.config.joints[0].home_velocity)
        if velocity <= 0:
            raise self.fail("PrepareLinDeltaHome needs a positive velocity", stmt.span)
        end = list(self.pos)
        for axis in range(3):
            end[axis] = self.config.joints[axis].home_position
        self._move("home", end, velocity * 60.0)

    def _kinematics_off(self) -> None:
        if self.kinematics_active:
            self.pos = list(self.canon.kinematics("OFF", (), tuple(self.pos), self.path, self.line))
            self.kinematics_active = False

    def _exec_kin(self, stmt: n.Kin) -> None:
        args = tuple(self.evaluator.value(a) for a in stmt.args)
        if stmt.mode not in ("ON", "OFF", "CTRL"):
            off = self.offset()
            args = (off[0], off[1])  # a mapping's rotation point defaults to the work zero
        self.pos = list(self.canon.kinematics(stmt.mode, args, tuple(self.pos), self.path, self.line))
        if stmt.mode != "CTRL":
            self.kinematics_active = stmt.mode != "OFF"

    def _exec_switch(self, stmt: n.Switch) -> None:
        if stmt.name == "tanknife":
            self.tanknife = stmt.on
            work_zero = tuple(self.offset()[:3])  # the bend knife's Z band is in work coordinates
            self.pos = list(self.canon.kinematics("TANKNIFE_ON" if stmt.on else "TANKNIFE_OFF", work_zero,
                                                  tuple(self.pos), self.path, self.line))
        self.canon.event(Event(stmt.name, self.path, self.line, {"on": stmt.on}))

    def _exec_command(self, stmt: n.Command) -> None:
        handler = self._COMMANDS.get(stmt.name)
        if handler is not None:
            handler(self, stmt)
        else:
            self.canon.event(Event(stmt.name, self.path, self.line, {"args": stmt.args}))

    def _get_tool_info(self, stmt: n.Command) -> None:
        parts = stmt.args.split()
        if len(parts) != 2 or parts[0].lower() not in ("first", "next", "num") or not parts[1].isdigit():
            raise self.fail("GetToolInfo expects first|next|num and a parameter number, e.g. "
                            "GetToolInfo first 100", stmt.span)
        tools = sorted(k for k, tool in self.config.tools.items() if tool.length or tool.diameter)
        kind, index = parts[0].lower(), param_index(float(parts[1]), stmt.span)
        if kind == "num":
            value = float(len(tools))
        else:
            after = 0 if kind == "first" else self._tool_cursor
            following = [k for k in tools if k > after]
            value = float(following[0]) if following else -1.0
            self._tool_cursor = int(value) if following else t.MAX_TOOL
        self.params.write(index, value, self.where(stmt.span))

    def _exec_program(self, stmt: n.Command) -> None:
        if not self.allow_exec:
            self.message("warn", f"Exec {stmt.args} was not run: running programs needs --allow-exec")
            return
        import subprocess  # only for Exec: not worth its import time on every run

        argv = [quoted or bare for quoted, bare in _EXEC_ARG.findall(stmt.args)]
        try:
            result = subprocess.run(argv, check=False)
        except OSError as err:
            raise self.fail(f"Exec {stmt.args}: {err.strerror}", stmt.span) from None
        self.canon.event(Event("exec", self.path, self.line, {"args": stmt.args, "status": result.returncode}))

    _COMMANDS: dict[str, Callable[[Interpreter, n.Command], None]] = {
        "gettoolinfo": _get_tool_info, "exec": _exec_program,
    }

    # ------------------------------------------------------------------ blocks
    def _exec_block(self, block: n.Block) -> None:
        if block.block_delete and self.block_delete:
            return
        value = self.evaluator.value
        words: dict[str, float] = {}
        g_codes: dict[str, int] = {}
        m_codes: dict[str, int] = {}
        for word in block.words:
            self._add_word(words, g_codes, m_codes, word.letter, value(word.value), word.span.col)
        # Deferred assignment: every expression of the line is evaluated before any parameter changes.
        pending = [(self.evaluator.index(a.target), value(a.value), a.span) for a in block.assigns]
        for index, number, span in pending:
            self.params.write(index, number, self.where(span))
        if block.message is not None:
            self.message("msg", block.message)
        self._dispatch(words, g_codes, m_codes, block.span)

    def _exec_plain_run(self, run: n.PlainRun) -> None:
        """Plain lines: straight moves in bulk while they are simple, any other line on its own."""
        lines = run.lines
        done = 0
        while done < len(lines):
            done = self._simple_moves(run.path, lines, done)
            if done < len(lines):
                lineno, text = lines[done]
                self.execute(plain_block(text, run.path, lineno))
                done += 1

    def _simple_moves(self, path: str, lines: tuple[tuple[int, str], ...], first: int) -> int:
        """Execute lines[first:] as long as each is a plain G0/G1 move; returns the first it left.

        This is the per-line work of ``_exec_plain`` and ``_execute_line`` for the case that
        dominates CAM output (axis words, F, G0/G1, N only; G94; no G68 or tangential knife),
        done without building nodes.  Anything unusual, including every error, is left to the
        general path so messages stay exactly the same.
        """
        if self.rotation is not None or self.tanknife or self.modal["feed_mode"] != G_94:
            return first
        motion: int | None = self.modal["motion"]
        if motion not in (G_0, G_1):
            motion = None  # the line must name G0 or G1 itself
        scale = self.scale
        offset = self.offset()
        incremental = self.modal["distance"] == G_91
        budget = self.max_steps
        pos = self.pos
        feed = self.feed
        batch: list[tuple[str, int, tuple[float, ...], float]] = []
        feeds: list[float] = []  # the feed in force at each move of the batch
        room = len(lines) if budget is None else budget - self.steps  # statements left in the step budget
        done = 0
        index = first
        for index in range(first, len(lines)):
            if done >= room:
                break
            lineno, text = lines[index]
            line_motion: int | None
            new_feed: float | None
            cam = CAM_LINE.match(text)
            if cam is not None:  # the usual shape: [G0|G1] [X] [Y] [Z] [A] [B] [C] [F], in that order
                g, x, y, z, a, b, c, f = cam.groups()
                if g is not None:
                    g_value = float(g)
                    if g_value != 0.0 and g_value != 1.0:
                        break
                    line_motion = G_0 if g_value == 0.0 else G_1
                else:
                    line_motion = motion
                if line_motion is None:
                    break
                if f is not None:
                    new_feed = float(f) * scale
                    if new_feed < 0:
                        break
                    feed = new_feed
                if x is None and y is None and z is None and a is None and b is None and c is None:
                    done += 1
                    motion = line_motion
                    continue
                base = pos if incremental else offset
                target = list(pos)
                if x is not None:
                    target[0] = base[0] + float(x) * scale
                if y is not None:
                    target[1] = base[1] + float(y) * scale
                if z is not None:
                    target[2] = base[2] + float(z) * scale
                if a is not None:
                    target[3] = base[3] + float(a)
                if b is not None:
                    target[4] = base[4] + float(b)
                if c is not None:
                    target[5] = base[5] + float(c)
            else:
                parsed = self._plain_move_words(text, motion, scale)
                if parsed is None:
                    break
                line_motion, axes, new_feed = parsed
                if line_motion is None:
                    break
                if new_feed is not None:
                    feed = new_feed
                if not axes:
                    done += 1
                    motion = line_motion
                    continue
                base = pos if incremental else offset
                target = list(pos)
                for axis, value in axes:
                    target[axis] = base[axis] + value
            if line_motion == G_1:
                if feed <= 0:
                    break
                batch.append(("linear", lineno, tuple(target), feed))
            else:
                batch.append(("rapid", lineno, tuple(target), 0.0))
            feeds.append(feed)
            pos = target
            done += 1
            motion = line_motion
        else:
            index = len(lines)
        self.steps += done
        if batch:
            self.path, self.line = path, batch[-1][1]
            try:
                self.canon.straight_moves(path, tuple(self.pos), batch)
            except EcncError as err:  # a move was refused: the state is that of the move before it
                failed = next((k for k, item in enumerate(batch)
                               if err.location is not None and item[1] == err.location.line), 0)
                if failed:
                    self.pos = list(batch[failed - 1][2])
                self.feed = feeds[failed]
                self.modal["motion"] = G_1 if batch[failed][0] == "linear" else G_0
                self.line = batch[failed][1]
                raise
        self.pos = list(pos)
        self.feed = feed
        if motion is not None:
            self.modal["motion"] = motion
        return index

    @staticmethod
    def _plain_move_words(text: str, motion: int | None, scale: float
                          ) -> tuple[int | None, list[tuple[int, float]], float | None] | None:
        """A plain line's motion code, axis values and feed, if it is nothing but a straight move."""
        seen: set[str] = set()
        axes: list[tuple[int, float]] = []
        new_feed = None
        for letter, number in plain_words(text):
            letter = letter.upper()
            if letter in seen:
                return None
            seen.add(letter)
            value = float(number)
            axis = AXIS_INDEX.get(letter)
            if axis is not None:
                axes.append((axis, value * scale if axis < 3 else value))
            elif letter == "F" and value >= 0:
                new_feed = value * scale
            elif letter == "G" and (value == 0.0 or value == 1.0):
                motion = G_0 if value == 0.0 else G_1
            elif letter != "N":
                return None
        return motion, axes, new_feed

    def _exec_plain(self, block: n.PlainBlock) -> None:
        words: dict[str, float] = {}
        g_codes: dict[str, int] = {}
        m_codes: dict[str, int] = {}
        for letter, number, col in block.words:
            self._add_word(words, g_codes, m_codes, letter, number, col)
        self._dispatch(words, g_codes, m_codes, block.span)

    def _add_word(self, words: dict[str, float], g_codes: dict[str, int], m_codes: dict[str, int],
                  letter: str, number: float, col: int) -> None:
        """Sort one evaluated word into axis/parameter words, G codes by group and M codes by group."""
        if letter == "G" or letter == "M":
            key = int(round(number * 10))
            table, found = (t.G_GROUPS, g_codes) if letter == "G" else (t.M_GROUPS, m_codes)
            group = table.get(key)
            if group is None:
                if letter == "G":
                    raise MachineError(f"unknown G code {t.code_name('G', key)}", Location(self.path, self.line, col))
                group = f"user_{key}"
            if group in found:
                raise MachineError(f"{t.code_name(letter, found[group])} and {t.code_name(letter, key)} are in the "
                                   "same modal group; use one per line", Location(self.path, self.line, col))
            found[group] = key
        elif letter in words:
            raise MachineError(f"word {letter} appears twice on this line", Location(self.path, self.line, col))
        else:
            words[letter] = number

    def _dispatch(self, words: dict[str, float], g_codes: dict[str, int], m_codes: dict[str, int],
                  span: n.Span) -> None:
        """Run the sorted words of one line: an M-code sub call, or the built-in actions."""
        if not words and not g_codes and not m_codes:  # assignments or a message only
            return
        if len(m_codes) > t.MAX_M_WORDS:
            raise self.fail(f"{len(m_codes)} M words on one line; at most {t.MAX_M_WORDS} are allowed", span)
        if m_codes:
            user_m = [k for k in m_codes.values() if self._user_m_sub(k)]
            if user_m:
                self._call_m_sub(user_m[0], words, g_codes, m_codes, span)
                return
        self._execute_line(words, g_codes, m_codes, span)

    def _user_m_sub(self, key: int) -> str | None:
        """The sub overriding M<key>, unless we are inside it (then the built-in runs)."""
        if key % 10:
            return None
        name = f"m{key // 10}"
        if name in self.subs and all(frame.name != name for frame in self.stack):
            return name
        return None

    def _call_m_sub(self, key: int, words: dict[str, float], g_codes: Mapping[str, int],
                    m_codes: Mapping[str, int], span: n.Span) -> None:
        if g_codes or len(m_codes) > 1:
            raise self.fail(f"a line calling M{key // 10} (a macro sub) may hold only its letter arguments", span)
        self._feed_speed_tool(words, span)  # F, S and T act as usual before the sub runs
        for i, letter in enumerate(t.LETTER_ARGS, 1):
            self.params.set(i, words.get(letter, t.ABSENT_ARGUMENT))
        self.call_sub(f"m{key // 10}", span)

    def _execute_line(self, words: dict[str, float], g: Mapping[str, int], m: Mapping[str, int],
                      span: n.Span) -> None:
        """One line's actions in the controller's order of execution (tables.ORDER_OF_EXECUTION)."""
        sources = {"G": g, "M": m, "word": words}
        for handler, source, key in self._LINE_STEPS:
            if source == "always":
                handler(self, g.get("motion"), words, g, span)
            else:
                found = sources[source]
                if key in found:
                    handler(self, found[key], words, g, span)

    # ------------------------------------------------------------------ line steps
    # Each step takes the value that triggered it (a G/M key or a word's value), the line's words,
    # its G codes by group and its span.
    def _step_feed_mode(self, code: int, words: Mapping[str, float], g: Mapping[str, int], span: n.Span) -> None:
        if code != self.modal["feed_mode"]:
            self.modal["feed_mode"] = code
            self.feed = 0.0  # an F of the old mode means something else: the next feed move needs a new F

    def _step_feed(self, value: float, words: Mapping[str, float], g: Mapping[str, int], span: n.Span) -> None:
        if value < 0:
            raise self.fail("negative feed rate", span)
        self.feed = value * (1.0 if self.modal["feed_mode"] == G_93 else self.scale)

    def _step_spindle_speed(self, value: float, words: Mapping[str, float], g: Mapping[str, int],
                            span: n.Span) -> None:
        if value < 0:
            raise self.fail(f"spindle speed S{format_value(value)} is negative", span)
        self.speed = value
        if self.spindle != 5:
            self.params.set(t.SPINDLE_SPEED, self.speed / 60.0)

    def _step_tool_select(self, value: float, words: Mapping[str, float], g: Mapping[str, int],
                          span: n.Span) -> None:
        if value != int(value) or not 0 <= value <= t.MAX_TOOL:
            raise self.fail(f"tool T{format_value(value)} does not exist (tools are T0..T{t.MAX_TOOL})", span)
        self.selected_tool = int(value)

    def _step_tool_change(self, code: int, words: Mapping[str, float], g: Mapping[str, int], span: n.Span) -> None:
        self._tool_change(span)

    def _step_spindle(self, code: int, words: Mapping[str, float], g: Mapping[str, int], span: n.Span) -> None:
        self.spindle = code // 10
        on = self.spindle != 5
        self.params.set(t.SPINDLE_ON, 1.0 if on else 0.0)
        self.params.set(t.SPINDLE_SPEED, self.speed / 60.0 if on else 0.0)
        self.canon.event(Event("spindle", self.path, self.line, {"m": self.spindle, "speed": self.speed}))

    def _step_coolant(self, code: int, words: Mapping[str, float], g: Mapping[str, int], span: n.Span) -> None:
        self.coolant = set() if code == 90 else self.coolant | {code // 10}
        self.canon.event(Event("coolant", self.path, self.line, {"m": code // 10}))

    def _step_overrides(self, code: int, words: Mapping[str, float], g: Mapping[str, int], span: n.Span) -> None:
        self.canon.event(Event("override", self.path, self.line, {"m": code // 10}))

    def _step_io(self, code: int, words: Mapping[str, float], g: Mapping[str, int], span: n.Span) -> None:
        self._io(code // 10, words, span)

    def _step_m_state(self, code: int, words: Mapping[str, float], g: Mapping[str, int], span: n.Span) -> None:
        self.canon.event(Event("m_code", self.path, self.line, {"m": code // 10}))

    def _step_dwell(self, code: int, words: Mapping[str, float], g: Mapping[str, int], span: n.Span) -> None:
        if code == G_4:
            self._dwell(words, span)

    def _step_modal(self, code: int, words: Mapping[str, float], g: Mapping[str, int], span: n.Span) -> None:
        """Plane, units, cutter compensation, path control, distance and return mode: state only."""
        self.modal[t.G_GROUPS[code]] = code

    def _step_length_offset(self, code: int, words: Mapping[str, float], g: Mapping[str, int],
                            span: n.Span) -> None:
        self._length_offset(code, words, span)

    def _step_coord_system(self, code: int, words: Mapping[str, float], g: Mapping[str, int],
                           span: n.Span) -> None:
        self._select_coord_system(code)

    def _step_rotation(self, code: int, words: Mapping[str, float], g: Mapping[str, int], span: n.Span) -> None:
        self._rotation(code, words, span)

    def _step_scaling(self, code: int, words: Mapping[str, float], g: Mapping[str, int], span: n.Span) -> None:
        if code == G_51:
            raise self.fail("G51 scaling is not supported", span)

    def _step_non_modal(self, code: int, words: Mapping[str, float], g: Mapping[str, int], span: n.Span) -> None:
        handler = self._NON_MODAL.get(code)
        if handler is not None:
            handler(self, code, words, span)

    def _step_motion(self, code: int | None, words: Mapping[str, float], g: Mapping[str, int],
                     span: n.Span) -> None:
        self._motion(words, g, g.get("non_modal"), span)

    def _step_stopping(self, code: int, words: Mapping[str, float], g: Mapping[str, int], span: n.Span) -> None:
        self._stop(code, span)

    def _feed_speed_tool(self, words: Mapping[str, float], span: n.Span) -> None:
        """The F, S and T steps alone (a line calling an M-code sub still sets them)."""
        for letter, step in (("F", Interpreter._step_feed), ("S", Interpreter._step_spindle_speed),
                             ("T", Interpreter._step_tool_select)):
            if letter in words:
                step(self, words[letter], words, {}, span)

    def _tool_change(self, span: n.Span) -> None:
        if "change_tool" in self.subs and all(f.name != "change_tool" for f in self.stack):
            self.params.set(t.TOOL_NEW, float(self.selected_tool))
            self.params.set(t.TOOL_CHANGED, 0.0)
            self.call_sub("change_tool", span)
            return
        old = int(self.params.read(t.TOOL_CURRENT))
        self.params.set(t.TOOL_CURRENT, float(self.selected_tool))
        tool = self.selected_tool
        self.params.set(t.TOOL_RADIUS, self.params.read(t.TOOL_DIAMETER + tool) / 2.0 if tool else 0.0)
        self.params.set(t.TOOL_Z_OFFSET, self.params.read(t.TOOL_LENGTH + tool) if tool else 0.0)
        self.canon.event(Event("tool_change", self.path, self.line, {"tool": tool, "previous": old}))

    def _io(self, code: int, words: Mapping[str, float], span: n.Span) -> None:
        port = int(words.get("P", words.get("E", 0)))
        if code in (54, 55):
            self.outputs[port] = code == 54
            self.canon.event(Event("output", self.path, self.line, {"port": port, "on": code == 54,
                                                                     "pwm": words.get("Q")}))
        elif code == 56:
            level = float(self.host.read_input(port)) if self.host.read_input else 0.0
            wait = int(words.get("L", 0))
            if wait in (1, 2) and (level != 0.0) != (wait == 1):
                level = -1.0  # the wait for high (L1) / low (L2) timed out
            self.params.set(t.IO_RESULT, level)
        else:
            self.params.set(t.IO_RESULT, 1.0 if self.outputs.get(port) else 0.0)

    def _dwell(self, words: Mapping[str, float], span: n.Span) -> None:
        if "P" not in words or words["P"] < 0:
            raise self.fail("G4 needs a dwell time P (seconds) of 0 or more", span)
        seconds = words["P"] / 1000.0 if self.config.g4_in_milliseconds else words["P"]
        self.canon.event(Event("dwell", self.path, self.line, {"seconds": seconds}))

    def _length_offset(self, code: int, words: Mapping[str, float], span: n.Span) -> None:
        if code == G_49:
            self.tool_z = 0.0
        else:
            tool = int(words.get("H", self.params.read(t.TOOL_CURRENT)))
            if not 0 <= tool <= t.MAX_TOOL:
                raise self.fail(f"G43 H{tool}: no such tool", span)
            if code == G_43_1:  # dynamic offset: K is the tool length (I, the lathe X offset, has no effect)
                self.tool_z = words.get("K", 0.0) * self.scale
            else:
                self.tool_z = self.params.read(t.TOOL_LENGTH + tool) if tool else 0.0
        self.modal["length_offset"] = code
        self.params.set(t.TOOL_G43_OFFSET, self.tool_z)
        self._offset = None

    def _select_coord_system(self, code: int) -> None:
        self.modal["coord_system"] = code
        self.params.set(t.COORD_SYSTEM, float(t.COORD_SYSTEM_CODES.index(code) + 1))

    def _rotation(self, code: int, words: Mapping[str, float], span: n.Span) -> None:
        if code == G_69:
            self.rotation = None
            self.params.set(t.G68_ACTIVE, 0.0)
        else:
            work = self.work_position()
            px = words.get("X", work[0] / self.scale) * self.scale
            py = words.get("Y", work[1] / self.scale) * self.scale
            angle = words.get("R", 0.0)
            self.rotation = (px, py, angle)
            for offset, number in enumerate((1.0, px, py, 0.0, 0.0, 0.0, angle)):
                self.params.set(t.G68_ACTIVE + offset, number)
        self.modal["rotation"] = code

    def _axis_values(self, words: Mapping[str, float]) -> dict[int, float]:
        """The axis words of a line, in mm / degrees."""
        scale = self.scale
        return {AXIS_INDEX[a]: v * (scale if a in LINEAR_AXES else 1.0) for a, v in words.items() if a in AXIS_INDEX}

    def _g10(self, code: int, words: Mapping[str, float], span: n.Span) -> None:
        level = int(words.get("L", -1))
        p = words.get("P")
        if level == 1:
            tool = int(p) if p is not None else -1
            if not 1 <= tool <= t.MAX_TOOL:
                raise self.fail("G10 L1 needs a tool number P1..P99", span)
            if "Z" in words:
                self.params.set(t.TOOL_LENGTH + tool, words["Z"] * self.scale)
            if "R" in words:
                self.params.set(t.TOOL_DIAMETER + tool, 2 * words["R"] * self.scale)
            return
        if level not in (2, 20):
            raise self.fail("G10 needs L1 (tool table), L2 or L20 (coordinate system)", span)
        system = int(p) if p is not None else -1
        if p is None or p != system or not 0 <= system <= 9:
            raise self.fail(f"G10 L{level} needs a coordinate system P0..P9 (P1 = G54, P0 = the active one)", span)
        if system == 0:
            system = int(self.params.read(t.COORD_SYSTEM))
        for axis, number in self._axis_values(words).items():
            if level == 20:
                others = self.offset()[axis] - self.params.read(t.coord_offset_param(
                    int(self.params.read(t.COORD_SYSTEM)), axis))
                number = self.pos[axis] - number - others
            self.params.set(t.coord_offset_param(system, axis), number)

    def _g28_g30(self, code: int, words: Mapping[str, float], span: n.Span) -> None:
        base = t.G28_HOME if code == G_28 else t.G30_HOME
        axes = self._axis_values(words)
        if axes:  # the intermediate point, in the current coordinates
            self._move("rapid", self._target(words))
        chosen = sorted(axes) if axes else list(range(6))
        home = list(self.pos)
        for axis in chosen:
            home[axis] = self.params.read(base + axis)
        z_first = home[2] > self.pos[2]
        if z_first and 2 in chosen:
            self._move("rapid", self.pos[:2] + [home[2]] + self.pos[3:])
        if any(axis != 2 for axis in chosen):
            self._move("rapid", [home[i] if i != 2 else self.pos[i] for i in range(6)])
        if not z_first and 2 in chosen:
            self._move("rapid", self.pos[:2] + [home[2]] + self.pos[3:])

    def _g92(self, code: int, words: Mapping[str, float], span: n.Span) -> None:
        axes = self._axis_values(words)
        if not axes:
            raise self.fail("G92 needs at least one axis word", span)
        system = int(self.params.read(t.COORD_SYSTEM))
        for axis, number in axes.items():
            tool = self.tool_z if axis == 2 else 0.0
            g5x = self.params.read(t.coord_offset_param(system, axis))
            self.params.set(t.G92_OFFSET + axis, self.pos[axis] - g5x - tool - number)
        for axis in range(6):
            if axis not in axes and not self.g92_active:
                self.params.set(t.G92_OFFSET + axis, 0.0)
        self.g92_active = True
        self._offset = None

    def _g92_1(self, code: int, words: Mapping[str, float], span: n.Span) -> None:
        for axis in range(6):
            self.params.set(t.G92_OFFSET + axis, 0.0)
        self.g92_active = False
        self._offset = None

    def _g92_2(self, code: int, words: Mapping[str, float], span: n.Span) -> None:
        self.g92_active = False
        self._offset = None

    def _g92_3(self, code: int, words: Mapping[str, float], span: n.Span) -> None:
        self.g92_active = True
        self._offset = None

    _NON_MODAL: dict[int, Callable[[Interpreter, int, Mapping[str, float], n.Span], None]] = {
        G_10: _g10, G_28: _g28_g30, G_30: _g28_g30, G_92: _g92, G_92_1: _g92_1,
        G_92_2: _g92_2, G_92_3: _g92_3,
    }

    def _stop(self, code: int, span: n.Span) -> None:
        if code in PAUSE_CODES:
            self.canon.event(Event("pause", self.path, self.line, {"m": code // 10}))
            return
        for group, reset in (("plane", G_17), ("distance", G_90), ("feed_mode", G_94),
                             ("cutter_comp", G_40), ("motion", G_0)):
            self.modal[group] = reset
        self.spindle = 5
        self.coolant = set()
        self.params.set(t.SPINDLE_ON, 0.0)
        self.ended_by = f"M{code // 10}"
        self.canon.event(Event("end", self.path, self.line, {"m": code // 10}))
        raise ProgramEnd()

    # ------------------------------------------------------------------ motion
    def _target(self, words: Mapping[str, float], machine: bool = False) -> list[float]:
        """Machine position the axis words of a line point at."""
        axes = self._axis_values(words)
        if machine:  # G53: machine coordinates, absolute
            return [axes.get(i, p) for i, p in enumerate(self.pos)]
        if self.rotation is None:  # the common case, without converting the whole position
            target = list(self.pos)
            if self.modal["distance"] == G_91:
                for axis, number in axes.items():
                    target[axis] += number
            else:
                offset = self.offset()
                for axis, number in axes.items():
                    target[axis] = number + offset[axis]
            return target
        work = self.work_position()
        if self.modal["distance"] == G_91:
            for axis, number in axes.items():
                work[axis] += number
        else:
            work = [axes.get(i, w) for i, w in enumerate(work)]
        return self.to_machine(work)

    def _move(self, kind: str, end: list[float], feed: float = 0.0, arc: Arc | None = None) -> None:
        start = tuple(self.pos)
        self.canon.move(Move(kind, self.path, self.line, start, tuple(end), feed, arc))  # type: ignore[arg-type]
        self.pos = list(end)  # only a move the machine made changes the position

    def _feed_for(self, length: float, words: Mapping[str, float], span: n.Span) -> float:
        """The feed (mm/min) of a feed move of ``length`` mm under the active feed mode."""
        mode = self.modal["feed_mode"]
        if mode == G_93:
            if "F" not in words or words["F"] <= 0:
                raise self.fail("inverse time mode (G93) needs a positive F on every feed move", span)
            return length * words["F"]
        rate = self.feed * self.speed if mode == G_95 else self.feed
        if rate <= 0:
            raise self.fail("feed rate is 0: program an F word before this feed move (EdingCNC error G1516)",
                            span)
        return rate

    def _motion(self, words: Mapping[str, float], g: Mapping[str, int], non_modal: int | None,
                span: n.Span) -> None:
        motion = g.get("motion")
        g53 = non_modal == G_53
        has_axes = not AXIS_SET.isdisjoint(words)
        if motion == G_80:
            if has_axes:
                raise self.fail("G80 cancels the canned cycle; it takes no axis words", span)
            self.modal["motion"] = G_80
            self.cycle_words.clear()
            return
        previous = self.modal["motion"]
        if motion is not None:
            if motion in UNSUPPORTED_MOTION:
                raise self.fail(f"{t.code_name('G', motion)} is not supported by this simulator", span)
            self.modal["motion"] = motion
        elif not has_axes or non_modal in t.AXIS_WORD_USERS or g.get("rotation") == G_68:
            if g53:
                raise self.fail("G53 needs an axis word and G0 or G1", span)
            return
        motion = self.modal["motion"]
        if motion == G_80:
            raise self.fail("axis words without a motion mode: G80 is active, add G0 or G1", span)
        if g53 and motion not in (G_0, G_1):
            raise self.fail("G53 moves in machine coordinates only with G0 or G1", span)
        if g53 and self.modal["cutter_comp"] != G_40:
            raise self.fail("G53 is not allowed while cutter compensation (G41/G42) is on", span)
        if motion in t.CANNED_CYCLES:
            self._cycle(motion, words, span, new_sequence=previous != motion)
        elif motion in (G_2, G_3):
            self._arc(motion, words, span)
        elif has_axes:
            target = self._target(words, g53)
            if motion == G_0:
                self._move("rapid", target)
            elif motion == G_1:
                feed = self._feed_for(_distance(self.pos, target), words, span)
                if self.tanknife and math.hypot(target[0] - self.pos[0], target[1] - self.pos[1]) > 1e-9:
                    target[5] = self._knife_align(math.degrees(math.atan2(target[1] - self.pos[1],
                                                                          target[0] - self.pos[0])))
                self._move("linear", target, feed)
            else:
                self._probe(target, words, span)
        elif motion == G_38_2:
            raise self.fail("G38.2 needs at least one of X, Y, Z", span)

    def _arc(self, motion: int, words: Mapping[str, float], span: n.Span) -> None:
        plane = PLANE_OF[self.modal["plane"]]
        first, second, normal = PLANES[plane]
        clockwise = (motion == G_2) != self.config.reverse_g2g3
        end = self._target(words)
        start = self.pos
        s = (start[first], start[second])
        e = (end[first], end[second])
        scale = self.scale
        center: tuple[float, float] | None = None
        try:
            if "R" in words:
                center = center_from_radius(s, e, words["R"] * scale, clockwise)
            else:
                w1, w2 = CENTER_WORDS[plane]
                if w1 not in words and w2 not in words:
                    raise ArcError(f"an arc needs R or centre words {w1}/{w2} in the {plane} plane")
                if self.config.absolute_center_coords:
                    work = self.work_position()
                    work[first], work[second] = words.get(w1, 0.0) * scale, words.get(w2, 0.0) * scale
                    machine = self.to_machine(work)
                    center = (machine[first], machine[second])
                else:
                    d1, d2 = words.get(w1, 0.0) * scale, words.get(w2, 0.0) * scale
                    if self.rotation and plane == "XY":
                        c, sn = math.cos(math.radians(self.rotation[2])), math.sin(math.radians(self.rotation[2]))
                        d1, d2 = c * d1 - sn * d2, sn * d1 + c * d2
                    center = (s[0] + d1, s[1] + d2)
                check_radius(s, center, e)
        except ArcError as err:
            where = f"start ({_fmt(s)})" + (f", centre ({_fmt(center)})" if center else "") + f", end ({_fmt(e)})"
            raise self.fail(f"{err}; {where} in the {plane} plane", span) from None
        assert center is not None
        angle, full = sweep(s, center, e, clockwise, self.config.full_circle_theta_epsilon)
        radius = math.hypot(s[0] - center[0], s[1] - center[1])
        along = end[normal] - start[normal]
        length = math.hypot(radius * angle, along)
        feed = self._feed_for(length, words, span)
        named = (center[1], center[0]) if plane == "XZ" else center
        if self.tanknife and plane == "XY":  # the knife follows the tangent all along the arc
            normal_deg = -90.0 if clockwise else 90.0
            start_tangent = math.degrees(math.atan2(s[1] - center[1], s[0] - center[0])) + normal_deg
            c_start = self._knife_align(start_tangent)
            end[5] = c_start + math.degrees(angle) * (-1.0 if clockwise else 1.0)
        self._move("arc", end, feed, Arc(named, plane, -1 if clockwise else 1, full))

    def _knife_align(self, direction: float) -> float:
        """Turn C to ``direction`` (the equivalent angle nearest the current C) before a cut.

        A turn larger than tanKnifeAngleForLiftUp lifts the knife, turns it and lowers it
        again (three moves); a smaller one turns in place.  Returns the new C.
        """
        current = self.pos[5]
        target = current + ((direction - current + 180.0) % 360.0 - 180.0)
        turn = abs(target - current)
        if turn < 1e-9:
            return current
        knife = self.config.tanknife
        if turn > knife.angle_for_lift_up:
            down = self.pos[2]
            self._move("rapid", self.pos[:2] + [down + knife.lift_up_distance] + self.pos[3:])
            self._move("rapid", self.pos[:5] + [target])
            self._move("rapid", self.pos[:2] + [down] + self.pos[3:])
        else:
            self._move("rapid", self.pos[:5] + [target])
        return target

    def _probe(self, target: list[float], words: Mapping[str, float], span: n.Span) -> None:
        if any(abs(target[i] - self.pos[i]) > 1e-9 for i in range(3, 6)):
            raise self.fail("G38.2 cannot move a rotary axis", span)
        if self.modal["feed_mode"] == G_93:
            raise self.fail("G38.2 is not allowed in inverse time mode (G93)", span)
        distance = _distance(self.pos, target)
        if distance < MIN_PROBE_DISTANCE:
            raise self.fail(f"G38.2 target is {distance:.4f} mm away; it must be at least {MIN_PROBE_DISTANCE} mm",
                            span)
        feed = self._feed_for(distance, words, span)
        start = tuple(self.pos)
        trip = self.host.probe(start, tuple(target)) if self.host.probe else tuple(target)  # type: ignore[arg-type]
        end = list(trip) if trip is not None else target
        self._move("probe", end, feed)
        if trip is not None:
            work = self.work_position()
            for axis in range(6):
                self.params.set(t.PROBE_MACHINE + axis, end[axis])
                self.params.set(t.PROBE_WORK + axis, work[axis])
                self.params.set(t.PROBE_JOINTS + axis, end[axis])
        self.params.set(t.PROBE_TRIPPED, 1.0 if trip is not None else 0.0)

    def _cycle(self, motion: int, words: Mapping[str, float], span: n.Span, new_sequence: bool) -> None:
        from .cycles import (  # most jobs drill nothing: not worth its import time
            CYCLES,
            NEEDS_Q,
            CycleError,
        )

        plane = PLANE_OF[self.modal["plane"]]
        first, second, normal = PLANES[plane]
        drill = AXES[normal]
        sticky = self.cycle_words
        for letter, key in (("R", "R"), (drill, "Z"), ("P", "P"), ("Q", "Q")):
            if letter in words:
                sticky[key] = words[letter]
        if any(a in words for a in "ABC"):
            raise self.fail("canned cycles cannot move rotary axes", span)
        if self.modal["feed_mode"] == G_93:
            raise self.fail("canned cycles are not allowed in inverse time mode (G93)", span)
        if self.modal["cutter_comp"] != G_40:
            raise self.fail("canned cycles are not allowed with cutter compensation on (G41/G42)", span)
        for needed in ("R", "Z"):
            if needed not in sticky:
                raise self.fail(f"{t.code_name('G', motion)} needs {needed if needed == 'R' else drill}", span)
        if motion in NEEDS_Q and sticky.get("Q", 0) <= 0:
            raise self.fail(f"{t.code_name('G', motion)} needs a peck depth Q greater than 0", span)
        repeats = words.get("L", 1)
        if repeats != int(repeats) or repeats < 1:
            raise self.fail("L (repeat count) must be a whole number of at least 1", span)
        scale = self.scale
        work = self.work_position()
        if new_sequence:  # a new cycle sequence: G98 returns to the level it started from
            self.cycle_initial = work[normal]
        old = work[normal] if self.modal["return_mode"] == G_99 else self.cycle_initial
        incremental = self.modal["distance"] == G_91
        r_level = (old if incremental else 0.0) + sticky["R"] * scale
        bottom = (r_level if incremental else 0.0) + sticky["Z"] * scale
        if r_level < bottom:
            raise self.fail(f"R ({format_value(r_level / scale)}) is below the hole bottom "
                            f"{drill} ({format_value(bottom / scale)})", span)
        feed = self._feed_for(1.0, words, span)
        if old < r_level:  # start below R: climb to R first
            self._cycle_move("rapid", work, normal, r_level, feed)
            old = self.cycle_initial = r_level
        clear = r_level if self.modal["return_mode"] == G_99 else old
        dwell = sticky.get("P", 0.0) / (1000.0 if self.config.g4_in_milliseconds else 1.0)
        try:
            steps = CYCLES[motion](r_level, bottom, clear, dwell, sticky.get("Q", 0.0) * scale)
        except CycleError as err:
            raise self.fail(str(err), span) from None
        hole = list(work)
        for _ in range(int(repeats)):
            self.spend(1 + len(steps), span)
            for axis, letter in ((first, AXES[first]), (second, AXES[second])):
                if letter in words:
                    hole[axis] = (hole[axis] + words[letter] * scale) if incremental else words[letter] * scale
            hole[normal] = old
            self._cycle_move("rapid", hole, normal, old, feed)
            if old != r_level:
                self._cycle_move("rapid", hole, normal, r_level, feed)
            self._cycle_steps(steps, hole, normal, feed)
            old = clear

    def _cycle_move(self, kind: str, work: list[float], normal: int, level: float, feed: float) -> None:
        point = list(work)
        point[normal] = level
        self._move("rapid" if kind == "rapid" else "linear", self.to_machine(point), feed if kind == "feed" else 0.0)

    def _cycle_steps(self, steps: list[Step], hole: list[float], normal: int, feed: float) -> None:
        for step in steps:
            if step.kind in ("rapid", "feed"):
                self._cycle_move(step.kind, hole, normal, step.level, feed)
            elif step.kind == "dwell":
                self.canon.event(Event("dwell", self.path, self.line, {"seconds": step.level}))
            else:
                self.canon.event(Event("spindle", self.path, self.line,
                                       {"m": 5 if step.kind == "spindle_stop" else self.spindle,
                                        "speed": self.speed}))

    _EXECUTE: dict[type, Callable[[Interpreter, Any], None]] = {}
    _LINE_STEPS: tuple[tuple[Callable[..., None], str, str], ...] = ()


_EXEC_ARG = re.compile(r'"([^"]*)"|(\S+)')  # Windows-style arguments: quotes group, backslashes are text


def _distance(a: list[float] | Pose, b: list[float] | Pose) -> float:
    return math.dist(a[:3], b[:3])


def _fmt(point: tuple[float, float]) -> str:
    return ", ".join(f"{v:.4f}" for v in point)


_STEP_ALIASES = {"plane": "modal", "units": "modal", "cutter_comp": "modal", "path_control": "modal",
                 "distance": "modal", "return_mode": "modal"}
Interpreter._LINE_STEPS = tuple(
    (getattr(Interpreter, f"_step_{_STEP_ALIASES.get(name, name)}"), source, key)
    for name, source, key in t.ORDER_OF_EXECUTION)

Interpreter._EXECUTE = {
    n.Block: Interpreter._exec_block, n.PlainBlock: Interpreter._exec_plain,
    n.PlainRun: Interpreter._exec_plain_run, n.If: Interpreter._exec_if, n.While: Interpreter._exec_while,
    n.GoSub: Interpreter._exec_gosub, n.Sub: Interpreter._exec_sub, n.Message: Interpreter._exec_message,
    n.Dialog: Interpreter._exec_dialog, n.LogFile: Interpreter._exec_logfile, n.Home: Interpreter._exec_home,
    n.PrepareLinDeltaHome: Interpreter._exec_prepare_delta, n.Kin: Interpreter._exec_kin,
    n.Switch: Interpreter._exec_switch, n.Command: Interpreter._exec_command,
}
