"""Lathe mode end to end through the API: diameter programming, spindle modes, threading, offsets."""
from __future__ import annotations

import math
from pathlib import Path

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from edingcnc_lang import RunOptions, run_string
from edingcnc_lang.canon import Event, Move
from edingcnc_lang.errors import EcncError

EMPTY_MACRO_TEXT = ";@unit mm\n"


def lathe(tmp_path: Path, diameter: bool = True, extra: str = "") -> Path:
    ini = tmp_path / "cnc.ini"
    ini.write_text(f"[SYSTEM]\nmachineType = 1\n[INTERPRETER]\ndiameterProgramming = {int(diameter)}\n"
                   "[SPINDLE]\nspindleNmax = 3000\nspindleNmin = 50\n"
                   "[TOOL_2]\nlength = 4\nwidth = -1.5\nzDelta = 0.25\nxDelta = 0.1\norientation = 3\n" + extra)
    (tmp_path / "macro.cnc").write_text(EMPTY_MACRO_TEXT)
    return ini


def run(tmp_path: Path, job: str, diameter: bool = True, extra: str = "") -> tuple[list[Move], list[Event], object]:
    moves: list[Move] = []
    events: list[Event] = []
    result = run_string(job, RunOptions(ini=lathe(tmp_path, diameter, extra), macro=tmp_path / "macro.cnc",
                                        on_move=lambda m, _j: moves.append(m), on_event=events.append))
    return moves, events, result


def failure(tmp_path: Path, job: str, diameter: bool = True) -> str:
    with pytest.raises(EcncError) as info:
        run(tmp_path, job, diameter)
    return info.value.format()


# ----------------------------------------------------------------- diameter programming

def test_x_words_are_diameters_and_the_work_position_reads_as_one(tmp_path: Path) -> None:
    moves, _, result = run(tmp_path, "G0 X50 Z2\nG91 G1 X-4 F100\n#100 = #5001\n#101 = #5071\nG90\n")
    assert moves[0].end[0] == 25.0 and moves[1].end[0] == 23.0
    assert result.variables[100] == 46.0 and result.variables[101] == 23.0  # type: ignore[attr-defined]
    assert result.position[0] == 46.0 and result.machine[0] == 23.0  # type: ignore[attr-defined]


def test_radius_mode_lathe_and_mill_keep_x(tmp_path: Path) -> None:
    moves, _, result = run(tmp_path, "G0 X50\n#100 = #5001\n", diameter=False)
    assert moves[0].end[0] == 50.0 and result.variables[100] == 50.0  # type: ignore[attr-defined]


def test_lathe_starts_and_ends_in_g18(tmp_path: Path) -> None:
    moves, _, result = run(tmp_path, "G0 X20 Z0\nG2 X20 Z-10 R5 F100\nM30\n")
    assert moves[-1].arc is not None and moves[-1].arc.plane == "XZ"
    assert "G18" in result.modal  # type: ignore[attr-defined]


@pytest.mark.parametrize("code, hint", [("G7", "diameterProgramming = 1"), ("G8", "diameterProgramming = 0")])
def test_linuxcnc_diameter_codes_are_errors_with_a_hint(tmp_path: Path, code: str, hint: str) -> None:
    message = failure(tmp_path, f"G0 X10\n{code}\n")
    assert f":2:1: error: unknown G code {code}: " in message and hint in message


@pytest.mark.parametrize("line", ["G96 S200 D2000", "G76 P1.5 Z-20 I-1 J0.1 K1"])
def test_lathe_codes_stop_a_mill_at_their_line(line: str) -> None:
    with pytest.raises(EcncError) as info:
        run_string(f"G21\nM3 S500\n{line}\n")
    code = line.split()[0]
    assert info.value.format().startswith(f"<string>:3:1: error: {code} is a lathe code and this machine is a mill: ")
    assert "machineType = 1" in info.value.format()
    run_string("G21\nG97 S500 M3\nG95 G1 Z-1 F0.1\nG33 Z-5 K1\nG94\nM96\nM30\n")  # what a mill has too (M96 is not G96)


def test_g28_moves_x_first_on_a_lathe(tmp_path: Path) -> None:
    moves, _, _ = run(tmp_path, "#5161 = 100\n#5163 = 300\nG0 X20 Z-50\nG28\n")
    assert [(m.end[0], m.end[2]) for m in moves[1:]] == [(100.0, -50.0), (100.0, 300.0)]


