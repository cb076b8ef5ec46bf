"""Shared CLI plumbing: the parser class, the record each parser leaves in the namespace, path types."""
from __future__ import annotations

import argparse
import gc
import os
import re
from collections.abc import Callable, Iterable, Iterator
from contextlib import contextmanager
from dataclasses import dataclass
from typing import TYPE_CHECKING, Any

if TYPE_CHECKING:
    from typing import TypeAlias

Handler = Callable[[argparse.Namespace], int]

# "-5", "-.5", "-2.5e-3", "-inf": values, not options (argparse by itself knows only the first two).
NEGATIVE_NUMBER = re.compile(r"-\.?\d|-inf|-nan", re.IGNORECASE)


@dataclass(frozen=True)
class Command:
    """What a command line asks for, left as the ``command`` default by the deepest parser it reached.

    ``parser`` shows its usage with a usage error; ``handler`` does the work and returns the exit
    code, or is None for ``ecnc`` and ``ecnc kins`` alone (which print their help).
    """

    parser: argparse.ArgumentParser
    handler: Handler | None


class UsageError(Exception):
    """A command line argparse accepts but that makes no sense (``--save-vars`` without ``--ini``): exit 2."""


class CommandParser(argparse.ArgumentParser):
    """argparse, reading command lines the way scripts wrote them for the click-based ``ecnc``.

    Options may stand between a command's arguments (``ecnc lint a.nc --select E b.nc``,
    ``ecnc kins inverse NAME --ini FILE X Y Z``), an argument such as ``-2.5e-3`` is a number,
    not an unknown option, and options must be spelt out (``--no`` is not ``--no-simulation``:
    an abbreviation would change meaning when an option is added).  A parser with subcommands
    (``intermixed=False``) cannot intermix.
    """

    def __init__(self, *, intermixed: bool = True, **kwargs: Any) -> None:
        super().__init__(allow_abbrev=False, **kwargs)
        self._negative_number_matcher = NEGATIVE_NUMBER
        self._intermixes = intermixed
        self._intermixing = False

    def parse_known_args(self, args: Iterable[str] | None = None, namespace: Any = None) -> tuple[Any, list[str]]:
        arguments = list(args) if args is not None else None
        # After "--" everything is an argument (ecnc run -- -x.nc); argparse's intermixed parsing
        # loses that between its two passes, so such a command line is read the plain way.
        if not self._intermixes or self._intermixing or (arguments is not None and "--" in arguments):
            return super().parse_known_args(arguments, namespace)
        # parse_known_intermixed_args calls parse_known_args for its two passes (3.10 to 3.13 at least)
        self._intermixing = True
        try:
            return self.parse_known_intermixed_args(arguments, namespace)
        finally:
            self._intermixing = False


if TYPE_CHECKING:
    Subcommands: TypeAlias = argparse._SubParsersAction[CommandParser]


def add_command(commands: Subcommands, name: str, handler: Handler | None, summary: str,
                **kwargs: Any) -> CommandParser:
    """A subcommand's parser, which leaves ``Command(parser, handler)`` in the namespace."""
    parser = commands.add_parser(name, help=summary, description=summary, **kwargs)
    parser.set_defaults(command=Command(parser, handler))
    return parser


@contextmanager
def whole_trees() -> Iterator[None]:
    """Pause the cyclic garbage collector while a command builds whole syntax trees.

    A tree is hundreds of thousands of small acyclic objects that all stay alive; the collector
    would walk them again and again as they pile up (it took about 40 % of ``ecnc lint`` on a
    big macro file) and free nothing: reference counting frees everything they hold.
    """
    enabled = gc.isenabled()
    gc.disable()
    try:
        yield
    finally:
        if enabled:
            gc.enable()


def existing_path(value: str) -> str:
    """An input file or folder that must exist (argparse makes the error a usage error, exit 2)."""
    if not os.path.exists(value):
        raise argparse.ArgumentTypeError(f"{value!r} does not exist")
    if not os.access(value, os.R_OK):
        raise argparse.ArgumentTypeError(f"{value!r} is not readable")
    return value


def existing_file(value: str) -> str:
    """An input file that must exist, and not be a folder."""
    if not os.path.exists(value):
        raise argparse.ArgumentTypeError(f"file {value!r} does not exist")
    if os.path.isdir(value):
        raise argparse.ArgumentTypeError(f"{value!r} is a folder, not a file")
    return existing_path(value)


def existing_folder(value: str) -> str:
    """A folder that must exist (``--log-dir``: the job's log files go nowhere else)."""
    if not os.path.exists(value):
        raise argparse.ArgumentTypeError(f"folder {value} does not exist")
    if not os.path.isdir(value):
        raise argparse.ArgumentTypeError(f"{value!r} is a file, not a folder")
    return value


def output_file(value: str) -> str:
    """A file to write: it need not exist, but a folder there is a mistake to report up front."""
    if os.path.isdir(value):
        raise argparse.ArgumentTypeError(f"{value!r} is a folder, not a file")
    return value


def positive_int(value: str) -> int:
    """A whole number of at least 1 (``--max-steps``)."""
    try:
        number = int(value)
    except ValueError:
        raise argparse.ArgumentTypeError(f"{value!r} is not a whole number") from None
    if number < 1:
        raise argparse.ArgumentTypeError(f"{number} is less than 1")
    return number
