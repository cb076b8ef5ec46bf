"""``ecnc kins``: list, try out and build kinematics plug-ins from the shell.

``inverse``/``forward`` first switch the kinematics ON at the machine origin (control ID 4 with
dData all zero), as ``KIN ON`` would at X0 Y0 Z0: rotatekins, for one, only transforms while on.
"""
from __future__ import annotations

import os
from collections.abc import Mapping, Sequence
from pathlib import Path
from typing import TYPE_CHECKING

import click

from edingcnc_lang.errors import EXIT_OK
from edingcnc_lang.cli.base import Argument, Command, LazyGroup, usage_error
from edingcnc_lang.cli.options import ini_option, json_option
from edingcnc_lang.cli.value_types import EXISTING_FILE, FLOAT, KINEMATICS_NAME, OUTPUT_FILE

if TYPE_CHECKING:
    from edingcnc_lang.kinematics.base import Kinematics, Pose

# The subcommands, "module:attribute" in this package (a new one is one line here).
SUBCOMMANDS = {"list": "kins_cmd:list_kinematics", "inverse": "kins_cmd:inverse", "forward": "kins_cmd:forward",
               "build": "kins_cmd:build_library", "check": "kins_check_cmd:check",
               "compare": "kins_check_cmd:compare", "plot": "kins_check_cmd:plot"}

kins = LazyGroup("kins", lazy=SUBCOMMANDS, short_help="List, evaluate, build and prove kinematics plug-ins.",
                 help="List, evaluate, build and prove kinematics plug-ins.")


def _settings(ini: Path | None) -> tuple[Mapping[str, str], tuple[Path, ...]]:
    """The ``[KINEMATICS]`` section and the ini's folder (where plug-in files are looked for)."""
    from edingcnc_lang.config.machine_config import load_config

    if ini is None:
        return {}, ()
    config = load_config(ini)
    return config.kinematics_settings, (config.folder,) if config.folder else ()


def _switched_on(name: str, ini: str | None) -> Kinematics:
    from edingcnc_lang.errors import PluginError
    from edingcnc_lang.kinematics import abi
    from edingcnc_lang.kinematics.loader import load_kinematics

    settings, search_dirs = _settings(Path(ini) if ini else None)
    kins = guarded(load_kinematics(name, settings, search_dirs))
    rc = kins.control(abi.ON, [0.0] * abi.CONTROL_DATA_LEN)
    if rc != 0:
        raise PluginError(f"kinematics plug-in {name!r}: switching it ON failed (control returned {rc})")
    return kins


def _pose(values: Sequence[float], names: Sequence[str]) -> Pose:
    if not 3 <= len(values) <= 6:
        raise usage_error(f"expected 3 to 6 numbers ({' '.join(n.upper() for n in names)}), got {len(values)}")
    import math

    for name, value in zip(names, values):
        if not math.isfinite(value):
            raise usage_error(f"{name.upper()} must be a finite number, not {value}")
    x, y, z, a, b, c = (*values, *[0.0] * (6 - len(values)))
    return (x, y, z, a, b, c)


def _print_pose(values: Pose, names: Sequence[str], plugin: str, call: str) -> None:
    """JSON with repr-exact floats (json uses float.__repr__); NaN or infinity (from finite input, which
    ``_pose`` ensures) is the plug-in's error."""
    import json
    import math

    from edingcnc_lang.errors import PluginError

    if not all(math.isfinite(v) for v in values):
        shown = " ".join(f"{n}={v}" for n, v in zip(names, values))
        raise PluginError(f"kinematics plug-in {plugin!r}: {call} returned a value that is not a finite number "
                          f"({shown}); a plug-in must raise KinematicsDomainError for a pose out of reach")
    print(json.dumps(dict(zip(names, values))))


@click.command("list", cls=Command, short_help="Registered kinematics: name, type and version (tab separated).")
@json_option("Print a JSON array instead of a table.")
@ini_option("Also list the plug-in this cnc.ini names (kinematicsDLLName), loaded with its settings.")
def list_kinematics(as_json: bool, ini: str | None) -> int:
    """Registered kinematics: name, type and version (tab separated); with --ini also the ini's plug-in."""
    import json

    from edingcnc_lang.kinematics.loader import available_kinematics

    rows = available_kinematics()
    if ini:
        rows.append(_ini_plugin(Path(ini)))
    if as_json:
        print(json.dumps([{"name": n, "type": t, "version": v} for n, t, v in rows]))
    else:
        for name, kin_type, version in rows:
            print(f"{name}\t{kin_type}\t{version}")
    return EXIT_OK