def test_g43_applies_x_and_z_offsets_with_wear(tmp_path: Path) -> None:
    """On a diameter lathe the table's width + xDelta is a diameter value: G43 moves X by half of it."""
    moves, _, result = run(tmp_path, "G43 H2\nG0 X20 Z5\n#100 = #5001\n#101 = #5003\nG49\nG0 X20 Z5\n")
    assert moves[0].end[0] == pytest.approx(10 + (-1.5 + 0.1) / 2) and moves[0].end[2] == pytest.approx(5 + 4 + 0.25)
    assert result.variables[100] == pytest.approx(20.0)  # type: ignore[attr-defined]
    assert result.variables[101] == pytest.approx(5.0)  # type: ignore[attr-defined]
    assert (moves[1].end[0], moves[1].end[2]) == (10.0, 5.0)


def test_tool_table_keys_load_into_the_tool_parameters(tmp_path: Path) -> None:
    _, _, result = run(tmp_path, "#100 = #5402\n#101 = #5602\n#102 = #5702\n#103 = #5802\n#104 = #5902\n")
    assert [result.variables[n] for n in range(100, 105)] == [4.0, -1.5, 3.0, 0.1, 0.25]  # type: ignore[attr-defined]


# ----------------------------------------------------------------- spindle modes

def test_css_follows_the_radius_clamped_to_d_and_the_machine(tmp_path: Path) -> None:
    moves, events, _ = run(tmp_path, "G0 X100 Z1\nG96 S150 D2500 M3\nG1 X40 F100\nG1 X2\nG96 S150 D9000\nG1 X1\n")
    assert moves[1].spindle == pytest.approx(150_000 / (2 * math.pi * 20))
    assert moves[1].css is not None and moves[1].css.rpm(50.0) == pytest.approx(150_000 / (2 * math.pi * 50))
    assert moves[2].spindle == 2500.0      # D
    assert moves[3].spindle == 3000.0      # spindleNmax caps a higher D
    setting = [e for e in events if e.kind == "spindle_speed"][-1]
    assert setting.data["mode"] == "css" and setting.data["max_rpm"] == 3000.0


def test_g97_keeps_the_speed_css_reached_and_clamps_s(tmp_path: Path) -> None:
    moves, _, result = run(tmp_path, "G0 X40 Z1\nG96 S100 D2000 M3\nG97\nG0 X80\nG97 S5000\nG0 X20\nG97 S10\nG0 X30\n")
    reached = 100_000 / (2 * math.pi * 20)
    assert moves[1].spindle == pytest.approx(reached) and moves[1].css is None
    assert moves[2].spindle == 3000.0 and moves[3].spindle == 50.0
    assert result.spindle["mode"] == "G97" and result.spindle["rpm"] == 50.0  # type: ignore[attr-defined]


def test_g95_feed_uses_the_speed_along_the_move(tmp_path: Path) -> None:
    moves, _, _ = run(tmp_path, "G97 S1000 M3\nG95 F0.2\nG0 X40 Z1\nG1 Z-20\nG96 S100 D2000\nG1 X0\n")
    assert moves[1].feed == pytest.approx(200.0)
    face = moves[2]  # radius 20 -> 0: rpm 796 rising to the 2000 clamp
    css = face.css
    assert css is not None
    n = 100_000
    minutes = sum(1 / css.rpm(20 - 20 * (i + 0.5) / n) for i in range(n)) / n * 20 / 0.2
    assert face.feed == pytest.approx(20 / minutes, rel=1e-6)


def test_g95_without_a_spindle_speed_is_an_error(tmp_path: Path) -> None:
    assert "feed per revolution (G95) with no spindle speed" in failure(tmp_path, "G95 F0.1\nG1 Z-5\n")


def test_css_to_the_centre_without_any_maximum_is_an_error(tmp_path: Path) -> None:
    ini = lathe(tmp_path)
    ini.write_text(ini.read_text().replace("spindleNmax = 3000", "spindleNmax = 0"))
    with pytest.raises(EcncError, match="no maximum spindle speed"):
        run_string("G0 X40\nG96 S100 M3\nG95 F0.1\nG1 X0\n", RunOptions(ini=ini, macro=tmp_path / "macro.cnc"))


def test_negative_d_is_an_error(tmp_path: Path) -> None:
    assert "G96 D-5: the maximum spindle speed must not be negative" in failure(tmp_path, "G96 S100 D-5\n")


