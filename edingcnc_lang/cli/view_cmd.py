"""``ecnc view JOB``: one self-contained HTML page with an interactive 3D view of the toolpath."""
from __future__ import annotations

import contextlib
import sys
from collections.abc import Iterator
from pathlib import Path
from typing import TYPE_CHECKING, Any

import click

from edingcnc_lang.errors import EXIT_OK, JobAborted
from edingcnc_lang.plot.names import VIEW_NAMES
from edingcnc_lang.cli.base import Command
from edingcnc_lang.cli.options import MachineOptions, job_argument, machine_options, override_options
from edingcnc_lang.cli.value_types import EXISTING_FILE, OUTPUT_FILE, POSITIVE_INT, PlainFloat
from edingcnc_lang.cli.sim_cmd import BarSize, Cylinder, StockBox
from edingcnc_lang.cli.streams import job_to_read_twice

if TYPE_CHECKING:
    from edingcnc_lang.plot.actions import Written
    from edingcnc_lang.sim.tools import Tool


STOCK_RESOLUTION = 0.5  # mm: the page shows a coarse map anyway (sim/frames.py)
BAR_RESOLUTION = 0.1    # mm: a bar's slices (the page shows at most 400 of them: sim/bar_frames.py)
CYLINDER_RESOLUTION = 0.5  # mm: a bar on a rotary axis (the page shows at most 8192 blocks: sim/rotary_frames.py)


class LineRange(click.ParamType):
    """``A:B`` job lines, both included (``A:`` to the end, ``:B`` from the start)."""

    name = "A:B"

    def convert(self, value: Any, param: click.Parameter | None, ctx: click.Context | None) -> tuple[int, int]:
        if isinstance(value, tuple):
            return value
        from edingcnc_lang.plot.actions import parse_line_range

        try:
            return parse_line_range(str(value))
        except ValueError as err:
            self.fail(str(err), param, ctx)


@click.command("view", cls=Command, short_help="Write an interactive 3D view of JOB as one HTML file.")
@job_argument
@machine_options
@override_options
@click.option("-o", "--output", metavar="FILE", type=OUTPUT_FILE,
              help="HTML file to write (default: JOB.html beside the job).")
@click.option("--view", type=click.Choice(("auto", *VIEW_NAMES)), default="auto", show_default=True,
              help="The view the page opens with; auto: iso, or lathe (Z across, X up) for a job that never moves Y.")
@click.option("--max-moves", metavar="N", type=POSITIVE_INT,
              help="Moves in the page before long runs of feed moves are thinned (default 25000).")
@click.option("--lines", metavar="A:B", type=LineRange(),
              help="Only the moves made by job lines A to B (with the subs they call), in full.")
@click.option("--stock", "stock_box", metavar="XMIN,YMIN,ZMIN,XMAX,YMAX,ZMAX", type=StockBox(),
              help="Show this stock (work coordinates) being cut as the player runs (see ecnc sim); "
                   "cylinder:DIAMETER,LENGTH[,X0]: a bar on the rotary axis, its unrolled depth map.")
@click.option("--bar", metavar="DIAMETER,LENGTH[,Z0]", type=BarSize(),
              help="Lathe: show this bar being turned as the player runs, as a half section (see ecnc sim --bar).")
@click.option("--chuck", metavar="LENGTH", type=PlainFloat(0, min_open=True, max=1e9),
              help="With --bar: the length the chuck grips at the bar's far end.")
@click.option("--tools", "tools_file", metavar="FILE", type=EXISTING_FILE,
              help="With --stock or --bar: tool shapes as TOML, as ecnc sim reads them.")
@click.option("--resolution", metavar="MM", type=PlainFloat(0, min_open=True),
              help="With --stock or --bar: the cell (slice) of the simulation the page shows (default 0.5 mm; "
                   "0.1 for --bar).")
@click.option("--diff", "old", metavar="OLD", type=EXISTING_FILE,
              help="Also run OLD: the page shows OLD and JOB (NEW), a button (D) switches (ecnc view --diff OLD NEW).")
@click.option("--embed-sources", is_flag=True,
              help="Put full file paths and the text of ecnc's own macro.cnc into the page (left out by "
                   "default, as the page gets shared).")
def view(job: str, machine: MachineOptions, feed_override: float, rapid_override: float, output: str | None,
         view: str, max_moves: int | None, lines: tuple[int, int] | None,
         stock_box: tuple[float, ...] | None = None, tools_file: str | None = None, old: str | None = None,
         embed_sources: bool = False, bar: tuple[float, ...] | None = None, chuck: float | None = None,
         resolution: float | None = None) -> int:
    """Run JOB and write a page to open in any browser, without network access: rotate, pan,
    zoom, top/front/side/iso, and a slider that plays the job move by move beside its program
    lines and the machine position. Prints the file written."""
    from edingcnc_lang.plot.actions import view_job
    from edingcnc_lang.sim.stock import StockError

    _check_stock(stock_box, bar, chuck, lines, tools_file, resolution)
    tools = None
    if tools_file:  # a bad file is told before the job runs
        from edingcnc_lang.sim.tools import load_tools

        tools = load_tools(tools_file)
    options = machine.run_options(feed_override=feed_override, rapid_override=rapid_override, write_job_files=False)
    with job_to_draw(job, output) as (path, name):
        changes = None
        if old and lines is None:  # what ecnc diff finds, coloured and listed on the page
            from edingcnc_lang.diff import diff_files
            from edingcnc_lang.diff.style import page_data

            quiet = machine.run_options(show_messages=False, feed_override=feed_override, rapid_override=rapid_override)
            changes = page_data(diff_files(Path(old), path, quiet))
        written = view_job(path, options, Path(output) if output else None,
                           max_moves=max_moves, lines=lines, view=view, name=name,
                           old=Path(old) if old else None, embed_sources=embed_sources, changes=changes)
        try:
            _add_stock(written, path, name, machine, stock_box, bar, chuck, resolution, tools, max_moves)
        except StockError:  # the stock does not fit the machine (a bar on a mill, a cylinder on a lathe)
            written.out.unlink(missing_ok=True)  # the page just written, without its stock: not left half made
            raise
    return report(written)


