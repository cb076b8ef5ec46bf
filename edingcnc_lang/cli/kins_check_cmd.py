"""``ecnc kins check|compare|plot``: prove a plug-in before it meets a machine (docs/kinematics.md).

Exit 0 when nothing was found, 1 for findings (or plug-ins that differ), 2 for usage errors and 70
when a plug-in cannot be loaded at all.
"""
from __future__ import annotations

import re
from collections.abc import Callable
from typing import TYPE_CHECKING, Any, TypeVar

import click

from edingcnc_lang.errors import EXIT_FINDINGS, EXIT_OK
from edingcnc_lang.cli.base import Command, usage_error
from edingcnc_lang.cli.kins_cmd import guarded, in_child_if_compiled
from edingcnc_lang.cli.options import ini_option, json_option
from edingcnc_lang.syntax.input_limits import MAX_CHECK_SAMPLES, MAX_ENVELOPE_RESOLUTION
from edingcnc_lang.cli.value_types import FLOAT, INT, KINEMATICS_NAME, OUTPUT_FILE, PlainInt

if TYPE_CHECKING:
    from edingcnc_lang.kinematics.workbench import CheckOptions

F = TypeVar("F", bound=Callable[..., Any])
PLUGIN_HELP = "PLUGIN is a registered name (see `ecnc kins list`) or the path of a .so or .py plug-in."


def _workspace_options(func: F) -> F:
    """--ini, --box, --seed, --samples, --tolerance: where and how densely to look."""
    func = click.option("--tolerance", type=FLOAT, metavar="T",
                        help="Absolute tolerance (default: 1e-6 of the workspace diagonal).")(func)
    func = click.option("--samples", type=PlainInt(1, MAX_CHECK_SAMPLES), default=2000, show_default=True,
                        help=f"Random poses, after the centre and the corners (at most {MAX_CHECK_SAMPLES:,}).")(func)
    func = click.option("--seed", type=INT, default=0, show_default=True,
                        help="Seed of the sample poses: the same seed gives the same report.")(func)
    func = click.option("--box", metavar="X0,X1,Y0,Y1,Z0,Z1[,A0,A1...]",
                        help="Workspace to prove: 6 to 12 numbers, commas or spaces between them "
                             "(default: the ini's Cartesian limits, else its joint limits).")(func)
    return ini_option("cnc.ini: [KINEMATICS] settings, limits and the folder plug-ins are found in.")(func)


class WorkspaceCommand(Command):
    """``--box`` as one value (commas or spaces) or as separate numbers (``--box 10 100 -50 50 -5 5``)."""

    number_lists = ("--box",)


def _options(ini: str | None, box: str | None, seed: int, samples: int, tolerance: float | None,
             **extra: Any) -> CheckOptions:
    from edingcnc_lang.kinematics.workbench import CheckOptions
    from edingcnc_lang.kinematics.workbench.check import box_values
    from edingcnc_lang.syntax.source import plain_float

    values = None
    if box is not None:
        try:
            values = box_values([plain_float(v, special=True) for v in re.split(r"[,\s]+", box.strip()) if v])
        except ValueError as err:
            message = str(err) if "--box" in str(err) else f"--box: not a list of numbers: {box!r}"
            raise usage_error(message) from None
    if tolerance is not None and not tolerance > 0.0:
        raise usage_error(f"--tolerance must be a positive number, not {tolerance:g}")
    return CheckOptions(ini=ini, box=values, seed=seed, samples=samples, tolerance=tolerance, **extra)


def _workspace_argv(ini: str | None, box: str | None, seed: int, samples: int, tolerance: float | None) -> list[str]:
    """The workspace options again, for the same command in a child process."""
    argv = ["--seed", str(seed), "--samples", str(samples)]
    argv += ["--ini", ini] if ini else []
    argv += [f"--box={box}"] if box is not None else []
    return argv + ([f"--tolerance={tolerance!r}"] if tolerance is not None else [])


