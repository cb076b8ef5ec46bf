"""``ecnc plot JOB``: a picture of the toolpath (or of the joints over time) with matplotlib."""
from __future__ import annotations

from pathlib import Path

import click

from edingcnc_lang.plot.names import COLOR_MODES, VIEW_NAMES
from edingcnc_lang.cli.base import Command
from edingcnc_lang.cli.options import MachineOptions, job_argument, machine_options, override_options
from edingcnc_lang.cli.value_types import OUTPUT_FILE
from edingcnc_lang.cli.view_cmd import job_to_draw, report


@click.command("plot", cls=Command, short_help="Draw the toolpath of JOB as a PNG, SVG or PDF picture.")
@job_argument
@machine_options
@override_options
@click.option("-o", "--output", metavar="FILE", type=OUTPUT_FILE,
              help="Picture to write; .png, .svg or .pdf (default: JOB.png beside the job).")
@click.option("--view", type=click.Choice(("auto", *VIEW_NAMES)), default="auto", show_default=True,
              help="Seen from above, the front, the right side, isometric, or the lathe's ZX plane (Z across, "
                   "X up); auto: top, or lathe for a job that never moves Y.")
@click.option("--color", type=click.Choice(COLOR_MODES), default="tool", show_default=True,
              help="Colour the feed moves by tool, by kind, by programmed feed or by the planner's speed.")
@click.option("--fit", type=click.Choice(("job", "part", "machine")), default="job", show_default=True,
              help="Fit the picture to the whole job, to the part's bounding box, or to the machine's travel.")
@click.option("--joints", is_flag=True,
              help="Plot the joint positions over time instead (default file: JOB-joints.png).")
def plot(job: str, machine: MachineOptions, feed_override: float, rapid_override: float, output: str | None,
         view: str, color: str, fit: str, joints: bool) -> int:
    """Run JOB and draw its toolpath: rapids dashed, feeds solid, arcs as arcs, the work zero, the
    part's bounding box and the machine limits. Prints the file written."""
    from edingcnc_lang.plot.actions import plot_job

    options = machine.run_options(feed_override=feed_override, rapid_override=rapid_override, write_job_files=False)
    with job_to_draw(job, output) as (path, name):
        written = plot_job(path, options, Path(output) if output else None,
                           view=view, color=color, fit=fit, joints=joints, name=name)
    return report(written)
