"""The ``ecnc`` command line, on click: one module per command, loaded when that command runs.

``COMMANDS`` names each command's module; ``ecnc --help`` and each command start without what the
other commands need (the parser, numpy, ...), since command modules import their implementation
inside the command.  ``main()`` reads the command line and turns every outcome into an exit code
(docs/cli.md): usage errors 2, ``EcncError``s their own code, never a traceback.
"""
from __future__ import annotations

import os
import sys
from collections.abc import Sequence
from typing import Any, NoReturn

import click

from .. import __version__
from ..errors import EXIT_OK, EXIT_USAGE, EcncError
from .base import CONTEXT_SETTINGS, LazyGroup, show_usage_error

# What click exited with on Ctrl-C and on a closed output pipe; scripts may rely on it.
EXIT_ABORTED = 1

# Every command: its name and "module:attribute" in this package (see docs/cli.md, "Adding a command").
COMMANDS = {
    "kins": "kins_cmd:kins",
    "lint": "lint_cmd:lint",
    "lsp": "lsp_cmd:lsp",
    "parse": "parse_cmd:parse",
    "plot": "plot_cmd:plot",
    "run": "run_cmd:run",
    "view": "view_cmd:view",
}

COMPLETE_VAR = "_ECNC_COMPLETE"


class Ecnc(LazyGroup):
    """The ``ecnc`` group; its ``main`` (which click's ``CliRunner`` calls too) is ``run_command_line``."""

    def main(self, args: Sequence[str] | None = None, prog_name: str | None = None, complete_var: str | None = None,
             standalone_mode: bool = True, **extra: Any) -> Any:
        code = run_command_line(sys.argv[1:] if args is None else list(args))
        if standalone_mode:
            sys.exit(code)
        return code


ecnc = Ecnc("ecnc", lazy=COMMANDS, context_settings=CONTEXT_SETTINGS,
            help="Parse, run, lint and simulate EdingCNC G-code and macro files.")
ecnc = click.version_option(__version__, "--version", prog_name="ecnc",
                            message="%(prog)s, version %(version)s")(ecnc)


def run_command_line(argv: list[str]) -> int:
    """Run ``ecnc ARGV`` and return its exit code; every error is reported here, on stderr."""
    if os.environ.get(COMPLETE_VAR):
        from click.shell_completion import shell_complete

        return shell_complete(ecnc, {}, "ecnc", COMPLETE_VAR, os.environ[COMPLETE_VAR])
    reconfigure = getattr(sys.stdout, "reconfigure", None)
    if reconfigure is not None:  # a source line with 'é' on an ASCII console: \xe9, not a traceback
        reconfigure(errors="backslashreplace")
    try:
        with ecnc.make_context("ecnc", argv) as ctx:
            code = ecnc.invoke(ctx)
        sys.stdout.flush()  # so that a closed pipe shows up here
        return code if isinstance(code, int) else EXIT_OK
    except click.exceptions.Exit as done:  # --help, --version
        return done.exit_code
    except click.UsageError as err:
        show_usage_error(err)
        return EXIT_USAGE
    except EcncError as err:
        print(err.format(), file=sys.stderr)
        return err.exit_code
    except (KeyboardInterrupt, click.Abort):
        print("\nAborted!", file=sys.stderr)
        return EXIT_ABORTED
    except BrokenPipeError:  # `ecnc ... | head` stopped reading: end quietly
        os.dup2(os.open(os.devnull, os.O_WRONLY), sys.stdout.fileno())  # nothing left to flush at exit
        return EXIT_ABORTED


def main(argv: Sequence[str] | None = None) -> int:
    """Run ``ecnc ARGV`` (default: ``sys.argv[1:]``) and return its exit code."""
    return run_command_line(sys.argv[1:] if argv is None else list(argv))


def entry() -> NoReturn:
    """The ``ecnc`` program: ``main()``, then the end of the process at once.

    By then every file the command wrote is closed, and stdout and stderr are flushed here, so
    the interpreter's own teardown (clearing every module, a last full garbage collection) can be
    skipped: it took ~20 ms of a short run. ``atexit`` handlers do not run. Code that embeds the
    command line calls ``main()``, which returns.
    """
    code = main()
    for stream in (sys.stdout, sys.stderr):
        try:
            stream.flush()
        except (OSError, ValueError, AttributeError):  # a reader that went away, a closed stream
            pass
    os._exit(code)
