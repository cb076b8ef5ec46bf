"""``ecnc sim JOB --stock ...``: cut a stock with the job and report collisions (docs/simulation.md)."""
from __future__ import annotations

import math
import sys
from collections.abc import Callable, Iterable
from pathlib import Path
from typing import Any, NamedTuple

import click

from edingcnc_lang.errors import EXIT_FINDINGS, EXIT_OK, EcncError, JobAborted
from edingcnc_lang.cli.base import Command, usage_error
from edingcnc_lang.cli.options import MachineOptions, job_or_stdin_argument, json_option, machine_options
from edingcnc_lang.cli.value_types import EXISTING_FILE, OUTPUT_FILE, PlainFloat
from edingcnc_lang.cli.streams import job_to_read_twice


class Cylinder(NamedTuple):
    """``--stock cylinder:DIAMETER,LENGTH[,X0]``: a bar on the rotary A axis, from X0 to X0 + LENGTH."""

    diameter: float
    length: float
    x0: float


class StockBox(click.ParamType):
    """``XMIN,YMIN,ZMIN,XMAX,YMAX,ZMAX``: six numbers, each minimum below its maximum; or
    ``cylinder:DIAMETER,LENGTH[,X0]`` (a ``Cylinder``)."""

    name = "XMIN,YMIN,ZMIN,XMAX,YMAX,ZMAX"

    def convert(self, value: Any, param: click.Parameter | None, ctx: click.Context | None) -> tuple[float, ...]:
        if isinstance(value, tuple):
            return value
        from edingcnc_lang.syntax.source import plain_float  # plain decimals only, as every number the CLI takes

        if str(value).startswith("cylinder:"):
            return self._cylinder(str(value), param, ctx)

        try:
            numbers = tuple(plain_float(v) for v in str(value).split(","))
        except ValueError:
            numbers = ()
        if len(numbers) != 6 or not all(math.isfinite(v) for v in numbers):
            self.fail(f"{value!r} is not six numbers XMIN,YMIN,ZMIN,XMAX,YMAX,ZMAX (e.g. 0,0,-20,100,60,0)", param, ctx)
        if any(numbers[i] >= numbers[i + 3] for i in range(3)):
            self.fail(f"{value!r}: each minimum must be below its maximum (XMIN < XMAX, YMIN < YMAX, ZMIN < ZMAX)",
                      param, ctx)
        return numbers

    def _cylinder(self, value: str, param: click.Parameter | None, ctx: click.Context | None) -> Cylinder:
        return Cylinder(*_round_size(self, value[len("cylinder:"):], value, "cylinder:DIAMETER,LENGTH[,X0]",
                                    "cylinder:40,100", param, ctx))


def _round_size(kind: click.ParamType, text: str, value: str, form: str, example: str, param: click.Parameter | None,
               ctx: click.Context | None) -> tuple[float, float, float]:
    """``DIAMETER,LENGTH[,START]`` of round stock (a bar on a lathe or on a rotary axis), START 0 when
    left out; a usage error (``kind.fail``) naming ``value`` and ``form`` otherwise."""
    from edingcnc_lang.syntax.input_limits import MAX_SIM_LENGTH
    from edingcnc_lang.syntax.source import plain_float

    try:
        numbers = tuple(plain_float(v) for v in text.split(","))
    except ValueError:
        numbers = ()
    if len(numbers) not in (2, 3) or not all(abs(v) <= MAX_SIM_LENGTH for v in numbers):
        kind.fail(f"{value!r} is not {form} (e.g. {example})", param, ctx)
    if numbers[0] <= 0 or numbers[1] <= 0:
        kind.fail(f"{value!r}: the diameter and the length must be above 0", param, ctx)
    return numbers[0], numbers[1], numbers[2] if len(numbers) == 3 else 0.0


class BarSize(click.ParamType):
    """``DIAMETER,LENGTH[,Z0]``: a lathe bar, its face at work Z0 (default 0), reaching to Z0 - LENGTH."""

    name = "DIAMETER,LENGTH[,Z0]"

    def convert(self, value: Any, param: click.Parameter | None, ctx: click.Context | None) -> tuple[float, ...]:
        if isinstance(value, tuple):
            return value
        return _round_size(self, str(value), str(value), "DIAMETER,LENGTH[,Z0]", "40,100 or 40,100,2", param, ctx)


@click.command("sim", cls=Command, short_help="Cut a stock with JOB: the part, its volumes and every collision.")
@job_or_stdin_argument
@click.option("--stock", "box", metavar="XMIN,YMIN,ZMIN,XMAX,YMAX,ZMAX", type=StockBox(),
              help="The stock as a box in the job's work coordinates (its first work offset); "
                   "cylinder:DIAMETER,LENGTH[,X0]: a bar on the rotary A axis (along X from X0, through Y0 Z0; "
                   "on B where the ini shows B and hides A: along Y from Y0, through X0 Z0).")
