"""Integrity of the committed LinuxCNC goldens (tests/golden), checked without LinuxCNC.

The differential tests compare our interpreter and kinematics with these files, so a truncated,
orphaned or malformed golden would make them pass or fail for the wrong reason.
"""

from __future__ import annotations

import json
import math
import re
from pathlib import Path
from typing import Any

import pytest

GOLDEN = Path(__file__).resolve().parent
PROGRAMS = GOLDEN / "linuxcnc" / "programs"
EXPECTED = GOLDEN / "linuxcnc" / "expected"
DELTA = GOLDEN / "lineardelta" / "cases.json"

PROGRAM_NAMES = sorted(p.stem for p in PROGRAMS.glob("*.ngc"))
MOVE_KINDS = {"rapid", "linear", "arc"}
ARC_KEYS = {"line", "kind", "end", "center", "plane", "turn"}
STRAIGHT_KEYS = {"line", "kind", "end"}
# Words outside the subset both dialects share (docs/goldens.md lists the reasons).
FORBIDDEN_WORDS = re.compile(
    r"\b(G43(\.\d)?|G38(\.\d)?|G33(\.\d)?|G76|G52|G0?5(\.\d)?\b|G7\b|G8\b|G64|M0?6\b|O\d+)",
    re.IGNORECASE,
)
ARC_WITH_P = re.compile(r"\bG0?[23]\b[^(]*\bP", re.IGNORECASE)
COMMENT = re.compile(r"\([^)]*\)")


def load(name: str) -> dict[str, Any]:
    return json.loads((EXPECTED / f"{name}.json").read_text())


def code_lines(name: str) -> list[str]:
    """The program's lines with comments removed (index 0 is line 1)."""
    return [COMMENT.sub("", line).strip() for line in (PROGRAMS / f"{name}.ngc").read_text().splitlines()]


def test_enough_programs() -> None:
    assert len(PROGRAM_NAMES) >= 45


def test_programs_and_expected_files_pair_up() -> None:
    assert sorted(p.stem for p in EXPECTED.glob("*.json")) == PROGRAM_NAMES


@pytest.mark.parametrize("name", PROGRAM_NAMES)
def test_expected_file_shape(name: str) -> None:
    data = load(name)
    assert set(data) == {"program", "source", "moves", "dwells"}
    assert data["program"] == f"{name}.ngc"
    assert data["source"].startswith("rs274 -g (LinuxCNC ")
    assert data["moves"], "every golden must record at least one move"
    assert all(isinstance(d, float) and d >= 0 for d in data["dwells"])
    lines = code_lines(name)
    for move in data["moves"]:
        assert move["kind"] in MOVE_KINDS
        assert set(move) == (ARC_KEYS if move["kind"] == "arc" else STRAIGHT_KEYS)
        assert len(move["end"]) == 6 and all(math.isfinite(v) for v in move["end"])
        assert 1 <= move["line"] <= len(lines) and lines[move["line"] - 1], "move must come from a code line"
        if move["kind"] == "arc":
            assert move["plane"] in {"XY", "XZ", "YZ"}
            assert move["turn"] in {1, -1}
            assert len(move["center"]) == 2


@pytest.mark.parametrize("name", PROGRAM_NAMES)
def test_moves_are_in_line_order(name: str) -> None:
    lines = [move["line"] for move in load(name)["moves"]]
    assert lines == sorted(lines)


@pytest.mark.parametrize("name", PROGRAM_NAMES)
def test_program_stays_in_shared_subset(name: str) -> None:
    source = (PROGRAMS / f"{name}.ngc").read_text()
    code = [line for line in code_lines(name) if line and not line.startswith("%")]
    assert ";" not in source
    assert not any(FORBIDDEN_WORDS.search(line) for line in code)
    assert not any(ARC_WITH_P.search(line) for line in code)
    assert re.search(r"\bM(2|30)\b", code[-1], re.IGNORECASE)


def test_full_circle_golden_by_hand() -> None:
    """G2 X25 Y0 I-25 J0 from (25, 0): one clockwise turn about the origin."""
    arc = load("arc_g17_full_circle_cw")["moves"][2]
    assert arc == {
        "line": 5, "kind": "arc", "end": [25.0, 0.0, 0.0, 0.0, 0.0, 0.0],
        "center": [0.0, 0.0], "plane": "XY", "turn": -1,
    }


def test_xz_arc_golden_maps_axes_by_hand() -> None:
    """G18 G2 X-6 Z-8 I10 K0 from (-10, 5, 0): the centre is listed as [x, z]."""
    arc = load("arc_g18_ijk")["moves"][3]
    assert arc["end"] == [-6.0, 5.0, -8.0, 0.0, 0.0, 0.0]
    assert arc["center"] == [0.0, 0.0] and arc["plane"] == "XZ" and arc["turn"] == -1


def test_inch_golden_is_in_millimetres() -> None:
    assert load("inch_moves")["moves"][2]["end"][:3] == [63.5, 31.75, -3.175]


def delta_towers(radius: float) -> list[tuple[float, float]]:
    """The tower layout observed in LinuxCNC's lineardeltakins (docs/goldens.md)."""
    s60, c60 = math.sin(math.pi / 3), math.cos(math.pi / 3)
    return [(0.0, radius), (-radius * s60, -radius * c60), (radius * s60, -radius * c60)]


def delta_joints(pos: list[float], radius: float, arm: float) -> list[float]:
    x, y, z = pos
    return [z + math.sqrt(arm**2 - (x - tx) ** 2 - (y - ty) ** 2) for tx, ty in delta_towers(radius)]


def test_lineardelta_file_shape() -> None:
    data = json.loads(DELTA.read_text())
    assert (data["R"], data["L"]) == (125.0, 250.0)
    assert len(data["cases"]) >= 150 and len(data["forward"]) >= 5
    positions = [case["pos"] for case in data["cases"]]
    assert [0.0, 0.0, 0.0] in positions and [0.0, 0.0, 200.0] in positions
    for case in data["cases"] + data["forward"]:
        assert len(case["pos"]) == 3 and len(case["joints"]) == 3


def test_lineardelta_cases_match_the_documented_layout() -> None:
    data = json.loads(DELTA.read_text())
    for case in data["cases"] + data["forward"]:
        assert delta_joints(case["pos"], data["R"], data["L"]) == pytest.approx(case["joints"], abs=1e-6)


def test_lineardelta_includes_poses_near_the_reach_limit() -> None:
    data = json.loads(DELTA.read_text())
    nearest = min(
        data["L"] - math.dist(case["pos"][:2], tower)
        for case in data["cases"]
        for tower in delta_towers(data["R"])
    )
    assert nearest < 0.05
