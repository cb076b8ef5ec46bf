"""The canon's events: one frozen record per kind of thing the machine does besides moving.

The interpreter makes them, the stages and sinks match them by class (``isinstance`` or
``match``), and mypy checks every field on both sides of the seam.  ``kind`` (the name in the
JSON Lines events file and ``--json``) is a class attribute; ``data`` is the event's payload as
the dict those outputs print: every field after ``path`` and ``line`` in declaration order, a
field whose default is None left out while it is None, a field named in ``internal`` never
(``ZhcEvent.map``, an object for the height stage, not a record).

**To add a kind**: one class here, a subclass of ``Event`` (or of ``MessageEvent`` or
``SwitchEvent``) decorated with ``record(frozen=True, slots=True)``, with ``kind`` set and the
payload as fields; it registers itself (``EVENT_KINDS``), and ``tests/stages/test_events.py`` proves
its JSON round trip.  A payload whose keys follow the input (``ModbusEvent``) overrides
``data`` and ``from_payload``.
"""
from __future__ import annotations

from collections.abc import Mapping, Sequence
from dataclasses import fields
from typing import Any, ClassVar, Protocol

from edingcnc_lang.records import record

EVENT_KINDS: dict[str, type[Event]] = {}  # kind -> its record class, filled as the classes are made
_PAYLOADS: dict[type, tuple[tuple[str, bool], ...]] = {}  # class -> (field, left out while None)


@record(frozen=True, slots=True)
class Event:
    """Anything the machine does besides moving: dwell, tool change, spindle, messages, dialogs, I/O, ...

    ``data`` gives the payload as a dict (the JSON Lines ``data`` object), for programs written
    against the old ``Event(kind, path, line, data)``.
    """

    kind: ClassVar[str] = ""
    internal: ClassVar[frozenset[str]] = frozenset()  # fields that are not part of the payload
    path: str
    line: int

    def __init_subclass__(cls) -> None:  # the record class replaces the one it was made from: last wins
        if "kind" in cls.__dict__:
            EVENT_KINDS[cls.kind] = cls

    @property
    def data(self) -> dict[str, Any]:
        """The payload, as the JSON outputs print it."""
        payload: dict[str, Any] = {}
        for name, optional in _payload(type(self)):
            value = getattr(self, name)
            if value is not None or not optional:
                payload[name] = value
        return payload

    @classmethod
    def from_payload(cls, path: str, line: int, data: Mapping[str, Any]) -> Event:
        """The event of this class with the payload ``data`` (the inverse of ``data``)."""
        return cls(path, line, **data)


def event_from_json(kind: str, path: str, line: int, data: Mapping[str, Any]) -> Event:
    """The event a JSON record (``kind``, ``file``, ``line``, ``data``) describes; KeyError for an unknown kind."""
    return EVENT_KINDS[kind].from_payload(path, line, data)


def _payload(cls: type) -> tuple[tuple[str, bool], ...]:
    """The payload's fields of an event class, each with whether it is left out while None."""
    found = _PAYLOADS.get(cls)
    if found is None:
        internal: frozenset[str] = getattr(cls, "internal", frozenset())
        found = _PAYLOADS[cls] = tuple((f.name, f.default is None) for f in fields(cls)[2:]
                                       if f.name not in internal)
    return found


class HeightSurface(Protocol):
    """What the height stage reads of a ZHC height map (``config.heightmap.HeightMap``)."""

    def height(self, x: float, y: float) -> float: ...

    def crossings(self, a: Sequence[float], b: Sequence[float]) -> list[float]: ...


# -- the spindle, coolant and tools ---------------------------------------------------------------------------

@record(frozen=True, slots=True)
class SpindleEvent(Event):
    """M3/M4/M5 (and the turns of a tapping cycle): ``m`` the direction, ``rpm`` the speed now (0 stopped)."""

    kind: ClassVar[str] = "spindle"
    m: int
    speed: float
    rpm: float
    rigid_tap: bool | None = None  # True inside a rigid tapping cycle (G33.1, G84 with a pitch)


@record(frozen=True, slots=True)
class SpindleSpeedEvent(Event):
    """S, G96 or G97: ``mode`` "rpm" or "css" (surface speed), the programmed speed and the rpm now."""

    kind: ClassVar[str] = "spindle_speed"
    mode: str
    speed: float
    max_rpm: float
    rpm: float