@click.option("--stock-stl", metavar="FILE", type=EXISTING_FILE,
              help="The stock as an STL mesh (work coordinates); its top surface is what is cut.")
@click.option("--bar", metavar="DIAMETER,LENGTH[,Z0]", type=BarSize(),
              help="Lathe: the stock as a bar turning about Z, its face at work Z0 (default 0), to Z0 - LENGTH.")
@click.option("--chuck", metavar="LENGTH", type=PlainFloat(0, min_open=True, max=1e9),
              help="With --bar: the length the chuck grips at the bar's far end (a tool reaching it: kind chuck).")
@click.option("--resolution", metavar="MM", type=PlainFloat(0, min_open=True), default=0.25,
              show_default=True, help="Cell size of the height field.")
@click.option("--tools", "tools_file", metavar="FILE", type=EXISTING_FILE,
              help="Tool shapes as TOML, [tool.N] tables (default: the ini's diameters as flat end mills).")
@machine_options
@json_option("Print the stock's volumes and the collisions as JSON on stdout.")
@click.option("-o", "--output", metavar="FILE", type=OUTPUT_FILE,
              help="Picture of the cut stock with the findings marked: .png, .svg or .pdf.")
@click.option("--stl", metavar="FILE", type=OUTPUT_FILE, help="Write the cut stock as a binary STL mesh.")
@click.option("--compare-stl", metavar="FILE", type=EXISTING_FILE,
              help="The intended part as STL: report (and draw) over- and under-cut against it.")
def sim(job: str, box: tuple[float, ...] | None, stock_stl: str | None, bar: tuple[float, ...] | None,
        chuck: float | None, resolution: float, tools_file: str | None,
        machine: MachineOptions, as_json: bool, output: str | None, stl: str | None,
        compare_stl: str | None) -> int:
    """Run JOB and cut the stock with it as a height field (3-axis milling): report rapids into the
    stock, shank and holder hits, cuts with the spindle stopped (exit 1), plunges and cuts below the
    stock (hints), with the removed and remaining volumes.  With --bar, on a lathe ini: turn a bar
    (each cut a revolution) and report rapids into it, cuts with the spindle stopped, the holder
    and the chuck; with --stock cylinder:, cut a bar on the rotary A axis."""
    from edingcnc_lang.outputs import check_outputs, ensure_parent
    from edingcnc_lang.picture_formats import picture_target
    from edingcnc_lang.sim import report
    from edingcnc_lang.sim.findings import failing
    from edingcnc_lang.sim.job import simulate
    from edingcnc_lang.sim.stock import Stock
    from edingcnc_lang.sim.stl import stock_from_stl
    from edingcnc_lang.sim.tools import load_tools

    if bar is not None or chuck is not None or isinstance(box, Cylinder):
        return _sim_round(job, box, stock_stl, bar, chuck, resolution, tools_file, machine, as_json, output, stl,
                        compare_stl)
    if (box is None) == (stock_stl is None):
        raise usage_error("give the stock as exactly one of --stock XMIN,YMIN,ZMIN,XMAX,YMAX,ZMAX and --stock-stl FILE")
    check_outputs({"-o": output, "--stl": stl},
                  [job, stock_stl, tools_file, compare_stl, *machine.input_files()])  # before anything runs
    fmt = picture_target(Path(output)) if output else None  # told before the job runs
    tools = load_tools(tools_file) if tools_file else None
    if box is not None:
        stock = Stock.box(box[:3], box[3:], resolution)  # type: ignore[arg-type]
    else:
        stock = stock_from_stl(str(stock_stl), resolution)
    options = machine.run_options(show_messages=not as_json, write_job_files=False)
    with job_to_read_twice(job) as (path, name):
        result = simulate(path, stock, options, tools, machine.spindle_tool, name=name)
    deviation = None
    if compare_stl:
        from edingcnc_lang.sim.compare import compare

        deviation = compare(stock, compare_stl)
    if output and fmt:
        from edingcnc_lang.sim.picture import draw_stock

        draw_stock(stock, ensure_parent(Path(output)), fmt, result.findings,
                   _title(name or job, stock.removed_volume, len(result.findings)), deviation)
    if stl:
        from edingcnc_lang.sim.stl import stock_mesh, write_stl

        write_stl(ensure_parent(Path(stl)), stock_mesh(stock))
    return _report(as_json, lambda: report.to_json(result, deviation), lambda: report.summary(result, deviation),
                   (output, stl), result.error, failing(result.findings))


