"""Differential test: our moves against LinuxCNC's interpreter on the shared G-code subset.

The expectations were recorded from ``rs274 -g`` by scripts/regen_linuxcnc_goldens.py
(see docs/goldens.md); LinuxCNC is not needed to run this test.  End points and arc
centres are compared in machine coordinates (mm).  Two documented differences:
LinuxCNC leaves zero-length moves out of its goldens, so ours are dropped too, and
G28/G30 split their final move differently (EdingCNC moves Z first or last), so for
those lines the intermediate point and the final position are compared.  Under cutter
compensation rs274 holds each move back until the next line and prints it with that later
line's number, so the compensation goldens (``comp_*``) are compared as one ordered sequence.
"""
from __future__ import annotations

import json
import math
import re
from collections import defaultdict
from pathlib import Path

import pytest

from edingcnc_lang.canon import Move, Pose
from edingcnc_lang.runner import RunOptions, run_file

pytestmark = pytest.mark.slow  # the whole module (pyproject's slow marker)

GOLDENS = Path(__file__).resolve().parent.parent / "golden" / "linuxcnc"
PROGRAMS = sorted((GOLDENS / "programs").glob("*.ngc"))
TOOLS = GOLDENS / "tools.ini"  # the tool table rs274 got (in inches) for the compensation goldens
# the same on a turning machine: compensation in ZX is for turning (manual 3.6.13, p. 27), rs274 allows it anywhere
LATHE_TOOLS = GOLDENS / "tools_lathe.ini"
TOLERANCE = 0.002  # rs274 prints 4 decimals (inch programs convert them to mm)
HOME_LINE = re.compile(r"\bG(28|30)(?![.\d])", re.IGNORECASE)


def _our_moves(program: Path) -> list[Move]:
    moves: list[Move] = []

    def keep(move: Move, _joints: Pose) -> None:
        if math.dist(move.start, move.end) > 1e-9 or move.arc is not None:
            moves.append(move)

    run_file(program, RunOptions(ini=LATHE_TOOLS if program.name.startswith("comp_g18") else TOOLS, on_move=keep))
    return moves


def _by_line(items: list) -> dict[int, list]:
    grouped: dict[int, list] = defaultdict(list)
    for item in items:
        grouped[item["line"] if isinstance(item, dict) else item.line].append(item)
    return grouped


def _close(a: list[float] | tuple[float, ...], b: list[float] | tuple[float, ...]) -> bool:
    return len(a) == len(b) and all(abs(x - y) <= TOLERANCE for x, y in zip(a, b))


def _same_move(mine: Move, ref: dict, where: str) -> None:
    assert mine.kind == ref["kind"], f"{where}: {mine.kind} != {ref['kind']}"
    assert _close(mine.end, ref["end"]), f"{where}: end {mine.end} != {ref['end']}"
    if ref["kind"] == "arc":
        assert mine.arc is not None
        assert mine.arc.plane == ref["plane"], where
        assert mine.arc.turn == ref["turn"], where
        assert _close(mine.arc.center, ref["center"]), f"{where}: centre {mine.arc.center} != {ref['center']}"


@pytest.mark.parametrize("program", PROGRAMS, ids=lambda p: p.stem)
def test_moves_match_linuxcnc(program: Path) -> None:
    expected = json.loads((GOLDENS / "expected" / f"{program.stem}.json").read_text())
    source = program.read_text().splitlines()
    if program.stem.startswith("comp_"):
        moves = _our_moves(program)
        assert len(moves) == len(expected["moves"]), f"{len(moves)} moves, LinuxCNC made {len(expected['moves'])}"
        for index, (mine, ref) in enumerate(zip(moves, expected["moves"])):
            _same_move(mine, ref, f"{program.name}:{mine.line} (move {index + 1}): {source[mine.line - 1].strip()}")
        return
    ours = _by_line(_our_moves(program))
    theirs = _by_line(expected["moves"])
    assert sorted(ours) == sorted(theirs), "moves come from different lines"
    for line, want in theirs.items():
        got = ours[line]
        where = f"{program.name}:{line}: {source[line - 1].strip()}"
        if HOME_LINE.search(source[line - 1]):
            assert _close(got[-1].end, want[-1]["end"]), where
            if len(want) > 1:
                assert _close(got[0].end, want[0]["end"]), where
            continue
        assert len(got) == len(want), f"{where}: {len(got)} moves, LinuxCNC made {len(want)}"
        for mine, ref in zip(got, want):
            _same_move(mine, ref, where)
