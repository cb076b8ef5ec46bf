"""Shared CLI plumbing: turning our errors into messages and exit codes."""
from __future__ import annotations

import functools
import sys
from collections.abc import Callable
from typing import Any, TypeVar

import click

from ..errors import EcncError

F = TypeVar("F", bound=Callable[..., Any])


def reports_errors(func: F) -> F:
    """Print an EcncError as ``PATH:LINE:COL: error: ...`` on stderr and exit with its code."""

    @functools.wraps(func)
    def wrapper(*args: Any, **kwargs: Any) -> Any:
        try:
            return func(*args, **kwargs)
        except EcncError as err:
            click.echo(err.format(), err=True)
            sys.exit(err.exit_code)

    return wrapper  # type: ignore[return-value]


def existing_file() -> click.Path:
    """A click path type for an input file that must exist (missing -> usage error, exit 2)."""
    return click.Path(exists=True, dir_okay=False)
