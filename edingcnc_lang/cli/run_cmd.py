"""``ecnc run JOB``: run a job on the virtual machine and report what it did."""
from __future__ import annotations

import sys
from pathlib import Path
from typing import TYPE_CHECKING

import click

from edingcnc_lang.errors import EXIT_OK
from edingcnc_lang.cli import progress
from edingcnc_lang.cli.base import Command, usage_error
from edingcnc_lang.cli.options import (
    MachineOptions,
    job_or_stdin_argument,
    json_option,
    machine_options,
    override_options,
)
from edingcnc_lang.cli.value_types import OUTPUT_FILE, STDOUT
from edingcnc_lang.cli.streams import STDIN_NAME, job_to_read_twice

if TYPE_CHECKING:
    from edingcnc_lang.runner import Run


@click.command("run", cls=Command, short_help="Run JOB as the controller would (in simulation).")
@job_or_stdin_argument
@machine_options
@json_option("Print the final machine state as JSON on stdout.")
@click.option("--trace", metavar="FILE", type=OUTPUT_FILE, help="Write one CSV row per executed move (-: standard output).")
@click.option("--samples", metavar="FILE", type=OUTPUT_FILE, help="Write the interpolated trajectory (.csv or .npz; -: CSV on standard output).")
@click.option("--events", metavar="FILE", type=OUTPUT_FILE,
              help="Write every move (with its spindle speed) and event as JSON Lines (-: standard output).")
@click.option("--save-vars", is_flag=True, help="Write persistent variables back to the ini.")
@override_options
def run(job: str, machine: MachineOptions, as_json: bool, trace: str | None, samples: str | None,
        events: str | None, save_vars: bool, feed_override: float, rapid_override: float) -> int:
    """Run JOB as the controller would (in simulation) and report what the machine does.

    JOB - reads the job from standard input.
    """
    from edingcnc_lang.runner import Run

    quiet = machine.quiet
    if save_vars and not machine.ini:
        raise usage_error("--save-vars needs --ini (the file to write the variables to)")
    to_stdout = [name for name, value in (("--json", as_json), ("--trace -", trace), ("--samples -", samples),
                                          ("--events -", events)) if value in (True, STDOUT)]
    if len(to_stdout) > 1:
        raise usage_error(f"only one output can go to standard output, not {' and '.join(to_stdout)}")
    if samples:
        from edingcnc_lang.motion.sinks import samples_format_problem

        problem = samples_format_problem(Path(samples))
        if problem:
            raise usage_error(f"--samples {problem}")
    options = machine.run_options(show_messages=not as_json, trace=Path(trace) if trace else None,
                                  samples=Path(samples) if samples else None,
                                  events=Path(events) if events else None, save_vars=save_vars,
                                  feed_override=feed_override, rapid_override=rapid_override,
                                  # the summary line and --json report the planner's estimate; the
                                  # trace, samples and events make the runner plan anyway
                                  plan=as_json or progress.wanted(quiet))
    # an error carries the state so far: main() prints it with --json
    run = Run(options)
    with job_to_read_twice(job) as (path, name):
        show = name != STDIN_NAME and progress.wanted(quiet or as_json)
        with progress.Progress(_probe(run, job), show):
            result = run.execute_file(path, name)
    if as_json:
        from edingcnc_lang.syntax.serialize import json_text  # only with --json: a short run starts faster without it

        print(json_text(result.to_json(), indent=1))
    if progress.wanted(quiet) and result.estimate is not None:  # for people at a terminal; scripts read --json
        print(result.estimate.summary(), file=sys.stderr)
    return EXIT_OK


def _probe(run: Run, job: str) -> progress.Probe:
    """How far the run is: the job line reached (lines of macro subs keep the caller's) of the lines the
    check pass counted, moves so far."""
    path, reached = str(Path(job)), [0]

    def probe() -> tuple[int, int, str]:
        interp = run.interpreter
        total = run.job_lines
        if interp.path == path:
            reached[0] = interp.line
        return reached[0], total, f"line {reached[0]:,}/{total:,}  moves {run.motion.moves:,}"
    return probe
