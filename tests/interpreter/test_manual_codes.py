"""G and M codes as the EdingCNC 4.03 manual defines them (issue 21); each test names its section."""
from __future__ import annotations

from pathlib import Path

import pytest

from edingcnc_lang.canon import Event, Move
from edingcnc_lang.errors import MachineError
from edingcnc_lang.runner import RunOptions, RunResult, run_string

EMPTY_MACRO = Path(__file__).parent / "data" / "empty_macro.cnc"


def run(text: str, moves: list[Move] | None = None, events: list[Event] | None = None,
        **options: object) -> RunResult:
    moves = moves if moves is not None else []
    events = events if events is not None else []
    return run_string(text, RunOptions(on_move=lambda m, j: moves.append(m), on_event=events.append,
                                       **options))  # type: ignore[arg-type]


def kinds(events: list[Event], kind: str) -> list[Event]:
    return [e for e in events if e.kind == kind]


# --------------------------------------------------------------------------- 3.6.16 G64

def test_vectric_g64_header_does_not_set_the_spindle_speed() -> None:
    """3.6.16: S on a G64 line is the second look-ahead angle, not a spindle speed."""
    events: list[Event] = []
    result = run("M3 S18000\nG64 P0.1 R6 S100 D0.002\nG1 X10 F500\n", events=events)
    assert result.spindle["s"] == 18000.0
    assert [e.line for e in kinds(events, "spindle_speed")] == [1]
    control = kinds(events, "path_control")[-1].data
    assert control == {"mode": "G64", "p": 0.1, "r": 6.0, "s": 100.0, "d": 0.002}


def test_g64_f_is_the_ramp_filter_not_the_feed() -> None:
    """3.6.16: G64 F.. is the acceleration filter behind look-ahead; the cut keeps its feed."""
    moves: list[Move] = []
    events: list[Event] = []
    run("G1 X1 F1200\nG64 P0.1 F1\nG1 X10\n", moves, events)
    assert moves[-1].feed == 1200.0
    assert kinds(events, "path_control")[-1].data == {"mode": "G64", "p": 0.1, "f": 1.0}


def test_g64_lengths_follow_the_units() -> None:
    events: list[Event] = []
    run("G20\nG64 P0.01 Q0.001 D0.0001 R3 S90\n", events=events)
    data = kinds(events, "path_control")[-1].data
    assert data["p"] == pytest.approx(0.254) and data["q"] == pytest.approx(0.0254)
    assert data["d"] == pytest.approx(0.00254) and (data["r"], data["s"]) == (3.0, 90.0)


def test_g64_negative_words_are_errors() -> None:
    with pytest.raises(MachineError, match="G64 D-1: must be 0 or more"):
        run("G64 D-1\n")


# --------------------------------------------------------------------------- 3.6.12 G43, 3.7.3 M6

TOOLS = "#5401 = 10\n#5402 = 25\n"


def test_plain_g43_follows_every_tool_change() -> None:
    """3.6.12 A: G43 always compensates the tool in the spindle, so it follows M6."""
    moves: list[Move] = []
    result = run(TOOLS + "T1 M6\nG43\nG0 Z0\nT2 M6\nG0 Z0\n", moves, macro=EMPTY_MACRO)
    assert [m.end[2] for m in moves] == [10.0, 25.0]
    assert result.variables[5013] == 25.0


@pytest.mark.parametrize("g43", ["G43 H1", "G43.1 K10"])
def test_g43_h_and_g43_1_stay_after_a_tool_change(g43: str) -> None:
    """3.6.12 warning: with B (G43 H) or C (G43.1) the length is not adapted to the new tool after M6 T."""
    moves: list[Move] = []
    run(TOOLS + f"T1 M6\n{g43}\nG0 Z0\nT2 M6\nG0 Z0\n", moves, macro=EMPTY_MACRO)
    assert [m.end[2] for m in moves] == [10.0, 10.0]


def test_plain_g43_takes_the_length_the_change_tool_sub_measured() -> None:
    moves: list[Move] = []
    job = ("T1 M6\nG43\nG0 Z0\nT2 M6\nG0 Z0\nM30\n"
           "Sub change_tool\n  #[5400 + #5011] = 40\n  M6 T[#5011]\nEndSub\n")
    run(TOOLS + job, moves, macro=EMPTY_MACRO)
    assert [m.end[2] for m in moves] == [40.0, 40.0]


def test_m6_leaves_the_spindle_stopped() -> None:
    """3.7.3: when the tool change is complete the spindle is stopped."""
    events: list[Event] = []
    result = run("M3 S1000\nT1 M6\n", events=events, macro=EMPTY_MACRO)
    assert result.spindle["m"] == 5 and result.variables[5152] == 0.0
    assert [(e.line, e.data["m"]) for e in kinds(events, "spindle")] == [(1, 3), (2, 5)]


