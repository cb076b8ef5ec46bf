"""Motion and modal state: the moves a job makes (machine coordinates, mm) and the errors it meets."""
from __future__ import annotations

import math
from pathlib import Path

import pytest

from edingcnc_lang.canon import Move, Pose
from edingcnc_lang.errors import MachineError
from edingcnc_lang.host import Host
from edingcnc_lang.runner import RunOptions, RunResult, run_string

DATA = Path(__file__).parent / "data"
EMPTY_MACRO = DATA / "empty_macro.cnc"
MACHINE_INI = DATA / "machine.ini"


def run(source: str, **options: object) -> tuple[RunResult, list[Move]]:
    moves: list[Move] = []
    options.setdefault("macro", EMPTY_MACRO)
    result = run_string(source, RunOptions(on_move=lambda move, _joints: moves.append(move), **options),
                        path="job.nc")  # type: ignore[arg-type]
    return result, moves


def ends(source: str, **options: object) -> list[tuple[int, str, tuple[float, ...]]]:
    """(line, kind, X Y Z end point rounded to 1e-6) of every move."""
    return [(m.line, m.kind, tuple(round(v, 6) + 0.0 for v in m.end[:3])) for m in run(source, **options)[1]]


def error_of(source: str, **options: object) -> MachineError:
    with pytest.raises(MachineError) as info:
        run(source, **options)
    return info.value


def close(a: tuple[float, ...], b: tuple[float, ...]) -> bool:
    return len(a) == len(b) and all(math.isclose(x, y, abs_tol=1e-9) for x, y in zip(a, b))


# ------------------------------------------------------------------ lines and arcs

def test_rapid_and_feed_moves() -> None:
    result, moves = run("G0 X10 Y5\nG1 Z-2 F300\nX0\n")
    assert [(m.kind, m.end[:3], m.feed) for m in moves] == [
        ("rapid", (10.0, 5.0, 0.0), 0.0), ("linear", (10.0, 5.0, -2.0), 300.0), ("linear", (0.0, 5.0, -2.0), 300.0)]
    assert result.position[:3] == (0.0, 5.0, -2.0) and result.moves == 3


ARCS = [
    # (source, end XYZ, centre in the plane's axis order, plane, turn, full circle)
    ("G0 X10\nG2 X0 Y10 I-10 J0 F100\n", (0, 10, 0), (0, 0), "XY", -1, 0),
    ("G0 X10\nG3 X0 Y10 I-10 F100\n", (0, 10, 0), (0, 0), "XY", 1, 0),
    ("G0 Y10\nG3 X10 Y0 R10 F100\n", (10, 0, 0), (10, 10), "XY", 1, 0),
    ("G0 Y10\nG3 X10 Y0 R-10 F100\n", (10, 0, 0), (0, 0), "XY", 1, 0),
    ("G0 X10\nG2 X10 Y0 I-10 F100\n", (10, 0, 0), (0, 0), "XY", -1, 1),
    ("G0 X10\nG3 X10 I-10 Z-6 F100\n", (10, 0, -6), (0, 0), "XY", 1, 1),       # helix, one turn
    ("G0 X10\nG2 X0 Y10 I-10 Z-3 F100\n", (0, 10, -3), (0, 0), "XY", -1, 0),   # helix, quarter
    ("G18 G0 X10\nG2 X0 Z10 I-10 K0 F100\n", (0, 0, 10), (0, 0), "XZ", -1, 0),
    ("G18 G0 X10\nG3 X0 Z-10 R10 F100\n", (0, 0, -10), (0, 0), "XZ", 1, 0),
    ("G18 G0 X10\nG2 X10 I-10 F100\n", (10, 0, 0), (0, 0), "XZ", -1, 1),
    ("G19 G0 Y10\nG2 Y0 Z10 J-10 F100\n", (0, 0, 10), (0, 0), "YZ", -1, 0),
    ("G19 G0 Y10\nG3 Y-10 Z0 R10 X5 F100\n", (5, -10, 0), (0, 0), "YZ", 1, 0),  # helix along X
    ("G19 G2 Y0 Z0 J5 K0 F100\n", (0, 0, 0), (5, 0), "YZ", -1, 1),
    ("G91 G0 X10 Y10\nG2 X10 Y-10 I0 J-10 F100\n", (20, 0, 0), (10, 0), "XY", -1, 0),
    ("G10 L2 P1 X100 Y50\nG0 X10 Y0\nG3 X0 Y10 I-10 F100\n", (100, 60, 0), (100, 50), "XY", 1, 0),
]


