"""``ecnc run JOB``: run a job on the virtual machine and report what it did."""
from __future__ import annotations

import sys
from pathlib import Path
from typing import TYPE_CHECKING

import click

from ..errors import EXIT_OK, EcncError, JobAborted
from .base import Command, usage_error
from .options import MachineOptions, job_argument, json_option, machine_options
from .params import OUTPUT_FILE

if TYPE_CHECKING:
    from ..runner import RunResult


@click.command("run", cls=Command, short_help="Run JOB as the controller would (in simulation).")
@job_argument
@machine_options
@json_option("Print the final machine state as JSON on stdout.")
@click.option("--trace", metavar="FILE", type=OUTPUT_FILE, help="Write one CSV row per executed move.")
@click.option("--samples", metavar="FILE", type=OUTPUT_FILE, help="Write the interpolated trajectory (.csv or .npz).")
@click.option("--save-vars", is_flag=True, help="Write persistent variables back to the ini.")
def run(job: str, machine: MachineOptions, as_json: bool, trace: str | None, samples: str | None,
        save_vars: bool) -> int:
    """Run JOB as the controller would (in simulation) and report what the machine does."""
    # Handles its own errors: after a runtime error --json still prints the state so far.
    from ..runner import run_file

    if save_vars and not machine.ini:
        raise usage_error("--save-vars needs --ini (the file to write the variables to)")
    options = machine.run_options(show_messages=not as_json, trace=Path(trace) if trace else None,
                                  samples=Path(samples) if samples else None, save_vars=save_vars)
    try:
        result = run_file(job, options)
    except EcncError as err:
        partial: RunResult | None = getattr(err, "result", None)
        if as_json and partial is not None:
            _print_json(partial.to_json())
        if not isinstance(err, JobAborted):  # an errmsg text was shown as it ran (or is in the JSON)
            print(err.format(), file=sys.stderr)
        return err.exit_code
    if as_json:
        _print_json(result.to_json())
    return EXIT_OK


def _print_json(data: object) -> None:
    import json  # only with --json: a short run starts faster without it

    print(json.dumps(data, indent=1))
