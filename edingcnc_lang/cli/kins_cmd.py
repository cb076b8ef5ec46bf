"""``ecnc kins``: list, try out and build kinematics plug-ins from the shell.

``inverse``/``forward`` first switch the kinematics ON at the machine origin (control ID 4 with
dData all zero), as ``KIN ON`` would at X0 Y0 Z0: rotatekins, for one, only transforms while on.
"""
from __future__ import annotations

import argparse
import os
from collections.abc import Mapping, Sequence
from pathlib import Path
from typing import TYPE_CHECKING

from ..errors import EXIT_OK
from .common import UsageError, add_command, existing_file, output_file

if TYPE_CHECKING:
    from ..kinematics.base import Kinematics, Pose
    from .common import Subcommands


def _settings(ini: Path | None) -> tuple[Mapping[str, str], tuple[Path, ...]]:
    """The ``[KINEMATICS]`` section and the ini's folder (where plug-in files are looked for)."""
    from ..ini import read_ini

    if ini is None:
        return {}, ()
    return read_ini(ini).section("KINEMATICS"), (ini.parent,)


def _switched_on(name: str, ini: str | None) -> Kinematics:
    from ..errors import PluginError
    from ..kinematics import abi
    from ..kinematics.loader import load_kinematics

    settings, search_dirs = _settings(Path(ini) if ini else None)
    kins = load_kinematics(name, settings, search_dirs)
    rc = kins.control(abi.ON, [0.0] * abi.CONTROL_DATA_LEN)
    if rc != 0:
        raise PluginError(f"kinematics plug-in {name!r}: switching it ON failed (control returned {rc})")
    return kins


def _pose(values: Sequence[float], names: Sequence[str]) -> Pose:
    if not 3 <= len(values) <= 6:
        raise UsageError(f"expected 3 to 6 numbers ({' '.join(n.upper() for n in names)}), got {len(values)}")
    x, y, z, a, b, c = (*values, *[0.0] * (6 - len(values)))
    return (x, y, z, a, b, c)


def _print_pose(values: Pose, names: Sequence[str]) -> None:
    """JSON with repr-exact floats (json uses float.__repr__)."""
    import json

    print(json.dumps(dict(zip(names, values))))


def add_parser(commands: Subcommands) -> None:
    kins = add_command(commands, "kins", None, "List, evaluate and build kinematics plug-ins.", intermixed=False)
    subcommands = kins.add_subparsers(title="commands", metavar="COMMAND")

    listing = add_command(subcommands, "list", list_kinematics,
                          "Registered kinematics: name, type and version (tab separated).")
    listing.add_argument("--json", dest="as_json", action="store_true", help="Print a JSON array instead of a table.")

    for name, handler, summary, values in (
            ("inverse", inverse, "Joints for a Cartesian position (missing A B C are 0).", "X Y Z [A B C]"),
            ("forward", forward, "Cartesian position for joint positions (missing JA JB JC are 0).",
             "JX JY JZ [JA JB JC]")):
        # argparse would write the values as "X Y Z [A B C] [X Y Z [A B C] ...]"
        parser = add_command(subcommands, name, handler, summary,
                             usage=f"%(prog)s [-h] [--ini FILE] NAME {values}")
        parser.add_argument("name", metavar="NAME",
                            help="A registered name (see list) or the path of a .so or .py plug-in.")
        parser.add_argument("--ini", metavar="FILE", type=existing_file,
                            help="cnc.ini whose [KINEMATICS] section configures the plug-in.")
        parser.add_argument("values", metavar=values, nargs="+", type=float, help="3 to 6 numbers.")

    build = add_command(subcommands, "build", build_library,
                        "Compile a C plug-in against edingcnc_kins.h; prints the library's path.")
    build.add_argument("source", metavar="SOURCE", type=existing_file)
    build.add_argument("-o", "--output", metavar="FILE", type=output_file,
                       help="Library to write (default: SOURCE with .so).")
    build.add_argument("--cc", default=os.environ.get("CC", "cc"), help="C compiler to run (default: $CC or cc).")


def list_kinematics(args: argparse.Namespace) -> int:
    import json

    from ..kinematics.loader import available_kinematics

    rows = available_kinematics()
    if args.as_json:
        print(json.dumps([{"name": n, "type": t, "version": v} for n, t, v in rows]))
    else:
        for name, kin_type, version in rows:
            print(f"{name}\t{kin_type}\t{version}")
    return EXIT_OK


def inverse(args: argparse.Namespace) -> int:
    from ..kinematics.base import AXES, JOINTS

    pos = _pose(args.values, AXES)
    _print_pose(_switched_on(args.name, args.ini).inverse(pos), JOINTS)
    return EXIT_OK


def forward(args: argparse.Namespace) -> int:
    from ..kinematics.base import AXES, JOINTS

    joints = _pose(args.values, JOINTS)
    _print_pose(_switched_on(args.name, args.ini).forward(joints), AXES)
    return EXIT_OK


def build_library(args: argparse.Namespace) -> int:
    from ..kinematics.build import build_plugin

    print(build_plugin(Path(args.source), Path(args.output) if args.output else None, args.cc))
    return EXIT_OK
