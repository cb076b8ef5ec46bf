#!/usr/bin/env python3
"""Regenerate tests/golden/lathe/expected/*.json by running LinuxCNC's ``rs274 -g`` on lathe programs.

The same machinery as regen_linuxcnc_goldens.py (numbered copy, zeroed parameters, canon folded
into machine-coordinate moves in mm), plus what turning adds:

- every program runs in the XZ plane: ``G18`` is put in front of line 1, as our lathe starts in
  G18; programs named ``dia_*`` also get ``G7``, LinuxCNC's diameter mode, because our side runs
  them with ``diameterProgramming = 1`` (docs/goldens.md, "Lathe goldens");
- spindle-synchronised moves (G33, the cuts of G76) carry ``sync``, the path length per spindle
  revolution in mm; ``RIGID_TAP`` (G33.1) becomes a synchronised move in and one back out;
- feed moves carry ``feed`` (mm/min, or mm per revolution with ``per_rev``);
- ``spindle`` lists every speed setting: constant surface speed (``css``, S and the D maximum)
  or a fixed rpm;
- the tool table holds tool 1 with X 0.1 in and Z 0.2 in for ``G43 H1``;
- a line ending in ``(linuxcnc: ...)`` reaches rs274 as that comment's text: the G76 lines are
  written as EdingCNC reads them (I the crest diameter, J and K radial) and LinuxCNC gets the same
  thread in its own words (I an offset from the drive line, halved with J and K in G7).

Run with the rs274 lock held: ``flock /tmp/rs274.lock python3 scripts/regen_lathe_goldens.py``.
"""

from __future__ import annotations

import importlib.util
import re
import sys
from dataclasses import dataclass, field, replace
from pathlib import Path
from typing import Any, Callable

HERE = Path(__file__).resolve().parent
_SPEC = importlib.util.spec_from_file_location("regen_linuxcnc_goldens", HERE / "regen_linuxcnc_goldens.py")
assert _SPEC and _SPEC.loader
base = importlib.util.module_from_spec(_SPEC)
sys.modules[_SPEC.name] = base
_SPEC.loader.exec_module(base)

ROOT = HERE.parent
GOLDENS = ROOT / "tests" / "golden" / "lathe"
PROGRAMS = GOLDENS / "programs"
EXPECTED = GOLDENS / "expected"
TOOL_TABLE = "T1 P1 X0.1 Z0.2 ;lathe tool for G43 H1\n"
FORBIDDEN = base.FORBIDDEN - {"RIGID_TAP", "USE_TOOL_LENGTH_OFFSET"}


@dataclass(frozen=True)
class LatheFrame(base.Frame):
    """The canon frame plus the lathe state: tool offset, synchronisation, feed and spindle modes."""

    tool: base.Vec6 = base.ZERO6
    sync: float = 0.0
    per_rev: bool = False
    feed: float = 0.0
    css_max: float = 0.0

    def to_machine(self, values: tuple[float, ...]) -> base.Vec6:
        return tuple(v + t for v, t in zip(super().to_machine(values), self.tool))  # type: ignore[return-value]


@dataclass
class LatheGolden(base.Golden):
    spindle: list[dict[str, Any]] = field(default_factory=list)


def _feed_extra(frame: LatheFrame) -> dict[str, Any]:
    if frame.sync:
        return {"sync": base.clean(frame.sync * frame.scale)}
    return {"feed": base.clean(frame.feed * frame.scale), **({"per_rev": True} if frame.per_rev else {})}


def on_feed(frame: LatheFrame, canon: base.Canon, golden: LatheGolden) -> LatheFrame:
    end = frame.to_machine(base.numbers(canon, 6))
    base.add_move(golden, base.require_line(canon), "linear", end, _feed_extra(frame))
    return frame


def on_arc(frame: LatheFrame, canon: base.Canon, golden: LatheGolden) -> LatheFrame:
    count = len(golden.moves)
    base.on_arc(frame, canon, golden)
    golden.moves[count].update(_feed_extra(frame))
    return frame