@record(frozen=True, slots=True)
class CoolantEvent(Event):
    """M7/M8 on, M9 off."""

    kind: ClassVar[str] = "coolant"
    m: int


@record(frozen=True, slots=True)
class ToolChangeEvent(Event):
    """M6 (the built-in change): the tool now in the spindle and the one before."""

    kind: ClassVar[str] = "tool_change"
    tool: int
    previous: int


# -- timing, overrides and the end ----------------------------------------------------------------------------

@record(frozen=True, slots=True)
class DwellEvent(Event):
    """G4 (or a cycle's dwell at the bottom of a hole), in seconds."""

    kind: ClassVar[str] = "dwell"
    seconds: float


@record(frozen=True, slots=True)
class PauseEvent(Event):
    """M0/M1 (and G88's stop for the operator, ``cycle`` "G88")."""

    kind: ClassVar[str] = "pause"
    m: int
    cycle: str | None = None


@record(frozen=True, slots=True)
class OverrideEvent(Event):
    """M48..M51: the overrides enabled or disabled (``p`` as programmed, ``M50 P0`` off)."""

    kind: ClassVar[str] = "override"
    m: int
    p: float | None = None


@record(frozen=True, slots=True)
class OperatorWaitEvent(Event):
    """``M50 P0``/``M51 P0``: the override set to 0 %, so the machine waits for the operator to turn the
    knob (``override`` "feed" or "spindle"); the run goes on at the knob's value (``--feed-override``)."""

    kind: ClassVar[str] = "operator_wait"
    m: int
    override: str


@record(frozen=True, slots=True)
class PathControlEvent(Event):
    """G61/G64: exact stop or a path tolerance ``p`` (mm) and G64's other words as programmed."""

    kind: ClassVar[str] = "path_control"
    mode: str
    p: float
    q: float | None = None
    r: float | None = None
    s: float | None = None
    d: float | None = None
    f: float | None = None


@record(frozen=True, slots=True)
class EndEvent(Event):
    """M2/M30 (M60): the program ends."""

    kind: ClassVar[str] = "end"
    m: int


@record(frozen=True, slots=True)
class MCodeEvent(Event):
    """An M code with no effect the run models beyond its state (M26/M27, M90..M97, M100 P, ...)."""

    kind: ClassVar[str] = "m_code"
    m: int
    p: float | None = None


# -- devices and outputs --------------------------------------------------------------------------------------

@record(frozen=True, slots=True)
class OutputEvent(Event):
    """M54/M55 (an output on or off; ``pwm`` Q as given, None without one) or a PWM output's duty."""

    kind: ClassVar[str] = "output"
    port: int
    on: bool
    pwm: float | None


@record(frozen=True, slots=True)
class LaserEvent(Event):
    """M10 laser off, M11 on."""

    kind: ClassVar[str] = "laser"
    m: int
    on: bool


@record(frozen=True, slots=True)
class ThcEvent(Event):
    """M20/M21 torch height control off/on, M22 Q the set voltage, M23 as given."""

    kind: ClassVar[str] = "thc"
    m: int
    on: bool | None = None
    q: float | None = None


@record(frozen=True, slots=True)
class PrinterEvent(Event):
    """3D printing: a heater's temperature (degrees C) or the fan's percent, by the M code; M30 all off."""

    kind: ClassVar[str] = "printer"
    m: int
    extruder: float | None = None
    bed: float | None = None
    extruder_max: float | None = None
    fan: float | None = None
    unit: str | None = None
    percent: float | None = None  # the fan (M106 S, 0..255) as a percent
    wait: bool | None = None
    off: bool | None = None


@record(frozen=True, slots=True)
class ModbusEvent(Event):
    """A modbus transfer: its arguments, their words (letters in the order written) and the values read."""

    kind: ClassVar[str] = "modbus"
    args: str
    words: Mapping[str, float]
    values: tuple[float, ...] | None = None

    @property
    def data(self) -> dict[str, Any]:
        """``args``, each word by its letter, then ``values`` (a read)."""
        return {"args": self.args, **self.words, **({} if self.values is None else {"values": list(self.values)})}

    @classmethod
    def from_payload(cls, path: str, line: int, data: Mapping[str, Any]) -> Event:
        values = data.get("values")
        return cls(path, line, data["args"], {k: v for k, v in data.items() if k not in ("args", "values")},
                   None if values is None else tuple(values))


