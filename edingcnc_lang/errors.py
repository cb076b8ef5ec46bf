"""Error types shared by every stage.

Every error the user can cause carries a location so the CLI can print
``PATH:LINE:COL: error: MESSAGE`` and never a traceback.  The exit code that
belongs to an error is part of its type (see docs/cli.md).
"""
from __future__ import annotations

import importlib
import re

from types import ModuleType
from typing import Any

from edingcnc_lang.codes import runtime_code
from edingcnc_lang.records import record

EXIT_OK = 0
EXIT_FINDINGS = 1
EXIT_USAGE = 2
EXIT_SYNTAX = 65
EXIT_RUNTIME = 70
EXIT_INTERRUPTED = 130  # 128 + SIGINT, as shells report a job stopped with Ctrl-C


# Characters a terminal would act on rather than show: C0 controls but tab and newline, DEL, C1
# controls (a Latin-1 job can hold them) and the bidirectional overrides that reorder what is shown.
_UNPRINTABLE = re.compile("[\x00-\x08\x0b-\x1f\x7f-\x9f\u202a-\u202e\u2066-\u2069]")


def printable(text: str) -> str:
    """``text`` safe to show on a terminal: a control character becomes ``\\xNN`` (``\\uNNNN``), so a
    job cannot retitle or clear the user's terminal through an error message or a ``msg``."""
    return _UNPRINTABLE.sub(lambda m: f"\\x{ord(m[0]):02x}" if ord(m[0]) < 0x100 else f"\\u{ord(m[0]):04x}", text)


# A message quotes what the user wrote (a name, a number); past these lengths the quote is cut in
# the middle, so a 65,000-letter name or a 309-digit number does not fill the terminal.
_LONG_WORD = re.compile(r"[^\s'\",:;()]{121,}")
_LONG_NUMBER = re.compile(r"(?<![\w.])-?\d{18,}(?:\.\d+)?(?![\w.])")


def shortened(text: str) -> str:
    """``text`` with every number of 18 digits or more written as ``1.23457e+308`` and every word
    longer than 120 characters cut to its ends and its length (``abc…xyz (65,000 characters)``)."""
    if len(text) < 18:
        return text
    text = _LONG_NUMBER.sub(lambda m: f"{float(m[0]):.6g}", text)
    return _LONG_WORD.sub(lambda m: f"{m[0][:60]}…{m[0][-20:]} ({len(m[0]):,} characters)", text)


@record(frozen=True)
class Location:
    """Where something happened; line and col are 1-based, 0 means unknown."""

    path: str
    line: int = 0
    col: int = 0

    def __str__(self) -> str:
        parts = [self.path]
        if self.line:
            parts.append(str(self.line))
            if self.col:
                parts.append(str(self.col))
        return ":".join(parts)


@record(frozen=True)
class Frame:
    """One sub call on the way to an error, innermost first: the sub as its ``Sub`` line names it, and
    the file and line of the ``GoSub`` (or M-code line) that called it."""

    sub: str
    path: str
    line: int