def _add_stock(written: Written, path: Path, name: str | None, machine: MachineOptions, stock_box: tuple[float, ...] | None,
               bar: tuple[float, ...] | None, chuck: float | None, resolution: float | None,
               tools: dict[int, Tool] | None, max_moves: int | None) -> None:
    """Simulate the stock beside the page's run and put its frames into the page."""
    if isinstance(stock_box, Cylinder):
        from edingcnc_lang.plot.viewer import MAX_MOVES, decimate
        from edingcnc_lang.sim.frames import add_to_page
        from edingcnc_lang.sim.rotary_frames import rotary_frames
        from edingcnc_lang.sim.round_stock import RoundStock

        cylinder = RoundStock.cylinder(stock_box.diameter, stock_box.length, stock_box.x0,
                                       resolution or CYLINDER_RESOLUTION)
        quiet = machine.run_options(show_messages=False, write_job_files=False)
        shown = decimate(written.path, max_moves or MAX_MOVES).keep
        add_to_page(written.out, rotary_frames(path, cylinder, quiet, len(written.path), shown, tools,
                                               machine.spindle_tool, name), "rotary-data")
    elif stock_box is not None:
        from edingcnc_lang.sim.frames import add_to_page, stock_frames
        from edingcnc_lang.sim.stock import Stock

        stock = Stock.box(stock_box[:3], stock_box[3:], resolution or STOCK_RESOLUTION)  # type: ignore[arg-type]
        quiet = machine.run_options(show_messages=False, write_job_files=False)
        add_to_page(written.out, stock_frames(path, stock, quiet, len(written.path), tools, machine.spindle_tool, name))
    if bar is not None:
        from edingcnc_lang.sim.bar_frames import bar_frames
        from edingcnc_lang.sim.frames import add_to_page
        from edingcnc_lang.sim.round_stock import RoundStock

        diameter, length, face = bar
        stock_bar = RoundStock.bar(diameter, length, face - length, resolution or BAR_RESOLUTION)
        quiet = machine.run_options(show_messages=False, write_job_files=False)
        chuck_face = face - length + chuck if chuck is not None else None
        add_to_page(written.out, bar_frames(path, stock_bar, quiet, len(written.path), tools, machine.spindle_tool,
                                            name, chuck_face), "bar-data")


def _check_stock(stock_box: tuple[float, ...] | None, bar: tuple[float, ...] | None, chuck: float | None,
                 lines: tuple[int, int] | None, tools_file: str | None, resolution: float | None = None) -> None:
    """The usage errors of the stock options, told before anything runs."""
    if stock_box is not None and bar is not None:
        what = "a bar on the rotary axis" if isinstance(stock_box, Cylinder) else "a box"
        raise click.UsageError(f"give the stock as one of --stock ({what}) and --bar (a lathe's bar)")
    if chuck is not None and bar is None:
        raise click.UsageError("--chuck LENGTH goes with --bar DIAMETER,LENGTH[,Z0] (a lathe's bar)")
    if bar is not None and chuck is not None and chuck >= bar[1]:
        raise click.UsageError(f"--chuck {chuck:g} grips the whole bar ({bar[1]:g} mm long)")
    if (stock_box is not None or bar is not None) and lines is not None:
        raise click.UsageError(f"{'--stock' if bar is None else '--bar'} shows the whole job being cut: "
                               "it does not go with --lines")
    if tools_file and stock_box is None and bar is None:
        raise click.UsageError("--tools gives the tools their shapes for --stock or --bar: give the stock too")
    if resolution is not None and stock_box is None and bar is None:
        raise click.UsageError("--resolution is the cell of the stock's simulation: give --stock or --bar too")


@contextlib.contextmanager
def job_to_draw(job: str, output: str | None) -> Iterator[tuple[Path, str | None]]:
    """The job to run for a picture or a page, as ``job_to_read_twice`` gives it (a pipe copied);
    a pipe needs ``-o``, since there is no folder to write ``JOB.png`` (``JOB.html``) beside."""
    if output is None and not Path(job).is_file():
        raise click.UsageError(f"{job} is a pipe, not a file: name the file to write with -o FILE")
    with job_to_read_twice(job) as found:
        yield found


def report(written: Written) -> int:
    """Print the file written; after a runtime error (the picture shows the path up to it) the error too."""
    print(written.out)
    error = written.path.error
    if error is None:
        return EXIT_OK
    if not isinstance(error, JobAborted):  # an errmsg text was shown as it ran
        print(error.format(), file=sys.stderr)
    return error.exit_code