def _title(name: str, removed: float, count: int) -> str:
    """The picture's title: the job, the volume removed, how many findings."""
    return f"{name}: {removed:,.0f} mm³ removed, {count} finding{'s' * (count != 1)}"


def _report(as_json: bool, document: Callable[[], dict[str, Any]], summary: Callable[[], Iterable[str]],
            written: tuple[str | None, ...], error: EcncError | None, failed: bool) -> int:
    """Print the result (``--json``'s document, or the summary and the files written), then the error
    that stopped the run; the exit code: the error's, 1 with a failing finding, else 0."""
    if as_json:
        import json

        print(json.dumps(document(), indent=1))
    else:
        for line in summary():
            print(line)
        for path in written:
            if path:
                print(f"wrote {path}")
    if error is not None:
        if not isinstance(error, JobAborted):
            print(error.format(), file=sys.stderr)
        return error.exit_code
    return EXIT_FINDINGS if failed else EXIT_OK


def _sim_round(job: str, box: tuple[float, ...] | None, stock_stl: str | None, bar: tuple[float, ...] | None,
               chuck: float | None, resolution: float, tools_file: str | None, machine: MachineOptions,
               as_json: bool, output: str | None, stl: str | None, compare_stl: str | None) -> int:
    """``ecnc sim --bar`` (a lathe job turning a bar) and ``--stock cylinder:`` (a bar on a mill's A
    axis): docs/simulation.md, round stock."""
    from edingcnc_lang.outputs import check_outputs, ensure_parent
    from edingcnc_lang.picture_formats import picture_target
    from edingcnc_lang.sim import bar_output
    from edingcnc_lang.sim.findings import failing
    from edingcnc_lang.sim.lathe import BarResult, simulate_bar
    from edingcnc_lang.sim.rotary import CylinderResult, simulate_cylinder
    from edingcnc_lang.sim.round_stock import RoundStock
    from edingcnc_lang.sim.tools import load_tools

    if bar is None and chuck is not None:
        raise usage_error("--chuck LENGTH goes with --bar DIAMETER,LENGTH[,Z0] (a lathe's bar)")
    if (bar is not None and box is not None) or stock_stl is not None:
        raise usage_error("give the stock as exactly one of --stock, --stock-stl and --bar")
    if bar is not None and chuck is not None and chuck >= bar[1]:
        raise usage_error(f"--chuck {chuck:g} grips the whole bar ({bar[1]:g} mm long)")
    check_outputs({"-o": output, "--stl": stl}, [job, tools_file, compare_stl, *machine.input_files()])
    fmt = picture_target(Path(output)) if output else None
    tools = load_tools(tools_file) if tools_file else None
    options = machine.run_options(show_messages=not as_json, write_job_files=False)
    result: BarResult | CylinderResult
    with job_to_read_twice(job) as (path, name):
        if bar is not None:
            diameter, length, face = bar
            stock = RoundStock.bar(diameter, length, face - length, resolution)
            chuck_face = face - length + chuck if chuck is not None else None
            result = simulate_bar(path, stock, options, tools, machine.spindle_tool, name=name, chuck=chuck_face)
        else:
            assert isinstance(box, Cylinder)
            stock = RoundStock.cylinder(box.diameter, box.length, box.x0, resolution)
            result = simulate_cylinder(path, stock, options, tools, machine.spindle_tool, name=name)
    deviation = None
    if compare_stl is not None:
        from edingcnc_lang.sim.rotary_output import compare_rotary

        deviation = compare_rotary(stock, compare_stl, "Z" if isinstance(result, BarResult) else result.axis)
    if output and fmt:
        title = _title(name or job, stock.removed_volume, len(result.findings))
        if isinstance(result, BarResult):
            bar_output.draw_bar(result, ensure_parent(Path(output)), fmt, title, deviation)
        else:
            bar_output.draw_unwrapped(result, ensure_parent(Path(output)), fmt, title, deviation)
    if stl:
        from edingcnc_lang.sim.stl import write_stl

        from edingcnc_lang.sim.rotary_output import rotary_mesh

        write_stl(ensure_parent(Path(stl)), bar_output.bar_mesh(stock) if isinstance(result, BarResult) else
                  rotary_mesh(stock, result.axis))
    compared = {} if deviation is None else {"compare": deviation.to_json()}
    return _report(as_json, lambda: {**bar_output.to_json(result), **compared},
                   lambda: bar_output.summary(result) + ([deviation.line()] if deviation else []),
                   (output, stl), result.error, failing(result.findings))
