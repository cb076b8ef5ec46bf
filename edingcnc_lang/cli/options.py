"""Options shared by the commands, as decorators, so every command spells and checks them alike.

``@machine_options`` gives a command the virtual machine a job runs on (``--ini``, ``--macro``,
``--user-macro``, ``--answer``, ``--max-steps``, ``--log-dir``, ``--allow-exec``,
``--no-simulation``, ``--block-delete``, ``--strict``, ``--probe-surface``, ``--probe-at``,
``--modbus``), its set-up without an ini (``--var``, ``--offset``, ``--tool``) and ``-q``, and hands
the command one ``machine: MachineOptions`` argument, which builds the ``RunOptions`` of the Python
API.  Every command that runs a job takes the same set.  See docs/cli.md, "Adding a command".
"""
from __future__ import annotations

import functools
import sys
from collections.abc import Callable
from dataclasses import dataclass
from pathlib import Path
from typing import TYPE_CHECKING, Any, TypeVar

import click

from edingcnc_lang.errors import printable
from edingcnc_lang.cli.value_types import (
    ANSWER,
    EXISTING_FILE,
    FLOAT,
    INI_FILE,
    INPUT_FILE,
    LOG_FOLDER,
    MODBUS_VALUES,
    POSITIVE_INT,
    PlainFloat,
)
from edingcnc_lang.cli.setup_values import OFFSET, TOOL, VARIABLE, Settings
from edingcnc_lang.machine.tables import TOOL_CURRENT

if TYPE_CHECKING:
    from collections.abc import Sequence

    from edingcnc_lang.diagnostics import Diagnostic
    from edingcnc_lang.host import DialogAnswer, DialogCallback, DialogField
    from edingcnc_lang.runner import Assumption, RunOptions

F = TypeVar("F", bound=Callable[..., Any])

# How a message of the job is labelled on stderr (``PATH:LINE: LABEL: TEXT``); dialogs are not shown.
MESSAGE_LABEL = {"msg": "msg", "warn": "warning", "error": "error", "log": "log"}


def ini_option(help: str = "Machine configuration (cnc.ini).") -> Callable[[F], F]:  # noqa: A002 - click's name
    return click.option("--ini", metavar="FILE", type=INI_FILE, help=help)


def macro_options(macro_help: str = "Macro file (default: the ini's, else the packaged one).",
                  user_macro_help: str = "User macro file.") -> Callable[[F], F]:
    """``--macro FILE`` and ``--user-macro FILE``, both files that must exist."""
    def decorate(func: F) -> F:
        func = click.option("--user-macro", metavar="FILE", type=EXISTING_FILE, help=user_macro_help)(func)
        return click.option("--macro", metavar="FILE", type=EXISTING_FILE, help=macro_help)(func)
    return decorate


def json_option(help: str) -> Callable[[F], F]:  # noqa: A002 - click's name
    """``--json``, passed to the command as ``as_json``."""
    return click.option("--json", "as_json", is_flag=True, help=help)


def override_options(func: F) -> F:
    """``--feed-override PCT`` and ``--rapid-override PCT``: the operator's knobs, which change the
    planner's timing (passed as ``feed_override`` and ``rapid_override``)."""
    func = click.option("--rapid-override", metavar="PCT", type=PlainFloat(0, 100, min_open=True),
                        default=100.0, help="Rapid override knob in percent, at most 100 (default 100).")(func)
    return click.option("--feed-override", metavar="PCT", type=PlainFloat(0, 1000, min_open=True),
                        default=100.0,
                        help="Feed override knob in percent (default 100; M48/M49/M50 in the job switch it).")(func)


def job_argument(func: F) -> F:
    """``JOB``: the file to run, passed as ``job``."""
    return click.argument("job", metavar="JOB", type=EXISTING_FILE)(func)


def job_or_stdin_argument(func: F) -> F:
    """``JOB``: the file to run, or ``-`` for standard input (the command handles ``STDIN``)."""
    return click.argument("job", metavar="JOB", type=INPUT_FILE)(func)


