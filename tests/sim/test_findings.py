"""Findings: each kind at its line, measured from the stock as it was just before the move."""
from __future__ import annotations

import pytest

from edingcnc_lang.sim import Tool

from .jobs import cut

ENDMILL = Tool(0, "flat", 6.0, flute_length=10.0, shank_diameter=6.0, holder_diameter=30.0, holder_length=12.0)


def kinds(result) -> list[tuple[str, int]]:  # type: ignore[no-untyped-def]
    """(kind, line) of each finding; the job's body starts on line 3 (after the preamble)."""
    return [(f.kind, f.line) for f in result.findings]


def test_rapid_through_the_stock_is_found_at_its_line(tmp_path):
    result = cut(tmp_path, "G0 Z5\nG0 X-5 Y10\nG0 Z-1\nG0 X45\nG0 Z5", ENDMILL)
    (finding,) = result.findings
    assert (finding.kind, finding.line, finding.severity) == ("rapid_into_stock", 6, "error")
    assert finding.depth == pytest.approx(1.0)
    assert finding.position[2] == pytest.approx(-1.0)


def test_a_rapid_in_a_slot_already_cut_is_no_finding(tmp_path):
    body = "G0 Z5\nG0 X-5 Y10\nG1 Z-1 F300\nG1 X45 F1000\nG0 X-5\nG0 Z5"
    assert cut(tmp_path, body, ENDMILL).findings == []


def test_stepping_down_within_the_flutes_hits_no_shank_but_going_past_them_does(tmp_path):
    # 4 mm passes with 10 mm flutes: each pass removes 4 mm, never more than the flutes
    steps = "G0 Z5\nG0 X10 Y15\n" + "\n".join(f"G1 Z-{z} F300\nG1 X30 F1000\nG1 X10" for z in (3, 6, 9)) + "\nG0 Z5"
    assert kinds(cut(tmp_path, steps, ENDMILL)) == []
    # the same depth in one go: a 9 mm plunge and a 9 mm deep slot... still within 10 mm flutes
    assert "shank" not in [k for k, _ in kinds(cut(tmp_path, "G0 X10 Y15\nG1 Z-9 F300\nG1 X30\nG0 Z5", ENDMILL))]
    # 11 mm in one pass: the shank rubs 1 mm
    deep = cut(tmp_path, "G0 X10 Y15\nG1 Z-3 F300\nG1 Z-11 X30 F1000\nG0 Z5", ENDMILL, box=(0, 0, -20, 40, 30, 0))
    shank = [f for f in deep.findings if f.kind == "shank"]
    assert [f.line for f in shank] == [5] and shank[0].depth == pytest.approx(1.0, abs=0.01)


def test_a_shank_wider_than_the_cutter_hits_the_wall_of_its_own_slot(tmp_path):
    small = Tool(0, "flat", 3.0, flute_length=5.0, shank_diameter=6.0)
    result = cut(tmp_path, "G0 X10 Y15\nG1 Z-6 F300\nG1 X30 F1000\nG0 Z5", small)
    assert ("shank", 4) in kinds(result) or ("shank", 5) in kinds(result)
    assert all(f.depth == pytest.approx(1.0, abs=0.01) for f in result.findings if f.kind == "shank")


def test_holder_below_the_top_is_found(tmp_path):
    result = cut(tmp_path, "G0 X10 Y15\nG1 Z-8 F300\nG1 Z-13 F300\nG1 X30\nG0 Z5", ENDMILL, box=(0, 0, -20, 40, 30, 0))
    holder = [f for f in result.findings if f.kind == "holder"]
    assert [f.line for f in holder] == [5, 6] and holder[0].depth == pytest.approx(1.0, abs=0.01)


def test_cutting_with_the_spindle_stopped(tmp_path):
    result = cut(tmp_path, "M5\nG0 X5 Y5\nG1 Z-1 F300\nG1 X35\nM3\nG1 Y25\nG0 Z5", ENDMILL)
    assert kinds(result) == [("spindle_off", 5), ("spindle_off", 6)]


def test_plunge_deeper_than_half_the_diameter_is_a_hint(tmp_path):
    result = cut(tmp_path, "G0 X10 Y15\nG1 Z-3 F300\nG1 Z-7\nG0 Z5\nG0 X30\nG1 Z-2\nG0 Z5", ENDMILL)
    assert kinds(result) == [("plunge", 5)]
    assert result.findings[0].severity == "hint"
    # a ball end plunging is not a flat tool's problem
    assert cut(tmp_path, "G0 X10 Y15\nG1 Z-7 F300\nG0 Z5", Tool(0, "ball", 6.0)).findings == []


def test_below_the_bottom_is_a_hint_once_per_move_down(tmp_path):
    result = cut(tmp_path, "G0 X10 Y15\nG1 Z-2.5 F300\nG1 X30\nG0 Z5", Tool(0, "ball", 6.0), box=(0, 0, -2, 40, 30, 0))
    assert kinds(result) == [("outside_stock", 4), ("outside_stock", 5)]
    assert result.findings[0].depth == pytest.approx(0.5)


def test_a_loop_in_one_line_is_one_finding_with_the_deepest_point(tmp_path):
    body = "G0 X-5 Y10\n#1=1\nwhile [#1 < 4]\nG0 Z[-#1]\nG0 X[-5+50*[#1 mod 2]]\n#1=[#1+1]\nendwhile\nG0 Z5"
    result = cut(tmp_path, body, ENDMILL)
    assert kinds(result) == [("rapid_into_stock", 7)]
    assert result.findings[0].depth == pytest.approx(1.0)  # each pass goes 1 mm below the last


def test_tool_change_changes_the_shape_and_the_report_names_the_tool(tmp_path):
    from edingcnc_lang.sim import Stock, simulate

    from .jobs import write_job

    tools = {1: Tool(1, "flat", 6.0), 2: Tool(2, "ball", 2.0)}
    # the packaged macro's tool change stops the spindle: the first cut without a new M3 is found
    job = write_job(tmp_path, "T1 M6\nG0 X10 Y15\nG1 Z-1 F300\nG1 X20\nG0 Z5\nT2 M6\nM3\nG0 X25\nG0 Z-1\nG0 Z5")
    result = simulate(job, Stock.box((0, 0, -10), (40, 30, 0), 0.1), tools=tools)
    assert kinds(result) == [("spindle_off", 5), ("spindle_off", 6), ("rapid_into_stock", 11)]
    assert [f.tool for f in result.findings] == [1, 1, 2]
    assert sorted(result.tools) == [1, 2]
