"""``ecnc diff examples/pocket.nc CASE``: each case in ``cases/`` is pocket.nc with one edit (its first
line says which).  The JSON of each comparison is a golden file beside it (``--regen-goldens``
rewrites them); the tests below also say what each must find, at which lines."""
from __future__ import annotations

import json
from pathlib import Path

import pytest

from edingcnc_lang.diff import diff_files
from tests.cli_runner import invoke

ROOT = Path(__file__).resolve().parents[2]
OLD = ROOT / "examples" / "pocket.nc"
CASES = Path(__file__).resolve().parent / "cases"


def new_text(name: str) -> list[str]:
    return (CASES / name).read_text(encoding="latin-1").splitlines()


def line_of(name: str, text: str) -> int:
    """The number of the first line of case ``name`` whose code is ``text``."""
    return next(i for i, line in enumerate(new_text(name), start=1) if line.split(";")[0].strip() == text)


def old_line_of(text: str, after: int = 0) -> int:
    lines = OLD.read_text(encoding="latin-1").splitlines()
    return next(i for i, line in enumerate(lines, start=1) if i > after and line.split(";")[0].strip() == text)


@pytest.fixture(scope="module")
def results() -> dict[str, tuple[int, dict]]:
    found = {}
    for case in sorted(CASES.glob("*.nc")):
        result = invoke("diff", OLD, case, "--json")
        found[case.name] = (result.exit_code, json.loads(result.stdout))
    return found


@pytest.mark.parametrize("case", sorted(p.name for p in CASES.glob("*.nc")))
def test_golden_json(case: str, results: dict[str, tuple[int, dict]], golden) -> None:
    code, doc = results[case]
    golden(CASES / f"{Path(case).stem}.json", json.dumps({"exit": code, **doc}, indent=1) + "\n")


def test_a_reformatted_copy_is_the_same(results: dict[str, tuple[int, dict]]) -> None:
    """Renumbered N words, G01 for G1, trailing zeros, comments, CRLF, an arc and a line each split in two."""
    code, doc = results["reformatted.nc"]
    assert code == 0 and doc["same"] is True
    assert doc["moves"] == {"old": 168, "new": 170}  # the split arc and line: two moves more, same path
    assert doc["max_deviation"] <= 0.001


def test_a_contour_moved_by_0_05_is_found_at_its_line(results: dict[str, tuple[int, dict]]) -> None:
    code, doc = results["moved.nc"]
    assert code == 1 and doc["same"] is False
    assert doc["max_deviation"] == pytest.approx(0.05, abs=1e-6)
    [change] = doc["deviations"]
    assert change["new_line"] == line_of("moved.nc", "X31")  # the move along the moved wall
    assert change["old_line"] == old_line_of("Y26")
    assert change["tool"] == 1
    assert doc["feeds"] == doc["spindle"] == doc["rapids"] == []


def test_a_feed_change_is_one_range(results: dict[str, tuple[int, dict]]) -> None:
    code, doc = results["feed.nc"]
    assert code == 1 and doc["deviations"] == []
    [feed] = doc["feeds"]
    assert (feed["old"], feed["new"]) == (1200, 1500)
    assert feed["new_line"] == line_of("feed.nc", "G1 X65 F1500")
    assert feed["old_line"] == old_line_of("G1 X65 F1200")
    assert doc["time"]["new"] < doc["time"]["old"]


def test_a_spindle_speed_change(results: dict[str, tuple[int, dict]]) -> None:
    code, doc = results["speed.nc"]
    assert code == 1
    [speed] = doc["spindle"]
    assert (speed["old"], speed["new"], speed["tool"]) == (12000, 10000, 1)
    assert doc["deviations"] == doc["feeds"] == []


def test_another_tool(results: dict[str, tuple[int, dict]]) -> None:
    code, doc = results["tool.nc"]
    assert code == 1
    assert doc["tools"]["old"] == [1, 2] and doc["tools"]["new"] == [1, 5]
    [moves] = doc["tools"]["moves"]
    assert (moves["old"], moves["new"]) == (2, 5)


def test_the_order_of_the_tools(results: dict[str, tuple[int, dict]]) -> None:
    code, doc = results["order.nc"]
    assert code == 1
    assert doc["tools"]["old"] == [1, 2] and doc["tools"]["new"] == [2, 1]


def test_a_dwell_changes_the_time(results: dict[str, tuple[int, dict]]) -> None:
    code, doc = results["dwell.nc"]
    assert code == 1
    assert doc["time"]["new"] == pytest.approx(doc["time"]["old"] + 3.0, abs=0.01)
    [dwell] = doc["dwell"]
    assert dwell["old_line"] is None and dwell["new_line"] == line_of("dwell.nc", "G4 P3") and dwell["new"] == 3
    assert doc["deviations"] == doc["feeds"] == []


def test_a_lower_rapid_is_called_out(results: dict[str, tuple[int, dict]]) -> None:
    code, doc = results["rapid.nc"]
    assert code == 1
    [rapid] = doc["rapids"]
    assert rapid["new_line"] == line_of("rapid.nc", "G0 Z-13")
    assert rapid["new"] < rapid["old"]


def test_an_inserted_lead_in_does_not_shift_what_follows(results: dict[str, tuple[int, dict]]) -> None:
    """Two lines inserted: they differ, nothing after them does (alignment by geometry, not index)."""
    code, doc = results["leadin.nc"]
    assert code == 1
    [change] = doc["deviations"]
    assert change["new_lines"] == [line_of("leadin.nc", "G1 X76.85 Y29.7 F600"), line_of("leadin.nc", "G1 X77 Y30")]
    assert doc["feeds"] == doc["spindle"] == doc["tools"]["moves"] == []
    assert doc["moves"]["new"] == doc["moves"]["old"] + 2


def test_the_python_api_gives_the_same() -> None:
    comparison = diff_files(OLD, CASES / "feed.nc")
    assert not comparison.same
    assert [c.what for c in comparison.changes["feeds"]] == ["feed"]
    assert diff_files(OLD, CASES / "reformatted.nc").same