@pytest.mark.parametrize(("source", "end", "center", "plane", "turn", "full"), ARCS,
                         ids=[s.replace("\n", " | ") for s, *_ in ARCS])
def test_arc_end_point_and_centre(source: str, end: tuple[float, ...], center: tuple[float, float], plane: str,
                                  turn: int, full: int) -> None:
    arc = run(source)[1][-1]
    assert arc.kind == "arc" and arc.arc is not None
    assert close(arc.end[:3], tuple(map(float, end)))
    assert close(arc.arc.center, tuple(map(float, center)))
    assert (arc.arc.plane, arc.arc.turn, arc.arc.full_turns) == (plane, turn, full)


def test_absolute_arc_centres_when_the_ini_says_so(tmp_path: Path) -> None:
    ini = tmp_path / "cnc.ini"
    ini.write_text("[INTERPRETER]\nabsoluteCenterCoords = 1\n")
    arc = run("G0 X20 Y10\nG2 X10 Y20 I10 J10 F100\n", ini=ini)[1][-1]
    assert arc.arc is not None and close(arc.arc.center, (10.0, 10.0))


def test_radius_mismatch_shows_start_centre_end_and_both_radii() -> None:
    err = error_of("G0 X10\nG2 X0 Y11 I-10 J0 F100\n")
    assert str(err.location) == "job.nc:2:1"
    for part in ("start radius 10.0000", "end radius 11.0000", "start (10.0000, 0.0000)",
                 "centre (0.0000, 0.0000)", "end (0.0000, 11.0000)", "XY plane"):
        assert part in err.message


def test_radius_mismatch_within_tolerance_is_accepted() -> None:
    assert run("G0 X10\nG2 X0 Y10.001 I-10 J0 F100\n")[1][-1].kind == "arc"


def test_radius_tolerance_is_linuxcncs_in_the_programs_units() -> None:
    # radii 0.05 and 0.05015: 0.00015 apart, over 0.1 % of the radius; 0.0038 mm is past
    # the 0.002 mm of a G21 program but within the 0.0002 in of a G20 one (as rs274 has it)
    assert run("G20 G0 X0 Y0\nG2 X0.10015 Y0 I0.05 J0 F10\n")[1][-1].kind == "arc"
    assert "not on one circle" in error_of("G21 G0 X0 Y0\nG2 X2.5438 Y0 I1.27 J0 F10\n").message


# ------------------------------------------------------------------ distance mode and units

def test_incremental_moves() -> None:
    assert ends("G91 G0 X1\nX1 Y-2\nG90 X1\n") == [
        (1, "rapid", (1.0, 0.0, 0.0)), (2, "rapid", (2.0, -2.0, 0.0)), (3, "rapid", (1.0, -2.0, 0.0))]


def test_inch_program_reports_millimetres() -> None:
    result, moves = run("G20 G0 X1 Y2\nG1 Z-0.5 F10\nG91 X0.1\n#100 = #5001\n")
    assert close(moves[-1].end[:3], (27.94, 50.8, -12.7))
    assert moves[1].feed == pytest.approx(254.0)
    assert result.position[0] == pytest.approx(27.94) and result.variables[100] == pytest.approx(27.94)
    assert "G20" in result.modal


def test_inch_arc_radius_is_converted() -> None:
    arc = run("G20 G0 X1\nG3 X0 Y1 R1 F10\n")[1][-1]
    assert arc.arc is not None and arc.arc.center == pytest.approx((0.0, 0.0), abs=1e-9)
    assert close(arc.end[:2], (0.0, 25.4))


# ------------------------------------------------------------------ coordinate systems

def test_g10_l2_l20_and_l1() -> None:
    result, _ = run("G0 X5 Y5\nG10 L20 P1 X0 Y1\n#100 = #5221 #101 = #5222\n"
                    "G10 L1 P3 Z12 R2\nG10 L2 P1 Z3\nG10 L2 P2 X7\n")
    v = result.variables
    assert (v[100], v[101], v[5223], v[5241]) == (5.0, 4.0, 3.0, 7.0)
    assert (v[5403], v[5503]) == (12.0, 4.0)
    assert result.position[:3] == (0.0, 1.0, -3.0)


