#!/usr/bin/env python3
"""Regenerate tests/golden/linuxcnc/expected/*.json by running LinuxCNC's ``rs274 -g``.

Each program in tests/golden/linuxcnc/programs is copied into a fresh temporary directory with
every line prefixed by ``N<line number>`` (rs274 reports a block's N word, not its source line)
and assignments to machine-unit parameters rescaled from mm to rs274's inches, next to a zeroed
parameter file and the tool table of tests/golden/linuxcnc/tools.ini (diameters in mm there,
written in inches for rs274, which has no ini), so no state leaks between programs.
The canonical commands are folded into machine-coordinate moves in millimetres. The committed
JSON is what the test suite uses; LinuxCNC is only needed to regenerate it.
"""

from __future__ import annotations

import argparse
import json
import re
import shutil
import subprocess
import sys
import tempfile
from dataclasses import dataclass, field, replace
from pathlib import Path
from typing import Any, Callable

ROOT = Path(__file__).resolve().parent.parent
PROGRAMS = ROOT / "tests" / "golden" / "linuxcnc" / "programs"
EXPECTED = ROOT / "tests" / "golden" / "linuxcnc" / "expected"
TOOLS = ROOT / "tests" / "golden" / "linuxcnc" / "tools.ini"
TOOL_SECTION = re.compile(r"^\s*\[TOOL_(\d+)\]\s*$", re.IGNORECASE)
DIAMETER = re.compile(r"^\s*diameter\s*=\s*([-+0-9.eE]+)\s*$", re.IGNORECASE)
MM_PER_INCH = 25.4
DIGITS = 6

Vec6 = tuple[float, float, float, float, float, float]
ZERO6: Vec6 = (0.0, 0.0, 0.0, 0.0, 0.0, 0.0)

# rs274 prints "<count> N<word or .....> NAME(args)"; the count is the canon call's ordinal.
CANON_LINE = re.compile(r"^\s*\d+\s+N(?P<n>\d+|\.+)\s+(?P<name>[A-Z_0-9]+)\((?P<args>.*)\)\s*$")
N_WORD_AT_START = re.compile(r"^\s*/?\s*N\d", re.IGNORECASE)
ASSIGNMENT = re.compile(r"^\s*#(?P<number>\d+)\s*=\s*(?P<value>[^()]+?)\s*$")
PARAMETER = re.compile(r"#\s*(\d+)")
COMMENT = re.compile(r"\([^)]*\)")

UNIT_SCALE = {"CANON_UNITS_MM": 1.0, "CANON_UNITS_INCHES": MM_PER_INCH}
PLANE_NAMES = {"CANON_PLANE_XY": "XY", "CANON_PLANE_XZ": "XZ", "CANON_PLANE_YZ": "YZ"}
# ARC_FEED's (first, second, normal) axes as indices into x, y, z: LinuxCNC's XZ plane is (Z, X).
ARC_AXES = {"XY": (0, 1, 2), "XZ": (2, 0, 1), "YZ": (1, 2, 0)}
# The JSON lists an arc centre in the order of the plane's name.
CENTER_AXES = {"XY": (0, 1), "XZ": (0, 2), "YZ": (1, 2)}
# Canon calls that would make the golden silently wrong if they appeared.
FORBIDDEN = frozenset({"STRAIGHT_PROBE", "RIGID_TAP", "NURBS_FEED", "SPLINE_FEED", "USE_TOOL_LENGTH_OFFSET"})
# Parameters holding X/Y/Z lengths in external (machine) units: G28/G30 positions, G92 offsets and
# the G54..G59.3 offsets. rs274's stand-alone canon hard-codes inches as the external unit, while
# the shared programs mean millimetres, so assignments to these are rescaled (see rs274_source).
UNIT_PARAMETERS = frozenset(
    [*range(5161, 5164), *range(5181, 5184), *range(5211, 5214)]
    + [5221 + 20 * system + axis for system in range(9) for axis in range(3)]
)
# Zeroed persistent parameters: G28/G30 positions, G92 offsets, active system 1, G54..G59.3.
VAR_PARAMETERS = (
    [*range(5161, 5170), *range(5181, 5190), *range(5210, 5220)]
    + [5221 + 20 * system + axis for system in range(9) for axis in range(10)]
)


class GoldenError(Exception):
    """A program or rs274's answer that cannot become a trustworthy golden."""


@dataclass(frozen=True)
class Canon:
    """One canonical machine command with the source line that produced it."""

    line: int | None
    name: str
    args: tuple[str, ...]


