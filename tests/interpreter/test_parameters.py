"""Parameters: deferred assignment, read-only system variables, live positions, simulation flag,
and persistent variables loaded from and written back to cnc.ini."""
from __future__ import annotations

import shutil
from pathlib import Path

import pytest

from edingcnc_lang.errors import MachineError
from edingcnc_lang.runner import RunOptions, RunResult, run_string

DATA = Path(__file__).parent / "data"
EMPTY_MACRO = DATA / "empty_macro.cnc"


def run(source: str, **options: object) -> RunResult:
    options.setdefault("macro", EMPTY_MACRO)
    return run_string(source, RunOptions(**options), path="job.nc")  # type: ignore[arg-type]


# ------------------------------------------------------------------ deferred assignment

def test_assignment_takes_effect_after_the_line_is_evaluated() -> None:
    result = run("#3 = 15\n#3 = 6 G1 X#3 F100\n")
    assert result.position[0] == 15.0
    assert result.variables[3] == 6.0


def test_an_expression_on_the_line_sees_the_old_value() -> None:
    result = run("#1 = 2\n#1 = 5 #2 = #1\n")
    assert (result.variables[1], result.variables[2]) == (5.0, 2.0)


def test_last_of_two_writes_on_a_line_wins() -> None:
    assert run("#3 = 1 #3 = 2\n").variables[3] == 2.0


def test_indirect_assignment_target_is_evaluated_before_any_write() -> None:
    result = run("#1 = 40\n#1 = 50 #[#1] = 7\n")
    assert result.variables[40] == 7.0 and 50 not in result.variables


# ------------------------------------------------------------------ read-only system variables

READ_ONLY = [5001, 5003, 5006, 5051, 5056, 5061, 5067, 5068, 5070, 5071, 5076, 5081, 5086,
             5101, 5116, 5126, 5150, 5151, 5152, 5380, 5397]


@pytest.mark.parametrize("index", READ_ONLY)
def test_read_only_system_variable_is_refused(index: int) -> None:
    with pytest.raises(MachineError) as info:
        run(f"G0 X1\n#{index} = 3\n")
    assert str(info.value.location) == "job.nc:2:1"
    assert f"#{index}" in info.value.message and "read-only" in info.value.message


WRITABLE = [5008, 5011, 5015, 5020, 5050, 5161, 5221, 5398, 5399, 5401, 5599, 5999]


@pytest.mark.parametrize("index", WRITABLE)
def test_macro_writable_system_variable_accepts_a_value(index: int) -> None:
    assert run(f"#{index} = 3\n").variables[index] == 3.0


# ------------------------------------------------------------------ live positions

def test_work_and_machine_position_follow_moves_and_offsets() -> None:
    result = run(
        "G10 L2 P1 X10 Y20 Z-5\n"    # G54 offset
        "G0 X2 Y3 Z4 A5 B6 C7\n"
        "#101 = #5001 #102 = #5002 #103 = #5003 #104 = #5004 #105 = #5005 #106 = #5006\n"
        "#111 = #5071 #112 = #5072 #113 = #5073 #114 = #5074 #115 = #5075 #116 = #5076\n"
        "G92 X0\n"                   # the current X becomes work X0
        "#121 = #5001 #122 = #5071 #123 = #5211\n")
    v = result.variables
    assert [v[i] for i in range(101, 107)] == [2.0, 3.0, 4.0, 5.0, 6.0, 7.0]
    assert [v[i] for i in range(111, 117)] == [12.0, 23.0, -1.0, 5.0, 6.0, 7.0]
    assert (v[121], v[122], v[123]) == (0.0, 12.0, 2.0)


def test_live_position_inside_a_line_is_the_one_before_its_move() -> None:
    result = run("G0 X4\nG0 X9 #100 = #5001\n")
    assert result.variables[100] == 4.0