def _ini_plugin(ini: Path) -> tuple[str, int, str]:
    """(name as the ini writes it, type, version) of the ini's plug-in; a broken one says why, as in the list."""
    from edingcnc_lang.errors import PluginError
    from edingcnc_lang.config.ini import read_ini
    from edingcnc_lang.kinematics.loader import load_kinematics

    name = read_ini(ini).get_str("KINEMATICS", "kinematicsDLLName", "").strip()
    if not name:
        raise usage_error(f"{ini} names no kinematics plug-in ([KINEMATICS] kinematicsDLLName)")
    settings, search_dirs = _settings(ini)
    try:
        kins = load_kinematics(name, settings, search_dirs)
    except PluginError as err:
        return name, 0, f"failed to load: {err.message}"
    return name, kins.kin_type(), kins.version()


def _conversion(name: str, summary: str, values: str) -> click.Command:
    """``inverse`` or ``forward``: NAME, --ini and 3 to 6 numbers."""
    def decorate(func: click.decorators.FC) -> click.Command:
        func = click.argument("values", metavar=values, nargs=-1, required=True, type=FLOAT, cls=Argument)(func)
        func = ini_option("cnc.ini whose [KINEMATICS] section configures the plug-in.")(func)
        func = click.argument("name", metavar="NAME", type=KINEMATICS_NAME)(func)
        return click.command(name, cls=Command, short_help=summary,
                             help=f"{summary}\n\nNAME is a registered name (see list) or the path of a .so or .py "
                                  "plug-in.")(func)
    return decorate  # type: ignore[return-value]


@_conversion("inverse", "Joints for a Cartesian position (missing A B C are 0).", "X Y Z [A B C]")
def inverse(name: str, ini: str | None, values: tuple[float, ...]) -> int:
    from edingcnc_lang.kinematics.base import AXES, JOINTS

    pos = _pose(values, AXES)
    isolated = _in_child("inverse", name, ini, pos)
    if isolated is not None:
        return isolated
    _print_pose(_switched_on(name, ini).inverse(pos), JOINTS, name, "inverse")
    return EXIT_OK


@_conversion("forward", "Cartesian position for joint positions (missing JA JB JC are 0).", "JX JY JZ [JA JB JC]")
def forward(name: str, ini: str | None, values: tuple[float, ...]) -> int:
    from edingcnc_lang.kinematics.base import AXES, JOINTS

    joints = _pose(values, JOINTS)
    isolated = _in_child("forward", name, ini, joints)
    if isolated is not None:
        return isolated
    _print_pose(_switched_on(name, ini).forward(joints), AXES, name, "forward")
    return EXIT_OK


def _in_child(command: str, name: str, ini: str | None, values: Pose) -> int | None:
    """inverse/forward of a compiled plug-in, in a child process (see in_child_if_compiled)."""
    return in_child_if_compiled(name, ini, ["kins", command, *(["--ini", ini] if ini else []), "--", name,
                                            *(repr(v) for v in values)])


def in_child_if_compiled(name: str, ini: str | None, argv: list[str]) -> int | None:
    """Run ``ecnc ARGV`` in a child process when ``name`` is a compiled plug-in, so that a crash in
    the library is an error naming the call and the pose (exit 70) instead of killing ecnc; its
    output is passed on and its status returned.  None: not compiled, or already the child."""
    import sys

    from edingcnc_lang.kinematics.loader import is_compiled_plugin
    from edingcnc_lang.kinematics.workbench.isolate import GUARD_VARIABLE, run_command_isolated

    if GUARD_VARIABLE in os.environ or not is_compiled_plugin(name, _settings(Path(ini) if ini else None)[1]):
        return None  # already the child, or a Python plug-in
    status, out, err = run_command_isolated(argv, name)
    sys.stdout.write(out)
    sys.stderr.write(err)
    return status


def guarded(kins: Kinematics) -> Kinematics:
    """In the child of in_child_if_compiled, a compiled plug-in's calls are recorded before they are made."""
    from edingcnc_lang.kinematics.workbench.isolate import GUARD_VARIABLE, guard_calls

    guard = os.environ.get(GUARD_VARIABLE)
    if guard and hasattr(kins, "_fn"):
        guard_calls(kins, guard)
    return kins


@click.command("build", cls=Command,
               short_help="Compile a C plug-in against edingcnc_kins.h; prints the library's path.")
@click.argument("source", metavar="SOURCE", type=EXISTING_FILE)
@click.option("-o", "--output", metavar="FILE", type=OUTPUT_FILE, help="Library to write (default: SOURCE with .so).")
@click.option("--cc", default=lambda: os.environ.get("CC", "cc"), show_default="$CC or cc", help="C compiler to run.")
def build_library(source: str, output: str | None, cc: str) -> int:
    """Compile a C plug-in against edingcnc_kins.h; prints the library's path."""
    from edingcnc_lang.kinematics.build import build_plugin
    from edingcnc_lang.outputs import check_outputs

    check_outputs({"-o": Path(output) if output else None}, [Path(source)])  # the compiler would destroy it
    print(build_plugin(Path(source), Path(output) if output else None, cc))
    return EXIT_OK