# ----------------------------------------------------------------- threading

def test_g33_is_a_synchronised_linear_move(tmp_path: Path) -> None:
    moves, _, _ = run(tmp_path, "G97 S400 M3\nG0 X20 Z2\nG33 Z-20 K1.5\nG0 X24\nG33 X20 Z-30\n")
    cut = moves[1]
    assert (cut.kind, cut.sync, cut.feed, cut.spindle) == ("linear", 1.5, 600.0, 400.0)
    assert moves[3].sync == 1.5  # K stays in force


def test_g33_1_taps_in_reverses_and_comes_back(tmp_path: Path) -> None:
    moves, events, _ = run(tmp_path, "G97 S200 M3\nG0 X0 Z5\nG33.1 Z-15 K1.25\n")
    assert [(m.end[2], m.sync) for m in moves[1:]] == [(-15.0, 1.25), (5.0, 1.25)]
    taps = [e.data["m"] for e in events if e.kind == "spindle" and e.data.get("rigid_tap")]
    assert taps == [4, 3]


@pytest.mark.parametrize("job, message", [
    ("G0 X20\nG33 Z-10 K1\n", "G33 needs the spindle turning"),
    ("G97 S100 M3\nG33 Z-10\n", "G33 needs K"),
    ("G97 S100 M3\nG33.1 Z-10 K-1\n", "G33.1 K-1: the pitch"),
    ("G97 S100 M3\nG17\nG76 P1 Z-10 I18 J0.1 K0.6\n", "G76 threads in the XZ plane"),
    ("G97 S100 M3\nG76 X10 P1 Z-10 I18 J0.1 K0.6\n", "G76 takes no X word"),
    ("G97 S100 M3\nG0 X20 Z0\nG76 P1 Z-10 I18 J0.1 K0.6 R0.5\n", "R0.5: the depth degression must be at least 1"),
    ("G97 S100 M3\nG0 X20 Z0\nG76 P1 Z-10 I18 J0.1 K0.6 E6\n", "longer than half the drive line"),
    ("G97 S100 M3\nG0 X20 Z0\nG76 P1 Z-10 I18 J0.1 K0.6 H-2\n", "spring passes"),
    ("G97 S100 M3\nG0 X20 Z0\nG76 P-1 Z-10 I18 J0.1 K0.6\n", "P-1: the pitch must be greater than 0"),
    ("G97 S100 M3\nG0 X20 Z0\nG76 P1 Z-10 I18 J-0.1 K0.6\n", "J-0.1: the first cut depth must be greater than 0"),
    ("G97 S100 M3\nG0 X20 Z0\nG76 P1 Z-10 I18 J0.1 K-0.6\n", "K-0.6: the thread depth must be greater than 0"),
    ("G97 S100 M3\nG0 X20 Z0\nG76 P1 Z-10 I18 J0.8 K0.6\n", "K0.6 must be greater than J0.8"),
    ("G20\nG97 S100 M3\nG0 X1 Z0\nG76 P0.05 Z-1 I0.96 J0.004 K0.03 E0.6\n", "E0.6 is longer than half the drive line (0.5)"),
    ("G97 S100 M3\nG0 X14 Z3\nG76 P1.5 Z-20 I-2 J0.4 K1.84\n",
     "G76 I-2: EdingCNC reads I as the thread's crest diameter (an X position, always positive, manual 3.6.18)"),
    ("G97 S100 M3\nG0 X14 Z3\nG76 P1.5 Z-20 I-2 J0.4 K1.84\n", "write the crest diameter I12"),
    ("G97 S100 M3\nG0 X14 Z3\nG76 P1.5 Z-20 I0 J0.2 K0.92\n", "G76 I0: EdingCNC reads I as the thread's crest"),
])
def test_threading_errors_name_the_line(tmp_path: Path, job: str, message: str) -> None:
    """The words are quoted as written, in the program's units."""
    text = failure(tmp_path, job)
    assert message in text and f"<string>:{job.count(chr(10))}:" in text


