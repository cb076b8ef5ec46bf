"""The click classes every ``ecnc`` command is built from, and how a usage error is shown.

They keep the command line the way scripts wrote it before: ``-h`` and ``--help``, ``usage: ...``
then ``ecnc COMMAND: error: MESSAGE`` naming the option or argument at fault, options anywhere
between the arguments, ``-2.5e-3`` read as a number (not an unknown option), long options written
out in full, and commands loaded only when they are asked for (``LazyGroup``).
"""
from __future__ import annotations

import importlib
import re
from collections.abc import Iterable, Mapping
from typing import Any

import click

try:  # click >= 8.2
    from click.parser import _OptionParser as OptionParser
except ImportError:  # pragma: no cover - click 8.1
    from click.parser import OptionParser  # type: ignore[attr-defined,no-redef,unused-ignore]

# "-5", "-.5", "-2.5e-3", "-inf": values, not options.
NEGATIVE_NUMBER = re.compile(r"-\.?\d|-inf|-nan", re.IGNORECASE)

CONTEXT_SETTINGS: dict[str, Any] = {"help_option_names": ["-h", "--help"]}

def until_exit() -> list[object] | None:
    """Where a command may leave what it built when ``entry()`` ends the process (``os._exit``, nothing
    freed); None when it runs through ``main()`` (embedded, or click's test runner) and frees as usual.

    Freeing a whole syntax tree object by object is work for nothing when the process is about to
    end: about 60 ms of ``ecnc lint`` on 30,000 lines.
    """
    ctx = click.get_current_context(silent=True)
    kept = ctx.find_root().obj if ctx is not None else None
    return kept if isinstance(kept, list) else None


class ArgvParser(OptionParser):  # type: ignore[misc,unused-ignore]
    """click's parser, taking a negative number where an argument may stand for that argument."""

    def _process_opts(self, arg: str, state: Any) -> None:
        if (self.allow_interspersed_args and NEGATIVE_NUMBER.match(arg)
                and arg not in self._short_opt and arg not in self._long_opt):
            state.largs.append(arg)
            return
        super()._process_opts(arg, state)


class UsageWriter:
    """``usage: ecnc run [OPTIONS] JOB`` in lower case, as before (and as argparse and git write it),
    and every usage error tied to the command it belongs to (for that usage line)."""

    def parse_args(self, ctx: click.Context, args: list[str]) -> list[str]:
        try:
            return super().parse_args(ctx, args)  # type: ignore[misc,no-any-return,unused-ignore]
        except click.UsageError as err:
            if err.ctx is None:  # click's parser leaves it out for "--cc" without a value
                err.ctx = ctx
            raise

    def format_usage(self, ctx: click.Context, formatter: click.HelpFormatter) -> None:
        pieces = self.collect_usage_pieces(ctx)  # type: ignore[attr-defined]
        formatter.write_usage(ctx.command_path, " ".join(pieces), prefix="usage: ")


# A token that is a number (or a number followed by a comma): one of a list given as separate words.
_LIST_NUMBER = re.compile(r"[+-]?(?:(?:[0-9]+\.?[0-9]*|\.[0-9]+)(?:[eE][+-]?[0-9]+)?|inf|nan),?", re.IGNORECASE)


def join_number_lists(args: list[str], options: Iterable[str]) -> list[str]:
    """``--box 10 100 -50 50 -5 5`` as ``--box '10 100 -50 50 -5 5'``: the numbers that follow one of
    ``options`` become its one value, as a script may write them; ``--`` ends the search."""
    names = set(options)
    joined: list[str] = []
    i = 0
    while i < len(args):
        arg = args[i]
        joined.append(arg)
        i += 1
        if arg == "--":
            return joined + args[i:]
        if arg in names and i < len(args):
            values = [args[i]]
            i += 1
            while i < len(args) and _LIST_NUMBER.fullmatch(args[i]):
                values.append(args[i])
                i += 1
            joined.append(" ".join(values))
    return joined


class Command(UsageWriter, click.Command):
    """A leaf command: negative numbers as arguments, and a stray argument is a usage error.

    ``number_lists``: options whose value may also be written as separate numbers (``--box``).
    """

    number_lists: tuple[str, ...] = ()

    def __init__(self, *args: Any, **kwargs: Any) -> None:
        kwargs["context_settings"] = {"allow_extra_args": True, **(kwargs.get("context_settings") or {})}
        super().__init__(*args, **kwargs)

    def make_parser(self, ctx: click.Context) -> OptionParser:
        parser = ArgvParser(ctx)
        for param in self.get_params(ctx):
            param.add_to_parser(parser, ctx)
        return parser

    def parse_args(self, ctx: click.Context, args: list[str]) -> list[str]:
        rest = super().parse_args(ctx, join_number_lists(args, self.number_lists) if self.number_lists else args)
        if rest and not ctx.resilient_parsing:
            raise click.UsageError(f"unrecognized arguments: {' '.join(rest)}", ctx)
        return rest