def test_writing_a_coordinate_slot_moves_the_work_position() -> None:
    result = run("G0 X3\n#5221 = 1\n#100 = #5001\n")
    assert result.variables[100] == 2.0
    assert result.machine[0] == 3.0


def test_tool_length_shows_in_machine_z_while_g43_is_on() -> None:
    result = run("T1 M6\nG43\nG0 Z0\n#101 = #5003 #102 = #5073 #103 = #5013\nG49\n#104 = #5073\n",
                 ini=DATA / "machine.ini")
    v = result.variables
    assert (v[101], v[102], v[103]) == (0.0, 40.5, 40.5)
    assert v[104] == 40.5  # G49 changes the offset, not the machine position


# ------------------------------------------------------------------ simulation flag

def test_simulation_flag_is_1_by_default_and_0_on_request() -> None:
    source = "#100 = #5380\n"
    assert run(source).variables[100] == 1.0
    assert run(source, simulation=False).variables[100] == 0.0


def test_simulation_guard_idiom_skips_machine_only_code() -> None:
    source = "#100 = 0\nIf [[#5380 == 0] and [#5397 == 0]]\n  #100 = 1\nEndIf\n"
    assert run(source).variables[100] == 0.0
    assert run(source, simulation=False).variables[100] == 1.0


# ------------------------------------------------------------------ persistent variables

def test_persistent_variables_are_loaded_from_the_ini() -> None:
    result = run("#100 = #4000 #101 = #4001 #102 = #5161 #103 = #4999\n", ini=DATA / "machine.ini")
    v = result.variables
    assert (v[100], v[101], v[102], v[103]) == (12.5, 250.0, 10.0, 0.0)
    assert 4000 not in v  # loaded values are not "written during the run"


def test_tool_table_is_loaded_from_the_ini() -> None:
    result = run("#100 = #5401 #101 = #5501 #102 = #5402 #103 = #5502 #104 = #5403\n", ini=DATA / "machine.ini")
    assert [result.variables[i] for i in range(100, 105)] == [40.5, 6.0, 55.25, 5.0, 0.0]


def _copy_ini(tmp_path: Path) -> Path:
    ini = tmp_path / "cnc.ini"
    shutil.copyfile(DATA / "machine.ini", ini)
    return ini


def test_save_vars_writes_persistent_variables_back_and_keeps_every_other_byte(tmp_path: Path) -> None:
    ini = _copy_ini(tmp_path)
    before = ini.read_bytes()
    run("#4000 = 1.25\n#4002 = 3\n#5163 = 31\nG10 L2 P2 X4\n#100 = 9\n", ini=ini, save_vars=True)
    expected = (before.replace(b"#4000 = 12.500000", b"#4000 = 1.250000")
                .replace(b"#5163 = 30.000000", b"#5163 = 31.000000")
                + b"#4002 = 3.000000\r\n#5241 = 4.000000\r\n")
    assert ini.read_bytes() == expected
    again = run("#100 = #4000 #101 = #5241 #102 = #4002\n", ini=ini).variables
    assert (again[100], again[101], again[102]) == (1.25, 4.0, 3.0)


def test_without_save_vars_the_ini_is_not_touched(tmp_path: Path) -> None:
    ini = _copy_ini(tmp_path)
    before = ini.read_bytes()
    run("#4000 = 1.25\n", ini=ini)
    assert ini.read_bytes() == before


def test_save_vars_keeps_lf_line_endings(tmp_path: Path) -> None:
    ini = tmp_path / "cnc.ini"
    ini.write_bytes(b"[INTERPRETER]\ng4InMilliseconds = 0\n\n[VARIABLES]\n#4010 = 1.000000\n")
    run("#4010 = 2\n#4011 = 0.5\n", ini=ini, save_vars=True)
    assert ini.read_bytes() == (b"[INTERPRETER]\ng4InMilliseconds = 0\n\n[VARIABLES]\n#4010 = 2.000000\n"
                                b"#4011 = 0.500000\n")
