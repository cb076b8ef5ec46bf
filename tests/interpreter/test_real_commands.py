"""Commands real macro files use, with their effect: ZHC, G53 G38.2, M60, M26, M90..M93, GetJobDistance, G10 L10/L11."""
from __future__ import annotations

import math
from pathlib import Path

import pytest

from edingcnc_lang.canon import Move
from edingcnc_lang.errors import MachineError
from edingcnc_lang.config.heightmap import HeightMap, ProbeAt
from edingcnc_lang.host import Host
from edingcnc_lang.runner import RunOptions, RunResult, run_string

TILTED = HeightMap((0.0, 100.0), (0.0, 60.0), ((0.0, 0.4), (0.2, 0.6)))  # z = x/250 + y/300

GRID = """#4100 = 5
#4101 = 4
#4104 = 25
G0 Z5
G0 X0 Y0
ZHCINIT [#4104] [#4100] [#4101]
#111 = 0
While [#111 < #4101]
  #110 = 0
  While [#110 < #4100]
    G0 Z5
    G0 X[#110 * #4104] Y[#111 * #4104]
    G38.2 F200 Z-5
    If [#5067 == 1]
      ZHCADDPOINT
    EndIf
    #110 = [#110 + 1]
  EndWhile
  #111 = [#111 + 1]
EndWhile
G0 Z5
"""


def run(text: str, moves: list[Move] | None = None, **options: object) -> RunResult:
    sink = moves if moves is not None else []
    return run_string(text, RunOptions(host=Host(probe=ProbeAt(TILTED)), on_move=lambda m, j: sink.append(m),
                                       **options))  # type: ignore[arg-type]


def error_of(text: str, **options: object) -> MachineError:
    with pytest.raises(MachineError) as info:
        run(text, **options)
    return info.value


def test_a_probed_grid_makes_an_engraving_follow_the_surface(tmp_path: Path) -> None:
    moves: list[Move] = []
    result = run(GRID + "ZHCS table.txt\nZHCcheck 20\nZHC on\nG0 X10 Y10\nG1 Z-0.1 F300\nG1 X90\nZHC off\n"
                 "G0 Z5\nM30\n", moves, log_dir=tmp_path)
    assert result.variables[5151] == 0.0
    cut = [m for m in moves if m.line == 27]  # G1 X90, split where it crosses the grid lines X25, X50, X75
    assert [m.end[0] for m in cut] == pytest.approx([25.0, 50.0, 75.0, 90.0])
    for m in cut:
        assert m.end[2] == pytest.approx(-0.1 + m.end[0] / 250 + 10 / 300, abs=1e-9)
    assert (tmp_path / "table.txt").read_text().startswith("; ecnc ZHC height table\nnx 5\nny 4\n")
    assert "20 measured" in result.messages[0].data["text"]


def test_zhc_on_sets_5151_and_a_loaded_table_works_like_a_probed_one(tmp_path: Path) -> None:
    run(GRID + "ZHCS t.txt\n", log_dir=tmp_path)
    moves: list[Move] = []
    result = run("ZHCL t.txt\nZHC on\n#1 = #5151\nG1 X50 Y30 Z0 F100\n", moves, log_dir=tmp_path)
    assert result.variables[1] == 1.0 and result.variables[5151] == 1.0
    assert moves[-1].end[2] == pytest.approx(50 / 250 + 30 / 300, abs=1e-6)


def test_g53_g38_2_probes_in_machine_coordinates() -> None:
    result = run("G10 L2 P1 Z-20\nG54\nG53 G38.2 Z-50 F100\n")
    assert result.variables[5067] == 1.0
    assert result.variables[5053] == pytest.approx(0.0)  # the surface at X0 Y0, machine Z


def test_m60_ends_the_program_like_m30() -> None:
    result = run("G91\nM60\nG0 X5\n")
    assert result.ended_by == "M60" and result.machine[0] == 0.0 and "G90" in result.modal


def test_m26_clamps_the_rotary_axes_until_m27() -> None:
    err = error_of("M26\nG0 X5\nG0 A10\n")
    assert "clamped (M26)" in err.message and err.location.line == 3  # type: ignore[union-attr]
    assert run("M26\nM27\nG0 A10\n").machine[3] == 10.0


@pytest.mark.parametrize("m, value", [(90, 0.0), (91, 1.0), (92, 2.0), (93, 3.0)])
def test_m90_to_m93_select_the_spindle_in_5390(m: int, value: float) -> None:
    assert run(f"M{m}\n").variables[5390] == value