@pytest.mark.parametrize(("code", "system"), [("G54", 1), ("G55", 2), ("G56", 3), ("G57", 4), ("G58", 5),
                                              ("G59", 6), ("G59.1", 7), ("G59.2", 8), ("G59.3", 9)])
def test_work_coordinate_systems(code: str, system: int) -> None:
    slot = 5221 + 20 * (system - 1)
    result, moves = run(f"#{slot} = 10 #{slot + 1} = -4\n{code}\nG0 X1 Y1\n#100 = #5220\n")
    assert moves[-1].end[:2] == (11.0, -3.0)
    assert result.variables[100] == system
    assert code in result.modal


def test_selecting_a_system_through_5220() -> None:
    result, moves = run("#5241 = 5\n#5220 = 2\nG0 X1\n")
    assert moves[-1].end[0] == 6.0 and result.position[0] == 1.0


def test_selecting_a_system_through_5220_shows_in_the_modal_state() -> None:
    assert "G55" in run("#5220 = 2\n")[0].modal


def test_g53_moves_in_machine_coordinates_for_one_line() -> None:
    assert ends("G10 L2 P1 X10\nG53 G0 X1\nG0 G53 Y2\nG53 X3\nG1 G53 X5 F100\nG0 X0\n") == [
        (2, "rapid", (1.0, 0.0, 0.0)), (3, "rapid", (1.0, 2.0, 0.0)), (4, "rapid", (3.0, 2.0, 0.0)),
        (5, "linear", (5.0, 2.0, 0.0)), (6, "rapid", (10.0, 2.0, 0.0))]


def test_g92_family() -> None:
    result, _ = run("G0 X1 Y1 Z5\nG92 X0 Y0\n#100 = #5211 #101 = #5001\n"
                    "G92 X2\nG0 X0\n#102 = #5071\n"
                    "G92.2\n#103 = #5001 #104 = #5211\n"
                    "G92.3\n#105 = #5001\n"
                    "G92.1\n#106 = #5001 #107 = #5211\n")
    v = result.variables
    assert (v[100], v[101]) == (1.0, 0.0)      # offset stored, work X is 0
    assert v[102] == -1.0                      # X0 with G92 X2 at machine 1
    assert (v[103], v[104]) == (-1.0, -1.0)    # G92.2: off, values kept
    assert v[105] == 0.0                       # G92.3: back on
    assert (v[106], v[107]) == (-1.0, 0.0)     # G92.1: off and zeroed


def test_g92_needs_an_axis_word() -> None:
    assert "axis" in error_of("G92\n").message


def test_g68_rotates_the_program_around_a_pivot() -> None:
    moves = run("G68 R90\nG0 X10 Y0\n#100 = #5001 #101 = #5002\nG69\nG0 X10 Y0\n")[1]
    assert close(moves[0].end[:2], (0.0, 10.0))
    assert close(moves[1].end[:2], (10.0, 0.0))


def test_g68_pivot_words_do_not_move() -> None:
    result, moves = run("G0 X10 Y0\nG68 X5 Y5 R90\nG0 X10 Y0\n")
    assert len(moves) == 2
    assert close(moves[1].end[:2], (10.0, 10.0))  # (10, 0) turned 90 degrees about (5, 5)
    # manual 3.1: #5194 is the XY angle (#5195 YZ, #5196 XZ)
    assert (result.variables[5191], result.variables[5192], result.variables[5194]) == (5.0, 5.0, 90.0)


# ------------------------------------------------------------------ G28 / G30

def test_g28_goes_z_last_when_going_down() -> None:
    assert ends("#5161 = 10 #5162 = 20 #5163 = 30\nG0 X1 Y1 Z40\nG28\n")[1:] == [
        (3, "rapid", (10.0, 20.0, 40.0)), (3, "rapid", (10.0, 20.0, 30.0))]


def test_g28_goes_z_first_when_going_up() -> None:
    assert ends("#5161 = 10 #5162 = 20 #5163 = 30\nG0 X1 Y1 Z-5\nG28\n")[1:] == [
        (3, "rapid", (1.0, 1.0, 30.0)), (3, "rapid", (10.0, 20.0, 30.0))]