@dataclass(frozen=True)
class MachineOptions:
    """The machine options of one command line, as given."""

    ini: str | None = None
    macro: str | None = None
    user_macro: str | None = None
    answers: tuple[DialogAnswer, ...] = ()
    max_steps: int | None = None
    log_dir: str | None = None
    allow_exec: bool = False
    no_simulation: bool = False
    block_delete: bool = False
    strict: bool = False
    probe_surface: str | None = None
    modbus: tuple[tuple[float, ...], ...] = ()
    variables: tuple[Settings, ...] = ()  # --var, --offset and --tool, each the parameters it sets
    offsets: tuple[Settings, ...] = ()
    tools: tuple[Settings, ...] = ()
    probe_at: float | None = None
    quiet: bool = False
    verbose: bool = False

    @property
    def spindle_tool(self) -> int | None:
        """The tool ``--tool N`` put in the spindle (#5008) at the start, if any."""
        chosen = [value for given in self.tools for index, value in given if index == TOOL_CURRENT]
        return int(chosen[-1]) if chosen else None

    def run_options(self, show_messages: bool = True, **extra: Any) -> RunOptions:
        """``RunOptions`` for these options; ``extra`` sets the rest (``trace=Path(...)``, ...).

        With ``show_messages`` the job's ``msg``/``warnmsg``/``errmsg`` print on stderr as they happen;
        what the run assumes (no ini, the packaged macro, a simulated probe) prints there unless ``-q``.
        """
        from edingcnc_lang.host import Host, scripted_dialogs, scripted_modbus
        from edingcnc_lang.syntax.input_limits import DEFAULT_MAX_STEPS
        from edingcnc_lang.runner import RunOptions

        probe: Any = None
        if self.probe_surface:
            from edingcnc_lang.config.heightmap import ProbeAt, read_surface

            probe = ProbeAt(read_surface(self.probe_surface))
        elif self.probe_at is not None:
            from edingcnc_lang.config.heightmap import ProbePlane

            probe = ProbePlane(self.probe_at)
        if self.log_dir and extra.get("write_job_files", True):
            Path(self.log_dir).mkdir(parents=True, exist_ok=True)  # --log-dir makes its folder

        def path(value: str | None) -> Path | None:
            return Path(value) if value else None

        dialogs = ShownDialogs(scripted_dialogs(list(self.answers)))
        message = dialogs.print_message if show_messages else None
        return RunOptions(ini=path(self.ini), macro=path(self.macro), user_macro=path(self.user_macro),
                          host=Host(dialog=dialogs.ask, message=message, probe=probe,
                                    modbus=scripted_modbus(self.modbus) if self.modbus else None),
                          max_steps=self.max_steps or DEFAULT_MAX_STEPS, log_dir=path(self.log_dir),
                          allow_exec=self.allow_exec, simulation=not self.no_simulation,
                          block_delete=self.block_delete, strict=self.strict, on_warning=print_warning,
                          variables=dict(pair for given in (*self.variables, *self.offsets, *self.tools)
                                         for pair in given),
                          on_assumption=None if self.quiet else print_assumption,
                          on_setup=print_setup if self.verbose and not self.quiet else None, **extra)

    def input_files(self) -> list[Path]:
        """Every file a run with these options reads besides its job (the ini, the macro files, the
        ini's own included, the probe surface): what no output of the command may be."""
        from edingcnc_lang.runner import RunOptions, input_files

        def path(value: str | None) -> Path | None:
            return Path(value) if value else None

        files = input_files(RunOptions(ini=path(self.ini), macro=path(self.macro), user_macro=path(self.user_macro)))
        return files + ([Path(self.probe_surface)] if self.probe_surface else [])


def print_setup(line: str) -> None:
    """``-v``: what the run uses that was given, on stderr: ``ecnc: using ...``."""
    print(printable("ecnc: using " + line), file=sys.stderr)


def print_assumption(assumption: Assumption) -> None:
    """What the run assumed, on stderr (never stdout): ``ecnc: assuming ...`` or, where it first
    mattered, ``PATH:LINE: note: ...``."""
    where = assumption.location
    head = f"{where.path}:{where.line}: note: " if where is not None and where.line else "ecnc: assuming "
    print(printable(head + assumption.text), file=sys.stderr)


def print_message(kind: str, text: str, path: str, line: int) -> None:
    """A message of the job on stderr: ``PATH:LINE: msg|warning|error|log: TEXT``."""
    if kind in MESSAGE_LABEL:
        from edingcnc_lang.cli.style import styled

        print(styled(printable(f"{path}:{line}: {MESSAGE_LABEL[kind]}: {text}"), sys.stderr), file=sys.stderr)