def test_g76_i_is_the_crest_diameter_and_j_k_radial_depths(tmp_path: Path) -> None:
    """Manual 3.6.18: I the thread's diameter, J and K depths beyond it. An M12x1.5 from X14:
    crest radius 6, the first cut 0.2 and the last 0.92 below it (root diameter 10.16)."""
    moves, _, _ = run(tmp_path, "G97 S500 M3\nG0 X14 Z3\nG76 P1.5 Z-20 I12 J0.2 K0.92\n")
    cuts = [m for m in moves if m.sync]
    assert cuts[0].end[0] == pytest.approx(6 - 0.2) and cuts[-1].end[0] == pytest.approx(6 - 0.92)
    assert all(m.feed == pytest.approx(750.0) for m in cuts)
    assert (moves[-1].end[0], moves[-1].end[2]) == (7.0, -20.0)


def test_g76_manual_example_cuts_an_outer_thread_of_15_in_10_passes(tmp_path: Path) -> None:
    """The manual's example (3.6.18): G0 X20 Z20, G76 P1.0 Z10 I15 J0.1 K1.0."""
    moves, _, _ = run(tmp_path, "G97 S400 M3\nG0 X20 Z20\nG76 P1.0 Z10 I15 J0.1 K1.0\n")
    cuts = [m for m in moves if m.sync]
    assert len(cuts) == 10
    assert [round(2 * c.end[0], 6) for c in cuts] == [round(15 - 0.2 * n, 6) for n in range(1, 11)]
    assert all(c.start[2] == 20.0 and c.end[2] == 10.0 for c in cuts)
    assert all(m.end[0] >= 7.5 for m in moves if not m.sync and m.start[0] == m.end[0])  # the returns: outside


def test_g76_i_is_absolute_in_g91_and_follows_the_work_offset(tmp_path: Path) -> None:
    moves, _, _ = run(tmp_path, "G10 L2 P1 X4\nG97 S400 M3\nG0 X20 Z2\nG91\nG76 P1 Z-10 I16 J0.1 K0.5\n")
    cuts = [m for m in moves if m.sync]
    assert cuts[-1].end[0] == pytest.approx(2 + 8 - 0.5)       # G54 X4 (a diameter): radius 2, crest radius 8
    assert cuts[-1].end[2] == pytest.approx(-8.0)              # Z incremental, as any Z word in G91


def test_spindle_speed_variable_follows_x_under_css(tmp_path: Path) -> None:
    _, _, result = run(tmp_path, "G0 X100\nG96 S120 D3000 M3\n#100 = #5070\nG0 X50\n#101 = #5070\nM5\n#102 = #5070\n")
    rps = [result.variables[n] for n in (100, 101, 102)]  # type: ignore[attr-defined]
    assert rps[0] == pytest.approx(120_000 / (2 * math.pi * 50) / 60)
    assert rps[1] == pytest.approx(2 * rps[0]) and rps[2] == 0.0


def test_css_in_inches_is_feet_per_minute(tmp_path: Path) -> None:
    moves, _, _ = run(tmp_path, "G20\nG0 X2\nG96 S500 D3000 M3\nG0 Z0.1\n")
    assert moves[-1].spindle == pytest.approx(500 * 304.8 / (2 * math.pi * 25.4))


def test_offsets_read_x_as_a_diameter(tmp_path: Path) -> None:
    job = "G0 X60 Z10\nG10 L20 P1 X50\n#100 = #5001\n#101 = #5221\nG92 X40\n#102 = #5001\n#103 = #5211\n"
    _, _, result = run(tmp_path, job)
    values = [result.variables[n] for n in range(100, 104)]  # type: ignore[attr-defined]
    assert values == [50.0, 5.0, 40.0, 5.0]  # radius 30 shown as 50 -> offset 5; then G92 shifts 5 more


def test_css_centre_is_work_x0_with_the_tool_offset(tmp_path: Path) -> None:
    moves, _, _ = run(tmp_path, "G10 L2 P1 X7\nG43 H2\nG96 S100 D3000 M3\nG0 X40 Z5\n")
    css = moves[0].css
    assert css is not None and css.axis_x == pytest.approx(7 / 2 + (-1.5 + 0.1) / 2)  # G10 L2 X is a diameter too
    assert moves[0].spindle == pytest.approx(100_000 / (2 * math.pi * 20))


@settings(max_examples=40)
@given(st.lists(st.tuples(st.sampled_from(["G0", "G1", "G33"]), st.floats(0.5, 80).map(lambda v: round(v, 3)),
                          st.floats(-60, 5).map(lambda v: round(v, 3))), min_size=1, max_size=8),
       st.booleans())