def test_g28_goes_via_the_intermediate_point_to_the_home_of_all_axes() -> None:
    """Manual 3.6.8: a rapid to the programmed point, then a rapid to the home position (all axes;
    LinuxCNC homes only the named axes)."""
    moves = ends("#5161 = 10 #5162 = 20\nG0 X1 Y1 Z-5\nG28 X3\n")
    assert moves[1:] == [(3, "rapid", (3.0, 1.0, -5.0)), (3, "rapid", (3.0, 1.0, 0.0)),  # Z first: home is higher
                         (3, "rapid", (10.0, 20.0, 0.0))]


def test_g30_uses_its_own_positions_from_the_ini() -> None:
    result, moves = run("G0 Z-1\nG30\n", ini=MACHINE_INI)
    assert moves[1].end[:3] == (0.0, 0.0, 7.0) and moves[-1].end[:3] == (-5.0, -6.0, 7.0)


# ------------------------------------------------------------------ probing

def test_probe_trips_at_the_target_in_simulation() -> None:
    result, moves = run("G10 L2 P1 X100\nG0 X5 Z10\nG38.2 Z-20 F100\n")
    assert (moves[-2].kind, moves[-2].end[:3], moves[-2].feed) == ("probe", (105.0, 0.0, -20.0), 100.0)
    # manual 3.6.10.1 (p. 25): "wird die Sonde am Ende der Befehlsausführung leicht vom Auslösepunkt zurückgezogen"
    assert (moves[-1].kind, moves[-1].end[:3]) == ("probe", (105.0, 0.0, pytest.approx(-19.746)))
    v = result.variables
    assert (v[5061], v[5063], v[5051], v[5053], v[5067]) == (5.0, -20.0, 105.0, -20.0, 1.0)


def test_probe_callback_decides_where_it_trips() -> None:
    seen: list[tuple[Pose, Pose]] = []

    def probe(start: Pose, target: Pose) -> Pose:
        seen.append((start, target))
        return (*start[:2], -7.5, *start[3:])  # type: ignore[return-value]

    result, moves = run("G0 Z10\nG38.2 G91 Z-20 F100\nG90\n#100 = #5063\n", host=Host(probe=probe))
    assert seen == [((0.0, 0.0, 10.0, 0.0, 0.0, 0.0), (0.0, 0.0, -10.0, 0.0, 0.0, 0.0))]
    assert moves[-2].end[2] == -7.5 and result.position[2] == pytest.approx(-7.5 + 0.254)  # backed off (p. 25)
    assert (result.variables[100], result.variables[5067]) == (-7.5, 1.0)


def test_probe_that_misses_is_an_error_at_its_line() -> None:
    """Manual 3.6.10.1: a probe that does not trip even slightly past the target is an error."""
    with pytest.raises(MachineError, match="without the probe tripping") as info:
        run("G0 Z10\nG38.2 Z-20 F100\nIf [#5067 == 0]\n  #100 = 1\nEndIf\n",
            host=Host(probe=lambda start, target: None))
    assert info.value.location.line == 2


def test_probe_needs_an_axis_word() -> None:
    assert "G38.2" in error_of("G38.2 F100\n").message


# ------------------------------------------------------------------ tool length

def test_g43_g43h_and_g49_with_the_ini_tool_table() -> None:
    result, moves = run("T1 M6\nG43\nG0 Z10\n#100 = #5013\nG43 H2\nG0 Z10\nG49\nG0 Z10\n", ini=MACHINE_INI)
    assert [m.end[2] for m in moves] == [50.5, 65.25, 10.0]
    assert result.variables[100] == 40.5
    assert "G49" in result.modal


def test_g43_h_out_of_range_is_an_error() -> None:
    assert "H" in error_of("G43 H100\n").message


# ------------------------------------------------------------------ canned cycles

def test_every_canned_cycle_the_tables_name_has_an_expansion() -> None:
    from edingcnc_lang.machine.cycles import CYCLES, NEEDS_Q
    from edingcnc_lang.machine.tables import CANNED_CYCLES

    assert set(CYCLES) == CANNED_CYCLES and NEEDS_Q <= CANNED_CYCLES


