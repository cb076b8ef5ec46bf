"""The interpreter, assembled from its parts; each part is a mixin in a module of its own, but
``devices`` and ``zhc_commands``, composed parts (functions of the few things of the machine each
declares it uses, in a ``Protocol``).

Reading order for a newcomer: ``state`` (what the machine knows), ``parts`` (the state records the
parts own: files, devices, tool offsets, G51, ZHC, messages, canned cycles, the spindle, G68, the
motion guards), ``flow`` (statements, subs), ``line`` and ``steps`` (one G-code line in the order
of execution), ``spindle_modes`` (S, M3-M5, G96/G97), ``comp_words`` and ``scaling_words``
(G40-G42, G50/G51 as programmed), ``offsets`` (work and machine coordinates), ``moves``, ``canned``
and ``threads`` (what a line moves), ``bulk`` (the fast path for plain CAM lines), ``devices``,
``messages``, ``named_commands`` and ``zhc_commands``.
The interpreter emits every move and event to a ``Canon``: in a run that is the head of the
pipeline (``pipeline/``), whose last stage is the motion stage.
"""
from __future__ import annotations


from edingcnc_lang.machine import tables as t
from edingcnc_lang.machine import (
    bulk,
    named_commands as commands,
    comp_words as compensation,
    devices,
    flow,
    line,
    messages,
    scaling_words as scaling,
    spindle_modes,
    steps,
)
from edingcnc_lang.machine.bulk import BulkPath
from edingcnc_lang.machine.canned import CannedCycles
from edingcnc_lang.machine.named_commands import Commands
from edingcnc_lang.machine.comp_words import CompensationSteps
from edingcnc_lang.machine.flow import ControlFlow
from edingcnc_lang.machine.line import LineWords
from edingcnc_lang.machine.messages import Messages
from edingcnc_lang.machine.moves import Moves
from edingcnc_lang.machine.offsets import CoordinateSystems
from edingcnc_lang.machine.scaling_words import ScalingWords
from edingcnc_lang.machine.spindle_modes import SpindleModes
from edingcnc_lang.machine.steps import LineSteps
from edingcnc_lang.machine.threads import Threading


class Interpreter(ControlFlow, LineWords, LineSteps, SpindleModes, CompensationSteps, ScalingWords, CoordinateSystems,
                  Moves, CannedCycles, Threading, BulkPath, Messages, Commands):
    """Runs EdingCNC statements against one virtual machine; create one per job run."""


# Statement type -> the function that executes it, from each part's STATEMENTS table.
Interpreter._EXECUTE = {kind: run for part in (flow, line, bulk, messages, commands)
                        for kind, run in part.STATEMENTS.items()}

# The line's steps in the controller's order (tables.ORDER_OF_EXECUTION), from each part's STEPS table;
# a row of the order that no part performs fails here, at import.
_STEPS = {name: step for part in (steps, spindle_modes, compensation, scaling, devices) for name, step in part.STEPS.items()}
Interpreter._LINE_STEPS = tuple((_STEPS[name], source, key) for name, source, key in t.ORDER_OF_EXECUTION)

