"""The M codes of attached devices (manual 3.7.2, 3.7.10..3.7.12) and the modbus command.

None of them moves the machine, but each has an effect a job or its simulation can see: an
event with the values the line gave (the laser, the torch height control, the 3D printer's
heaters and fan), the alternate spindle's offsets (M91..M97) and the values a modbus read
writes into its variables.

A composed part, not a mixin: each step and command is a function of the machine as
``DeviceMachine``, the few things it uses (its own state ``machine.devices``, the parameters, the
host's modbus, the canon, errors naming the line, the selected spindle's offsets), so mypy refuses
a use of anything else.
"""
from __future__ import annotations

import re
from collections.abc import Mapping
from typing import Protocol

from edingcnc_lang.syntax import nodes as n
from edingcnc_lang.machine import tables as t
from edingcnc_lang.events import LaserEvent, ModbusEvent, PrinterEvent, ThcEvent
from edingcnc_lang.errors import Location
from edingcnc_lang.host import Host
from edingcnc_lang.machine.parts import DeviceState, PartMachine
from edingcnc_lang.machine.evaluator import param_index
from edingcnc_lang.machine.state import CommandTable, StepTable, format_value

# 3D printing (3.7.12): what S means for each code, and its unit.
PRINTER = {104: ("extruder", "degC"), 109: ("extruder", "degC"), 140: ("bed", "degC"), 190: ("bed", "degC"),
           143: ("extruder_max", "degC"), 106: ("fan", "0..255"), 107: ("fan", "0..255")}
FAN_FULL = 255.0  # M106 S: the table's scale (p. 55, "S = 0-255, für 0-100% PWM"), as slicers write it (docs/dialect.md)
WAITS = frozenset({109, 190})  # set the temperature and wait until it is reached
MODBUS_READS = frozenset({1, 2, 3, 4})  # read coils, discrete inputs, holding and input registers
_MODBUS_WORD = re.compile(r"([a-z])\s*(-?\d+(?:\.\d*)?)", re.IGNORECASE)


class DeviceMachine(PartMachine, Protocol):
    """What the devices' codes use of the machine, read-only (their state changes inside ``devices``)."""

    @property
    def devices(self) -> DeviceState: ...
    @property
    def host(self) -> Host: ...
    @property
    def spindle_offset(self) -> tuple[float, float, float]: ...
    def where(self, span: n.Span | None = None) -> Location: ...
    def _offsets_changed(self) -> None: ...


def laser(machine: DeviceMachine, code: int, words: Mapping[str, float], g: Mapping[str, int],
          span: n.Span) -> None:
    """M10 laser off, M11 on (3.7.11); under ``LaserEngrave on`` they switch on the moves' path."""
    machine.canon.event(LaserEvent(machine.path, machine.line, code // 10, code == 110))


def thc(machine: DeviceMachine, code: int, words: Mapping[str, float], g: Mapping[str, int], span: n.Span) -> None:
    """M20 torch height control off, M21 on, M22 Q the set voltage (3.7.10); M23 reported as given."""
    m = code // 10
    if m == 22 and "Q" not in words:
        raise machine.fail("M22 needs Q, the torch height control's set voltage", span)
    machine.canon.event(ThcEvent(machine.path, machine.line, m, m == 21 if m in (20, 21) else None, words.get("Q")))


def printer(machine: DeviceMachine, code: int, words: Mapping[str, float], g: Mapping[str, int],
            span: n.Span) -> None:
    """3D printing (3.7.12): S is a temperature (degrees C) or the fan's PWM on the 0..255 scale (the event
    adds its percentage), never a spindle speed."""
    m = code // 10
    target, unit = PRINTER[m]
    fan = target == "fan"
    value = 0.0 if m == 107 else words.get("S", FAN_FULL if fan else 0.0)
    if value < 0 or (fan and value > FAN_FULL):
        problem = "fan value must lie in 0..255 (255 = 100 %)" if fan else "temperature must not be negative"
        raise machine.fail(f"M{m} S{format_value(value)}: the {problem}", span)
    machine.devices.heaters[target] = value
    heat = {name: value if name == target else None for name in ("extruder", "bed", "extruder_max", "fan")}
    machine.canon.event(PrinterEvent(machine.path, machine.line, m, heat["extruder"], heat["bed"], heat["extruder_max"],
                                     heat["fan"], unit, value * 100.0 / FAN_FULL if fan else None, m in WAITS))


def heaters_off(machine: DeviceMachine) -> None:
    """M30 (3.7.1: "Alle 3D-Drucker heizen AUS")."""
    if any(machine.devices.heaters.values()):
        machine.devices.heaters = {}
        machine.canon.event(PrinterEvent(machine.path, machine.line, 30, off=True))


def select_spindle(machine: DeviceMachine, m: int) -> None:
    """M90..M97: #5390, and the selected spindle's offsets move the controlled point (3.7.2)."""
    machine.params.set(t.SPINDLE_SELECTED, float(m - 90))
    before = machine.spindle_offset
    machine.devices.spindle_selected = m
    if machine.spindle_offset != before:
        machine._offsets_changed()


def modbus(machine: DeviceMachine, stmt: n.Command) -> None:
    """``modbus s<slave> f<function> a<address> n<count> u<variable>`` reads (f1..f4) into #u..;
    the host's modbus callback answers, else 0 (no bus in simulation).  Every transfer is an event."""
    words = {k.lower(): float(v) for k, v in _MODBUS_WORD.findall(stmt.args)}
    values: tuple[float, ...] | None = None
    function = int(words.get("f", 0))
    if function in MODBUS_READS:
        if "u" not in words:
            raise machine.fail("a modbus read (f1..f4) needs u<variable>, where the values go, e.g. "
                               "modbus s1 f3 a100 n1 u1000", stmt.span)
        count = int(words.get("n", 1))
        if not 1 <= count <= 125:
            raise machine.fail("modbus n: read 1..125 values", stmt.span)
        first = param_index(words["u"], stmt.span)
        read = machine.host.modbus
        read_values = list(read(int(words.get("s", 0)), function, int(words.get("a", 0)), count)) if read else []
        values = tuple((read_values + [0.0] * count)[:count])
        for offset, value in enumerate(values):
            machine.params.write(param_index(first + offset, stmt.span), float(value), machine.where(stmt.span))
    machine.canon.event(ModbusEvent(machine.path, machine.line, stmt.args, words, values))


# The order-of-execution steps this part performs, by tables.ORDER_OF_EXECUTION name (interpreter.py merges them).
STEPS: StepTable = {"laser": laser, "thc": thc, "printer": printer}

# Named commands of this part, by lower-case name (named_commands.py dispatches them).
COMMANDS: CommandTable = {"modbus": modbus}
