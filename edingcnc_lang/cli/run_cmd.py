"""``ecnc run JOB``: run a job on the virtual machine and report what it did."""
from __future__ import annotations

import argparse
import sys
from pathlib import Path
from typing import TYPE_CHECKING

from ..errors import EXIT_OK, EcncError, JobAborted
from .common import (
    UsageError,
    add_command,
    existing_file,
    existing_folder,
    output_file,
    positive_int,
)

if TYPE_CHECKING:
    from ..host import DialogAnswer
    from ..runner import RunResult
    from .common import Subcommands

MESSAGE_LABEL = {"msg": "msg", "warn": "warning", "error": "error", "log": "log", "dialog": "dialog"}


def _answer(value: str) -> DialogAnswer:
    from ..host import DialogAnswer

    try:
        return DialogAnswer.parse(value)
    except ValueError as err:
        raise argparse.ArgumentTypeError(str(err)) from None


def add_parser(commands: Subcommands) -> None:
    parser = add_command(commands, "run", run,
                         "Run JOB as the controller would (in simulation) and report what the machine does.")
    parser.add_argument("job", metavar="JOB", type=existing_file)
    parser.add_argument("--ini", metavar="FILE", type=existing_file, help="Machine configuration (cnc.ini).")
    parser.add_argument("--macro", metavar="FILE", type=existing_file,
                        help="Macro file (default: the ini's, else the packaged one).")
    parser.add_argument("--user-macro", metavar="FILE", type=existing_file, help="User macro file.")
    parser.add_argument("--json", dest="as_json", action="store_true",
                        help="Print the final machine state as JSON on stdout.")
    parser.add_argument("--trace", metavar="FILE", type=output_file, help="Write one CSV row per executed move.")
    parser.add_argument("--samples", metavar="FILE", type=output_file,
                        help="Write the interpolated trajectory (.csv or .npz).")
    parser.add_argument("--answer", dest="answers", metavar="VALUE", type=_answer, action="append", default=[],
                        help="Answer for the next dlgmsg: ok, cancel or ok:#N=V,#M=W (repeatable).")
    parser.add_argument("--max-steps", metavar="N", type=positive_int,
                        help="Stop with an error after this many statements (at least 1).")
    parser.add_argument("--log-dir", metavar="DIRECTORY", type=existing_folder,
                        help="Folder for logfile/logmsg (default: the job's).")
    parser.add_argument("--allow-exec", action="store_true", help="Let Exec start external programs.")
    parser.add_argument("--save-vars", action="store_true", help="Write persistent variables back to the ini.")
    parser.add_argument("--no-simulation", action="store_true", help="Run with #5380 = 0 (as if on the real machine).")
    parser.add_argument("--block-delete", action="store_true", help="Skip lines that start with '/'.")
    parser.add_argument("--strict", action="store_true",
                        help="Macro-file lines that do not parse are errors at load (default: warnings, "
                             "an error only if the run reaches them).")


def run(args: argparse.Namespace) -> int:
    """Handles its own errors: after a runtime error ``--json`` still prints the state so far."""
    from ..host import Host, scripted_dialogs
    from ..runner import RunOptions, run_file

    if args.save_vars and not args.ini:
        raise UsageError("--save-vars needs --ini (the file to write the variables to)")

    def show(kind: str, text: str, path: str, line: int) -> None:
        if not args.as_json and kind in MESSAGE_LABEL and kind != "dialog":
            print(f"{path}:{line}: {MESSAGE_LABEL[kind]}: {text}", file=sys.stderr)

    def path(value: str | None) -> Path | None:
        return Path(value) if value else None

    options = RunOptions(
        ini=path(args.ini), macro=path(args.macro), user_macro=path(args.user_macro),
        host=Host(dialog=scripted_dialogs(args.answers), message=show),
        max_steps=args.max_steps, trace=path(args.trace), samples=path(args.samples),
        log_dir=path(args.log_dir), allow_exec=args.allow_exec, simulation=not args.no_simulation,
        block_delete=args.block_delete, save_vars=args.save_vars, strict=args.strict,
        on_warning=lambda d: print(d.format(), file=sys.stderr))
    try:
        result = run_file(args.job, options)
    except EcncError as err:
        partial: RunResult | None = getattr(err, "result", None)
        if args.as_json and partial is not None:
            _print_json(partial.to_json())
        if not isinstance(err, JobAborted):  # an errmsg text was shown as it ran (or is in the JSON)
            print(err.format(), file=sys.stderr)
        return err.exit_code
    if args.as_json:
        _print_json(result.to_json())
    return EXIT_OK


def _print_json(data: object) -> None:
    import json  # only with --json: a short run starts faster without it

    print(json.dumps(data, indent=1))
