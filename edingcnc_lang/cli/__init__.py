"""The ``ecnc`` command line: one argparse parser, one module per subcommand.

argparse rather than click: importing click took about a quarter of the start-up of a short
``ecnc run``.  A subcommand module imports its implementation inside its handler, so ``ecnc --help``
and each command start without loading what the other commands need (the parser, numpy, ...).
"""
from __future__ import annotations

import argparse
import os
import sys
from collections.abc import Sequence
from typing import NoReturn

from .. import __version__
from ..errors import EXIT_USAGE, EcncError
from . import kins_cmd, lint_cmd, parse_cmd, run_cmd
from .common import Command, CommandParser, UsageError

# What click exited with on Ctrl-C and on a closed output pipe; scripts may rely on it.
EXIT_ABORTED = 1


COMMANDS = {"kins": kins_cmd, "lint": lint_cmd, "parse": parse_cmd, "run": run_cmd}


def build_parser(argv: Sequence[str] = ()) -> argparse.ArgumentParser:
    """The command line; built for each call, so defaults such as ``$CC`` are read then.

    When ``argv`` names a command, only that command's parser is built (each costs about a
    millisecond, mostly argparse looking up translations); otherwise all of them, for the help.
    """
    parser = argparse.ArgumentParser(prog="ecnc", allow_abbrev=False,
                                     description="Parse, run, lint and simulate EdingCNC G-code and macro files.")
    parser.add_argument("--version", action="version", version=f"ecnc, version {__version__}")
    commands = parser.add_subparsers(title="commands", metavar="COMMAND", parser_class=CommandParser)
    named = COMMANDS.get(argv[0]) if argv else None
    for module in [named] if named else COMMANDS.values():
        module.add_parser(commands)
    parser.set_defaults(command=Command(parser, None))
    return parser


def main(argv: Sequence[str] | None = None) -> int:
    """Run ``ecnc ARGV`` (default: ``sys.argv[1:]``) and return its exit code.

    argparse raises SystemExit itself for ``--help``, ``--version`` (0) and malformed command
    lines (2, with the usage on stderr).
    """
    argv = sys.argv[1:] if argv is None else list(argv)
    reconfigure = getattr(sys.stdout, "reconfigure", None)
    if reconfigure is not None:  # a source line with 'é' on an ASCII console: \xe9, not a traceback
        reconfigure(errors="backslashreplace")
    args, unknown = build_parser(argv).parse_known_args(argv)
    command: Command = args.command
    if unknown:  # reported by the command's own parser, with its usage
        command.parser.error(f"unrecognized arguments: {' '.join(unknown)}")
    if command.handler is None:  # `ecnc` or `ecnc kins` alone: what there is, as a usage error
        command.parser.print_help(sys.stderr)
        return EXIT_USAGE
    try:
        code = command.handler(args)
        sys.stdout.flush()  # so that a closed pipe shows up here
        return code
    except UsageError as err:
        command.parser.error(str(err))
    except EcncError as err:
        print(err.format(), file=sys.stderr)
        return err.exit_code
    except KeyboardInterrupt:
        print("\nAborted!", file=sys.stderr)
        return EXIT_ABORTED
    except BrokenPipeError:  # `ecnc ... | head` stopped reading: end quietly
        os.dup2(os.open(os.devnull, os.O_WRONLY), sys.stdout.fileno())  # nothing left to flush at exit
        return EXIT_ABORTED


def entry() -> NoReturn:
    """The ``ecnc`` program: ``main()``, then the end of the process at once.

    By then every file the command wrote is closed, and stdout and stderr are flushed here, so
    the interpreter's own teardown (clearing every module, a last full garbage collection) can be
    skipped: it took ~20 ms of a short run. ``atexit`` handlers do not run. Code that embeds the
    command line calls ``main()``, which returns.
    """
    try:
        code = main()
    except SystemExit as exc:  # argparse's --help, --version and usage errors
        if not isinstance(exc.code, int):
            raise
        code = exc.code
    for stream in (sys.stdout, sys.stderr):
        try:
            stream.flush()
        except (OSError, ValueError):  # a reader that went away: nothing more to tell it
            pass
    os._exit(code)
