"""Cutter radius compensation end to end: where the radius comes from, what is refused and where."""
from __future__ import annotations

from pathlib import Path

import pytest

from edingcnc_lang.canon import Move
from edingcnc_lang.errors import MachineError
from edingcnc_lang.runner import RunOptions, run_file, run_string

EMPTY_MACRO = Path(__file__).parent / "data" / "empty_macro.cnc"
SQUARE = "G0 X-10 Y-10\n{on}\nG1 X0 Y0 F600\nG1 X20\nG1 Y20\nG1 X0\nG1 Y0\nG40\nG1 X-10 Y-10\nM30\n"
TOOLS = "[TOOL_1]\ndiameter = 4\n[TOOL_2]\ndiameter = 10\n"


def xy_ends(source: str, tmp_path: Path | None = None, **options: object) -> list[tuple[int, float, float]]:
    moves: list[Move] = []
    if tmp_path is not None:
        ini = tmp_path / "cnc.ini"
        ini.write_text(TOOLS)
        options["ini"] = ini
    run_string(source, RunOptions(macro=EMPTY_MACRO, on_move=lambda m, _j: moves.append(m), **options),
               path="job.nc")  # type: ignore[arg-type]
    return [(m.line, round(m.end[0], 4) + 0.0, round(m.end[1], 4) + 0.0) for m in moves]


def error_of(source: str, tmp_path: Path) -> MachineError:
    ini = tmp_path / "cnc.ini"
    ini.write_text(TOOLS)
    with pytest.raises(MachineError) as err:
        run_string(source, RunOptions(macro=EMPTY_MACRO, ini=ini), path="job.nc")
    return err.value


@pytest.mark.parametrize("on", ["G41 D1", "#5008 = 1\nG41", "G10 L1 P5 R2\nG41 D5", "#5505 = 4\nG41 D5", "G41.1 D4"])
def test_the_radius_comes_from_the_tool_table_g10_parameters_or_d(on: str, tmp_path: Path) -> None:
    moves = xy_ends(SQUARE.format(on=on), tmp_path)
    assert (moves[-2][1], moves[-2][2]) == (2.0, 0.0)  # inside the square by the 2 mm radius


def test_inch_diameter_with_g41_1(tmp_path: Path) -> None:
    moves = xy_ends("G20\n" + SQUARE.format(on="G41.1 D0.1").replace("X20", "X1").replace("Y20", "Y1"))
    assert moves[-2][1:] == (1.27, 0.0)


def test_subs_and_expressions_between_compensated_moves() -> None:
    job = ("#1 = 20\nG0 X-10 Y-10\nG41.1 D4\nG1 X0 Y0 F600\nGoSub side\nG1 Y[#1]\nG1 X0\nG1 Y0\nG40\n"
           "G1 X-10 Y-10\nM30\nSub side\n  G1 X[#1]\nEndSub\n")
    assert xy_ends(job)[1:6] == [(4, -1.4142, 1.4142), (13, 0.0, 2.0), (13, 18.0, 2.0), (6, 18.0, 18.0), (7, 2.0, 18.0)]


def test_a_real_looking_file_crlf_latin1(tmp_path: Path) -> None:
    job = tmp_path / "kontur.cnc"
    text = "(Außenkontur, Fräser Ø10)\r\nG0 X-20 Y-20\r\nG42 D2 (rechts)\r\nG1 X0 Y0 F600\r\nG1 X40\r\nG1 Y30\r\n" \
           "G1 X0\r\nG1 Y0\r\nG40\r\nG1 X-20 Y-20\r\nM30\r\n"
    job.write_bytes(text.encode("latin-1"))
    ini = tmp_path / "cnc.ini"
    ini.write_text(TOOLS)
    moves: list[Move] = []
    run_file(job, RunOptions(macro=EMPTY_MACRO, ini=ini, on_move=lambda m, _j: moves.append(m)))
    assert max(m.end[0] for m in moves) == pytest.approx(45.0)  # outside the 40 mm plate by 5 mm