def test_m3_on_the_m6_line_starts_the_new_tool() -> None:
    """Order of execution: M6 before M3, so `T1 M6 M3 S1000` turns the new tool."""
    assert run("T1 M6 M3 S1000\n", macro=EMPTY_MACRO).spindle["m"] == 3


# --------------------------------------------------------------------------- 3.6.20 canned cycles

def test_g84_f_is_per_spindle_revolution() -> None:
    """3.6.20.6: with M3 S600, F1 feeds 600 mm/min, synchronised; the spindle reverses at the bottom and back."""
    moves: list[Move] = []
    events: list[Event] = []
    run("M3 S600\nG0 Z5\nG98 G84 X0 Y0 Z-10 R1 F1\n", moves, events)
    taps = [(m.end[2], m.feed, m.sync) for m in moves if m.line == 3 and m.kind == "linear"]
    assert taps == [(-10.0, 600.0, 1.0), (5.0, 600.0, 1.0)]  # out at the same pitch to the clear level (G98)
    assert [(e.data["m"], e.data["rigid_tap"]) for e in kinds(events, "spindle") if e.line == 3] == [(4, True), (3, True)]


def test_g84_pitch_is_the_same_under_g95_and_in_inches() -> None:
    moves: list[Move] = []
    run("G20\nM3 S500\nG95\nG0 Z0.2\nG99 G84 X0 Y0 Z-0.5 R0.1 F0.05\n", moves)
    tap = [m for m in moves if m.kind == "linear"][0]
    assert tap.sync == pytest.approx(1.27) and tap.feed == pytest.approx(635.0)


def test_tapping_is_not_scaled_by_the_feed_override() -> None:
    """3.6.20.6: the feed follows the spindle, so the feed override knob does not change it (as G33.1)."""
    job = "M3 S600\nG0 Z5\nG99 G84 X0 Y0 Z-20 R5 F1\n"
    full = run(job).estimate
    half = run(job, feed_override=50.0).estimate
    assert full is not None and half is not None and half.seconds == pytest.approx(full.seconds)


@pytest.mark.parametrize("cycle", ["G84 X0 Z-5 R1 F1", "G74 X0 Z-5 R1 F1", "G86 X0 Z-5 R1 F100",
                                   "G87 X0 Z-5 R1 I2 K-2 F100", "G88 X0 Z-5 R1 F100"])
def test_cycles_that_need_a_turning_spindle_refuse_without_one(cycle: str) -> None:
    """3.6.20.9: it is an error if the spindle is not turning before G86 runs; the taps feed per
    revolution and G87/G88 restart the spindle in the direction it went."""
    code = cycle.split()[0]
    with pytest.raises(MachineError, match=f"{code} needs the spindle turning") as info:
        run(f"G0 Z5\n{cycle}\n")
    assert info.value.location.line == 2


def test_g88_stops_for_the_operator_and_moves_nothing_itself() -> None:
    """3.6.20.11: feed to Z, dwell, spindle stop, program stop for a manual retract, spindle on again."""
    moves: list[Move] = []
    events: list[Event] = []
    run("M3 S800\nG0 Z5\nG98 G88 X0 Y0 Z-10 R1 P0.5 F100\n", moves, events)
    assert [(m.kind, m.end[2]) for m in moves if m.line == 3] == [("rapid", 5.0), ("rapid", 1.0), ("linear", -10.0)]
    steps = [(e.kind, e.data.get("m")) for e in events if e.line == 3]
    assert steps == [("dwell", None), ("spindle", 5), ("pause", 0), ("spindle", 3)]


# --------------------------------------------------------------------------- 3.7.1 M30, M60

def test_m30_resets_as_the_manual_lists() -> None:
    """3.7.1: G17, G90, G94, M48, G40, M5, G1, M9; the coordinate system is kept."""
    events: list[Event] = []
    result = run("G19 G91 G95 G0 X1\nG55 M3 S100 M8\nM49\nM30\n", events=events)
    assert {"G17", "G90", "G94", "G40", "G1", "G55"} <= set(result.modal)
    assert result.spindle["m"] == 5
    assert [e.data["m"] for e in kinds(events, "override")] == [49, 48]


def test_m60_keeps_the_spindle_and_coolant_on() -> None:
    """3.7.1: M60 instead of M30 when the spindle and coolant should stay on (nesting)."""
    result = run("M3 S100 M8\nM60\n")
    assert result.spindle["m"] == 3 and result.variables[5152] == 1.0 and result.ended_by == "M60"


# --------------------------------------------------------------------------- 3.6.8 G28/G30