def test_the_machine_position_of_a_run_includes_the_height_compensation() -> None:
    """--json's machine Z (and MDI's machine line) is where the machine is, as the trace shows it:
    the work Z plus the surface height under it while ZHC is on; after ZHC off the next move ramps back."""
    moves: list[Move] = []
    result = run(GRID + "ZHC on\nG0 X50 Y30 Z-0.1\n", moves)
    height = 50 / 250 + 30 / 300
    assert result.machine[2] == pytest.approx(-0.1 + height) == pytest.approx(moves[-1].end[2])
    assert result.position[2] == pytest.approx(-0.1)
    assert run(GRID + "ZHC on\nG0 X50 Y30 Z-0.1\nZHC off\nG0 X60\n").machine[2] == pytest.approx(-0.1)


def test_get_job_distance_counts_lines_arcs_and_rapids() -> None:
    result = run("G0 X10\nG1 X10 Y10 F100\nG2 X10 Y10 I5 J0\nGetJobDistance 100\n")
    assert result.variables[100] == pytest.approx(20 + 10 * math.pi)


def test_get_job_distance_counts_the_bulk_moves_of_a_job_file(tmp_path: Path) -> None:
    """A job file's plain G0/G1 lines take the bulk path; their travel counts as any other move's."""
    from edingcnc_lang.runner import run_file

    job = tmp_path / "job.nc"
    job.write_text("G0 X10\nG1 Y10 F100\nX0 Y0 Z-5\nGetJobDistance 100\nG1 X3 Y4 Z-5\nGetJobDistance 101\n")
    result = run_file(job, RunOptions())
    first = 20 + math.sqrt(200 + 25)
    assert result.variables[100] == pytest.approx(first)
    assert result.variables[101] == pytest.approx(first + 5)


def test_get_tool_info_enumerates_the_tools_the_loaded_job_uses(tmp_path: Path) -> None:
    """As the stock macro.cnc's measure_used_tools: the job's T words, not the tool table's entries."""
    from edingcnc_lang.machine.named_commands import tools_used
    from edingcnc_lang.runner import run_file

    macro = tmp_path / "macro.cnc"
    macro.write_text("Sub used\n  GetToolInfo num 100\n  GetToolInfo first 101\n  GetToolInfo next 102\n"
                     "  GetToolInfo next 103\nEndSub\nSub change_tool\nEndSub\n")
    job = tmp_path / "job.nc"
    job.write_text("GoSub used\nT4 M6 (T9 is the spare)\nG0 X1\nmsg \"T7 next\"\nM6 T2 ; T8\nZHCINIT 10 2 2\nT0\n")
    result = run_file(job, RunOptions(macro=macro))
    assert [result.variables[i] for i in (100, 101, 102, 103)] == [2.0, 2.0, 4.0, -1.0]
    assert tools_used(["t3m6", "G43 H3 T12", "M6 T[#1]", "GetToolInfo first 5"]) == [3, 12]


def test_height_control_voltages_read_zero_in_simulation() -> None:
    assert run("#101 = 5\nGetHeightControlVact 101\nGetHeightControlVset 102\n").variables[101] == 0.0
    assert "parameter number" in error_of("GetJobDistance #100\n").message


def test_g10_l10_and_l11_set_the_tool_length_from_the_position() -> None:
    result = run("G10 L2 P1 Z-30\nG10 L2 P9 Z-40\nG54\nG0 Z-50\nG10 L10 P3 Z2\nG10 L11 P4 Z0\n"
                 "G43 H3\n#100 = #5003\n")
    assert result.variables[5403] == pytest.approx(-80 + 30 - 2)  # machine Z -80 is work Z -50 in G54 (Z-30)
    assert result.variables[5404] == pytest.approx(-80 + 40)  # the same against G59.3 (Z-40)
    assert result.variables[100] == pytest.approx(2.0)


def test_g10_l10_leaves_the_wear_out_so_the_position_reads_z_under_g43() -> None:
    """G43 adds zDelta to the length; G10 L10 must set the length that, with the wear, reads Z."""
    result = run("#5903 = 0.2\nG0 Z20\nG10 L10 P3 Z0\nG43 H3\n#100 = #5003\nG10 L11 P3 Z5\nG43 H3\n#101 = #5003\n")
    assert result.variables[5403] == pytest.approx(20 - 5 - 0.2)
    assert result.variables[100] == pytest.approx(0.0)
    assert result.variables[101] == pytest.approx(5.0)


def test_g43_adds_the_tool_wear(tmp_path: Path) -> None:
    result = run("#5405 = 20\n#5905 = -0.05\nG43 H5\n")
    assert result.variables[5013] == pytest.approx(19.95)


def test_a_height_table_that_does_not_load_is_named_once(tmp_path: Path) -> None:
    (tmp_path / "bad.txt").write_text("; ecnc ZHC height table\nnx 1e308\nny 4\n")
    err = error_of("ZHCL bad.txt\n", log_dir=tmp_path)
    assert err.message.startswith(f"ZHCL: the height table {tmp_path / 'bad.txt'}")
    assert err.message.count("error") == 0 and err.format().count(": error: ") == 1
