"""A machine's state before the job, given as text: a parameter, a work offset, a tool of the table.

``--var 4520=1``, ``--offset G54=10,20,-5`` and ``--tool 3=42.5,6`` on the command line and the
``vars``/``offsets``/``tools`` of the debugger's launch arguments are read here, once, into the
parameters the controller keeps them in (``--offset G54=...`` is #5221..#5223, ``--tool 3=42.5,6``
is #5403 and #5503), which ``RunOptions.variables`` sets before the job's first line.  Each reader
raises ValueError with the reason (a read-only system variable, a work offset that does not exist).
"""
from __future__ import annotations

from edingcnc_lang.machine import tables as t
from edingcnc_lang.syntax.source import plain_float, plain_int

Settings = tuple[tuple[int, float], ...]  # (parameter, value), in the order given
COORD_NAMES = ("G54", "G55", "G56", "G57", "G58", "G59", "G59.1", "G59.2", "G59.3")
AXES = "XYZABC"


def _number(text: str, what: str) -> float:
    try:
        return plain_float(text)
    except ValueError:
        raise ValueError(f"{what} {text.strip()!r} is not a plain decimal number") from None


def variable(name: str, value: str) -> Settings:
    """Parameter #``name`` (``4520`` or ``#4520``) starts at ``value``; not a read-only one."""
    try:
        index = plain_int(name.strip().lstrip("#"))
    except ValueError:
        raise ValueError(f"{name!r} is not a parameter number (write 4520=1)") from None
    if not t.FIRST_PARAM <= index <= t.LAST_PARAM:
        raise ValueError(f"#{index} is not a parameter (#{t.FIRST_PARAM}..#{t.LAST_PARAM})")
    if t.is_read_only(index):
        raise ValueError(f"#{index} is a read-only system variable: the machine sets it, a job or the "
                         "command line cannot")
    return ((index, _number(value, f"#{index}:")),)


def offset(name: str, values: str) -> Settings:
    """Work offset ``name`` (G54..G59.3) at ``values``, X,Y,Z[,A,B,C] in machine coordinates."""
    key = name.strip().upper()
    if key not in COORD_NAMES:
        raise ValueError(f"{name!r} is not a work offset (one of {', '.join(COORD_NAMES)})")
    numbers = values.split(",")
    if not 1 <= len(numbers) <= len(AXES):
        raise ValueError(f"{key}: give 1 to 6 numbers X,Y,Z,A,B,C, not {len(numbers)}")
    system = COORD_NAMES.index(key) + 1
    return tuple((t.coord_offset_param(system, axis), _number(text, f"{key} {AXES[axis]}:"))
                 for axis, text in enumerate(numbers))


def tool(name: str, values: str | None) -> Settings:
    """Tool ``name``'s LENGTH[,DIAMETER] in the table; ``values`` None: tool ``name`` is in the spindle (#5008)."""
    try:
        number = plain_int(name.strip().lstrip("Tt"))
    except ValueError:
        raise ValueError(f"{name!r} is not a tool number (write 3=42.5,6, or 3 for the tool in the spindle)") from None
    if values is None:
        if not 0 <= number <= t.MAX_TOOL:
            raise ValueError(f"T{number}: tools are T0..T{t.MAX_TOOL}")
        return ((t.TOOL_CURRENT, float(number)),)
    if not 1 <= number <= t.MAX_TOOL:
        raise ValueError(f"T{number}: tools are T1..T{t.MAX_TOOL}")
    parts = values.split(",")
    if len(parts) > 2:
        raise ValueError(f"T{number}: give LENGTH or LENGTH,DIAMETER, not {len(parts)} numbers")
    settings = [(t.TOOL_LENGTH + number, _number(parts[0], f"T{number} length:"))]
    if len(parts) == 2:
        diameter = _number(parts[1], f"T{number} diameter:")
        if diameter < 0:
            raise ValueError(f"T{number}: the diameter must not be negative")
        settings.append((t.TOOL_DIAMETER + number, diameter))
    return tuple(settings)
