"""``ecnc diff OLD NEW``: run both jobs and report what the machine does differently."""
from __future__ import annotations

import dataclasses
from pathlib import Path
from typing import TYPE_CHECKING

import click

from edingcnc_lang.errors import EXIT_OK
from edingcnc_lang.plot.names import VIEW_NAMES
from edingcnc_lang.cli.base import Command
from edingcnc_lang.cli.options import MachineOptions, json_option, machine_options
from edingcnc_lang.cli.sim_cmd import StockBox
from edingcnc_lang.cli.value_types import ANSWER, EXISTING_FILE, INI_FILE, OUTPUT_FILE, POSITIVE_INT, PlainFloat
from edingcnc_lang.cli.streams import job_to_read_twice

if TYPE_CHECKING:
    from collections.abc import Callable

    from edingcnc_lang.host import DialogAnswer
    from edingcnc_lang.runner import RunOptions
    from edingcnc_lang.sim import SimResult

EXIT_DIFFERS = 1


def _finite(param: click.Parameter, value: float) -> float:
    """--tolerance inf or nan would make every path the same (or none): a finite number only."""
    if value != value:
        raise click.BadParameter("must be a finite number, not nan", param=param)
    return value


def _cutter(box: tuple[float, ...], resolution: float) -> Callable[[Path, RunOptions], SimResult]:
    """The stock ``box`` cut by a job (``ecnc sim``'s simulation), for the comparison of the parts."""
    from edingcnc_lang.sim import Stock, simulate

    def cut(job: Path, options: RunOptions) -> SimResult:
        return simulate(job, Stock.box((box[0], box[1], box[2]), (box[3], box[4], box[5]), resolution), options)
    return cut


@click.command("diff", cls=Command, short_help="Compare what the machine does for OLD and NEW.")
@click.argument("old", metavar="OLD", type=EXISTING_FILE)
@click.argument("new", metavar="NEW", type=EXISTING_FILE)
@machine_options
@click.option("--ini-new", metavar="FILE", type=INI_FILE,
              help="cnc.ini for NEW, where the machine changed (default: --ini).")
@click.option("--macro-new", metavar="FILE", type=EXISTING_FILE, help="Macro file for NEW (default: --macro).")
@click.option("--user-macro-new", metavar="FILE", type=EXISTING_FILE,
              help="User macro file for NEW (default: --user-macro).")
@click.option("--answer-new", "answers_new", metavar="VALUE", type=ANSWER, multiple=True,
              help="Dialog answers for NEW (default: those of --answer; repeatable).")
@click.option("--probe-surface-new", metavar="FILE", type=EXISTING_FILE,
              help="Height map for NEW's probing (default: --probe-surface).")
@click.option("--tolerance", metavar="MM", type=PlainFloat(0, 1000, min_open=True), default=0.001, show_default=True,
              callback=lambda _ctx, param, value: _finite(param, value), help="Paths closer than this are the same.")
@click.option("--limit", metavar="N", type=POSITIVE_INT, default=50, show_default=True,
              help="Changes listed per kind; the rest are counted.")
@click.option("--stock", "box", metavar="XMIN,YMIN,ZMIN,XMAX,YMAX,ZMAX", type=StockBox(),
              help="Cut this stock (work coordinates) with both jobs and compare the parts (as ecnc sim cuts).")
@click.option("--resolution", metavar="MM", type=click.FloatRange(0, min_open=True), default=0.25,
              show_default=True, help="Cell size of the height field of --stock.")
@json_option("Print the comparison as JSON on stdout.")
@click.option("-o", "--output", metavar="FILE", type=OUTPUT_FILE,
              help="Also draw both toolpaths with the differences highlighted (.png, .svg or .pdf).")
@click.option("--view", type=click.Choice(("auto", *VIEW_NAMES)), default="auto", show_default=True,
              help="The picture's view (auto: top, or lathe for a job that never moves Y).")
def diff(old: str, new: str, machine: MachineOptions, ini_new: str | None, macro_new: str | None,
         user_macro_new: str | None, answers_new: tuple[DialogAnswer, ...], probe_surface_new: str | None,
         tolerance: float, limit: int, box: tuple[float, ...] | None, resolution: float, as_json: bool,
         output: str | None, view: str) -> int:
    """Run OLD and NEW on the virtual machine and compare what the machine does, per tool and in
    order: the path (within --tolerance), feeds, spindle speeds, tools and their order, offsets,
    dwells, coolant, the planned time and rapids lower than OLD's at that place; with --stock, the
    cut parts. Renumbered lines, G01 for G1, trailing zeros or modal words left out change nothing.

    Exit status 0 when nothing differs, 1 when something does."""
    from edingcnc_lang.diff import diff_files
    from edingcnc_lang.diff.report import render
    from edingcnc_lang.outputs import check_outputs

    fmt = None
    if output:
        from edingcnc_lang.picture_formats import picture_target

        fmt = picture_target(Path(output))  # before the runs: a wrong name fails at once
    new_machine = dataclasses.replace(machine, ini=ini_new or machine.ini, macro=macro_new or machine.macro,
                                      user_macro=user_macro_new or machine.user_macro,
                                      answers=answers_new or machine.answers,
                                      probe_surface=probe_surface_new or machine.probe_surface)
    check_outputs({"-o": output}, [old, new, *machine.input_files(), *new_machine.input_files()])
    with job_to_read_twice(old) as (old_path, old_name), job_to_read_twice(new) as (new_path, new_name):
        # a pipe (<(cat old.nc)) is copied once: the check pass and the run read the same text
        comparison = diff_files(old_path, new_path, machine.run_options(show_messages=False, write_job_files=False),
                                new_machine.run_options(show_messages=False, write_job_files=False), tolerance,
                                limit, cut=None if box is None else _cutter(box, resolution),
                                names=(old_name, new_name))
    if output:
        from edingcnc_lang.diff.picture import draw_diff

        draw_diff(comparison, Path(output), view, fmt)
    if as_json:
        import json

        print(json.dumps(comparison.to_json(), indent=1, allow_nan=False))
    else:
        click.echo(render(comparison), nl=False)
        if output:
            click.echo(f"picture: {output}")
    return EXIT_OK if comparison.same else EXIT_DIFFERS
