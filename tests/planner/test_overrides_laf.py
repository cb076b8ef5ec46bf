"""The job's own overrides and look-ahead settings in the planned time (issue 38), as the manual says.

Manual 3.7.5 (p. 61): "M50 P .. Vorschubüberschreibung auf den angegebenen P-Wert einstellen, wenn
der P-Wert kleiner als Null ist, ist die Vorschubüberschreibung deaktiviert und der Wert bleibt
unverändert"; "M51 P .. Geschwindigkeitsüberschreibung auf den angegebenen P-Wert einstellen";
"M48 ... auf den letzten Wert für die Überschreibung des Benutzervorschubs zurücksetzen"; "M49 ...
deaktivieren und auf 100% einstellen".  3.6.16 (p. 38): "G64 R .. Der R- Parameter ist der
Vorausschau-Vorschubwinkel ... Mit R0 wird LAF ausgeschaltet"; p. 40: "Volle Geschwindigkeit, wenn
der Winkel kleiner als der R-Winkel ist. Reduzierte Geschwindigkeit abhängig von D, wenn der Winkel
zwischen dem R- und dem S-Winkel liegt".
"""
from __future__ import annotations

from pathlib import Path

import pytest

from edingcnc_lang import RunOptions, run_string
from edingcnc_lang.canon import Event
from edingcnc_lang.errors import EcncError
from tests.planner.test_planner_runs import machine, rest_to_rest, run
from tests.cli_runner import invoke


def seconds(tmp_path: Path, job: str, **options: object) -> float:
    return run(tmp_path, job, **options).estimate.seconds


def test_m50_p_is_the_feed_override_in_percent(tmp_path: Path) -> None:
    # the numbers: M50 P50 then G1 X100 F600 takes 20 s, not 10 s (10 mm/s against 1000 mm/s^2)
    assert seconds(tmp_path, "M50 P50\nG1 X100 F600\n") == pytest.approx(rest_to_rest(100.0, 5.0))
    assert seconds(tmp_path, "G1 X100 F600\n") == pytest.approx(rest_to_rest(100.0, 10.0))
    # the job's value replaces the knob's; M48 resets it to the knob's value
    assert seconds(tmp_path, "M50 P200\nG1 X100 F600\n", feed_override=50.0) == pytest.approx(
        rest_to_rest(100.0, 20.0))
    assert seconds(tmp_path, "M50 P200\nM48\nG1 X100 F600\n", feed_override=50.0) == pytest.approx(
        rest_to_rest(100.0, 5.0))


def test_a_negative_p_switches_the_override_off_and_keeps_its_value(tmp_path: Path) -> None:
    assert seconds(tmp_path, "M50 P50\nM50 P-1\nG1 X100 F600\n") == pytest.approx(rest_to_rest(100.0, 10.0))
    # M50 without P switches it on again at the value it kept
    assert seconds(tmp_path, "M50 P50\nM50 P-1\nM50\nG1 X100 F600\n") == pytest.approx(rest_to_rest(100.0, 5.0))
    # M49 switches it off (100 %)
    assert seconds(tmp_path, "M50 P50\nM49\nG1 X100 F600\n") == pytest.approx(rest_to_rest(100.0, 10.0))


def test_m50_p0_waits_for_the_operator_and_the_run_goes_on_at_the_knob(tmp_path: Path) -> None:
    events: list[Event] = []
    result = run(tmp_path, "M48\nM50 P0\nG1 X100 F600\n", feed_override=80.0, on_event=events.append)
    assert result.estimate.seconds == pytest.approx(rest_to_rest(100.0, 8.0))  # finite, at the knob's 80 %
    waits = [e for e in events if e.kind == "operator_wait"]
    assert [(e.line, e.data) for e in waits] == [(2, {"m": 50, "override": "feed"})]
    assert len(result.estimate.notes) == 1 and "M50 P0 waits for the operator" in result.estimate.notes[0]
    assert "at 80 %" in result.estimate.notes[0]
    assert result.estimate.to_json()["notes"] == result.estimate.notes
    assert "1 wait for the operator not counted" in result.estimate.summary()


