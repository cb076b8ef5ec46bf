"""The machine set up from the command line, without writing an ini: ``--var``, ``--offset``, ``--tool``.

Each is a parameter type over a reader of ``machine.start_state`` (shared with the debugger's launch
arguments), which turns its text into the parameters the controller keeps the value in; one
mechanism, ``RunOptions.variables``, sets them all before the job's first line.  A value that cannot
be (a read-only system variable, a work offset that does not exist) is a usage error with the reason.
"""
from __future__ import annotations

from collections.abc import Callable
from typing import Any

import click

from edingcnc_lang.machine import start_state
from edingcnc_lang.machine.start_state import Settings

__all__ = ["OFFSET", "TOOL", "VARIABLE", "Settings"]


class _Setting(click.ParamType):
    """``NAME=VALUES`` read by ``read``; with ``bare``, ``NAME`` alone too."""

    def __init__(self, name: str, read: Callable[..., Settings], bare: bool = False) -> None:
        self.name = name
        self.read = read
        self.bare = bare

    def convert(self, value: Any, param: click.Parameter | None, ctx: click.Context | None) -> Settings:
        if isinstance(value, tuple):
            return value
        key, equals, values = str(value).partition("=")
        if not equals and not self.bare:
            self.fail(f"{value!r}: expected {self.name}", param, ctx)
        try:
            return self.read(key, values if equals else None)
        except ValueError as err:
            self.fail(str(err), param, ctx)


VARIABLE = _Setting("N=VALUE", start_state.variable)
OFFSET = _Setting("G5x=X,Y,Z", start_state.offset)
TOOL = _Setting("N=LENGTH[,DIAMETER] or N", start_state.tool, bare=True)