@record(frozen=True, slots=True)
class ExecEvent(Event):
    """``Exec``: the program run and its exit status."""

    kind: ClassVar[str] = "exec"
    args: str
    status: int


@record(frozen=True, slots=True)
class ServiceEvent(Event):
    """``service``: reported as given (a controller service call, nothing to simulate)."""

    kind: ClassVar[str] = "service"
    args: str


# -- what the program switches on for the stages --------------------------------------------------------------

@record(frozen=True, slots=True)
class RotationEvent(Event):
    """G68 on (the pivot in machine coordinates, the angle, the plane) or G69 off; again when the pivot moves."""

    kind: ClassVar[str] = "rotation"
    on: bool
    pivot: tuple[float, ...] | None = None
    angle: float | None = None
    plane: str | None = None


@record(frozen=True, slots=True)
class ScalingEvent(Event):
    """G51 on (the X, Y, Z factors and the machine XY centre) or G50 off."""

    kind: ClassVar[str] = "scaling"
    on: bool
    factors: tuple[float, float, float] | None = None
    center: tuple[float, float] | None = None


@record(frozen=True, slots=True)
class CutterCompEvent(Event):
    """G41/G42 on (``side`` "left"/"right", the radius, the plane, inch units) or G40 (``side`` "off")."""

    kind: ClassVar[str] = "cutter_comp"
    side: str
    radius: float | None = None
    plane: str | None = None
    inch: bool | None = None
    orientation: int | None = None  # a lathe's tool in G18: its orientation 1..9 (the nose's controlled point)


@record(frozen=True, slots=True)
class ZhcEvent(Event):
    """``ZHC on`` (with the height map, for the height stage only) or ``ZHC off``."""

    kind: ClassVar[str] = "zhc"
    internal: ClassVar[frozenset[str]] = frozenset({"map"})
    on: bool
    map: HeightSurface | None = None


@record(frozen=True, slots=True)
class ZhcSaveEvent(Event):
    """``ZHCS``: the height table written to ``file``."""

    kind: ClassVar[str] = "zhcs"
    file: str


@record(frozen=True, slots=True)
class SwitchEvent(Event):
    """A named switch (``tanknife on``, ...); each switch is a subclass with its own kind."""

    on: bool


@record(frozen=True, slots=True)
class TanknifeEvent(SwitchEvent):
    kind: ClassVar[str] = "tanknife"


@record(frozen=True, slots=True)
class HomeIsEstopEvent(SwitchEvent):
    kind: ClassVar[str] = "homeisestop"


@record(frozen=True, slots=True)
class TcaGuardEvent(SwitchEvent):
    kind: ClassVar[str] = "tcaguard"


@record(frozen=True, slots=True)
class LaserEngraveEvent(SwitchEvent):
    kind: ClassVar[str] = "laserengrave"


# -- what the operator is told or asked -----------------------------------------------------------------------

@record(frozen=True, slots=True)
class MessageEvent(Event):
    """A message to the operator (the run's ``messages``): its text; each kind is a subclass."""

    text: str


@record(frozen=True, slots=True)
class MsgEvent(MessageEvent):
    """``msg`` and the built-in notes of a run."""

    kind: ClassVar[str] = "msg"


@record(frozen=True, slots=True)
class WarnEvent(MessageEvent):
    """``warnmsg`` and the run's warnings."""

    kind: ClassVar[str] = "warn"


@record(frozen=True, slots=True)
class ErrorEvent(MessageEvent):
    """``errmsg``: the job stops after it."""

    kind: ClassVar[str] = "error"


@record(frozen=True, slots=True)
class LogEvent(MessageEvent):
    """``logmsg``: the text written to the log ``file``."""

    kind: ClassVar[str] = "log"
    file: str


@record(frozen=True, slots=True)
class DialogEvent(MessageEvent):
    """``dlgmsg``: the title, whether it was answered OK and each field's value after it."""

    kind: ClassVar[str] = "dialog"
    ok: bool
    fields: Mapping[str, float]


# the switches by name, for the interpreter's ``tanknife on`` and the like
SWITCH_EVENTS: Mapping[str, type[SwitchEvent]] = {
    kind: cls for kind, cls in EVENT_KINDS.items() if issubclass(cls, SwitchEvent)}