def test_g81_with_g98_sticky_words_and_g99_repeats() -> None:
    assert ends("G0 X0 Y0 Z10\nG81 X5 Y5 Z-3 R2 F100\nX10\nG99 X15 L2\nG80\nG0 X0\n")[1:] == [
        (2, "rapid", (5.0, 5.0, 10.0)), (2, "rapid", (5.0, 5.0, 2.0)), (2, "linear", (5.0, 5.0, -3.0)),
        (2, "rapid", (5.0, 5.0, 10.0)),
        (3, "rapid", (10.0, 5.0, 10.0)), (3, "rapid", (10.0, 5.0, 2.0)), (3, "linear", (10.0, 5.0, -3.0)),
        (3, "rapid", (10.0, 5.0, 10.0)),
        (4, "rapid", (15.0, 5.0, 10.0)), (4, "rapid", (15.0, 5.0, 2.0)), (4, "linear", (15.0, 5.0, -3.0)),
        (4, "rapid", (15.0, 5.0, 2.0)),
        (4, "rapid", (15.0, 5.0, 2.0)), (4, "linear", (15.0, 5.0, -3.0)), (4, "rapid", (15.0, 5.0, 2.0)),
        (6, "rapid", (0.0, 5.0, 2.0))]


def test_incremental_cycle_with_repeats() -> None:
    holes = [m for m in ends("G0 Z10\nG91 G81 X5 Z-3 R-2 L3 F100\n") if m[1] == "linear"]
    assert holes == [(2, "linear", (5.0, 0.0, 5.0)), (2, "linear", (10.0, 0.0, 5.0)), (2, "linear", (15.0, 0.0, 5.0))]


def test_g83_pecks_and_reenters_above_the_last_depth() -> None:
    steps = [(kind, z) for _line, kind, (_x, _y, z) in ends("G0 Z10\nG83 X5 Z-3 R2 Q1.5 F100\n")[2:]]
    assert steps == [("rapid", 2.0), ("linear", 0.5), ("rapid", 2.0), ("rapid", 0.754), ("linear", -1.0),
                     ("rapid", 2.0), ("rapid", -0.746), ("linear", -2.5), ("rapid", 2.0), ("rapid", -2.246),
                     ("linear", -3.0), ("rapid", 10.0)]


def test_g73_breaks_chips_without_leaving_the_hole() -> None:
    zs = [z for _l, _k, (_x, _y, z) in ends("G0 Z10\nG73 X5 Z-3 R2 Q2 F100\n")[2:]]
    assert zs == pytest.approx([2.0, 0.0, 0.254, -2.0, -1.746, -3.0, 10.0])


def test_g18_cycle_drills_along_y() -> None:
    moves = ends("G18 G0 Y10\nG81 X5 Z5 Y-3 R2 F100\n")
    assert (2, "linear", (5.0, -3.0, 5.0)) in moves


# ------------------------------------------------------------------ feed modes

def test_inverse_time_needs_f_on_every_feed_line() -> None:
    err = error_of("G93 G1 X10 F2\nX20\n")
    assert str(err.location) == "job.nc:2:1" and "G93" in err.message


def test_inverse_time_feed_is_length_times_f() -> None:
    moves = run("G93 G1 X10 F2\nX20 F4\n")[1]
    assert [m.feed for m in moves] == [20.0, 40.0]


def test_feed_move_without_feed_is_g1516() -> None:
    assert "G1516" in error_of("G1 X10\n").message


# ------------------------------------------------------------------ M30 resets and word rules

def test_m30_resets_modes_but_not_the_coordinate_system() -> None:
    # G41 in G17: a mill compensates in XY only (manual 3.6.13, p. 27); G18 is reset by the second run
    result, _ = run("G91 G93 G1 X1 F100\nG10 L2 P2 X5\nG55 M3 S100 M8\nG41 D1\n#100 = #5152\nM30\n")
    assert "G17" in run("G18\nM30\n")[0].modal
    assert result.variables[100] == 1.0 and result.variables[5152] == 0.0
    for code in ("G1", "G17", "G90", "G94", "G40", "G55"):  # G1: manual 3.7.1 (LinuxCNC's M2 leaves G1 too)
        assert code in result.modal
    assert result.position[0] == -4.0 and result.ended_by == "M30"


def test_four_m_words_are_allowed() -> None:
    assert run("M3 M8 M48 M27 S100\n")[0].variables[5152] == 1.0


def test_changing_the_feed_mode_asks_for_a_new_feed() -> None:
    err = error_of("G93 G1 X10 F2\nG94 G1 X0\n")
    assert "feed rate is 0" in err.message and err.location.line == 2


def test_an_r_arc_that_cannot_reach_its_end_shows_no_centre() -> None:
    err = error_of("G0 X10 Y0\nG2 X0 Y10 R4 F100\n")
    assert "too small" in err.message and "centre" not in err.message
