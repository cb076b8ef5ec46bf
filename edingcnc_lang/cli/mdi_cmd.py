"""``ecnc mdi``: an MDI prompt on the virtual machine, like the controller's MDI line.

Each line typed runs at once; after a move the work and machine positions are printed; a line
that is only an expression or ``#n`` prints its value; an error prints its message and the prompt
goes on; ``If``/``While``/``Sub`` blocks are read until closed.  On a terminal the standard
library's readline gives editing and history (kept in ``~/.ecnc_mdi_history``); from a pipe
there is no prompt and each line's output follows it, so sessions can be scripted.
"""
from __future__ import annotations

import os
import sys
from collections.abc import Iterator
from typing import TYPE_CHECKING

import click

from edingcnc_lang.errors import EXIT_OK, EcncError, JobAborted
from edingcnc_lang.cli.base import Command
from edingcnc_lang.cli.options import MachineOptions, machine_options
from edingcnc_lang.cli.style import styled

if TYPE_CHECKING:
    from collections.abc import Sequence

    from edingcnc_lang.canon import Pose
    from edingcnc_lang.host import DialogAnswer, DialogField
    from edingcnc_lang.mdi import MdiOutcome

PROMPT, MORE = "MDI> ", "...> "
EXIT_WORDS = {"exit", "quit"}
HISTORY = os.path.join("~", ".ecnc_mdi_history")


@click.command("mdi", cls=Command, short_help="An MDI prompt: each line typed runs at once on the virtual machine.")
@machine_options
def mdi(machine: MachineOptions) -> int:
    """An MDI prompt on the virtual machine of --ini, --macro and --user-macro.

    Type G-code or macro statements (GoSub reaches the subs of the macro files); a line that is
    only an expression or #n prints its value. exit, quit or end of input (Ctrl-D) ends it. From
    a pipe there is no prompt; the exit status is then that of the first failing line (0 if none).
    """
    from edingcnc_lang.mdi import MdiSession, open_blocks

    interactive = sys.stdin.isatty() and sys.stdout.isatty()
    options = machine.run_options(show_messages=True)
    if interactive and not machine.answers:  # a dlgmsg asks, as the controller's dialog would
        options.host.dialog = ask_dialog
    session = MdiSession(options)
    if interactive:
        _history(load=True)
        print("ecnc mdi: G-code, macro statements or an expression; exit or Ctrl-D ends.")
    status, pending = EXIT_OK, list[str]()
    for line in _lines(interactive, lambda: MORE if pending else PROMPT):
        if line is None:  # Ctrl-C at the prompt: drop what was typed
            pending = []
            continue
        if not pending and line.strip().lower() in EXIT_WORDS:
            break
        pending.append(line)
        if open_blocks(pending):
            continue
        text, pending = "\n".join(pending), []
        try:
            _show(session.execute(text))
        except EcncError as err:
            if not isinstance(err, JobAborted):  # an errmsg text was shown as it ran
                print(styled(err.format(), sys.stderr), file=sys.stderr)
            status = status or err.exit_code
        except KeyboardInterrupt:
            print(styled(session.interrupted().format(), sys.stderr), file=sys.stderr)
    if pending:
        print(f"<mdi>: error: input ended inside a block ({len(pending)} lines not run)", file=sys.stderr)
        status = status or 65
    session.close()
    if interactive:
        _history(load=False)
    return EXIT_OK if interactive else status


def _lines(interactive: bool, prompt: object) -> Iterator[str | None]:
    """Typed lines (None after Ctrl-C at the prompt), or the lines of the pipe."""
    if not interactive:
        for line in sys.stdin:
            yield line.rstrip("\r\n")
        return
    while True:
        try:
            yield input(prompt())  # type: ignore[operator]
        except KeyboardInterrupt:
            print()
            yield None
        except EOFError:
            print()
            return


def _show(outcome: MdiOutcome) -> None:
    if outcome.value is not None:
        print(f"= {outcome.value + 0.0:.10g}")  # + 0.0: -0 shows as 0
    elif outcome.moved:
        print(f"work    {_pose(outcome.position)}\nmachine {_pose(outcome.machine)}")
    if outcome.ended:
        print("(program end: the machine keeps its position and state)")


def _pose(values: Pose) -> str:
    from edingcnc_lang.canon import format_pose

    return format_pose(values, spec=".4f")


def ask_dialog(title: str, fields: Sequence[DialogField]) -> DialogAnswer:
    """A dlgmsg at the prompt: each field with its value (Enter keeps it), then OK; Ctrl-C cancels."""
    from edingcnc_lang.host import DialogAnswer
    from edingcnc_lang.syntax.source import plain_float

    print(f"dialog: {title}")
    values: dict[int, float] = {}
    try:
        for item in fields:
            while True:
                typed = _answer_input(f"  {item.label} (#{item.index}) [{item.value:g}]: ").strip()
                try:
                    if typed:
                        values[item.index] = plain_float(typed)  # digits 0-9: not '１', not nan
                    break
                except ValueError:
                    print(f"  {typed!r} is not a number")
        ok = _answer_input("OK? [Y/n] ").strip().lower() in ("", "y", "yes", "ok")
    except (KeyboardInterrupt, EOFError):
        print()
        ok = False
    return DialogAnswer(ok, values if ok else {})


def _answer_input(prompt: str) -> str:
    """``input`` for a dialog's answer, which readline adds to the history like a command: taken
    out again, so the history (and Up at the prompt) holds the commands typed, not 12.5 and y."""
    typed = input(prompt)
    try:
        import readline
    except ImportError:
        return typed
    length = readline.get_current_history_length()
    if typed and length and readline.get_history_item(length) == typed:
        readline.remove_history_item(length - 1)
    return typed


def _history(load: bool) -> None:
    """Line editing and history through readline, where the platform has it."""
    try:
        import readline
    except ImportError:  # Windows without pyreadline: plain input()
        return
    path = os.path.expanduser(HISTORY)
    try:
        if load:
            if os.path.exists(path):
                readline.read_history_file(path)
        else:
            readline.set_history_length(1000)
            readline.write_history_file(path)
    except OSError:  # an unreadable or unwritable history file only loses the history
        pass