def test_a_refusal_held_back_in_the_stage_names_the_column_where_its_line_starts(tmp_path: Path) -> None:
    job = tmp_path / "job.nc"
    job.write_text("G0 X-10\nG42 D2\nG1 X0 F100\n    G2 X4 I2\n")
    (tmp_path / "cnc.ini").write_text(TOOLS)
    with pytest.raises(MachineError) as err:
        run_file(job, RunOptions(macro=EMPTY_MACRO, ini=tmp_path / "cnc.ini"))
    assert err.value.format().startswith(f"{job}:4:5: error: cutter compensation: the tool radius")


def test_m30_ends_compensation_and_the_next_run_starts_without_it(tmp_path: Path) -> None:
    moves = xy_ends("G0 X-10\nG41 D1\nG1 X0 Y0 F100\nM30\n", tmp_path)
    assert moves[-1] == (3, 0.0, 2.0)


@pytest.mark.parametrize("plane", ["G18", "G19"])
def test_a_mill_compensates_in_xy_only(plane: str) -> None:
    # manual 3.6.13 (p. 27): "Die Kompensation des Fräserradius darf nur durchgeführt werden, wenn die
    # XY-Ebene aktiv ist"; an error "die XY-Ebene ist nicht aktiv oder zum Drehen ist die ZX-Ebene nicht aktiv"
    with pytest.raises(MachineError, match="XY plane \\(G17\\) on a mill") as err:
        run_string(f"{plane}\nG0 Y-10 Z0\nG41.1 D4\nG1 Y0 Z0 F100\nM30\n", RunOptions(macro=EMPTY_MACRO), path="job.nc")
    assert err.value.location is not None and err.value.location.line == 3


def test_a_lathe_compensates_in_zx_only(tmp_path: Path) -> None:
    ini = tmp_path / "cnc.ini"
    ini.write_text("[SYSTEM]\r\nmachineType = 1\r\n[INTERPRETER]\r\ndiameterProgramming = 0\r\n")
    moves: list[Move] = []
    run_string("G18\nG0 X10 Z10\nG41.1 D4\nG1 X10 Z0 F100\nG1 Z-20\nG40\nM30\n",
               RunOptions(ini=ini, macro=EMPTY_MACRO, on_move=lambda m, _j: moves.append(m)), path="job.nc")
    assert any(m.line == 5 for m in moves)
    with pytest.raises(MachineError, match="ZX plane \\(G18\\) on a lathe"):
        run_string("G17\nG41.1 D4\nM30\n", RunOptions(ini=ini, macro=EMPTY_MACRO), path="job.nc")


GOLDEN_TOOLS = Path(__file__).resolve().parent.parent / "golden" / "linuxcnc" / "tools.ini"
# An inch contour whose last arc, joined near-tangentially, grows by more than 0.001 rad once G40 fixes
# its end: rs274 refuses it at the G40 line ("Arc move in concave corner"), found by a random
# comparison with rs274; in mm LinuxCNC allows 0.0254 rad (tests/golden: comp_near_tangent_arc_growth).
INCH_ARC_GROWS_AT_G40 = ("G20 G17 G90 G94\nG0 X-30 Y0\nG42 D3\nG1 X0 Y0 F19.6850\n"
                         "G3 X0.0820 Y0.2516 I-0.4791 J0.2954\nG2 X0.3910 Y0.1104 I0.1849 J-0.0041\n"
                         "G2 X-0.6368 Y1.3299 I-0.5496 J0.5797\nG40\nG1 X0.3092 Y2.0371\nM2\n")


def test_g40_checks_the_last_corner_as_any_move_does_and_inch_sweeps_are_strict() -> None:
    with pytest.raises(MachineError) as err:
        run_string(INCH_ARC_GROWS_AT_G40, RunOptions(macro=EMPTY_MACRO, ini=GOLDEN_TOOLS), path="job.nc")
    assert "an arc in an inside corner cannot be reached" in err.value.message
    assert err.value.location is not None and err.value.location.line == 8