class ShownDialogs:
    """Dialogs answered from the command line (``--answer``), shown on stderr like a message, so a
    tool-change prompt is not silent: ``PATH:LINE: dialog: TITLE``, each field with its value
    before and after, and the answer given."""

    def __init__(self, answers: DialogCallback) -> None:
        self.answers = answers
        self.asked: tuple[Sequence[DialogField], DialogAnswer | None] | None = None

    def ask(self, title: str, fields: Sequence[DialogField]) -> DialogAnswer | None:
        answer = self.answers(title, fields)
        self.asked = (fields, answer)
        return answer

    def print_message(self, kind: str, text: str, path: str, line: int) -> None:
        """``print_message``, and for a dialog this object answered: its fields and the answer."""
        if kind != "dialog" or self.asked is None:
            print_message(kind, text, path, line)
            return
        fields, answer = self.asked
        self.asked = None
        shown = [f"{path}:{line}: dialog: {text}"]
        for item in fields:
            after = answer.values.get(item.index, item.value) if answer and answer.ok else item.value
            change = f" -> {after:g}" if after != item.value else ""
            shown.append(f"    {item.label} (#{item.index}) = {item.value:g}{change}")
        if answer is None:
            shown.append("    answer: ok, values unchanged (no --answer left)")
        else:
            shown.append(f"    answer: {'ok' if answer.ok else 'cancel'} (--answer)")
        print(printable("\n".join(shown)), file=sys.stderr)


def print_warning(diagnostic: Diagnostic) -> None:
    """A macro-file line that does not parse, reported once at load: ``PATH:LINE:COL: warning: ...``."""
    print(diagnostic.format(), file=sys.stderr)


_MACHINE_OPTIONS = (
    ini_option(),
    macro_options(),
    click.option("--answer", "answers", metavar="VALUE", type=ANSWER, multiple=True,
                 help="Answer for the next dlgmsg: ok, cancel or ok:#N=V,#M=W (repeatable)."),
    click.option("--max-steps", metavar="N", type=POSITIVE_INT,
                 help="Stop with an error after this many statements, loop turns and drilled holes "
                      "(default 100,000,000)."),
    click.option("--log-dir", metavar="DIRECTORY", type=LOG_FOLDER,
                 help="Folder for logfile/logmsg, made if missing (default: the job's)."),
    click.option("--allow-exec", is_flag=True, help="Let Exec start external programs."),
    click.option("--no-simulation", is_flag=True, help="Run with #5380 = 0 (as if on the real machine)."),
    click.option("--block-delete", is_flag=True, help="Skip lines that start with '/'."),
    click.option("--strict", is_flag=True, help="Macro-file lines that do not parse are errors at load "
                 "(default: a warning each, and an error only if the run reaches the line)."),
    click.option("--probe-surface", metavar="FILE", type=EXISTING_FILE,
                 help="CSV height map x,y,z (machine coordinates): G38.2 trips where the probe meets it."),
    click.option("--modbus", "modbus", metavar="VALUES", type=MODBUS_VALUES, multiple=True,
                 help="Values the next modbus read gets, e.g. 7,8 (repeatable; later reads get 0)."),
    click.option("--probe-at", metavar="Z", type=FLOAT,
                 help="G38.2 trips where the tool reaches machine Z (a tool setter's height); default: at its target."),
    click.option("--var", "variables", metavar="N=VALUE", type=VARIABLE, multiple=True,
                 help="Parameter #N starts at VALUE, as if the machine had it (repeatable; not read-only ones)."),
    click.option("--offset", "offsets", metavar="G5x=X,Y,Z", type=OFFSET, multiple=True,
                 help="A work offset in machine coordinates, e.g. G54=100,50,-20 (repeatable)."),
    click.option("--tool", "tools", metavar="N=LENGTH[,DIA]", type=TOOL, multiple=True,
                 help="Tool N's length and diameter in the tool table, e.g. 3=42.5,6 (repeatable); "
                      "N alone: tool N is in the spindle at the start."),
    click.option("-q", "--quiet", is_flag=True,
                 help="Nothing on stderr but errors and the job's messages: no assumptions, progress or summary."),
    click.option("-v", "--verbose", is_flag=True,
                 help="Also say what the run uses that was given: the ini (machine, travel, tools) and the macro files."),
)
_MACHINE_NAMES = tuple(MachineOptions.__dataclass_fields__)


def machine_options(func: F) -> F:
    """Add the machine options; the command receives them as one ``machine: MachineOptions``."""
    @functools.wraps(func)
    def command(*args: Any, **kwargs: Any) -> Any:
        machine = MachineOptions(**{name: kwargs.pop(name) for name in _MACHINE_NAMES})
        return func(*args, machine=machine, **kwargs)

    decorated: Any = command
    for option in reversed(_MACHINE_OPTIONS):
        decorated = option(decorated)
    return decorated
