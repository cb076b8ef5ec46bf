"""The tangential knife's interpreter part: C turns to the cut direction before each XY feed move."""
from __future__ import annotations

import math
from pathlib import Path

import pytest

from edingcnc_lang import Move, RunOptions, run_string

INI = """[INTERPRETER]
tanKnifeAngleForLiftUp = 10
tanKnifeLiftUpDistance = 3
tanknifeBendingAngle = 0
"""


def _moves(source: str, tmp_path: Path) -> list[Move]:
    ini = tmp_path / "cnc.ini"
    ini.write_text(INI)
    moves: list[Move] = []
    run_string(source, RunOptions(ini=ini, on_move=lambda move, _joints: moves.append(move)))
    return moves


def test_a_large_turn_lifts_turns_and_lowers(tmp_path: Path) -> None:
    moves = _moves("G0 X0 Y0 Z0 C0\ntanknife on\nG1 X10 F600\nG1 Y10\n", tmp_path)
    turn = [(m.kind, m.end[2], m.end[5]) for m in moves if m.line == 4]
    assert turn == [("rapid", 3.0, 0.0), ("rapid", 3.0, 90.0), ("rapid", 0.0, 90.0), ("linear", 0.0, 90.0)]


def test_a_small_turn_is_made_in_place(tmp_path: Path) -> None:
    moves = _moves("G0 X0 Y0 C0\ntanknife on\nG1 X10 F600\nG1 X20 Y1\n", tmp_path)
    line4 = [m for m in moves if m.line == 4]
    assert [m.kind for m in line4] == ["rapid", "linear"]
    assert line4[0].end[2] == 0.0
    assert line4[1].end[5] == pytest.approx(math.degrees(math.atan2(1, 10)))


def test_the_nearest_equivalent_angle_is_chosen(tmp_path: Path) -> None:
    moves = _moves("G0 X0 Y0 C350\ntanknife on\nG1 X10 Y1 F600\n", tmp_path)
    assert moves[-1].end[5] == pytest.approx(360 + math.degrees(math.atan2(1, 10)))


def test_c_follows_the_tangent_along_an_arc(tmp_path: Path) -> None:
    # a counter-clockwise half circle from (10, 0) around the origin: tangent 90 -> 270 degrees
    moves = _moves("G0 X10 Y0 C90\ntanknife on\nG3 X-10 Y0 I-10 J0 F600\n", tmp_path)
    arc = moves[-1]
    assert arc.kind == "arc"
    assert arc.end[5] == pytest.approx(270.0)
    assert [m.kind for m in moves if m.line == 3] == ["arc"]  # already aligned: no turn before it


def test_z_moves_and_rapids_do_not_turn_the_knife(tmp_path: Path) -> None:
    moves = _moves("G0 X0 Y0 C0\ntanknife on\nG1 Z-1 F600\nG0 X10 Y10\n", tmp_path)
    assert [m.end[5] for m in moves] == [0.0, 0.0, 0.0]


def test_nothing_turns_once_the_knife_is_off(tmp_path: Path) -> None:
    moves = _moves("G0 X0 Y0 C0\ntanknife on\ntanknife off\nG1 Y10 F600\n", tmp_path)
    assert [m.kind for m in moves] == ["rapid", "linear"]
    assert moves[-1].end[5] == 0.0
