"""Differential test: lathe moves against LinuxCNC's interpreter (goldens recorded by
scripts/regen_lathe_goldens.py, see docs/goldens.md "Lathe goldens").

``dia_*`` programs run on a lathe with ``diameterProgramming = 1`` (LinuxCNC was told G7), the
others in radius mode.  End points, arc centres, which moves are spindle-synchronised and their
pitch, feed per revolution, and the spindle settings (CSS or rpm) are compared.
"""
from __future__ import annotations

import json
import math
from collections import defaultdict
from pathlib import Path

import pytest

from edingcnc_lang.canon import Event, Move, Pose
from edingcnc_lang.runner import RunOptions, run_file

GOLDENS = Path(__file__).resolve().parent.parent / "golden" / "lathe"
PROGRAMS = sorted((GOLDENS / "programs").glob("*.ngc"))
TOLERANCE = 0.002


def _run(program: Path) -> tuple[list[Move], list[Event]]:
    moves: list[Move] = []
    events: list[Event] = []

    def keep(move: Move, _joints: Pose) -> None:
        if math.dist(move.start, move.end) > 1e-9 or move.arc is not None:
            moves.append(move)

    ini = GOLDENS / ("lathe_diameter.ini" if program.stem.startswith("dia_") else "lathe_radius.ini")
    run_file(program, RunOptions(ini=ini, on_move=keep, on_event=events.append))
    return moves, events


def _close(a: list[float] | tuple[float, ...], b: list[float] | tuple[float, ...]) -> bool:
    return len(a) == len(b) and all(abs(x - y) <= TOLERANCE for x, y in zip(a, b))


@pytest.mark.parametrize("program", PROGRAMS, ids=lambda p: p.stem)
def test_lathe_moves_match_linuxcnc(program: Path) -> None:
    expected = json.loads((GOLDENS / "expected" / f"{program.stem}.json").read_text())
    source = program.read_text().splitlines()
    moves, events = _run(program)
    ours: dict[int, list[Move]] = defaultdict(list)
    for move in moves:
        ours[move.line].append(move)
    theirs: dict[int, list[dict]] = defaultdict(list)
    for ref in expected["moves"]:
        theirs[ref["line"]].append(ref)
    assert sorted(ours) == sorted(theirs), "moves come from different lines"
    for line, want in theirs.items():
        got = ours[line]
        where = f"{program.name}:{line}: {source[line - 1].strip()}"
        assert len(got) == len(want), f"{where}: {len(got)} moves, LinuxCNC made {len(want)}"
        for mine, ref in zip(got, want):
            assert mine.kind == ref["kind"], where
            assert _close(mine.end, ref["end"]), f"{where}: end {mine.end} != {ref['end']}"
            assert mine.sync == pytest.approx(ref.get("sync", 0.0), abs=1e-5), f"{where}: pitch"
            if ref.get("per_rev") and not mine.css:
                assert mine.feed == pytest.approx(ref["feed"] * mine.spindle), f"{where}: feed per rev"
            elif "feed" in ref and not ref.get("per_rev"):
                assert mine.feed == pytest.approx(ref["feed"]), f"{where}: feed"
            if ref["kind"] == "arc":
                assert mine.arc is not None and mine.arc.plane == ref["plane"] and mine.arc.turn == ref["turn"]
                assert _close(mine.arc.center, ref["center"]), f"{where}: centre"
    settings = [e for e in events if e.kind == "spindle_speed"]
    for ref in expected["spindle"]:
        at_line = [e for e in settings if e.line == ref["line"]]
        assert at_line, f"{program.name}:{ref['line']}: no spindle speed setting"
        data = at_line[-1].data
        assert (data["mode"] == "css") == ref["css"]
        assert data["speed"] == pytest.approx(ref["speed"])
        if ref["css"]:
            assert data["max_rpm"] == pytest.approx(ref["max"])
