"""Data breakpoints: stop when a parameter is written ("stop when #5011 is written"), and the names
the variables view shows beside numbers.

DAP's ``dataBreakpointInfo`` turns a variable of the view (``#1552 thread_major_diameter``), an
expression (``#1552``) or a name (``thread_major_diameter``) into a data id, ``setDataBreakpoints``
replaces the watched set.  The parameter store reports every write (``Parameters.on_write``); a
write to a watched number is noted, and the machine stops before the next statement, so the view
shows the value just written and the stack the line after the one that wrote it.
"""
from __future__ import annotations

import os
import re
from collections.abc import Mapping
from typing import Any

from edingcnc_lang.errors import EcncError
from edingcnc_lang.machine.state import format_value
from edingcnc_lang.machine.tables import FIRST_PARAM, LAST_PARAM
from edingcnc_lang.debug.launch import Launch

FIRST_ID = 1_000_000  # data breakpoint ids, apart from the line and function breakpoints' (counted from 1)
_NUMBER = re.compile(r"^\s*#\s*(\d+)\b")


def launch_names(launch: Launch) -> dict[int, str]:
    """The names the job and the macro files it runs with give their numbers (``varmap``)."""
    from edingcnc_lang.runner import Run, RunOptions
    from edingcnc_lang.varmap.names import names_of_paths

    try:
        run = Run(RunOptions(ini=launch.ini, macro=launch.macro, user_macro=launch.user_macro, plan=False))
        paths = [str(launch.program), *(str(path) for path, _program in run.load_macros())]
    except EcncError:  # the launch reports it (known_subs)
        return {}
    return names_of_paths(paths).labelled()


def number_of(text: str, names: Mapping[int, str]) -> int | None:
    """The parameter a variable's name, an expression ``#n`` or a name the files give stands for."""
    match = _NUMBER.match(text)
    if match:
        index = int(match.group(1))
        return index if FIRST_PARAM <= index <= LAST_PARAM else None
    wanted = text.strip().lower()
    return next((index for index, name in names.items() if name.lower() == wanted), None)


class DataBreakpoints:
    """The watched parameters and the write that hit one, until the machine stops for it."""

    def __init__(self) -> None:
        self.watched: dict[int, int] = {}  # parameter -> breakpoint id
        self.hit: int | None = None  # the watched parameter written since the last statement
        self._next_id = FIRST_ID

    def info(self, text: str, names: Mapping[int, str]) -> dict[str, Any]:
        """The ``dataBreakpointInfo`` body for a variable or expression."""
        from edingcnc_lang.varmap.names import label  # (loaded when first needed, not at start-up)

        index = number_of(text, names)
        if index is None:
            return {"dataId": None, "description": f"{text.strip()!r} is not a parameter (#1..#5999)"}
        return {"dataId": str(index), "description": f"when {label(index, names)} is written",
                "accessTypes": ["write"], "canPersist": True}

    def set(self, specs: list[dict[str, Any]]) -> list[dict[str, Any]]:
        """Replace the watched set (``setDataBreakpoints``); one answer per requested breakpoint."""
        self.watched, self.hit = {}, None
        answers = []
        for spec in specs:
            data_id = str(spec.get("dataId", ""))
            if not (data_id.isascii() and data_id.isdigit() and len(data_id) <= 4) \
                    or not FIRST_PARAM <= int(data_id) <= LAST_PARAM:
                answers.append({"verified": False, "message": f"{data_id!r} is not a parameter number"})
                continue
            if spec.get("accessType", "write") != "write":
                answers.append({"verified": False, "message": "only writes can be watched"})
                continue
            self._next_id += 1
            self.watched[int(data_id)] = self._next_id
            answers.append({"verified": True, "id": self._next_id})
        return answers

    def written(self, index: int) -> None:
        """A parameter was written (the first watched one written before the next statement counts)."""
        if index in self.watched and self.hit is None:
            self.hit = index

    def stopped_at(self, index: int, value: float, where: tuple[str, int], names: Mapping[int, str]) -> dict[str, Any]:
        """The ``stopped`` event's details for a hit: the breakpoint, and what was written where."""
        from edingcnc_lang.varmap.names import label

        text = f"{label(index, names)} = {format_value(value)} (written at {os.path.basename(where[0])}:{where[1]})"
        return {"hitBreakpointIds": [self.watched[index]], "description": text, "text": text}

    def take(self) -> int | None:
        """The watched parameter written since the last call, if any."""
        hit, self.hit = self.hit, None
        return hit
