"""Tool offsets on a diameter-programming lathe as the controller keeps them (manual p. 2, the
saved [VARIABLES] of a V4.03 lathe): the tool table's width and xDelta are diameter values, G43
moves X by half of them, #5010/#5012 read the table's values and #5013/#5014 the applied ones."""
from __future__ import annotations

from pathlib import Path

import pytest

from edingcnc_lang import RunOptions, run_string
from edingcnc_lang.config import load_config
from edingcnc_lang.host import DialogAnswer, Host

EXAMPLE = Path(__file__).resolve().parents[2] / "examples" / "lathe"
INI = EXAMPLE / "cnc.ini"


def _run(job: str, *answers: str) -> object:
    queue = [DialogAnswer.parse(a) for a in answers]
    host = Host(dialog=lambda _title, _fields: queue.pop(0))
    return run_string(job, RunOptions(ini=INI, macro=EXAMPLE / "macro.cnc", user_macro=EXAMPLE / "user_macro.cnc",
                                      host=host))


def test_the_saved_state_is_what_g43_of_the_saved_tool_applies() -> None:
    """The example ini was left with T3 under G43: #5013/#5014 in [VARIABLES] are its length + zDelta
    and half its width (a diameter value); a fresh M6 of the same tool gives the same numbers."""
    config = load_config(INI)
    tool = config.tools[3]
    assert config.variables[5013] == pytest.approx(tool.length + tool.z_delta)
    assert config.variables[5014] == pytest.approx((tool.width + tool.x_delta) / 2)
    result = _run("#5008 = 0\nT3 M6\nG0 X20 Z2\n")
    values = result.variables  # type: ignore[attr-defined]
    assert values[5008] == 3
    assert values[5010] == pytest.approx(tool.length + tool.z_delta)
    assert values[5012] == pytest.approx(tool.width + tool.x_delta)        # as the table keeps it
    assert (values[5013], values[5014]) == pytest.approx((config.variables[5013], config.variables[5014]))
    machine_x = result.machine[0]  # type: ignore[attr-defined]
    assert machine_x == pytest.approx(config.variables[5221] + 10 + (tool.width + tool.x_delta) / 2)
    assert result.position[0] == pytest.approx(20.0)  # type: ignore[attr-defined]


def test_writing_the_table_changes_the_next_g43() -> None:
    result = _run("T2 M6\nG0 X30 Z5\n#5602 = [#5602 + 0.5]\n#100 = #5001\nG43\n#101 = #5001\n#102 = #5012\n")
    values = result.variables  # type: ignore[attr-defined]
    assert values[100] == pytest.approx(30.0)            # the offset in force until G43
    assert values[101] == pytest.approx(29.5)            # 0.5 more width on the diameter: X reads 0.5 less
    assert values[102] == pytest.approx(-21.44 + 0.5)    # #5012 follows the table at G43


def test_tool_x_from_a_measured_diameter_is_right_and_idempotent() -> None:
    """The example's user_5 (a set_tool_offset_X in the turning macros' style): G43, read #5001 and
    #5012, write #56xx. The tool turned 30 on the display, the part measures 29.9."""
    job = "T2 M6\nG0 X30 Z5\ngosub user_5\n#100 = #5602\n#101 = #5001\ngosub user_5\n#102 = #5602\n"
    values = _run(job, "ok:#1490=29.9", "ok:#1490=29.9").variables  # type: ignore[attr-defined]
    assert values[100] == pytest.approx(-21.44 + 0.1)    # the width grows by the diameter's error
    assert values[101] == pytest.approx(29.9)            # the display now reads what was measured
    assert values[102] == pytest.approx(values[100])     # measuring again changes nothing


def test_g10_l10_sets_a_diameter_width_that_reads_back() -> None:
    values = _run("T2 M6\nG0 X30 Z5\nG10 L10 P2 X31\nG43\n#100 = #5001\n").variables  # type: ignore[attr-defined]
    assert values[100] == pytest.approx(31.0)
    assert values[5602] == pytest.approx(-21.44 - 1.0)   # a diameter value: 1 on the diameter


def test_g43_1_i_is_a_diameter_on_a_diameter_lathe() -> None:
    result = _run("G49\nG0 X20 Z0\n#100 = #5071\nG43.1 I-4 K0\nG0 X20\n#101 = #5071\n#102 = #5014\n")
    values = result.variables  # type: ignore[attr-defined]
    assert values[101] - values[100] == pytest.approx(-2.0) and values[102] == pytest.approx(-2.0)
