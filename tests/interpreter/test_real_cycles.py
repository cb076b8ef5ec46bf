"""G74 and G87 cycles, PWM outputs read back, the tool-change-area guard."""
from __future__ import annotations

from pathlib import Path

import pytest

from edingcnc_lang.canon import Event, Move
from edingcnc_lang.errors import MachineError
from edingcnc_lang.runner import RunOptions, RunResult, run_string


def run(text: str, moves: list[Move] | None = None, events: list[Event] | None = None,
        **options: object) -> RunResult:
    moves = moves if moves is not None else []
    events = events if events is not None else []
    return run_string(text, RunOptions(on_move=lambda m, j: moves.append(m), on_event=events.append,
                                       **options))  # type: ignore[arg-type]


def test_g74_taps_left_handed_reversing_the_spindle_at_the_bottom() -> None:
    """Manual 3.6.20.7: F is the pitch (mm per revolution), the feed follows the spindle, which
    reverses at the bottom; out at the same pitch to the clear level (R under G99)."""
    moves: list[Move] = []
    events: list[Event] = []
    run("M4 S500\nG0 Z10\nG99 G74 X5 Y5 Z-8 R2 F1.25\n", moves, events)
    cycle = [(m.kind, m.end[0], m.end[2], m.feed, m.sync) for m in moves if m.line == 3]
    assert cycle == [("rapid", 5.0, 10.0, 0.0, 0.0), ("rapid", 5.0, 2.0, 0.0, 0.0),
                     ("linear", 5.0, -8.0, 625.0, 1.25), ("linear", 5.0, 2.0, 625.0, 1.25)]
    spindle = [e.data for e in events if e.kind == "spindle" and e.line == 3]
    assert [e["m"] for e in spindle] == [3, 4]  # reversed to come out, then turning as programmed again
    assert [e["rpm"] for e in spindle] == [500.0, 500.0] and all(e["rigid_tap"] for e in spindle)


def test_g87_back_bores_from_below() -> None:
    """Manual 3.6.20.10, steps 2..13."""
    moves: list[Move] = []
    events: list[Event] = []
    run("M3 S800\nG0 Z5\nG98 G87 X10 Y0 Z-20 R2 I3 J0 K-12 F100\n", moves, events)
    path = [(m.kind, m.end[0], m.end[2]) for m in moves if m.line == 3]
    assert path == [("rapid", 10.0, 5.0), ("rapid", 10.0, 2.0),          # over the hole, down to R
                    ("rapid", 13.0, 2.0), ("rapid", 13.0, -20.0),        # shifted past the bar, below the part
                    ("rapid", 10.0, -20.0), ("linear", 10.0, -12.0),     # centred, bore up to K
                    ("linear", 10.0, -20.0),                             # and back down at the feed
                    ("rapid", 13.0, -20.0), ("rapid", 13.0, 5.0),        # shifted, out to the start level
                    ("rapid", 10.0, 5.0)]
    assert [e.data["m"] for e in events if e.kind == "spindle" and e.line == 3] == [5, 3, 5, 3]
    # the bar passes the part with the spindle stopped: those moves carry 0 rpm, the bore 800
    assert [m.spindle for m in moves if m.line == 3] == [800.0, 800.0, 800.0, 0.0, 0.0, 800.0, 800.0, 0.0, 0.0, 0.0]
    after = run("M3 S800\nG0 Z5\nG98 G87 X10 Y0 Z-20 R2 I3 J0 K-12 F100\n").spindle
    assert (after["m"], after["rpm"]) == (3, 800.0)  # turning as programmed after the cycle


def test_pwm_outputs_are_read_back_with_m57() -> None:
    result = run("M54 E2 Q500\nM57 E2\n#100 = #5399\nM55 E2\nM57 E2\n#101 = #5399\nM54 P3\nM57 P3\n#102 = #5399\n")
    assert (result.variables[100], result.variables[101], result.variables[102]) == (500.0, 0.0, 1.0)
    with pytest.raises(MachineError, match="must lie in 0..1000"):
        run("M54 E1 Q1500\n")


def tca_ini(tmp_path: Path) -> Path:
    ini = tmp_path / "cnc.ini"
    ini.write_text("[KINEMATICS]\r\nnegativeLimitTCAX = -20\r\npositiveLimitTCAX = 0\r\nnegativeLimitTCAY = 0\r\n"
                   "positiveLimitTCAY = 100\r\nnegativeLimitTCAZ = -50\r\npositiveLimitTCAZ = 0\r\n")
    return ini


def test_a_move_into_the_tool_change_area_is_refused_while_tcaguard_is_on(tmp_path: Path) -> None:
    ini = tca_ini(tmp_path)
    with pytest.raises(MachineError) as info:
        run("G0 X10 Y50 Z-10\nTCAGuard on\nG0 X5\nG1 X-10 F500\n", ini=ini)
    assert "tool-change area" in info.value.message and info.value.location.line == 4  # type: ignore[union-attr]
    result = run("TCAGuard on\nG0 Z10\nG0 X-10 Y50\nTCAGuard off\nG0 Z-10\nTCAGuard on\nG0 X10\n", ini=ini)
    assert result.machine[:3] == (10.0, 50.0, -10.0)  # passing over it, and leaving it, are allowed
