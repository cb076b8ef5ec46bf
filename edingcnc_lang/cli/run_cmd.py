"""``ecnc run JOB``: run a job on the virtual machine and report what it did."""
from __future__ import annotations

from pathlib import Path

import click

from ..errors import EXIT_OK
from .base import Command, usage_error
from .options import MachineOptions, job_or_stdin_argument, json_option, machine_options
from .params import OUTPUT_FILE, STDIN
from .streams import STDIN_NAME, read_stdin


@click.command("run", cls=Command, short_help="Run JOB as the controller would (in simulation).")
@job_or_stdin_argument
@machine_options
@json_option("Print the final machine state as JSON on stdout.")
@click.option("--trace", metavar="FILE", type=OUTPUT_FILE, help="Write one CSV row per executed move.")
@click.option("--samples", metavar="FILE", type=OUTPUT_FILE, help="Write the interpolated trajectory (.csv or .npz).")
@click.option("--events", metavar="FILE", type=OUTPUT_FILE,
              help="Write every move (with its spindle speed) and event as JSON Lines.")
@click.option("--save-vars", is_flag=True, help="Write persistent variables back to the ini.")
def run(job: str, machine: MachineOptions, as_json: bool, trace: str | None, samples: str | None,
        events: str | None, save_vars: bool) -> int:
    """Run JOB as the controller would (in simulation) and report what the machine does.

    JOB - reads the job from standard input.
    """
    from ..runner import run_file, run_string

    if save_vars and not machine.ini:
        raise usage_error("--save-vars needs --ini (the file to write the variables to)")
    options = machine.run_options(show_messages=not as_json, trace=Path(trace) if trace else None,
                                  samples=Path(samples) if samples else None,
                                  events=Path(events) if events else None, save_vars=save_vars)
    # an error carries the state so far: main() prints it with --json
    result = run_string(read_stdin(), options, STDIN_NAME) if job == STDIN else run_file(job, options)
    if as_json:
        import json  # only with --json: a short run starts faster without it

        print(json.dumps(result.to_json(), indent=1))
    return EXIT_OK
