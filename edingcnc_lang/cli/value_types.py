"""Parameter types of the command line: files that must exist, counts, lint codes, dialog answers.

A value click rejects is a usage error (exit 2) naming the option, before anything runs.  The
lint and host modules are imported only when a value of theirs is read, so the other commands
start without them.
"""
from __future__ import annotations

import os
from typing import TYPE_CHECKING, Any

import click
from click.shell_completion import CompletionItem

from edingcnc_lang.syntax.source import is_device, plain_float, plain_int
from edingcnc_lang.cli.streams import STDIN  # "-" as a job or lint path: read standard input (re-exported)

if TYPE_CHECKING:
    from edingcnc_lang.host import DialogAnswer


STDOUT = "-"  # as an output file (--trace -): write standard output


class _PathType(click.ParamType):
    """A path given as text (commands take ``str`` and make ``Path``s where they need them).

    With ``stdin``, ``-`` is accepted as is: the command reads standard input.
    """

    name = "path"
    completion = "file"

    def __init__(self, stdin: bool = False) -> None:
        self.stdin = stdin

    def check(self, value: str) -> str | None:
        """What is wrong with ``value``, or None."""
        raise NotImplementedError

    def convert(self, value: Any, param: click.Parameter | None, ctx: click.Context | None) -> str:
        text = os.fspath(value)
        if self.stdin and text == STDIN:
            return text
        problem = self.check(text)
        if problem:
            self.fail(problem, param, ctx)
        return text

    def shell_complete(self, ctx: click.Context, param: click.Parameter, incomplete: str) -> list[CompletionItem]:
        return [CompletionItem(incomplete, type=self.completion)]


def _unreadable(value: str) -> str | None:
    """Why ``value`` cannot be read as input, or None.

    A device (``/dev/zero``, ``/dev/urandom``) is refused: it never ends, so reading it would hang
    and fill memory.  A FIFO is allowed, for a generator's output (``ecnc run <(gen)``).
    """
    if not os.path.exists(value):
        return f"{value!r} does not exist"
    if not os.access(value, os.R_OK):
        return f"{value!r} is not readable"
    try:
        mode = os.stat(value).st_mode
    except OSError as exc:
        return f"{value!r} cannot be read: {exc.strerror or exc}"
    if is_device(mode):
        return f"{value!r} is a device, not a file"
    return None


class ExistingPath(_PathType):
    """An input file or folder that must exist and be readable."""

    def check(self, value: str) -> str | None:
        return _unreadable(value)


class ExistingFile(_PathType):
    """An input file that must exist, and not be a folder; ``suffix`` limits what completion offers."""

    name = "file"

    def __init__(self, stdin: bool = False, suffix: str | None = None) -> None:
        super().__init__(stdin)
        self.suffix = suffix

    def shell_complete(self, ctx: click.Context, param: click.Parameter, incomplete: str) -> list[CompletionItem]:
        if self.suffix is None:
            return super().shell_complete(ctx, param, incomplete)
        return [CompletionItem(path) for path in _paths_like(incomplete, self.suffix)]

    def check(self, value: str) -> str | None:
        if not os.path.exists(value):
            return f"file {value!r} does not exist"
        if os.path.isdir(value):
            return f"{value!r} is a folder, not a file"
        return _unreadable(value)


def _paths_like(incomplete: str, suffix: str) -> list[str]:
    """Folders (ending in /) and ``*suffix`` files (any case) whose path starts with ``incomplete``."""
    folder, _, start = incomplete.rpartition("/")
    where = folder or "."
    try:
        names = sorted(os.listdir(where if folder or not incomplete.startswith("/") else "/"))
    except OSError:
        return []
    found = []
    for name in names:
        if not name.startswith(start) or (name.startswith(".") and not start.startswith(".")):
            continue
        path = f"{folder}/{name}" if folder else name
        if os.path.isdir(path):
            found.append(path + "/")
        elif name.lower().endswith(suffix):
            found.append(path)
    return found


class ExistingFolder(_PathType):
    """A folder that must exist (``--log-dir``: the job's log files go nowhere else)."""

    name = "directory"
    completion = "dir"

    def check(self, value: str) -> str | None:
        if not os.path.exists(value):
            return f"folder {value} does not exist"
        if not os.path.isdir(value):
            return f"{value!r} is a file, not a folder"
        return None


class LogFolder(ExistingFolder):
    """A folder for the job's files (``--log-dir``): made if it does not exist yet, but not a file."""

    def check(self, value: str) -> str | None:
        return f"{value!r} is a file, not a folder" if os.path.exists(value) and not os.path.isdir(value) else None


class OutputFile(_PathType):
    """A file to write: it need not exist, but a folder there is a mistake to report up front."""

    name = "file"

    def check(self, value: str) -> str | None:
        if not value:  # --trace '' would otherwise be taken as no --trace at all
            return "the file name is empty"
        return f"{value!r} is a folder, not a file" if os.path.isdir(value) else None


class PlainFloat(click.FloatRange):
    """A number written with ASCII digits (``inf`` and ``nan`` are left to the range and the
    command to refuse); click's float() would also take '１００' and '1_0'."""

    def convert(self, value: Any, param: click.Parameter | None, ctx: click.Context | None) -> Any:
        if isinstance(value, str):
            try:
                value = plain_float(value, special=True)
            except ValueError:
                self.fail(f"{value!r} is not a number (digits 0-9, a point, an exponent)", param, ctx)
        return super().convert(value, param, ctx)