@dataclass(frozen=True)
class Frame:
    """The canon layer's coordinate state: units, plane and offsets (offsets kept in mm)."""

    scale: float = 1.0
    plane: str = "XY"
    g5x: Vec6 = ZERO6
    g92: Vec6 = ZERO6

    def to_mm(self, values: tuple[float, ...]) -> Vec6:
        """Scale the three linear components of a program-unit vector to millimetres."""
        return tuple(v * self.scale if i < 3 else v for i, v in enumerate(values))  # type: ignore[return-value]

    def to_machine(self, values: tuple[float, ...]) -> Vec6:
        """Program coordinates (current units) to machine coordinates in mm."""
        return tuple(v + o + g for v, o, g in zip(self.to_mm(values), self.g5x, self.g92))  # type: ignore[return-value]


@dataclass
class Golden:
    """The moves and dwells gathered while replaying one program's canon."""

    moves: list[dict[str, Any]] = field(default_factory=list)
    dwells: list[float] = field(default_factory=list)
    position: Vec6 = ZERO6


def clean(value: float) -> float:
    """Round to the precision rs274 gives (4 decimals) plus headroom, without -0.0."""
    return round(value, DIGITS) + 0.0


def numbers(canon: Canon, count: int) -> tuple[float, ...]:
    """The canon call's numeric arguments, checking how many there are."""
    if len(canon.args) != count:
        raise GoldenError(f"{canon.name} has {len(canon.args)} arguments, expected {count}")
    return tuple(float(a) for a in canon.args)


def require_line(canon: Canon) -> int:
    """Motion must come from a numbered block; anything else means the mapping broke."""
    if canon.line is None:
        raise GoldenError(f"{canon.name} has no source line")
    return canon.line


def on_units(frame: Frame, canon: Canon, golden: Golden) -> Frame:
    return replace(frame, scale=UNIT_SCALE[canon.args[0]])


def on_plane(frame: Frame, canon: Canon, golden: Golden) -> Frame:
    if canon.args[0] not in PLANE_NAMES:
        raise GoldenError(f"unsupported plane {canon.args[0]}")
    return replace(frame, plane=PLANE_NAMES[canon.args[0]])


def on_g5x(frame: Frame, canon: Canon, golden: Golden) -> Frame:
    return replace(frame, g5x=frame.to_mm(numbers(canon, 7)[1:]))


def on_g92(frame: Frame, canon: Canon, golden: Golden) -> Frame:
    return replace(frame, g92=frame.to_mm(numbers(canon, 6)))


def on_rotation(frame: Frame, canon: Canon, golden: Golden) -> Frame:
    if numbers(canon, 1) != (0.0,):
        raise GoldenError("XY rotation (G10 L2 R) is outside the shared subset")
    return frame


def on_dwell(frame: Frame, canon: Canon, golden: Golden) -> Frame:
    golden.dwells.append(clean(numbers(canon, 1)[0]))
    return frame


def add_move(golden: Golden, line: int, kind: str, end: Vec6, extra: dict[str, Any]) -> None:
    """Record a move unless it is a straight move that goes nowhere (see docs/goldens.md)."""
    rounded = tuple(clean(v) for v in end)
    if kind != "arc" and rounded == golden.position:
        return
    golden.moves.append({"line": line, "kind": kind, "end": list(rounded), **extra})
    golden.position = rounded  # type: ignore[assignment]


def on_straight(kind: str) -> Callable[[Frame, Canon, Golden], Frame]:
    def handler(frame: Frame, canon: Canon, golden: Golden) -> Frame:
        add_move(golden, require_line(canon), kind, frame.to_machine(numbers(canon, 6)), {})
        return frame

    return handler


def on_arc(frame: Frame, canon: Canon, golden: Golden) -> Frame:
    first_end, second_end, first_c, second_c, turn, normal_end, a, b, c = numbers(canon, 9)
    if abs(turn) != 1:
        raise GoldenError("multi-turn arcs (P word) are outside the shared subset")
    first, second, normal = ARC_AXES[frame.plane]
    end = [0.0, 0.0, 0.0, a, b, c]
    centre = [0.0, 0.0, 0.0, 0.0, 0.0, 0.0]
    end[first], end[second], end[normal] = first_end, second_end, normal_end
    centre[first], centre[second] = first_c, second_c
    machine_centre = frame.to_machine(tuple(centre))
    extra = {
        "center": [clean(machine_centre[i]) for i in CENTER_AXES[frame.plane]],
        "plane": frame.plane,
        "turn": int(turn),
    }
    add_move(golden, require_line(canon), "arc", frame.to_machine(tuple(end)), extra)
    return frame