def test_g28_via_the_programmed_point_to_the_home_of_all_axes() -> None:
    """3.6.8: a rapid to the programmed point, then to the home position; Z last when going down."""
    moves: list[Move] = []
    run("#5161 = 10 #5162 = 20 #5163 = -5\nG0 X1 Y1 Z5\nG28 X3\n", moves)
    assert [m.end[:3] for m in moves if m.line == 3] == [(3.0, 1.0, 5.0), (10.0, 20.0, 5.0), (10.0, 20.0, -5.0)]


def test_g30_z_first_when_home_is_higher() -> None:
    moves: list[Move] = []
    run("#5181 = 10 #5182 = 20 #5183 = 50\nG0 X1 Y1 Z5\nG30\n", moves)
    assert [m.end[:3] for m in moves if m.line == 3] == [(1.0, 1.0, 50.0), (10.0, 20.0, 50.0)]


# --------------------------------------------------------------------------- 3.6.10.1 G38.2, 3.6.5 G10

def test_probe_without_contact_is_an_error_at_its_line() -> None:
    """3.6.10.1: if the probe does not trip even slightly past the programmed point, an error."""
    from edingcnc_lang.host import Host
    with pytest.raises(MachineError, match="without the probe tripping") as info:
        run("G0 Z10\nG38.2 Z-5 F100\n", host=Host(probe=lambda start, target: None))
    assert info.value.location.line == 2


def test_g10_l2_p0_is_an_error() -> None:
    """3.6.5: an error if P is not an integer from 1 to 9."""
    with pytest.raises(MachineError, match="G10 L2 needs a coordinate system P1..P9"):
        run("G10 L2 P0 X1\n")


# --------------------------------------------------------------------------- 3.7.2 .. 3.7.13 M codes

@pytest.mark.parametrize("line, target, value", [
    ("M104 S200", "extruder", 200.0), ("M109 S210", "extruder", 210.0), ("M140 S60", "bed", 60.0),
    ("M190 S65", "bed", 65.0), ("M106 S50", "fan", 50.0), ("M143 S260", "extruder_max", 260.0),
])
def test_3d_printing_s_is_not_a_spindle_speed(line: str, target: str, value: float) -> None:
    """3.7.12: M104 S50 sets the extruder to 50 degrees C; the spindle keeps its speed."""
    events: list[Event] = []
    result = run(f"M3 S1000\n{line}\n", events=events)
    assert result.spindle["s"] == 1000.0
    assert kinds(events, "printer")[0].data[target] == value


def test_an_m104_sub_gets_its_s_without_setting_the_spindle() -> None:
    result = run("M3 S1000\nM104 S200\nM30\nSub m104\n  #100 = #19\nEndSub\n")
    assert result.spindle["s"] == 1000.0 and result.variables[100] == 200.0


def test_m30_switches_the_heaters_off() -> None:
    """3.7.1: all 3D printer heaters off."""
    events: list[Event] = []
    run("M104 S200\nM30\n", events=events)
    assert kinds(events, "printer")[-1].data == {"m": 30, "off": True}


def test_laser_thc_and_override_inputs_are_events() -> None:
    """3.7.11 M10/M11, 3.7.10 M20..M22, 3.7.5 M52/M53, 3.7.12 M100."""
    events: list[Event] = []
    run("M11\nM10\nM21\nM22 Q120\nM20\nM52 P1\nM53 P0\nM100 P1.01\n", events=events)
    seen = [(e.kind, e.data) for e in events]
    assert seen == [("laser", {"m": 11, "on": True}), ("laser", {"m": 10, "on": False}),
                    ("thc", {"m": 21, "on": True}), ("thc", {"m": 22, "q": 120.0}), ("thc", {"m": 20, "on": False}),
                    ("override", {"m": 52, "p": 1.0}), ("override", {"m": 53, "p": 0.0}),
                    ("m_code", {"m": 100, "p": 1.01})]


def test_an_m_code_without_meaning_or_sub_is_a_warning() -> None:
    """3.7.13: M1..M999 are allowed; one with no built-in and no sub of its name does nothing, said aloud."""
    result = run("M123\nM100\n")
    assert [m.data["text"] for m in result.messages] == [
        "M123 has no built-in meaning and no Sub m123 is defined: it does nothing"]


def test_modbus_read_writes_its_variables() -> None:
    from edingcnc_lang.host import Host
    asked: list[tuple[int, int, int, int]] = []

    def bus(slave: int, function: int, address: int, count: int) -> list[float]:
        asked.append((slave, function, address, count))
        return [7.0, 8.0]
    result = run("#1000 = 5\n#1001 = 5\nmodbus s1 f3 a100 n2 u1000\n", host=Host(modbus=bus))
    assert (result.variables[1000], result.variables[1001], asked) == (7.0, 8.0, [(1, 3, 100, 2)])
    result = run("#723 = 5\nmodbus s1 f2 a23 n1 u723\n")  # no bus in simulation: 0
    assert result.variables[723] == 0.0