def _print_json(data: object) -> None:
    from edingcnc_lang.syntax.serialize import json_text

    print(json_text(data, indent=2))


@click.command("check", cls=WorkspaceCommand, help=f"Prove a plug-in over a workspace: round trip, continuity, "
               f"singularities, domain, control and state, the compiled ABI and speed.\n\n{PLUGIN_HELP}",
               short_help="Prove a plug-in: round trip, continuity, singularities, domain, state, speed.")
@click.argument("plugin", metavar="PLUGIN", type=KINEMATICS_NAME)
@_workspace_options
@click.option("--no-speed", is_flag=True, help="Leave out the speed measurement (a faster check).")
@json_option("Print the report as JSON.")
def check(plugin: str, no_speed: bool, as_json: bool, **workspace: Any) -> int:
    from edingcnc_lang.kinematics.workbench import check_plugin

    report = check_plugin(plugin, _options(speed=not no_speed, **workspace))
    _print_json(report.to_json()) if as_json else print(report.format())
    return EXIT_OK if report.ok else EXIT_FINDINGS


@click.command("compare", cls=WorkspaceCommand, help=f"Run two plug-ins on the same seeded poses (e.g. a C port and the "
               f"Python it came from): the largest difference per joint and axis, and where.\n\n{PLUGIN_HELP}",
               short_help="Two plug-ins on the same poses: the largest difference per joint, and where.")
@click.argument("a", metavar="A", type=KINEMATICS_NAME)
@click.argument("b", metavar="B", type=KINEMATICS_NAME)
@_workspace_options
@json_option("Print the comparison as JSON.")
def compare(a: str, b: str, as_json: bool, **workspace: Any) -> int:
    from edingcnc_lang.kinematics.workbench import compare_plugins

    result = compare_plugins(a, b, _options(**workspace))
    _print_json(result.to_json()) if as_json else print(result.format())
    return EXIT_OK if result.ok else EXIT_FINDINGS


@click.command("plot", cls=WorkspaceCommand, help=f"Draw the reachable workspace and the Jacobian's condition number in "
               f"three slices through the centre (needs the plot extra).\n\n{PLUGIN_HELP}",
               short_help="Picture the reachable workspace and its singular regions (PNG, SVG, PDF).")
@click.argument("plugin", metavar="PLUGIN", type=KINEMATICS_NAME)
@click.option("-o", "--output", metavar="FILE", type=OUTPUT_FILE, required=True,
              help="Picture to write: .png, .svg or .pdf.")
@click.option("--resolution", type=PlainInt(1, MAX_ENVELOPE_RESOLUTION), default=60, show_default=True,
              help=f"Grid points per side (at most {MAX_ENVELOPE_RESOLUTION:,}).")
@_workspace_options
def plot(plugin: str, output: str, resolution: int, **workspace: Any) -> int:
    from pathlib import Path

    from edingcnc_lang.kinematics.workbench import check as workbench
    from edingcnc_lang.kinematics.workbench.envelope import plot_envelope

    from edingcnc_lang.outputs import check_outputs
    from edingcnc_lang.picture_formats import picture_format

    check_outputs({"-o": output}, [plugin, workspace.get("ini")])  # a plug-in that is a path, and the ini
    fmt = picture_format(Path(output))  # before the workspace is searched
    options = _options(**workspace)
    isolated = in_child_if_compiled(plugin, options.ini, [
        "kins", "plot", "-o", output, "--resolution", str(resolution), *_workspace_argv(**workspace), "--", plugin])
    if isolated is not None:
        return isolated
    machine = workbench.read_machine(options.ini)
    kins = guarded(workbench.load_plugin(plugin, machine))
    space = workbench.workspace_for(kins, options, machine)
    workbench.plug.switch_on(kins, space.centre)
    print(plot_envelope(kins, space, Path(output), plugin, resolution=resolution, fmt=fmt,
                        joint_limits=machine.joint_limits))
    return EXIT_OK
