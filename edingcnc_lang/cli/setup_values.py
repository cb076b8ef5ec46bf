"""The machine set up from the command line, without writing an ini: ``--var``, ``--offset``, ``--tool``.

Each is a parameter type that turns its text into the parameters the controller keeps the value in
(``--offset G54=10,20,-5`` is #5221..#5223, ``--tool 3=42.5,6`` is #5403 and #5503), so one
mechanism, ``RunOptions.variables``, sets them all before the job's first line, as a machine would
have them.  A read-only system variable is refused here, with the reason, before anything runs.
"""
from __future__ import annotations

from typing import Any

import click

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


class _Setting(click.ParamType):
    """``NAME=VALUES``: the part before ``=`` says where, the part after what."""

    def parse(self, name: str, values: str) -> Settings:
        raise NotImplementedError

    def convert(self, value: Any, param: click.Parameter | None, ctx: click.Context | None) -> Settings:
        if isinstance(value, tuple):
            return value
        name, equals, values = str(value).partition("=")
        if not equals:
            self.fail(f"{value!r}: expected {self.name}", param, ctx)
        try:
            return self.parse(name.strip(), values)
        except ValueError as err:
            self.fail(str(err), param, ctx)


class Variable(_Setting):
    """``--var N=V``: parameter #N starts at V (a user or persistent parameter; not a read-only one)."""

    name = "N=VALUE"

    def parse(self, name: str, values: str) -> Settings:
        try:
            index = plain_int(name.lstrip("#"))
        except ValueError:
            raise ValueError(f"{name!r} is not a parameter number (write --var 4520=1)") from None
        if not t.FIRST_PARAM <= index <= t.LAST_PARAM:
            raise ValueError(f"#{index} is not a parameter (#{t.FIRST_PARAM}..#{t.LAST_PARAM})")
        if t.is_read_only(index):
            raise ValueError(f"#{index} is a read-only system variable: the machine sets it, a job or the "
                             "command line cannot")
        return ((index, _number(values, f"#{index}:")),)


class Offset(_Setting):
    """``--offset G54=X,Y,Z[,A,B,C]``: a work offset (machine coordinates of that work zero)."""

    name = "G5x=X,Y,Z"

    def parse(self, name: str, values: str) -> Settings:
        key = name.upper()
        if key not in COORD_NAMES:
            raise ValueError(f"{name!r} is not a work offset (one of {', '.join(COORD_NAMES)})")
        numbers = [part for part in values.split(",")]
        if not 1 <= len(numbers) <= len(AXES):
            raise ValueError(f"{key}: give 1 to 6 numbers X,Y,Z,A,B,C, not {len(numbers)}")
        system = COORD_NAMES.index(key) + 1
        return tuple((t.coord_offset_param(system, axis), _number(text, f"{key} {AXES[axis]}:"))
                     for axis, text in enumerate(numbers))


class Tool(_Setting):
    """``--tool N=LENGTH[,DIAMETER]``: tool N's length (and diameter) in the tool table; ``--tool N``
    alone: tool N is in the spindle when the job starts (#5008)."""

    name = "N=LENGTH[,DIAMETER] or N"

    def convert(self, value: Any, param: click.Parameter | None, ctx: click.Context | None) -> Settings:
        if isinstance(value, str) and "=" not in value:
            try:
                number = plain_int(value.lstrip("Tt"))
            except ValueError:
                self.fail(f"{value!r}: expected N (the tool in the spindle) or N=LENGTH[,DIAMETER]", param, ctx)
            if not 0 <= number <= t.MAX_TOOL:
                self.fail(f"T{number}: tools are T0..T{t.MAX_TOOL}", param, ctx)
            return ((t.TOOL_CURRENT, float(number)),)
        return super().convert(value, param, ctx)

    def parse(self, name: str, values: str) -> Settings:
        try:
            number = plain_int(name.lstrip("Tt"))
        except ValueError:
            raise ValueError(f"{name!r} is not a tool number (write --tool 3=42.5,6)") from None
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


VARIABLE = Variable()
OFFSET = Offset()
TOOL = Tool()
