"""The scopes a user thinks in, built from the stopped machine, and each parameter's last writer.

Every frame shows the same scopes (the dialect's parameters are global): user parameters, the
persistent #4000..#4999, system #5000.., kinematics (when the machine has any), modal state and
positions.  A parameter's ``type`` says what it is (knowledge/variables.py) and where the run
last wrote it (``written at macro.cnc:67``).
"""
from __future__ import annotations

import os
from collections.abc import Mapping
from typing import TYPE_CHECKING, Any

from edingcnc_lang.machine import tables as t
from edingcnc_lang.canon import AXES
from edingcnc_lang.machine.state import format_value
from edingcnc_lang.records import record

if TYPE_CHECKING:
    from edingcnc_lang.machine.observe import MachineView
    from edingcnc_lang.runner import Run

USER, PERSISTENT, SYSTEM, KINEMATICS, MODAL, POSITION = range(1, 7)
SCOPES = ((USER, "User parameters #1..#3999", range(1, 4000)),
          (PERSISTENT, "Persistent #4000..#4999", range(4000, 5000)),
          (SYSTEM, "System #5000..", range(5000, 6000)))
# system parameters always shown: positions, tool, probe result, simulation, dialog result
ALWAYS = frozenset([*range(t.POS_WORK, t.POS_WORK + 6), t.TOOL_CURRENT, t.TOOL_NEW, t.TOOL_CHANGED, t.TOOL_Z_OFFSET,
                    t.PROBE_TRIPPED, *range(t.PROBE_MACHINE, t.PROBE_MACHINE + 3), t.SPINDLE_SPEED,
                    *range(t.POS_MACHINE, t.POS_MACHINE + 6), t.COORD_SYSTEM, t.SIMULATION, t.DIALOG_RESULT])
KINEMATICS_OUTPUT = range(1000, 2000)  # what a kinematics macro or plug-in writes back, by convention


Writers = dict[int, tuple[str, int]]


def scopes(run: Run) -> list[dict[str, Any]]:
    """The scopes of every frame; ``Kinematics`` only when the machine has one or the job uses #1000.."""
    found = [{"name": name, "variablesReference": ref, "expensive": False} for ref, name, _r in SCOPES]
    if _has_kinematics(run):
        found.append({"name": "Kinematics", "variablesReference": KINEMATICS, "expensive": False})
    found.append({"name": "Modal state", "variablesReference": MODAL, "expensive": False})
    found.append({"name": "Position", "variablesReference": POSITION, "expensive": False})
    return found


def variables(run: Run, ref: int, writers: Writers, names: Mapping[int, str] | None = None) -> list[dict[str, Any]]:
    """The variables of scope ``ref``; ``names``: what the files call the numbers (shown beside them)."""
    for number, _name, numbers in SCOPES:
        if ref == number:
            params = run.interpreter.params
            shown = (i for i in numbers
                     if i in params.written or params.values[i] != 0.0 or (ref == SYSTEM and i in ALWAYS))
            return [parameter(run, i, writers, names) for i in shown]
    if ref == KINEMATICS:
        return _kinematics(run, writers)
    if ref == MODAL:
        return _modal(run)
    if ref == POSITION:
        return _position(run)
    return []


def parameter(run: Run, index: int, writers: Writers, names: Mapping[int, str] | None = None) -> dict[str, Any]:
    """``#index`` as a DAP Variable: its value, its meaning and where it was last written."""
    from edingcnc_lang.knowledge import variable  # (loaded at the first stop, not at start-up)
    from edingcnc_lang.varmap.names import label

    entry = variable(index)
    what = [entry.title] if entry is not None else []
    if index in writers:
        path, line = writers[index]
        what.append(f"written at {os.path.basename(path)}:{line}" if line else f"set in {path}")
    return {"name": label(index, names or {}), "value": format_value(run.interpreter.params.read(index)),
            "type": " · ".join(what), "evaluateName": f"#{index}", "variablesReference": 0}


def _plain(name: str, value: object) -> dict[str, Any]:
    return {"name": name, "value": str(value), "variablesReference": 0}


def _has_kinematics(run: Run) -> bool:
    params = run.interpreter.params
    return run.kinematics.kin_type() != 1 or any(i in params.written for i in KINEMATICS_OUTPUT)


def _kinematics(run: Run, writers: Writers) -> list[dict[str, Any]]:
    interp, kin = run.interpreter, run.kinematics
    found = [_plain("name", kin.name), _plain("type (#5150)", kin.kin_type()),
             _plain("active", "yes" if interp.guards.kinematics_active else "no")]
    found += [_plain(f"joint {i + 1}", format_value(v)) for i, v in enumerate(run.motion.joints)]
    found += [parameter(run, i, writers) for i in KINEMATICS_OUTPUT if i in interp.params.written]
    return found


def _modal(run: Run) -> list[dict[str, Any]]:
    interp = run.interpreter
    found = [_plain(group.replace("_", " "), t.code_name("G", code)) for group, code in interp.modal.items()]
    spindle = {3: "M3 (clockwise)", 4: "M4 (counter-clockwise)", 5: "M5 (stopped)"}.get(interp.spindle.direction, "")
    found += [_plain("F", format_value(interp.feed)), _plain("S", format_value(interp.spindle.speed)),
              _plain("spindle", spindle), _plain("tool (#5008)", int(interp.params.read(t.TOOL_CURRENT))),
              _plain("tool selected (T)", interp.offsets.selected_tool),
              _plain("coolant", " ".join(f"M{c}" for c in sorted(interp.devices.coolant)) or "off"),
              _plain("G43 length", format_value(interp.offsets.tool_z)),
              *([_plain("G43 X offset (radius)", format_value(interp.offsets.tool_x))] if interp.config.lathe else []),
              _plain("G92 active", "yes" if interp.offsets.g92_active else "no"),
              _plain("work offset", _pose(interp.offset()))]
    return found


def _position(run: Run) -> list[dict[str, Any]]:
    interp = run.interpreter
    work, machine = interp.reported_position(), run.machine_position()
    return ([_plain(f"work {a}", format_value(v)) for a, v in zip(AXES, work)]
            + [_plain(f"machine {a}", format_value(v)) for a, v in zip(AXES, machine)])


def _pose(values: list[float] | tuple[float, ...]) -> str:
    return " ".join(f"{a}{format_value(v)}" for a, v in zip(AXES, values))


@record(frozen=True)
class Frame:
    """One frame of the stack shown at a stop: a sub (or the job) and where it is."""

    name: str
    path: str
    line: int


def frames_of(machine: MachineView) -> list[Frame]:
    """The stack, innermost first: each active sub at its current line, the job at its call."""
    stack = machine.stack
    found = [Frame(stack[-1].name if stack else "job", machine.path, machine.line)]
    for i in range(len(stack) - 1, -1, -1):
        found.append(Frame(stack[i - 1].name if i > 0 else "job", stack[i].path, stack[i].line))
    return found
