"""Host callbacks: how an embedding program answers what a real machine would ask.

Every callback is optional; the defaults are what a simulation needs (dialogs
answered OK with their values unchanged, inputs low, probes tripping at the
target).  Nothing here is global: each run gets its own Host.
"""
from __future__ import annotations

import math
from collections.abc import Callable, Iterable, Mapping, Sequence
from dataclasses import dataclass, field, fields, replace
from datetime import datetime
from typing import Any, TypeVar

from edingcnc_lang.canon import Pose
from edingcnc_lang.errors import CallbackError, EcncError, Location
from edingcnc_lang.syntax.source import plain_float, plain_int
from edingcnc_lang.records import record



@record(frozen=True)
class DialogField:
    """One input field of a dlgmsg dialog, as a host callback is shown it."""

    label: str
    index: int   # the parameter the field edits
    value: float  # its current value


@record(frozen=True)
class DialogAnswer:
    """OK with new values for some fields (by parameter number), or Cancel."""

    ok: bool = True
    values: Mapping[int, float] = field(default_factory=dict)

    @classmethod
    def parse(cls, text: str) -> "DialogAnswer":
        """The CLI form: ``ok``, ``cancel`` or ``ok:#N=V,#M=W``."""
        head, _, rest = text.partition(":")
        head = head.strip().lower()
        if head not in ("ok", "cancel") or (head == "cancel" and rest):
            raise ValueError(f"answer {text!r}: expected ok, cancel or ok:#N=V,...")
        values: dict[int, float] = {}
        for item in filter(None, (p.strip() for p in rest.split(","))):
            name, eq, value = item.partition("=")
            if not eq or not name.strip().startswith("#"):
                raise ValueError(f"answer {text!r}: field {item!r} is not #N=V")
            try:  # digits 0-9 only: float() would also take '1_0' and '１'
                values[plain_int(name.strip()[1:])] = plain_float(value, special=True)
            except ValueError:
                raise ValueError(f"answer {text!r}: field {item!r} is not #N=V") from None
            if not math.isfinite(values[plain_int(name.strip()[1:])]):
                raise ValueError(f"answer {text!r}: field {item!r} is not a finite number")
        return cls(head == "ok", values)


DialogCallback = Callable[[str, Sequence[DialogField]], "DialogAnswer | None"]
InputCallback = Callable[[int], float]
ProbeCallback = Callable[[Pose, Pose], "Pose | None"]
MessageCallback = Callable[[str, str, str, int], None]
ModbusCallback = Callable[[int, int, int, int], Sequence[float]]


def checked_answer(answer: object) -> DialogAnswer | None:
    """A dialog callback's answer, or ValueError saying what it returned instead."""
    if answer is None or isinstance(answer, DialogAnswer):
        return answer
    raise ValueError(f"the host's dialog callback returned {_shown(answer)}, not a DialogAnswer or None")


def checked_level(level: object) -> float:
    """An input callback's level as 0.0/1.0 (a number or a bool), or ValueError."""
    if isinstance(level, (bool, int, float)) and math.isfinite(level):
        return float(level)
    raise ValueError(f"the host's input callback returned {_shown(level)}, not a number (0 low, 1 high)")


def checked_trip(trip: object, start: Pose, goal: Pose) -> Pose | None:
    """A probe callback's trip point: None, or six finite numbers on the way from ``start`` to
    ``goal`` that leave the rotary axes where they are (G38.2 never turns them); else ValueError."""
    if trip is None:
        return None
    try:
        pose = tuple(float(v) for v in trip) if isinstance(trip, Iterable) else ()
    except (TypeError, ValueError):
        pose = ()
    if len(pose) != 6 or not all(math.isfinite(v) for v in pose):
        raise ValueError(f"the host's probe callback returned {_shown(trip)}, not None or 6 finite numbers "
                         "(x y z a b c, machine coordinates)")
    if any(abs(pose[i] - start[i]) > 1e-9 for i in range(3, 6)):
        raise ValueError("the host's probe callback moved a rotary axis, which G38.2 never moves")
    return pose


def _shown(value: object) -> str:
    text = repr(value)
    return f"{type(value).__name__} {text[:60]}{'...' if len(text) > 60 else ''}"


@dataclass
class Host:
    """Callbacks into the embedding program; ``None`` means the simulation default."""

    dialog: DialogCallback | None = None      # (title, fields) -> answer; None answer = OK unchanged
    read_input: InputCallback | None = None   # input port -> 0/1 (M56, #5068)
    probe: ProbeCallback | None = None        # (start, target) machine poses -> trip point or None (no contact)
    message: MessageCallback | None = None    # (kind, text, path, line) as they happen
    clock: Callable[[], datetime] | None = None  # the time %d shows in messages (default: now)
    # (slave, function, address, count) -> the values a modbus read (f1..f4) gets; default all 0
    modbus: ModbusCallback | None = None


def parse_modbus_values(text: str) -> tuple[float, ...]:
    """The CLI form of a modbus read's answer: finite numbers separated by commas, ``7`` or ``7,8``."""
    try:
        values = tuple(float(part) for part in text.split(","))
    except ValueError:
        raise ValueError(f"modbus answer {text!r}: expected numbers separated by commas, e.g. 7,8") from None
    if not all(math.isfinite(v) for v in values):
        raise ValueError(f"modbus answer {text!r}: the values must be finite numbers")
    return values


def scripted_modbus(answers: Sequence[Sequence[float]]) -> ModbusCallback:
    """A modbus callback answering the reads in order; once the answers run out, zeros."""
    queue = list(answers)

    def answer(_slave: int, _function: int, _address: int, count: int) -> Sequence[float]:
        return queue.pop(0) if queue else [0.0] * count

    return answer


def scripted_dialogs(answers: Sequence[DialogAnswer]) -> DialogCallback:
    """A dialog callback answering in order; once they run out, OK with values unchanged."""
    queue = list(answers)

    def answer(_title: str, _fields: Sequence[DialogField]) -> DialogAnswer | None:
        return queue.pop(0) if queue else None

    return answer


_F = TypeVar("_F", bound=Callable[..., Any])


def guarded(host: Host, where: Callable[[], Location]) -> Host:
    """``host`` with each callback's exception turned into a ``CallbackError`` at the line being run
    (the run then ends as after any error, with its partial result)."""
    def guard(name: str, callback: _F | None) -> _F | None:
        if callback is None or name == "clock":
            return callback
        function: Callable[..., Any] = callback

        def guarded(*args: Any) -> Any:
            try:
                return function(*args)
            except EcncError:  # the embedding program's own error, raised on purpose: as it is
                raise
            except Exception as exc:
                raise CallbackError.of(f"the host's {name} callback", exc, where()) from exc
        return guarded  # type: ignore[return-value]

    return replace(host, **{f.name: guard(f.name, getattr(host, f.name)) for f in fields(host)})
