"""Host callbacks: how an embedding program answers what a real machine would ask.

Every callback is optional; the defaults are what a simulation needs (dialogs
answered OK with their values unchanged, inputs low, probes tripping at the
target).  Nothing here is global: each run gets its own Host.
"""
from __future__ import annotations

import math
from collections.abc import Callable, Mapping, Sequence
from dataclasses import dataclass, field
from datetime import datetime

from .canon import Pose
from .source import plain_float, plain_int



@dataclass(frozen=True)
class DialogField:
    """One input field of a dlgmsg dialog, as a host callback is shown it."""

    label: str
    index: int   # the parameter the field edits
    value: float  # its current value


@dataclass(frozen=True)
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


@dataclass
class Host:
    """Callbacks into the embedding program; ``None`` means the simulation default."""

    dialog: DialogCallback | None = None      # (title, fields) -> answer; None answer = OK unchanged
    read_input: InputCallback | None = None   # input port -> 0/1 (M56, #5068)
    probe: ProbeCallback | None = None        # (start, target) machine poses -> trip point or None (no contact)
    message: MessageCallback | None = None    # (kind, text, path, line) as they happen
    clock: Callable[[], datetime] | None = None  # the time %d shows in messages (default: now)


def scripted_dialogs(answers: Sequence[DialogAnswer]) -> DialogCallback:
    """A dialog callback answering in order; once they run out, OK with values unchanged."""
    queue = list(answers)

    def answer(_title: str, _fields: Sequence[DialogField]) -> DialogAnswer | None:
        return queue.pop(0) if queue else None

    return answer
