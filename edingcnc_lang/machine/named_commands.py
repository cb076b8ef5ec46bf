"""Machine commands that are statements of their own: homing, KIN, switches, GetToolInfo, Exec."""
from __future__ import annotations

import re
import sys
from collections.abc import Iterable

from edingcnc_lang.syntax import nodes as n
from edingcnc_lang.machine import tables as t
from edingcnc_lang.canon import AXES
from edingcnc_lang.events import SWITCH_EVENTS, ExecEvent, ServiceEvent
from edingcnc_lang.machine.evaluator import param_index
from edingcnc_lang.machine import devices, zhc_commands as height_comp
from edingcnc_lang.machine.state import CommandTable, MachineState, StatementTable

_EXEC_ARG = re.compile(r'"([^"]*)"|(\S+)')  # Windows-style arguments: quotes group, backslashes are text
_NOT_CODE = re.compile(r'\([^)\n]*\)?|"[^"\n]*"?|;.*')  # comments and message texts (never past a line end)
_T_WORD = re.compile(r"(?<![A-Za-z_#])[Tt][ \t]*\+?([0-9]+)")


def tools_used(lines: Iterable[str]) -> list[int]:
    """The tool numbers a job's T words name (literal ones, T0 = no tool left out), in order: what
    ``GetToolInfo`` enumerates, as the controller scans the loaded G-code (the stock macro.cnc's
    ``measure_used_tools``).  An item of ``lines`` may hold several lines joined by LF."""
    found: set[int] = set()
    for line in lines:
        found.update(int(number) for number in _T_WORD.findall(_NOT_CODE.sub(" ", line)))
    found.discard(0)
    return sorted(found)