HANDLERS: dict[str, Callable[[Frame, Canon, Golden], Frame]] = {
    "USE_LENGTH_UNITS": on_units,
    "SELECT_PLANE": on_plane,
    "SET_G5X_OFFSET": on_g5x,
    "SET_G92_OFFSET": on_g92,
    "SET_XY_ROTATION": on_rotation,
    "DWELL": on_dwell,
    "STRAIGHT_TRAVERSE": on_straight("rapid"),
    "STRAIGHT_FEED": on_straight("linear"),
    "ARC_FEED": on_arc,
}


def parse_canon(output: str) -> list[Canon]:
    """Canon calls from rs274's stdout; other lines (banners, messages) are skipped."""
    calls = []
    for text in output.splitlines():
        match = CANON_LINE.match(text)
        if match:
            n = match["n"]
            args = tuple(a.strip() for a in match["args"].split(",")) if match["args"] else ()
            calls.append(Canon(None if n.startswith(".") else int(n), match["name"], args))
    return calls


def fold(calls: list[Canon]) -> Golden:
    """Replay the canon calls, tracking units, plane and offsets as LinuxCNC's canon layer does."""
    frame, golden = Frame(), Golden()
    for canon in calls:
        if canon.name in FORBIDDEN:
            raise GoldenError(f"{canon.name} is outside the shared subset")
        handler = HANDLERS.get(canon.name)
        if handler:
            frame = handler(frame, canon, golden)
    return golden


def rs274_line(index: int, text: str) -> str:
    """One program line as rs274 gets it: numbered, with machine-unit assignments in inches."""
    if text.strip().startswith("%"):
        return text
    if N_WORD_AT_START.match(text):
        raise GoldenError(f"line {index} already has an N word; the line mapping needs N-free programs")
    assignment = ASSIGNMENT.match(text)
    if assignment and int(assignment["number"]) in UNIT_PARAMETERS:
        return f"N{index} #{assignment['number']} = [[{assignment['value']}] / {MM_PER_INCH}]"
    if any(int(number) in UNIT_PARAMETERS for number in PARAMETER.findall(COMMENT.sub("", text))):
        raise GoldenError(
            f"line {index} uses a machine-unit parameter outside a plain assignment line; "
            "rs274 would see it in inches"
        )
    return f"N{index} {text}"


def rs274_source(source: str) -> str:
    """The program rewritten so rs274's N column is the source line and parameters mean mm."""
    return "".join(rs274_line(i, text) + "\n" for i, text in enumerate(source.splitlines(), start=1))


def var_file() -> str:
    """A parameter file with zero offsets and G54 active (rs274 insists on ascending order)."""
    values = {number: 0.0 for number in VAR_PARAMETERS} | {5220: 1.0}
    return "".join(f"{number}\t{value:.6f}\n" for number, value in sorted(values.items()))


def tool_table() -> str:
    """rs274's tool table (``T<n> P<n> D<inches>``) from the [TOOL_n] diameters (mm) of tools.ini."""
    diameters: dict[int, float] = {}
    tool = None
    for text in TOOLS.read_text().splitlines():
        section, diameter = TOOL_SECTION.match(text), DIAMETER.match(text)
        if section:
            tool = int(section[1])
        elif diameter and tool is not None:
            diameters[tool] = float(diameter[1])
    return "".join(f"T{n} P{n} D{d / MM_PER_INCH:.12f} ;\n" for n, d in sorted(diameters.items()))


@dataclass(frozen=True)
class GoldenSet:
    """A folder of programs and how its goldens are made (the lathe script defines another set)."""

    programs: Path
    expected: Path
    source: Callable[[Path], str]          # the numbered text rs274 gets
    fold: Callable[[list[Canon]], Golden]  # canon calls -> moves
    document: Callable[[Path, Golden, str], dict[str, Any]]  # the expected file's content
    tool_table: str = ""


def run_rs274(rs274: str, program: Path, goldens: GoldenSet | None = None) -> subprocess.CompletedProcess[str]:
    """Run rs274 on the numbered copy of ``program`` in a throw-away directory."""
    goldens = goldens or LINUXCNC
    with tempfile.TemporaryDirectory(prefix="rs274-golden-") as tmp:
        work = Path(tmp)
        (work / "program.ngc").write_text(goldens.source(program))
        (work / "golden.var").write_text(var_file())
        (work / "golden.tbl").write_text(goldens.tool_table)
        result = subprocess.run(
            [rs274, "-g", "-v", "golden.var", "-t", "golden.tbl", "program.ngc"],
            cwd=work,
            capture_output=True,
            text=True,
            timeout=60,
            check=False,
        )
    return result