class PlainInt(click.IntRange):
    """A whole number written with ASCII digits; click's int() would also take '١' and '1_0'."""

    def convert(self, value: Any, param: click.Parameter | None, ctx: click.Context | None) -> Any:
        if isinstance(value, str):
            try:
                value = plain_int(value)
            except ValueError:
                self.fail(f"{value!r} is not a whole number", param, ctx)
        return super().convert(value, param, ctx)


class PositiveInt(click.ParamType):
    """A whole number of at least 1 (``--max-steps``)."""

    name = "integer"

    def convert(self, value: Any, param: click.Parameter | None, ctx: click.Context | None) -> int:
        if isinstance(value, int):
            number = value
        else:
            try:
                number = plain_int(value)
            except ValueError:
                self.fail(f"{value!r} is not a whole number", param, ctx)
        if number < 1:
            self.fail(f"{number} is less than 1", param, ctx)
        return number


def _codes_starting(text: str, kins: bool = False) -> list[str]:
    """Lint codes (and with ``kins`` the ``ecnc kins check`` codes) that start with ``text``."""
    from edingcnc_lang.codes import CODES, KINS_CODES

    codes = [*CODES, *KINS_CODES] if kins else CODES
    return [code for code in codes if code.startswith(text.upper())]


class LintCodes(click.ParamType):
    """``E,S208,G5``: lint codes or prefixes of codes, checked against the registry."""

    name = "codes"

    def shell_complete(self, ctx: click.Context, param: click.Parameter, incomplete: str) -> list[CompletionItem]:
        done, _, last = incomplete.rpartition(",")
        return [CompletionItem(f"{done},{code}" if done else code) for code in _codes_starting(last)]

    def convert(self, value: Any, param: click.Parameter | None, ctx: click.Context | None) -> tuple[str, ...]:
        from edingcnc_lang.lint import UnknownCode, parse_codes

        if isinstance(value, tuple):
            return value
        try:
            return parse_codes(value)
        except UnknownCode as err:
            self.fail(f"no code starts with {err} (see --list-codes)", param, ctx)


class LintCode(click.ParamType):
    """One lint code (``--explain V302``); checked by the command, which says where to look."""

    name = "code"

    def shell_complete(self, ctx: click.Context, param: click.Parameter, incomplete: str) -> list[CompletionItem]:
        return [CompletionItem(code) for code in _codes_starting(incomplete)]


class HelpTopic(LintCode):
    """A word of ``ecnc help``: a command (of the group reached so far) or a lint code."""

    name = "topic"

    def shell_complete(self, ctx: click.Context, param: click.Parameter, incomplete: str) -> list[CompletionItem]:
        group: Any = ctx.find_root().command
        for word in ctx.params.get(param.name or "", ()) or ():
            group = group.get_command(ctx, word) if isinstance(group, click.Group) else None
        commands = group.list_commands(ctx) if isinstance(group, click.Group) else []
        found = [CompletionItem(name) for name in commands if name.startswith(incomplete)]
        codes = _codes_starting(incomplete, kins=True) if group is ctx.find_root().command else []
        return found + [CompletionItem(code) for code in codes]


class KinematicsName(click.ParamType):
    """A kinematics plug-in: a registered name (completed) or the path of a .so or .py file."""

    name = "name"

    def shell_complete(self, ctx: click.Context, param: click.Parameter, incomplete: str) -> list[CompletionItem]:
        from edingcnc_lang.kinematics.loader import available_kinematics

        names = [CompletionItem(name) for name, _type, _version in available_kinematics() if name.startswith(incomplete)]
        return names or [CompletionItem(incomplete, type="file")]


class Answer(click.ParamType):
    """An answer for the next ``dlgmsg``: ``ok``, ``cancel`` or ``ok:#N=V,#M=W``."""

    name = "answer"

    def convert(self, value: Any, param: click.Parameter | None, ctx: click.Context | None) -> DialogAnswer:
        from edingcnc_lang.host import DialogAnswer

        if isinstance(value, DialogAnswer):
            return value
        try:
            return DialogAnswer.parse(value)
        except ValueError as err:
            self.fail(str(err), param, ctx)

    def shell_complete(self, ctx: click.Context, param: click.Parameter, incomplete: str) -> list[CompletionItem]:
        return [CompletionItem(word) for word in ("ok", "cancel", "ok:#") if word.startswith(incomplete)]


class ModbusValues(click.ParamType):
    """What the next modbus read gets: ``7`` or ``7,8``."""

    name = "values"

    def convert(self, value: Any, param: click.Parameter | None, ctx: click.Context | None) -> tuple[float, ...]:
        from edingcnc_lang.host import parse_modbus_values

        if isinstance(value, tuple):
            return value
        try:
            return parse_modbus_values(value)
        except ValueError as err:
            self.fail(str(err), param, ctx)


MODBUS_VALUES = ModbusValues()
EXISTING_FILE = ExistingFile()
INPUT_PATH = ExistingPath(stdin=True)  # a path to lint, or - for standard input
INPUT_FILE = ExistingFile(stdin=True)  # a job or file to parse, or - for standard input
EXISTING_FOLDER = ExistingFolder()
LOG_FOLDER = LogFolder()
INI_FILE = ExistingFile(suffix=".ini")
OUTPUT_FILE = OutputFile()
POSITIVE_INT = PositiveInt()
FLOAT = PlainFloat()
INT = PlainInt()
LINT_CODES = LintCodes()
LINT_CODE = LintCode()
HELP_TOPIC = HelpTopic()
KINEMATICS_NAME = KinematicsName()
ANSWER = Answer()
