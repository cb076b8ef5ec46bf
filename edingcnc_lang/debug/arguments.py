"""The arguments of every request the adapter answers, checked before it acts.

Each request's ``arguments`` object is checked against a table of the fields the adapter reads:
their JSON type, the range of a number, the length of a string (no NUL anywhere); a field the
table does not name is ignored, as the protocol allows.  A request that fails gets
``success: false`` with the first problem (``launch: maxSteps must be a whole number from 1``),
so no handler ever sees a list where it reads a string or a 5,000-character path.
"""
from __future__ import annotations

import math

from collections.abc import Callable, Mapping
from typing import Any

from edingcnc_lang.syntax.input_limits import MAX_LINE_LENGTH

MAX_PATH_CHARS = 4096  # a path (PATH_MAX on Linux); longer ones cannot be opened anyway
MAX_NAME_CHARS = 1024  # a sub's or a variable's name, a filter, a client's name
MAX_TEXT_CHARS = MAX_LINE_LENGTH  # an expression, condition, log message or value: one line of the dialect
MAX_ITEMS = 10_000  # breakpoints of one file, function breakpoints, scripted answers, filters
MAX_ID = 2**31 - 1  # lines, ids and references
MAX_STEPS = 2**53  # maxSteps (a JSON number exact in every client)
MAX_SETTING = 1e9  # a number of the machine's start state (vars, offsets, tools, probeAt): far beyond any machine

Check = Callable[[Any, str], "str | None"]  # (value, its name) -> the problem, or None


def _boolean(value: Any, where: str) -> str | None:
    return None if isinstance(value, bool) else f"{where} must be true or false"


def _whole(low: int = 0, high: int = MAX_ID) -> Check:
    def check(value: Any, where: str) -> str | None:
        if type(value) is not int or not low <= value <= high:
            return f"{where} must be a whole number from {low} to {high:,}"
        return None
    return check


def _string(limit: int) -> Check:
    def check(value: Any, where: str) -> str | None:
        if not isinstance(value, str):
            return f"{where} must be a string"
        if len(value) > limit:
            return f"{where} has {len(value):,} characters, more than the {limit:,} it may have"
        if "\0" in value:
            return f"{where} contains a NUL character"
        return None
    return check


def _list(item: Check, limit: int = MAX_ITEMS) -> Check:
    def check(value: Any, where: str) -> str | None:
        if not isinstance(value, list):
            return f"{where} must be a list"
        if len(value) > limit:
            return f"{where} has {len(value):,} items, more than the {limit:,} it may have"
        return next((p for i, v in enumerate(value) if (p := item(v, f"{where}[{i}]")) is not None), None)
    return check


def _object(fields: Mapping[str, Check], required: tuple[str, ...] = ()) -> Check:
    def check(value: Any, where: str) -> str | None:
        if not isinstance(value, dict):
            return f"{where} must be an object"
        for name in required:
            if value.get(name) is None:
                return f"{where} needs {name!r}"
        for name, field in fields.items():
            if value.get(name) is not None:
                problem = field(value[name], f"{where}.{name}" if where else name)
                if problem is not None:
                    return problem
        return None
    return check


def _number(value: Any, where: str) -> str | None:
    """A finite JSON number (a setting of the machine: a parameter's value, a length)."""
    if type(value) not in (int, float) or not math.isfinite(value) or abs(value) > MAX_SETTING:
        return f"{where} must be a finite number of at most {MAX_SETTING:g} in size"
    return None


def _table(value_check: Check) -> Check:
    """An object of at most MAX_ITEMS names (short strings) to values."""
    def check(value: Any, where: str) -> str | None:
        if not isinstance(value, dict):
            return f"{where} must be an object"
        if len(value) > MAX_ITEMS:
            return f"{where} has {len(value):,} entries, more than the {MAX_ITEMS:,} it may have"
        return next((p for k, v in value.items()
                     if (p := NAME(k, f"{where} key") or value_check(v, f"{where}.{k}")) is not None), None)
    return check