def canon_output(rs274: str, program: Path, goldens: GoldenSet | None = None) -> str:
    """rs274's stdout for ``program``; any interpreter error or message fails the golden."""
    result = run_rs274(rs274, program, goldens)
    stray = [t for t in result.stdout.splitlines() if t.strip() and not CANON_LINE.match(t)]
    if result.returncode != 0 or stray:
        raise GoldenError(f"rs274 failed (exit {result.returncode}): {' | '.join(stray) or result.stderr.strip()}")
    return result.stdout


def linuxcnc_version() -> str:
    """The installed package version, for the ``source`` field."""
    query = ["dpkg-query", "-W", "-f=${Version}", "linuxcnc-uspace"]
    if shutil.which("dpkg-query"):
        result = subprocess.run(query, capture_output=True, text=True, check=False)
        if result.returncode == 0 and result.stdout:
            return result.stdout
    return "unknown version"


def document(program: Path, golden: Golden, version: str) -> dict[str, Any]:
    """What an expected file holds."""
    return {
        "program": program.name,
        "source": f"rs274 -g (LinuxCNC {version})",
        "moves": golden.moves,
        "dwells": golden.dwells,
    }


def expected_json(data: dict[str, Any]) -> str:
    """The golden file's exact text: sorted keys, indent 1, trailing newline."""
    return json.dumps(data, indent=1, sort_keys=True) + "\n"


LINUXCNC = GoldenSet(PROGRAMS, EXPECTED, lambda program: rs274_source(program.read_text()), fold, document,
                     tool_table())


def find_rs274() -> str:
    """Path of rs274, or exit with a message that names the package to install."""
    rs274 = shutil.which("rs274")
    if rs274 is None:
        sys.exit("rs274 not found: install Debian's linuxcnc-uspace (apt-get install linuxcnc-uspace)")
    return rs274


def program_path(name: str, goldens: GoldenSet) -> Path:
    """A program by name, with or without the .ngc suffix."""
    path = goldens.programs / (name if name.endswith(".ngc") else f"{name}.ngc")
    if not path.is_file():
        sys.exit(f"no such program: {path}")
    return path


def regenerate(rs274: str, programs: list[Path], goldens: GoldenSet | None = None) -> int:
    """Write every expected file, print a summary, and return the number of failures."""
    goldens = goldens or LINUXCNC
    version = linuxcnc_version()
    goldens.expected.mkdir(parents=True, exist_ok=True)
    failures = changed = moves = arcs = synced = 0
    for program in programs:
        try:
            golden = goldens.fold(parse_canon(canon_output(rs274, program, goldens)))
            if not golden.moves:
                raise GoldenError("no moves")
        except GoldenError as error:
            print(f"FAILED {program.name}: {error}", file=sys.stderr)
            failures += 1
            continue
        target = goldens.expected / f"{program.stem}.json"
        text = expected_json(goldens.document(program, golden, version))
        if not target.exists() or target.read_text() != text:
            target.write_text(text)
            changed += 1
        moves += len(golden.moves)
        arcs += sum(move["kind"] == "arc" for move in golden.moves)
        synced += sum("sync" in move for move in golden.moves)
    stale = sorted({p.stem for p in goldens.expected.glob("*.json")} - {p.stem for p in goldens.programs.glob("*.ngc")})
    for name in stale:
        (goldens.expected / f"{name}.json").unlink()
    print(
        f"{len(programs) - failures}/{len(programs)} programs ok ({moves} moves, {arcs} arcs, {synced} synchronised); "
        f"{changed} expected files written, {len(stale)} stale removed; LinuxCNC {version}"
    )
    return failures


def main(goldens: GoldenSet | None = None, description: str = __doc__.splitlines()[0]) -> None:
    """Regenerate all goldens (or the named ones), or show one program's raw rs274 output."""
    goldens = goldens or LINUXCNC
    parser = argparse.ArgumentParser(description=description)
    parser.add_argument("names", nargs="*", help="programs to regenerate (default: all)")
    parser.add_argument("--raw", metavar="NAME", help="print rs274's full output for one program and exit")
    args = parser.parse_args()
    rs274 = find_rs274()
    if args.raw:
        result = run_rs274(rs274, program_path(args.raw, goldens), goldens)
        print(result.stdout, end="")
        print(result.stderr, end="", file=sys.stderr)
        sys.exit(result.returncode)
    programs = [program_path(n, goldens) for n in args.names] or sorted(goldens.programs.glob("*.ngc"))
    sys.exit(1 if regenerate(rs274, programs, goldens) else 0)


if __name__ == "__main__":
    main()
