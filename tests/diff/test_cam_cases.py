"""``ecnc diff old.nc CASE --stock ...`` on a pocket job as a CAM post-processor writes it (``cases/cam``:
``old.nc``, and one file per edit).  The text and the JSON of each comparison are golden files beside the
case (``--regen-goldens`` rewrites them); the tests below say which entries each edit must give, and only
those: one change is one entry, wherever it is."""
from __future__ import annotations

import json
from pathlib import Path

import pytest

from tests.cli_runner import invoke

CAM = Path(__file__).resolve().parent / "cases" / "cam"
STOCK = "0,0,-20,80,55,0"
CASES = sorted(p.name for p in CAM.glob("*.nc") if p.name != "old.nc")


@pytest.fixture(scope="module")
def results() -> dict[str, tuple[int, str, dict]]:
    found = {}
    with pytest.MonkeyPatch.context() as patch:
        patch.chdir(CAM)  # the names in the text are the folder's own, wherever the tests run
        for case in CASES:
            text = invoke("diff", "old.nc", case, "--stock", STOCK)
            doc = invoke("diff", "old.nc", case, "--stock", STOCK, "--json")
            assert text.exit_code == doc.exit_code, case
            found[case] = (doc.exit_code, text.stdout, json.loads(doc.stdout))
    return found


@pytest.mark.parametrize("case", CASES)
def test_golden(case: str, results: dict[str, tuple[int, str, dict]], golden) -> None:
    code, text, doc = results[case]
    stem = Path(case).stem
    golden(CAM / f"{stem}.txt", text)
    golden(CAM / f"{stem}.json", json.dumps({"exit": code, **doc}, indent=1) + "\n")


def entries(doc: dict) -> list[dict]:
    """Every change with lines, from every list."""
    lists = ("deviations", "feeds", "spindle", "rapids", "dwell", "coolant", "offsets")
    return [c for name in lists for c in doc[name]] + doc["tools"]["moves"]


def line_of(case: str, text: str, nth: int = 0) -> int:
    lines = (CAM / case).read_text(encoding="ascii").splitlines()
    return [i for i, line in enumerate(lines, start=1) if line == text][nth]


@pytest.mark.parametrize("case", ["lowered_rapid.nc", "lowered_retract.nc"])
def test_a_lowered_rapid_is_one_entry_at_its_line(case: str, results: dict[str, tuple[int, str, dict]]) -> None:
    code, _text, doc = results[case]
    [rapid] = [c for c in entries(doc) if c["what"] != "rapid_into_stock"]
    assert code == 1 and rapid["what"] == "rapid" and (rapid["old"], rapid["new"]) == (5, -1)
    lowered = line_of(case, "G00 Z-1.000")
    into = [c["new_line"] for c in doc["rapids"] if c["what"] == "rapid_into_stock"]
    if case == "lowered_rapid.nc":  # down into the pocket already cut: it hits nothing, the part is the same
        assert rapid["new_line"] == lowered and into == [] and doc["part"]["same"] is True
    else:  # the retract (up to Z-1) is not one; the rapid across at Z-1 is, and it goes through the stock
        assert rapid["new_line"] == lowered + 1 and into == [lowered + 1] and doc["part"]["same"] is False


def test_a_pocket_moved_2_mm_is_one_shifted_entry(results: dict[str, tuple[int, str, dict]]) -> None:
    code, text, doc = results["shifted.nc"]
    [shift] = entries(doc)
    assert code == 1 and shift["what"] == "shifted" and shift["by"] == [2.0, 0.0, 0.0]
    # from the rapid into the pocket to the tool change that leaves it (the moves out start where it moved to)
    first, last = line_of("shifted.nc", "G00 X27.000 Y20.000"), line_of("shifted.nc", "T2 M06")
    assert shift["new_lines"] == [first, last] and shift["old_lines"] == [first, last]
    assert "moved by (2, 0, 0) mm" in text
    assert doc["part"]["same"] is False and doc["part"]["max_deviation"] == pytest.approx(5.0)


def test_an_added_tool_is_its_own_moves(results: dict[str, tuple[int, str, dict]]) -> None:
    code, text, doc = results["added_tool.nc"]
    [added] = doc["tools"]["added"]
    assert added["tool"] == 3 and added["after"] == 2 and added["moves"] == 14 and added["seconds"] > 0  # with its change
    t3 = [c for c in doc["deviations"] if c.get("tool") == 3]
    assert [c["what"] for c in t3] == ["added"] and t3[0]["new_lines"] == added["lines"]
    assert "spindle M5 M4 M5 added" in text and "coolant M9 M7 M9 added" in text and " - " not in text
    assert doc["tools"]["new"] == [1, 2, 3] and doc["tools"]["removed"] == []


def test_a_deeper_cut_is_one_depth_entry_and_no_rapid(results: dict[str, tuple[int, str, dict]]) -> None:
    code, text, doc = results["deeper.nc"]
    [depth] = entries(doc)
    assert depth["what"] == "depth" and depth["by"] == [0.0, 0.0, -1.0] and (depth["old"], depth["new"]) == (-5, -6)
    assert depth["moves"] == 14 and doc["rapids"] == []  # the retract G0 Z20 from Z-6 is not "lower"
    assert "depth Z-5 -> Z-6 (machine), 14 moves" in text
    [region] = doc["part"]["regions"]
    assert region["deeper"] == "new" and region["max_deviation"] == pytest.approx(1.0)


def test_holes_drilled_in_another_order_are_the_same_part(results: dict[str, tuple[int, str, dict]]) -> None:
    code, text, doc = results["reordered.nc"]
    assert code == 1 and doc["part"] == {**doc["part"], "same": True, "max_deviation": 0.0, "regions": []}
    assert [c["what"] for c in doc["deviations"]] == ["reordered"]  # one change: the holes, and the rapids joining them
    assert doc["feeds"] == doc["rapids"] == [] and "part: the same part" in text


def test_a_feed_change_is_one_range(results: dict[str, tuple[int, str, dict]]) -> None:
    _code, _text, doc = results["feed.nc"]
    [feed] = entries(doc)
    assert (feed["old"], feed["new"], feed["moves"]) == (1500, 1200, 4)
    assert doc["part"]["same"] is True