class Argument(click.Argument):
    """An argument whose metavar is shown as written (``X Y Z [A B C]``, not ``X Y Z [A B C]...``)."""

    def make_metavar(self, *args: Any) -> str:
        return self.metavar or super().make_metavar(*args)


class UnknownCommand(click.UsageError):
    """``ecnc rn``: carries the commands that look like it, for "did you mean"."""

    def __init__(self, name: str, known: Iterable[str], ctx: click.Context) -> None:
        super().__init__(f"unknown command {name!r}", ctx)
        import difflib  # only for a mistyped name (start-up time)

        self.possibilities = difflib.get_close_matches(name, list(known))


class LazyGroup(UsageWriter, click.Group):
    """A group whose commands live in modules imported only when they run or are listed.

    ``commands`` maps a name to ``"module:attribute"`` relative to this package; the attribute is
    a click command.  Alone (``ecnc``, ``ecnc kins``) a group prints its help on stderr, exit 2.
    """

    def __init__(self, *args: Any, lazy: Mapping[str, str], **kwargs: Any) -> None:
        kwargs.setdefault("invoke_without_command", True)
        kwargs.setdefault("no_args_is_help", False)
        kwargs.setdefault("callback", _help_when_alone)
        kwargs.setdefault("subcommand_metavar", "COMMAND [ARGS]...")
        super().__init__(*args, **kwargs)
        self.lazy = dict(lazy)

    def list_commands(self, ctx: click.Context) -> list[str]:
        return list(dict.fromkeys([*self.lazy, *self.commands]))  # in the order of the table

    def get_command(self, ctx: click.Context, cmd_name: str) -> click.Command | None:
        if cmd_name in self.lazy and cmd_name not in self.commands:
            module_name, attribute = self.lazy[cmd_name].split(":")
            module = importlib.import_module(f"{__package__}.{module_name}")
            self.add_command(getattr(module, attribute), cmd_name)
        return self.commands.get(cmd_name)

    def resolve_command(self, ctx: click.Context, args: list[str]) -> tuple[str | None, click.Command | None,
                                                                           list[str]]:
        name = args[0]
        command = self.get_command(ctx, name)
        if command is None and not ctx.resilient_parsing:
            if name.startswith("-"):  # an option after all: let the parser report it
                self.parse_args(ctx, args)
            raise UnknownCommand(name, self.list_commands(ctx), ctx)
        return name if command else None, command, args[1:]



@click.pass_context
def _help_when_alone(ctx: click.Context) -> int | None:
    """A group's own callback: it runs before its command, or alone, when it prints the help."""
    if ctx.invoked_subcommand is None:
        click.echo(ctx.get_help(), err=True)
        return 2
    return None


def param_hint(param: click.Parameter | None) -> str:
    """How an error names a parameter: its long option (``--max-steps``) or metavar (``JOB``)."""
    if param is None:
        return ""
    if isinstance(param, click.Option):
        return max(param.opts, key=len)
    return param.metavar or (param.name or "").upper()


def usage_message(err: click.UsageError) -> str:
    """The text after ``error:`` for a usage error, with "did you mean" where click has a guess."""
    suggestions: list[str] = []
    if isinstance(err, click.NoSuchOption):
        message = f"unrecognized arguments: {err.option_name}"
        suggestions = _completions_of(err) or list(err.possibilities or [])
    elif isinstance(err, UnknownCommand):
        message, suggestions = err.message, err.possibilities
    elif isinstance(err, click.MissingParameter):
        message = f"the following arguments are required: {param_hint(err.param)}"
    elif isinstance(err, click.BadParameter):
        hint = param_hint(err.param)
        message = f"argument {hint}: {err.message}" if hint else err.message
    else:
        message = err.message
    if suggestions:
        message += f" (did you mean {' or '.join(suggestions)}?)"
    return message


def _completions_of(err: click.NoSuchOption) -> list[str]:
    """The long options that ``--no`` abbreviates: abbreviations are refused, so name them in full."""
    name, ctx = err.option_name, err.ctx
    if ctx is None or not name.startswith("--") or "=" in name:
        return []
    longs = {opt for param in ctx.command.get_params(ctx) for opt in (*param.opts, *param.secondary_opts)
             if opt.startswith(name) and opt != name}
    return sorted(longs)[:4]


def show_usage_error(err: click.UsageError) -> None:
    """``usage: ...`` and ``ecnc COMMAND: error: MESSAGE`` on stderr."""
    ctx = err.ctx
    prog = ctx.command_path if ctx else "ecnc"
    if ctx is not None:
        click.echo(ctx.get_usage(), err=True)
    click.echo(f"{prog}: error: {usage_message(err)}", err=True)


def usage_error(message: str) -> click.UsageError:
    """A command line click accepts but that makes no sense (``--save-vars`` without ``--ini``)."""
    return click.UsageError(message, click.get_current_context(silent=True))