def test_diameter_mode_is_radius_mode_with_doubled_x(moves_in: list[tuple[str, float, float]], inch: bool) -> None:
    import tempfile

    def lines(factor: float) -> str:
        body = "".join(f"{g} X{x * factor:.4f} Z{z}{' K1.5' if g == 'G33' else ''}\n" for g, x, z in moves_in)
        return f"{'G20' if inch else 'G21'}\nG97 S500 M3\nG95 F0.1\n{body}"

    with tempfile.TemporaryDirectory() as folder:
        dia, _, _ = run(Path(folder), lines(2.0), diameter=True)
    with tempfile.TemporaryDirectory() as folder:
        rad, _, _ = run(Path(folder), lines(1.0), diameter=False)
    assert [(m.kind, m.sync) for m in dia] == [(m.kind, m.sync) for m in rad]
    for a, b in zip(dia, rad):
        assert a.end == pytest.approx(b.end, abs=1e-9) and a.feed == pytest.approx(b.feed)


def test_probe_results_follow_the_diameter_convention(tmp_path: Path) -> None:
    _, _, result = run(tmp_path, "G0 X40 Z5\nG38.2 X10 F100\n#100 = #5061\n#101 = #5051\n")
    assert result.variables[100] == 10.0 and result.variables[101] == 5.0  # type: ignore[attr-defined]


def test_absolute_arc_centre_x_is_a_diameter(tmp_path: Path) -> None:
    moves, _, _ = run(tmp_path, "G0 X20 Z0\nG3 X40 Z-10 I20 K-10 F100\n",
                      extra="[INTERPRETER]\nabsoluteCenterCoords = 1\n")
    arc = moves[-1].arc
    assert arc is not None and arc.center == pytest.approx((10.0, -10.0))  # (x, z): radius 10, as I20 says


@pytest.mark.parametrize("diameter", [True, False])
def test_g10_l10_x_on_a_lathe_reads_the_programmed_x_with_the_wear(tmp_path: Path, diameter: bool) -> None:
    """G10 L10 P2 X.. takes X as a move does (a diameter in diameter mode) and leaves xDelta (#5802)
    out of the offset it sets, so that under G43 the current position reads the X written."""
    x = 30.0 if diameter else 15.0  # the same point: radius 15
    _, _, result = run(tmp_path, f"G0 X{x:g} Z5\nG10 L10 P2 X{x:g} Z5\nG43 H2\n#100 = #5001\n#101 = #5003\n",
                       diameter)
    assert result.variables[5602] == pytest.approx(-0.1)  # radius 15 - 15 - wear 0.1
    assert result.variables[5402] == pytest.approx(-0.25)
    assert (result.variables[100], result.variables[101]) == pytest.approx((x, 5.0))


def test_g76_in_the_turning_macros_external_form(tmp_path: Path) -> None:
    """A turning-macro set's external cycle: start on the crest (X = I = diameter A), K = (A - B) / 2
    for the minor diameter B of M12x1 (10.773); 7 degressive passes, K once, one spring pass."""
    moves, _, _ = run(tmp_path, "G97 S800 M4\nG0 X12 Z0\nG76 P1 Z-10 I12 J0.08 K0.6135 H1\n")
    cuts = [m for m in moves if m.sync]
    assert len(cuts) == 9
    assert 2 * cuts[0].end[0] == pytest.approx(12 - 0.16) and 2 * cuts[-1].end[0] == pytest.approx(10.773)
    assert all(m.end[0] >= 6.0 for m in moves if not m.sync and m.start[2] != m.end[2])  # travel: never in the bar


def test_g76_in_the_turning_macros_internal_form(tmp_path: Path) -> None:
    """Their internal cycle: start in the bore at X[B - pitch], I[A - 2K] (= B, the crest), K = (A - B) / 2:
    an inside thread cut outwards from 10.917 to 12."""
    moves, _, _ = run(tmp_path, "G97 S800 M4\nG0 X[10.917 - 1] Z0\nG76 P1 Z-10 I[12 - [2 * 0.5415]] J0.08 K0.5415 H1\n")
    cuts = [m for m in moves if m.sync]
    assert len(cuts) == 8
    assert 2 * cuts[0].end[0] == pytest.approx(10.917 + 0.16) and 2 * cuts[-1].end[0] == pytest.approx(12.0)
    assert all(m.end[0] <= 10.917 / 2 for m in moves if not m.sync and m.start[2] != m.end[2])  # travel: in the bore
