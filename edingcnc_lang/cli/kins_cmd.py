"""``ecnc kins``: list, try out and build kinematics plug-ins from the shell.

``inverse``/``forward`` first switch the kinematics ON at the machine origin (control ID 4 with
dData all zero), as ``KIN ON`` would at X0 Y0 Z0: rotatekins, for one, only transforms while on.
"""
from __future__ import annotations

import json
import os
from collections.abc import Mapping, Sequence
from pathlib import Path
from typing import TYPE_CHECKING

import click

from edingcnc_lang.cli.common import reports_errors

if TYPE_CHECKING:
    from edingcnc_lang.kinematics.base import Kinematics, Pose

# Let "-5" through as a number instead of an unknown option.
NUMBERS = {"ignore_unknown_options": True}


def _settings(ini: Path | None) -> tuple[Mapping[str, str], tuple[Path, ...]]:
    """The ``[KINEMATICS]`` section and the ini's folder (where plug-in files are looked for)."""
    from edingcnc_lang.config import read_ini

    if ini is None:
        return {}, ()
    return read_ini(ini).section("KINEMATICS"), (ini.parent,)


def _switched_on(name: str, ini: Path | None) -> Kinematics:
    from edingcnc_lang.errors import PluginError
    from edingcnc_lang.kinematics import abi
    from edingcnc_lang.kinematics.loader import load_kinematics

    settings, search_dirs = _settings(ini)
    kins = load_kinematics(name, settings, search_dirs)
    rc = kins.control(abi.ON, [0.0] * abi.CONTROL_DATA_LEN)
    if rc != 0:
        raise PluginError(f"kinematics plug-in {name!r}: switching it ON failed (control returned {rc})")
    return kins


def _pose(values: Sequence[float], names: Sequence[str]) -> Pose:
    if not 3 <= len(values) <= 6:
        raise click.UsageError(f"expected 3 to 6 numbers ({' '.join(n.upper() for n in names)}), "
                               f"got {len(values)}")
    x, y, z, a, b, c = (*values, *[0.0] * (6 - len(values)))
    return (x, y, z, a, b, c)


def _print_pose(values: Pose, names: Sequence[str]) -> None:
    """JSON with repr-exact floats (json uses float.__repr__)."""
    click.echo(json.dumps(dict(zip(names, values))))


@click.group("kins")
def kins() -> None:
    """List, evaluate and build kinematics plug-ins."""


@kins.command("list")
@click.option("--json", "as_json", is_flag=True, help="Print a JSON array instead of a table.")
@reports_errors
def list_cmd(as_json: bool) -> None:
    """Registered kinematics: name, type and version (tab separated)."""
    from edingcnc_lang.kinematics.loader import available_kinematics

    rows = available_kinematics()
    if as_json:
        click.echo(json.dumps([{"name": n, "type": t, "version": v} for n, t, v in rows]))
        return
    for name, kin_type, version in rows:
        click.echo(f"{name}\t{kin_type}\t{version}")


_INI = click.option("--ini", type=click.Path(exists=True, dir_okay=False, path_type=Path),
                    help="cnc.ini whose [KINEMATICS] section configures the plug-in.")


@kins.command("inverse", context_settings=NUMBERS)
@click.argument("name")
@_INI
@click.argument("coords", nargs=-1, type=float, metavar="X Y Z [A B C]")
@reports_errors
def inverse_cmd(name: str, ini: Path | None, coords: tuple[float, ...]) -> None:
    """Joints for a Cartesian position (missing A B C are 0)."""
    from edingcnc_lang.kinematics.base import AXES, JOINTS

    pos = _pose(coords, AXES)
    _print_pose(_switched_on(name, ini).inverse(pos), JOINTS)


@kins.command("forward", context_settings=NUMBERS)
@click.argument("name")
@_INI
@click.argument("joints", nargs=-1, type=float, metavar="JX JY JZ [JA JB JC]")
@reports_errors
def forward_cmd(name: str, ini: Path | None, joints: tuple[float, ...]) -> None:
    """Cartesian position for joint positions (missing JA JB JC are 0)."""
    from edingcnc_lang.kinematics.base import AXES, JOINTS

    values = _pose(joints, JOINTS)
    _print_pose(_switched_on(name, ini).forward(values), AXES)


@kins.command("build")
@click.argument("source", type=click.Path(exists=True, dir_okay=False, path_type=Path))
@click.option("-o", "--output", type=click.Path(dir_okay=False, path_type=Path),
              help="Library to write (default: SOURCE with .so).")
@click.option("--cc", default=lambda: os.environ.get("CC", "cc"), show_default="$CC or cc",
              help="C compiler to run.")
@reports_errors
def build_cmd(source: Path, output: Path | None, cc: str) -> None:
    """Compile a C plug-in against edingcnc_kins.h; prints the library's path."""
    from edingcnc_lang.kinematics.build import build_plugin

    click.echo(str(build_plugin(source, output, cc)))