class EcncError(Exception):
    """Base of all errors reported to the user; ``exit_code`` picks the CLI exit status.

    ``code`` is the stable code of the error (``R8xx`` for an error that stopped a run, docs/errors.md;
    ``ecnc help CODE`` explains it), ``frames`` the sub calls that led to it, innermost first, and
    ``result`` (set by a run that failed) the machine as the error left it: a ``runner.RunResult``.
    """

    exit_code = EXIT_RUNTIME
    kind = "error"  # the ``kind`` of the ``--json`` error object (docs/cli.md)
    # A move of a batch refused: how many moves of the batch were made before it (set where it is refused;
    # None when not known), so the machine's state can be that after them, as moving one at a time leaves it.
    done: int | None = None
    # the partial result of the run the error stopped (runner.RunResult; typed loosely here because
    # this foundation module is below the runner: ``runner.result_of(err)`` gives it typed)
    result: Any = None

    def __init__(self, message: str, location: Location | None = None,
                 notes: tuple[str, ...] = (), *, code: str | None = None) -> None:
        message = shortened(message)
        super().__init__(message)
        self.message = message
        self.location = location
        self.notes = notes
        self.frames: tuple[Frame, ...] = ()
        self._code = code

    @property
    def code(self) -> str:
        """The stable code: given where the error is raised, else by its kind and message (codes.py)."""
        return self._code or runtime_code(self.kind, self.message)

    def format(self) -> str:
        """Render as ``PATH:LINE:COL: error: MESSAGE`` plus indented notes."""
        head = f"{self.location}: error: {self.message}" if self.location else f"error: {self.message}"
        return printable("\n".join([head, *(f"  {n}" for n in self.notes)]))

    def to_json(self) -> dict[str, object]:
        """The ``error`` object of a ``--json`` document: kind, message, where, and the text as printed."""
        where = self.location or Location("")
        return {"kind": self.kind, "code": self.code, "message": self.message, "file": where.path or None,
                "line": where.line or None, "column": where.col or None, "text": self.format(),
                "frames": [{"sub": f.sub, "file": f.path, "line": f.line} for f in self.frames]}


class UnreadableFile(EcncError):
    """An input file that cannot be read (missing, a folder, no permission): a usage error."""

    exit_code = EXIT_USAGE

    @classmethod
    def of(cls, path: object, exc: OSError) -> "UnreadableFile":
        return cls(f"cannot read: {exc.strerror or exc}", Location(str(path)))


class ConfigError(EcncError):
    """A bad value in cnc.ini (location names the ini file and line)."""

    kind = "configuration"


class PluginError(EcncError):
    """A kinematics plug-in that failed to load or raised while running."""

    kind = "plugin"


class MissingExtra(EcncError):
    """An optional dependency (an extra such as ``plot``) is not installed: say how to install it."""

    exit_code = EXIT_USAGE


def require_extra(module: str, extra: str, feature: str) -> ModuleType:
    """Import ``module`` or fail with the one wording of how to install the ``extra`` that brings it.

    ``feature`` says who needs it ("the language server", "ecnc kins plot"), so the user knows
    why an optional package is asked for.
    """
    try:
        return importlib.import_module(module)
    except ImportError as err:
        missing = err.name or module
        raise MissingExtra(f"{feature} needs {module} ({missing} is missing): "
                           f"pip install 'edingcnc-lang[{extra}]'") from None


class MachineError(EcncError):
    """A runtime error while running a job: errmsg, limits, bad arguments, step budget."""

    kind = "runtime"


class JobAborted(MachineError):
    """``errmsg`` stopped the job; its text was already reported as a message when it ran."""

    kind = "errmsg"


class Interrupted(EcncError):
    """Ctrl-C: the location is the line the run had reached (exit 130)."""

    exit_code = EXIT_INTERRUPTED
    kind = "interrupted"


class Cancelled(Interrupted):
    """``Run.cancel()`` (or breaking out of ``Run.moves()``) stopped the run; ``result`` is the state so far."""

    kind = "cancelled"


class CallbackError(MachineError):
    """A callback of the embedding program (``on_move``, ``on_event``, a ``Host`` function) raised; the
    callback's exception is ``__cause__``, the location is the line whose move or event it was handed."""

    kind = "callback"

    @classmethod
    def of(cls, who: str, exc: Exception, where: Location | None) -> CallbackError:
        """``WHO raised ZeroDivisionError: division by zero`` at ``where``, the callback's exception its cause."""
        text = str(exc)
        error = cls(f"{who} raised {type(exc).__name__}{': ' + text if text else ''}", where)
        error.__cause__ = exc
        return error


class UsageFailure(EcncError):
    """A command line that cannot run (exit 2); for the ``--json`` error object of a usage error."""

    exit_code = EXIT_USAGE
    kind = "usage"