def _either(first: Check, second: Check) -> Check:
    def check(value: Any, where: str) -> str | None:
        return None if first(value, where) is None else second(value, where)
    return check


BOOLEAN, WHOLE, NUMBER = _boolean, _whole(), _number
PATH, NAME, TEXT = _string(MAX_PATH_CHARS), _string(MAX_NAME_CHARS), _string(MAX_TEXT_CHARS)
_SOURCE_BREAKPOINT = _object({"line": _whole(), "column": _whole(), "condition": TEXT, "hitCondition": NAME,
                              "logMessage": TEXT}, required=("line",))
_FUNCTION_BREAKPOINT = _object({"name": NAME, "condition": TEXT, "hitCondition": NAME}, required=("name",))
_THREAD = {"threadId": WHOLE}
_RESUME = _object({"threadId": WHOLE, "singleThread": BOOLEAN, "granularity": NAME})

# The fields each request's handler reads; a request not listed takes no arguments it reads.
REQUESTS: dict[str, Check] = {
    "initialize": _object({"adapterID": NAME, "clientID": NAME, "clientName": NAME, "locale": NAME,
                           "pathFormat": NAME, "linesStartAt1": BOOLEAN, "columnsStartAt1": BOOLEAN}),
    "launch": _object({"program": PATH, "cwd": PATH, "ini": PATH, "macro": PATH, "userMacro": PATH,
                       "probeSurface": PATH, "logDir": PATH, "answers": _list(NAME), "stopOnEntry": BOOLEAN,
                       "noDebug": BOOLEAN, "maxSteps": _whole(1, MAX_STEPS), "probeAt": NUMBER,
                       "vars": _table(NUMBER), "offsets": _table(_list(NUMBER, 6)),
                       "tools": _table(_either(NUMBER, _list(NUMBER, 2)))}),
    "setBreakpoints": _object({"source": _object({"path": PATH, "name": PATH}),
                               "breakpoints": _list(_SOURCE_BREAKPOINT),
                               "lines": _list(_whole()), "sourceModified": BOOLEAN}, required=("source",)),
    "setFunctionBreakpoints": _object({"breakpoints": _list(_FUNCTION_BREAKPOINT)}, required=("breakpoints",)),
    "setExceptionBreakpoints": _object({"filters": _list(NAME)}, required=("filters",)),
    "dataBreakpointInfo": _object({"name": NAME, "variablesReference": WHOLE, "frameId": WHOLE}, required=("name",)),
    "setDataBreakpoints": _object({"breakpoints": _list(_object({"dataId": NAME, "accessType": NAME, "condition": TEXT,
                                                                 "hitCondition": NAME}, required=("dataId",)))},
                                  required=("breakpoints",)),
    "stackTrace": _object({**_THREAD, "startFrame": WHOLE, "levels": WHOLE}),
    "scopes": _object({"frameId": WHOLE}),
    "variables": _object({"variablesReference": WHOLE, "filter": NAME, "start": WHOLE, "count": WHOLE},
                         required=("variablesReference",)),
    "setVariable": _object({"variablesReference": WHOLE, "name": NAME, "value": TEXT},
                           required=("variablesReference", "name", "value")),
    "evaluate": _object({"expression": TEXT, "frameId": WHOLE, "context": NAME}, required=("expression",)),
    "exceptionInfo": _object(_THREAD),
    "continue": _RESUME, "next": _RESUME, "stepIn": _RESUME, "stepOut": _RESUME, "stepBack": _RESUME,
    "reverseContinue": _RESUME,
    "pause": _object(_THREAD),
    "terminate": _object({"restart": BOOLEAN}),
    "disconnect": _object({"restart": BOOLEAN, "terminateDebuggee": BOOLEAN, "suspendDebuggee": BOOLEAN}),
}


def arguments_problem(command: str, arguments: Any) -> str | None:
    """Why ``arguments`` cannot be the arguments of ``command``; None when they can."""
    if not isinstance(arguments, dict):
        return f"{command}: arguments must be an object"
    check = REQUESTS.get(command)
    problem = check(arguments, "") if check is not None else None
    return f"{command}: {problem}" if problem is not None else None
