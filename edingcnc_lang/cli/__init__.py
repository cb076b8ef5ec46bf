"""The ``ecnc`` command line, on click: one module per command, loaded when that command runs.

``COMMANDS`` names each command's module; ``ecnc --help`` and each command start without what the
other commands need (the parser, numpy, ...), since command modules import their implementation
inside the command.  ``main()`` reads the command line and turns every outcome into an exit code
(docs/cli.md): usage errors 2, ``EcncError``s their own code, never a traceback.
"""
from __future__ import annotations

import gc
import os
import sys
import warnings
from collections.abc import Sequence
from typing import Any, NoReturn

import click

from edingcnc_lang import __version__
from edingcnc_lang.speedups import CORE
from edingcnc_lang.errors import EXIT_OK, EcncError, Interrupted, JobAborted, Location, UsageFailure
from edingcnc_lang.cli.base import CONTEXT_SETTINGS, LazyGroup, show_usage_error, usage_message
from edingcnc_lang.cli.streams import flush_quietly, make_streams_usable, quiet_stdout
from edingcnc_lang.cli.style import styled

# What click exits with on a closed output pipe; scripts may rely on it.
EXIT_ABORTED = 1

# Every command: its name and "module:attribute" in this package (see docs/cli.md, "Adding a command").
COMMANDS = {
    "debug": "debug_cmd:debug",
    "diff": "diff_cmd:diff",
    "help": "help_cmd:help_command",
    "kins": "kins_cmd:kins",
    "lint": "lint_cmd:lint",
    "lsp": "lsp_cmd:lsp",
    "mdi": "mdi_cmd:mdi",
    "parse": "parse_cmd:parse",
    "plot": "plot_cmd:plot",
    "run": "run_cmd:run",
    "sim": "sim_cmd:sim",
    "test": "test_cmd:test",
    "view": "view_cmd:view",
    "vars": "vars_cmd:vars_command",
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
                            message=f"%(prog)s, version %(version)s ({CORE} core)")(ecnc)


def _join_bash_equals(env: Any) -> None:
    """Bash splits ``--select=V30`` into ``--select``, ``=``, ``V30`` (``=`` is in COMP_WORDBREAKS) and
    completes only the text after the ``=``: join them back into the one word click reads as an
    option and its value, so ``ecnc lint --select=V30<Tab>`` offers V300..V309."""
    import shlex

    from click.shell_completion import split_arg_string  # as click reads COMP_WORDS

    words, current = split_arg_string(env.get("COMP_WORDS", "")), int(env.get("COMP_CWORD", "0") or 0)
    cword = current
    joined: list[str] = []
    for index, word in enumerate(words):
        after_equals = index > 1 and words[index - 1] == "=" and joined and joined[-1].endswith("=")
        if (word == "=" and joined and joined[-1].startswith("--")) or after_equals:
            joined[-1] += word
            cword -= index <= current
        else:
            joined.append(word)
    env["COMP_WORDS"], env["COMP_CWORD"] = shlex.join(joined), str(max(cword, 0))


def run_command_line(argv: list[str], until_exit: list[object] | None = None) -> int:
    """Run ``ecnc ARGV`` and return its exit code; every failure is reported here, never raised.

    Errors go to stderr as ``PATH:LINE:COL: error: MESSAGE``; with ``--json`` stdout still gets one
    JSON document: the state so far for a run that started, else ``{"error": {...}}``.
    ``until_exit`` is given by ``entry()``, which ends the process without freeing anything: a
    command may leave what it built there instead of freeing it (``base.until_exit``).
    """
    if os.environ.get(COMPLETE_VAR):
        from click.shell_completion import shell_complete

        if os.environ[COMPLETE_VAR] == "bash_complete":
            _join_bash_equals(os.environ)
        return shell_complete(ecnc, {}, "ecnc", COMPLETE_VAR, os.environ[COMPLETE_VAR])
    make_streams_usable()
    # numpy's overflow and invalid-value warnings name a source line of ours, which tells a user
    # nothing; what such a value does to a result is checked and reported where it matters
    warnings.filterwarnings("ignore", category=RuntimeWarning, module=r"edingcnc_lang\.|numpy")
    as_json = "--json" in (argv[:argv.index("--")] if "--" in argv else argv)
    try:
        with ecnc.make_context("ecnc", argv, obj=until_exit) as ctx:
            code = ecnc.invoke(ctx)
        sys.stdout.flush()  # so that a closed pipe or a full disk shows up here
        return code if isinstance(code, int) else EXIT_OK
    except click.exceptions.Exit as done:  # --help, --version
        return done.exit_code
    except click.UsageError as err:
        show_usage_error(err)
        return report(UsageFailure(usage_message(err)), as_json, to_stderr=False)
    except EcncError as err:
        return report(err, as_json)
    except (KeyboardInterrupt, click.Abort):  # outside a run (which names its line itself)
        print(file=sys.stderr)
        return report(Interrupted("interrupted (Ctrl-C)"), as_json)
    except MemoryError:  # this machine's memory ran out before a limit of syntax/input_limits.py was reached
        return report(EcncError("out of memory: the job needs more than this machine has (the limits are in "
                                "docs/language.md#limits; --samples FILE.csv streams where .npz does not)"), as_json)
    except BrokenPipeError:  # `ecnc ... | head` stopped reading: end quietly
        quiet_stdout()
        return EXIT_ABORTED
    except OSError as err:  # stdout on a full disk or closed; a file that cannot be written
        where = Location(err.filename) if err.filename else None
        what = err.strerror or str(err)
        return report(EcncError(what if where else f"cannot write standard output: {what}", where), as_json)