def test_m50_p0_on_the_command_line(tmp_path: Path) -> None:
    job = tmp_path / "job.nc"
    job.write_text("M48\nM50 P0\nG1 X100 F600\nM30\n")
    out = invoke("run", str(job), "--ini", str(machine(tmp_path)), "--feed-override", "50", "--json")
    assert out.exit_code == 0, out.output
    assert '"notes"' in out.output and "M50 P0 waits for the operator" in out.output


def test_m51_p_scales_the_spindle_speed_and_the_time_per_revolution(tmp_path: Path) -> None:
    # manual pp. 61, 67-68: 1000 rpm under M51 P50 turns at 500 rpm; #5070 (rev/s) reads it
    result = run(tmp_path, "M3 S1000\nM51 P50\n#1 = #5070\nG95 G1 X10 F0.1\n")
    assert result.variables[1] == pytest.approx(500.0 / 60.0)
    assert result.estimate.seconds == pytest.approx(rest_to_rest(10.0, 50.0 / 60.0))
    assert result.spindle["rpm"] == pytest.approx(500.0)
    # a negative P switches it off (1000 rpm again), M49 too, M48 back on at 100 %
    for job in ("M3 S1000\nM51 P50\nM51 P-1\n", "M3 S1000\nM51 P50\nM49\n", "M3 S1000\nM51 P50\nM48\n"):
        assert run(tmp_path, job).spindle["rpm"] == pytest.approx(1000.0), job
    # M51 P0 waits for the operator; the run goes on at 100 % (there is no spindle knob in a simulation)
    events: list[Event] = []
    result = run(tmp_path, "M3 S1000\nM51 P0\n", on_event=events.append)
    assert result.spindle["rpm"] == pytest.approx(1000.0)
    assert [e.data for e in events if e.kind == "operator_wait"] == [{"m": 51, "override": "spindle"}]


def test_an_override_over_1000_percent_is_an_error_at_its_line(tmp_path: Path) -> None:
    with pytest.raises(EcncError, match="at most 1000 percent") as err:
        run_string("G0 X1\nM50 P5000\n", RunOptions())
    assert err.value.location is not None and err.value.location.line == 2


ZIGZAG = "G1 X50 F6000\nX100 Y10\nX150 Y0\nX200 Y10\n"  # corners of 11.3, 22.6, 22.6 degrees; 100 mm/s


def test_g64_r_is_the_look_ahead_angle_and_r0_switches_it_off(tmp_path: Path) -> None:
    blended = seconds(tmp_path, "G64 R30\n" + ZIGZAG)  # every corner below R: full speed through them
    stopped = seconds(tmp_path, "G64 R0\n" + ZIGZAG)   # LAF off: every corner a stop
    assert stopped == pytest.approx(seconds(tmp_path, "G61\n" + ZIGZAG))
    assert seconds(tmp_path, "G64 R10\n" + ZIGZAG) == pytest.approx(stopped)  # above R the standard algorithm stops
    assert blended < seconds(tmp_path, "G64 R20\n" + ZIGZAG) < stopped  # the first corner blended, the others not
    assert blended < stopped - 0.2
    # the angle stays until the job changes it; G64 P alone keeps it
    assert seconds(tmp_path, "G64 R0\nG64 P0.01\n" + ZIGZAG) == pytest.approx(stopped)


def test_g64_s_and_d_limit_the_corners_between_r_and_s(tmp_path: Path) -> None:
    stopped = seconds(tmp_path, "G64 R0\n" + ZIGZAG)
    full = seconds(tmp_path, "G64 R30\n" + ZIGZAG)
    tight = seconds(tmp_path, "G64 R5 S90 D0.001\n" + ZIGZAG)  # a virtual circle 0.001 mm from the corner
    loose = seconds(tmp_path, "G64 R5 S90 D0.1\n" + ZIGZAG)
    assert full < loose < tight < stopped