def on_rigid_tap(frame: LatheFrame, canon: base.Canon, golden: LatheGolden) -> LatheFrame:
    line = base.require_line(canon)
    x, y, z = base.numbers(canon, 3)
    start = golden.position
    bottom = frame.to_machine((x, y, z, *start[3:]))
    extra = {"sync": base.clean(frame.sync * frame.scale)}
    base.add_move(golden, line, "linear", bottom, extra)
    base.add_move(golden, line, "linear", start, extra)
    return frame


def on_tool_offset(frame: LatheFrame, canon: base.Canon, golden: LatheGolden) -> LatheFrame:
    x, y, z = (float(v) for v in canon.args[0].split())
    return replace(frame, tool=(x, y, z, 0.0, 0.0, 0.0))  # USE_TOOL_LENGTH_OFFSET is in mm


def on_sync(frame: LatheFrame, canon: base.Canon, golden: LatheGolden) -> LatheFrame:
    return replace(frame, sync=float(canon.args[0]))


def on_sync_stop(frame: LatheFrame, canon: base.Canon, golden: LatheGolden) -> LatheFrame:
    return replace(frame, sync=0.0)


def on_feed_mode(frame: LatheFrame, canon: base.Canon, golden: LatheGolden) -> LatheFrame:
    return replace(frame, per_rev=canon.args[1] == "1")


def on_feed_rate(frame: LatheFrame, canon: base.Canon, golden: LatheGolden) -> LatheFrame:
    return replace(frame, feed=float(canon.args[0]))


def on_spindle_mode(frame: LatheFrame, canon: base.Canon, golden: LatheGolden) -> LatheFrame:
    return replace(frame, css_max=float(canon.args[0].split()[1]))


def on_spindle_speed(frame: LatheFrame, canon: base.Canon, golden: LatheGolden) -> LatheFrame:
    if canon.line is not None:
        speed = float(canon.args[1])
        golden.spindle.append({"line": canon.line, "css": frame.css_max > 0, "speed": base.clean(speed),
                               **({"max": base.clean(frame.css_max)} if frame.css_max > 0 else {})})
    return frame


HANDLERS: dict[str, Callable[[Any, base.Canon, Any], Any]] = {
    **base.HANDLERS,
    "STRAIGHT_FEED": on_feed,
    "ARC_FEED": on_arc,
    "RIGID_TAP": on_rigid_tap,
    "USE_TOOL_LENGTH_OFFSET": on_tool_offset,
    "START_SPEED_FEED_SYNC": on_sync,
    "STOP_SPEED_FEED_SYNCH": on_sync_stop,
    "SET_FEED_MODE": on_feed_mode,
    "SET_FEED_RATE": on_feed_rate,
    "SET_SPINDLE_MODE": on_spindle_mode,
    "SET_SPINDLE_SPEED": on_spindle_speed,
}


def fold(calls: list[base.Canon]) -> LatheGolden:
    frame, golden = LatheFrame(plane="XZ"), LatheGolden()
    for canon in calls:
        if canon.name in FORBIDDEN:
            raise base.GoldenError(f"{canon.name} is outside the shared subset")
        handler = HANDLERS.get(canon.name)
        if handler:
            frame = handler(frame, canon, golden)
    return golden


LINUXCNC_FORM = re.compile(r"^.*\(linuxcnc:\s*(?P<line>[^)]*)\)\s*$", re.M)


def lathe_source(program: Path) -> str:
    """The numbered copy with the lathe set-up our side gets from cnc.ini put on line 1."""
    lines = base.rs274_source(LINUXCNC_FORM.sub(r"\g<line>", program.read_text())).splitlines()
    setup = "G18 G7" if program.stem.startswith("dia_") else "G18"
    number, _, rest = lines[0].partition(" ")
    lines[0] = f"{number} {setup} {rest}"
    return "".join(line + "\n" for line in lines)


def document(program: Path, golden: LatheGolden, version: str) -> dict[str, Any]:
    return {**base.document(program, golden, version), "diameter_mode": program.stem.startswith("dia_"),
            "spindle": golden.spindle}


LATHE = base.GoldenSet(PROGRAMS, EXPECTED, lathe_source, fold, document, TOOL_TABLE)  # type: ignore[arg-type]


if __name__ == "__main__":
    base.main(LATHE, __doc__.splitlines()[0])