def report(err: EcncError, as_json: bool, to_stderr: bool = True) -> int:
    """Tell what stopped the command; return its exit code.

    With ``--json``, stdout gets the run's state so far (when a run started) or ``{"error": ...}``.
    An ``errmsg`` was already shown as a message when it ran, so it is not repeated on stderr.
    """
    if as_json:
        partial = getattr(err, "result", None)
        doc = partial.to_json() if partial is not None else {"error": err.to_json()}
        from edingcnc_lang.syntax.serialize import json_text

        try:
            print(json_text(doc, indent=1))
            sys.stdout.flush()
        except OSError:  # stdout is the trouble itself: stderr tells
            pass
    if to_stderr and not isinstance(err, JobAborted):
        print(styled(err.format(), sys.stderr), file=sys.stderr)
    return err.exit_code


def main(argv: Sequence[str] | None = None) -> int:
    """Run ``ecnc ARGV`` (default: ``sys.argv[1:]``) and return its exit code."""
    return run_command_line(sys.argv[1:] if argv is None else list(argv))


def entry() -> NoReturn:
    """The ``ecnc`` program: ``main()``, then the end of the process at once, nothing freed.

    By then every file the command wrote is closed, and stdout and stderr are flushed here, so
    the interpreter's own teardown (clearing every module, a last full garbage collection) can be
    skipped: it took ~20 ms of a short run. ``atexit`` handlers do not run. Code that embeds the
    command line calls ``main()``, which returns.
    """
    _terminate_cleanly()
    _one_blas_thread()
    # What start-up made (modules, classes, click's commands) lives until the process ends: out of the cyclic
    # collector's sight, its collections of a long run's young objects no longer walk it again and again; and
    # the youngest generation is collected every 10,000 allocations instead of 700 (a run makes millions of
    # small acyclic objects: moves, tuples, rows; reference counting frees them). Together 4-7 % of a 50k-move
    # run's CPU on the Python core, 2.5 % compiled. Only here, in the program, never in a process that embeds
    # the command line.
    gc.freeze()
    gc.set_threshold(10_000, *gc.get_threshold()[1:])
    until_exit: list[object] = []
    try:
        code = run_command_line(sys.argv[1:], until_exit)
    except SystemExit as stop:  # SIGTERM: the temporary copy of a piped job is removed by now
        code = stop.code if isinstance(stop.code, int) else EXIT_TERMINATED
    flush_quietly()
    os._exit(code)


def _one_blas_thread() -> None:
    """numpy's OpenBLAS starts a thread per core when numpy loads (the planner's arrays); ecnc makes no
    matrix products big enough to share out, so in the ``ecnc`` program those threads only cost CPU time
    (40-60 ms of a 0.15 s ``run --trace`` on 2 cores, issue 42).  Set before numpy loads; a user's own
    ``OPENBLAS_NUM_THREADS`` wins.  No result changes: a thread count splits the work, not a sum's order."""
    os.environ.setdefault("OPENBLAS_NUM_THREADS", "1")


EXIT_TERMINATED = 128 + 15  # what a shell reports for a process ended by SIGTERM


def _terminate_cleanly() -> None:
    """``kill``/``timeout`` (SIGTERM) unwinds the command like Ctrl-C does, so ``with`` blocks still
    clean up (the temporary copy of a job read from standard input or a pipe) before the exit."""
    import signal

    def stop(_signum: int, _frame: object) -> NoReturn:
        raise SystemExit(EXIT_TERMINATED)

    if hasattr(signal, "SIGTERM"):
        signal.signal(signal.SIGTERM, stop)