class Commands(MachineState):
    """Add a named command by writing a method and a row in ``COMMANDS``."""

    def _exec_home(self, stmt: n.Home) -> None:
        self._kinematics_off()
        axis = AXES.index(stmt.axis)
        end = list(self.machine_frame(self.pos))
        end[axis] = self.config.joints[axis].home_position
        self._machine_move("home", end)

    def _exec_prepare_delta(self, stmt: n.PrepareLinDeltaHome) -> None:
        self._kinematics_off()
        velocity = self.evaluator.value(stmt.velocity) if stmt.velocity is not None \
            else abs(self.config.joints[0].home_velocity)
        if velocity <= 0:
            raise self.fail("PrepareLinDeltaHome needs a positive velocity", stmt.span)
        end = list(self.machine_frame(self.pos))
        for axis in range(3):
            end[axis] = self.config.joints[axis].home_position
        self._machine_move("home", end, velocity * 60.0)

    def _kinematics_off(self) -> None:
        if self.guards.kinematics_active:
            self.pos = list(self.canon.kinematics("OFF", (), tuple(self.pos), self.path, self.line))
            self.guards.kinematics_active = False

    def _exec_kin(self, stmt: n.Kin) -> None:
        args = tuple(self.evaluator.value(a) for a in stmt.args)
        if stmt.mode not in ("ON", "OFF", "CTRL"):
            off = self.offset()
            args = (off[0], off[1])  # a mapping's rotation point defaults to the work zero
        self.pos = list(self.canon.kinematics(stmt.mode, args, tuple(self.pos), self.path, self.line))
        if stmt.mode != "CTRL":
            self.guards.kinematics_active = stmt.mode != "OFF"

    def _exec_switch(self, stmt: n.Switch) -> None:
        if stmt.name == "zhc":
            height_comp.switch(self, stmt.on, stmt.span)
            return
        if stmt.name == "tcaguard":
            self.guards.tca_guard = stmt.on
        if stmt.name == "tanknife":
            self.guards.tanknife = stmt.on
            work_zero = tuple(self.offset()[:3])  # the bend knife's Z band is in work coordinates
            self.pos = list(self.canon.kinematics("TANKNIFE_ON" if stmt.on else "TANKNIFE_OFF", work_zero,
                                                  tuple(self.pos), self.path, self.line))
        self.canon.event(SWITCH_EVENTS[stmt.name](self.path, self.line, stmt.on))

    def _exec_command(self, stmt: n.Command) -> None:
        COMMANDS[stmt.name](self, stmt)

    def _service(self, stmt: n.Command) -> None:
        """``service``: nothing to simulate; reported as given."""
        self.canon.event(ServiceEvent(self.path, self.line, stmt.args))

    def _get_tool_info(self, stmt: n.Command) -> None:
        parts = stmt.args.split()
        if len(parts) != 2 or parts[0].lower() not in ("first", "next", "num") or not _is_digits(parts[1]):
            raise self.fail("GetToolInfo expects first|next|num and a parameter number, e.g. "
                            "GetToolInfo first 100", stmt.span)
        tools = self.job_tools()
        kind, index = parts[0].lower(), param_index(float(parts[1]), stmt.span)
        if kind == "num":
            value = float(len(tools))
        else:
            after = 0 if kind == "first" else self.offsets.tool_cursor
            following = [k for k in tools if k > after]
            value = float(following[0]) if following else -1.0
            self.offsets.tool_cursor = int(value) if following else t.MAX_TOOL
        self.params.write(index, value, self.where(stmt.span))

    def _get_job_distance(self, stmt: n.Command) -> None:
        """``GetJobDistance N``: the distance the tool has travelled so far (mm, rapids included) into #N."""
        self.params.write(self._variable_argument(stmt, "GetJobDistance 100"), self.job_distance, self.where(stmt.span))

    def _get_height_control(self, stmt: n.Command) -> None:
        """``GetHeightControlVact/Vset N``: a torch height control voltage into #N (no THC in simulation: 0)."""
        self.params.write(self._variable_argument(stmt, f"{stmt.name} 100"), 0.0, self.where(stmt.span))

    def _variable_argument(self, stmt: n.Command, example: str) -> int:
        """The bare parameter number a command writes to (``GetJobDistance 100``)."""
        text = stmt.args.strip()
        if not _is_digits(text):
            raise self.fail(f"{stmt.name} expects a parameter number written without '#', e.g. {example}", stmt.span)
        return param_index(float(text), stmt.span)

    def _exec_program(self, stmt: n.Command) -> None:
        if not self.allow_exec:
            self.message("warn", f"Exec {stmt.args} was not run: running programs needs --allow-exec")
            return
        import subprocess  # only for Exec: not worth its import time on every run

        argv = [quoted or bare for quoted, bare in _EXEC_ARG.findall(stmt.args)]
        if not argv:
            raise self.fail('Exec needs the program to run, e.g. Exec "notepad.exe"', stmt.span)
        try:  # what the program prints is a message, never part of ecnc's output (--json, --trace -)
            result = subprocess.run(argv, check=False, stdin=subprocess.DEVNULL, stdout=_stderr_fd())
        except OSError as err:
            raise self.fail(f"Exec {stmt.args}: {err.strerror}", stmt.span) from None
        self.canon.event(ExecEvent(self.path, self.line, stmt.args, result.returncode))


def _stderr_fd() -> int:
    """Where an Exec'd program's standard output goes: ecnc's stderr (the null device if it has no
    descriptor, as under a test runner)."""
    import subprocess

    try:
        sys.stderr.flush()
        return sys.stderr.fileno()
    except (AttributeError, OSError, ValueError):
        return subprocess.DEVNULL


def _is_digits(text: str) -> bool:
    """ASCII digits only: str.isdigit() also takes '²' and '١', which float() then refuses."""
    return text.isascii() and text.isdigit()


# Named commands with a meaning of their own, by lower-case name; any other command is an event.
COMMANDS: CommandTable = {"gettoolinfo": Commands._get_tool_info, "exec": Commands._exec_program,
                          "getjobdistance": Commands._get_job_distance,
                          "getheightcontrolvact": Commands._get_height_control,
                          "getheightcontrolvset": Commands._get_height_control,
                          "service": Commands._service, **devices.COMMANDS,
                          **height_comp.COMMANDS}


# The statements this part executes, by method name (interpreter.py builds the dispatch table).
STATEMENTS: StatementTable = {n.Home: Commands._exec_home, n.PrepareLinDeltaHome: Commands._exec_prepare_delta,
                              n.Kin: Commands._exec_kin, n.Switch: Commands._exec_switch,
                              n.Command: Commands._exec_command}