def test_alternate_spindle_offsets_and_tool_change_area_from_the_ini(tmp_path: Path) -> None:
    """3.7.2: [SPINDLE_1] xOffset.. are relative to [SPINDLE_0]; 3.1: #5131..#5143 the TCA limits."""
    ini = tmp_path / "cnc.ini"
    ini.write_text("[SPINDLE_1]\nxOffset = 50.0\nyOffset = -10.0\nzOffset = 2.5\n"
                   "[KINEMATICS]\nnegativeLimitTCAX = -100\nnegativeLimitTCAY = 10\nnegativeLimitTCAZ = -50\n"
                   "positiveLimitTCAX = -80\npositiveLimitTCAY = 200\npositiveLimitTCAZ = 0\n")
    moves: list[Move] = []
    result = run("M91\nG0 X0 Y0 Z0\nM90\nG0 X0 Y0 Z0\n#1 = #5131 #2 = #5132 #3 = #5133 #4 = #5141 #5 = #5142 #6 = #5143\n",
                 moves, ini=ini)
    assert [m.end[:3] for m in moves] == [(50.0, -10.0, 2.5), (0.0, 0.0, 0.0)]
    assert [result.variables[i] for i in range(1, 7)] == [-100.0, 10.0, -50.0, -80.0, 200.0, 0.0]
    with pytest.raises(MachineError, match="read-only"):
        run("#5131 = 1\n")


# --------------------------------------------------------------------------- 3.6.17 G68

def ends(moves: list[Move]) -> list[tuple[float, ...]]:
    return [tuple(round(v, 6) + 0.0 for v in m.end[:3]) for m in moves]


def test_g68_i1_turns_about_x_in_the_yz_plane() -> None:
    """3.6.17: I1 rotation about X in the YZ plane; R positive is counter-clockwise."""
    moves: list[Move] = []
    result = run("G68 I1 R90\nG0 X1 Y10 Z0\n#1 = #5002 #2 = #5003\n", moves)
    assert ends(moves) == [(1.0, 0.0, 10.0)]  # +Y turns to +Z about X
    assert (result.variables[5195], result.variables[5194], result.variables[5196]) == (90.0, 0.0, 0.0)
    assert (result.variables[1], result.variables[2]) == pytest.approx((10.0, 0.0))


def test_g68_j1_turns_about_y_in_the_xz_plane() -> None:
    moves: list[Move] = []
    result = run("G68 J1 R90 X0 Z5\nG0 X0 Y0 Z15\n", moves)
    assert ends(moves) == [(10.0, 0.0, 5.0)]  # about (x 0, z 5): +Z turns to +X about Y
    assert (result.variables[5196], result.variables[5193]) == (90.0, 5.0)


def test_g68_without_ijk_turns_in_the_active_plane() -> None:
    moves: list[Move] = []
    run("G19\nG68 R90\nG0 Y10\n", moves)
    assert ends(moves) == [(0.0, 0.0, 10.0)]


def test_g68_pivot_defaults_to_the_work_zero() -> None:
    """3.6.17: without X Y Z the current work zero is the pivot (not the current position)."""
    moves: list[Move] = []
    run("G0 X10 Y0\nG68 R90\nG0 X10 Y0\n", moves)
    assert ends(moves)[-1] == (0.0, 10.0, 0.0)


@pytest.mark.parametrize("line, message", [
    ("G68 I1 K1 R30", "one of I1, J1 or K1"), ("G68 J2 R30", "write J1"),
])
def test_g68_axis_word_mistakes(line: str, message: str) -> None:
    with pytest.raises(MachineError, match=message):
        run(line + "\n")


def test_g68_yz_turns_g19_arcs_and_refuses_g17_arcs() -> None:
    moves: list[Move] = []
    run("G68 I1 R90\nG19 G0 Y10 Z0\nG2 Y0 Z10 J-10 K0 F100\n", moves)
    assert ends(moves)[-1] == (0.0, -10.0, 0.0)
    with pytest.raises(MachineError, match="turns the YZ plane"):
        run("G68 I1 R90\nG17 G0 X10\nG2 X0 Y10 I-10 J0 F100\n")


def test_modbus_answers_on_the_command_line(tmp_path: Path) -> None:
    from tests.cli_runner import invoke
    job = tmp_path / "job.nc"
    job.write_text("modbus s1 f3 a100 n2 u1000\nmodbus s1 f2 a23 n1 u723\nmodbus s1 f2 a23 n1 u724\n"
                   "msg #1000 \" \" #1001 \" \" #723 \" \" #724\n")
    result = invoke("run", job, "--modbus", "7,8", "--modbus", "1")
    assert result.exit_code == 0 and "msg: 7 8 1 0" in result.stderr
    refused = invoke("run", job, "--modbus", "7,x")
    assert refused.exit_code == 2 and "modbus answer '7,x'" in refused.stderr
