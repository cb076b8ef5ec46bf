"""Whole runs timed by the planner, against answers worked out by hand from the cnc.ini values."""
from __future__ import annotations

import csv
import math
from pathlib import Path

import pytest

from edingcnc_lang import RunOptions, run_string
from edingcnc_lang.motion.sinks import Timing
from edingcnc_lang.runner import RunResult
from tests.cli_runner import invoke

VELOCITY, ACCEL = 100.0, 1000.0   # every joint: mm/s, mm/s^2


def machine(tmp_path: Path, trajectory: str = "", interpreter: str = "", joint: str = "") -> Path:
    """A cnc.ini with six equal joints (100 mm/s, 1000 mm/s^2) and extra keys."""
    sections = [f"[JOINT_{i}]\r\nmaxVelocity = {VELOCITY}\r\nmaxAcceleration = {ACCEL}\r\n"
                f"negativeLimit = -500\r\npositiveLimit = 500\r\n{joint}" for i in range(6)]
    sections.append(f"[TRAJECTORY]\r\ninterpolationTime = 0.005\r\n{trajectory}")
    sections.append(f"[INTERPRETER]\r\n{interpreter}")
    path = tmp_path / "cnc.ini"
    path.write_text("".join(sections).replace("\n", "\r\n").replace("\r\r\n", "\r\n"), newline="")
    return path


def rest_to_rest(length: float, speed: float, accel: float = ACCEL) -> float:
    return length / speed + speed / accel if length >= speed * speed / accel else 2.0 * math.sqrt(length / accel)


def run(tmp_path: Path, job: str, **options: object) -> RunResult:
    ini = options.pop("ini", None) or machine(tmp_path)
    return run_string(job, RunOptions(ini=ini, **options))  # type: ignore[arg-type]


def test_single_feed_move_is_a_trapezoid(tmp_path: Path) -> None:
    result = run(tmp_path, "G1 X100 F3000\n")  # 50 mm/s
    assert result.estimate.seconds == pytest.approx(rest_to_rest(100.0, 50.0))
    assert result.estimate.feed_seconds == result.estimate.seconds
    assert result.estimate.feed_distance == pytest.approx(100.0)


def test_short_move_never_reaches_its_feed(tmp_path: Path) -> None:
    result = run(tmp_path, "G1 X1 F6000\n")  # would need 5 mm to reach 100 mm/s
    assert result.estimate.seconds == pytest.approx(2.0 * math.sqrt(1.0 / ACCEL))


def test_diagonal_is_limited_by_each_axis(tmp_path: Path) -> None:
    # X and Y each at most 100 mm/s: the diagonal runs at 100 sqrt 2, and accelerates at 1000 sqrt 2
    result = run(tmp_path, "G1 X300 Y300 F60000\n")
    assert result.estimate.seconds == pytest.approx(rest_to_rest(300 * math.sqrt(2), 100 * math.sqrt(2),
                                                                 ACCEL * math.sqrt(2)))


def test_rapid_runs_at_the_g0_factors(tmp_path: Path) -> None:
    ini = machine(tmp_path, "g0VelocityFactor = 0.5\r\ng0AccelelerationFactor = 0.25\r\n")
    result = run(tmp_path, "G0 X100\n", ini=ini)
    assert result.estimate.rapid_seconds == pytest.approx(rest_to_rest(100.0, 50.0, 250.0))
    assert result.estimate.rapid_distance == pytest.approx(100.0)


def test_exact_stop_square_is_four_single_moves(tmp_path: Path) -> None:
    result = run(tmp_path, "G61\nG1 X50 F3000\nY50\nX0\nY0\n")
    assert result.estimate.seconds == pytest.approx(4 * rest_to_rest(50.0, 50.0))


def test_g64_blends_collinear_moves_into_one(tmp_path: Path) -> None:
    job = "G1 F3000\n" + "".join(f"X{10 * k}\n" for k in range(1, 11))
    assert run(tmp_path, "G64\n" + job).estimate.seconds == pytest.approx(rest_to_rest(100.0, 50.0))
    assert run(tmp_path, "G61\n" + job).estimate.seconds == pytest.approx(10 * rest_to_rest(10.0, 50.0))


def test_g64_p_slows_the_corner_to_stay_within_the_tolerance(tmp_path: Path) -> None:
    """A right angle with P0.01: blend radius 0.01 cos45/(1 - cos45), corner speed sqrt(a R)."""
    radius = 0.01 * math.cos(math.pi / 4) / (1 - math.cos(math.pi / 4))
    corner = math.sqrt(ACCEL * radius)
    speed = 50.0
    # each leg: from rest or to rest at one end, down to or up from the corner speed at the other
    ramp = (speed - corner) / ACCEL
    leg = 100.0 / speed + speed / (2 * ACCEL) + ramp - (speed ** 2 - corner ** 2) / (2 * ACCEL) / speed
    result = run(tmp_path, "G64 P0.01\nG1 X100 F3000\nY100\n")
    assert result.estimate.seconds == pytest.approx(2 * leg)
    free = run(tmp_path, "G64\nG1 X100 F3000\nY100\n").estimate.seconds
    stop = run(tmp_path, "G61\nG1 X100 F3000\nY100\n").estimate.seconds
    assert free < result.estimate.seconds < stop


def test_arc_respects_the_centripetal_limit(tmp_path: Path) -> None:
    # full circle, r = 4: turning may use sqrt(3)/2 of a, v^2 / r <= 866 mm/s^2 gives 58.9 mm/s although F
    # asks for 100 mm/s; speeding up along the circle gets the rest, a - v^2 / r
    result = run(tmp_path, "G1 X4 F6000\nG61\nG2 X4 Y0 I-4 J0\n")
    speed = math.sqrt(ACCEL * math.sqrt(3) / 2 * 4.0)
    circle = rest_to_rest(2 * math.pi * 4.0, speed, ACCEL - speed ** 2 / 4.0)
    assert result.estimate.seconds == pytest.approx(rest_to_rest(4.0, 100.0) + circle)


def test_feed_per_revolution_uses_the_spindle_speed(tmp_path: Path) -> None:
    # G95 F0.1 at S500: 50 mm/min
    result = run(tmp_path, "S500 M3\nG95 G1 X10 F0.1\n")
    assert result.estimate.seconds == pytest.approx(rest_to_rest(10.0, 50.0 / 60.0))


def test_inverse_time_feed(tmp_path: Path) -> None:
    # G93 F2: the move takes half a minute at speed
    result = run(tmp_path, "G93 G1 X10 F2\n")
    assert result.estimate.seconds == pytest.approx(rest_to_rest(10.0, 20.0 / 60.0))


def test_dwell_stops_the_machine_and_adds_its_time(tmp_path: Path) -> None:
    result = run(tmp_path, "G1 X10 F3000\nG4 P2.5\nX20\n")
    assert result.estimate.dwell_seconds == 2.5
    assert result.estimate.seconds == pytest.approx(2 * rest_to_rest(10.0, 50.0) + 2.5)


def test_feed_override_and_m50(tmp_path: Path) -> None:
    base = rest_to_rest(100.0, 50.0)
    assert run(tmp_path, "G1 X100 F3000\n", feed_override=50.0).estimate.seconds == pytest.approx(
        rest_to_rest(100.0, 25.0))
    # M50 P-1 switches the knob off (manual p. 61: "wenn der P-Wert kleiner als Null ist, ist die
    # Vorschubüberschreibung deaktiviert"); M49 too; M48 gives it back
    assert run(tmp_path, "M50 P-1\nG1 X100 F3000\n", feed_override=50.0).estimate.seconds == pytest.approx(base)
    assert run(tmp_path, "M49\nG1 X100 F3000\n", feed_override=50.0).estimate.seconds == pytest.approx(base)
    assert run(tmp_path, "M49\nM48\nG1 X100 F3000\n", feed_override=50.0).estimate.seconds == pytest.approx(
        rest_to_rest(100.0, 25.0))
    # the override cannot take a move past the axes' limits
    assert run(tmp_path, "G1 X100 F6000\n", feed_override=200.0).estimate.seconds == pytest.approx(
        rest_to_rest(100.0, 100.0))


def test_rapid_override(tmp_path: Path) -> None:
    result = run(tmp_path, "G0 X100\n", rapid_override=25.0)
    assert result.estimate.seconds == pytest.approx(rest_to_rest(100.0, 25.0))


def test_time_per_tool(tmp_path: Path) -> None:
    macro = tmp_path / "macro.cnc"
    macro.write_text(";@unit mm\nSub change_tool\n    M6 T[#5011]\nEndSub\n")  # a tool change that does not move
    result = run(tmp_path, "T1 M6\nG1 X100 F3000\nT2 M6\nG1 X0\nG4 P1\n", macro=macro)
    per_tool = result.estimate.per_tool
    assert per_tool[1].seconds == pytest.approx(rest_to_rest(100.0, 50.0))
    assert per_tool[2].seconds == pytest.approx(rest_to_rest(100.0, 50.0) + 1.0)
    assert sum(share.seconds for share in per_tool.values()) == pytest.approx(result.estimate.seconds)


def test_trace_column_t_is_when_each_move_ends(tmp_path: Path) -> None:
    trace = tmp_path / "trace.csv"
    result = run(tmp_path, "G61\nG1 X10 F3000\nG4 P1\nG1 X20\nG0 X0\n", trace=trace)
    with open(trace, newline="") as handle:
        rows = list(csv.reader(handle))
    assert rows[0][:14] == "line,kind,x,y,z,a,b,c,jx,jy,jz,ja,jb,jc".split(",") and rows[0][-1] == "t"
    t = [float(row[-1]) for row in rows[1:]]
    leg = rest_to_rest(10.0, 50.0)
    assert t == pytest.approx([leg, 2 * leg + 1.0, 2 * leg + 1.0 + rest_to_rest(20.0, 100.0)])
    assert t[-1] == pytest.approx(result.estimate.seconds)


def test_timed_move_callback(tmp_path: Path) -> None:
    seen: list[tuple[int, Timing]] = []
    run(tmp_path, "G1 X10 F3000\nX20\nG1 X20.01 F6000\n",
        on_timed_move=lambda move, joints, timing: seen.append((move.line, timing)))
    assert [line for line, _ in seen] == [1, 2, 3]
    first, second, third = (timing for _, timing in seen)
    assert first.start == 0.0 and first.end == second.start and first.speed == 50.0 == second.speed
    # the last 0.01 mm: the machine arrives as fast as it can still stop in it, and cannot speed up
    assert third.speed == pytest.approx(math.sqrt(2 * ACCEL * 0.01))
    assert third.end == pytest.approx(rest_to_rest(20.01, 50.0), rel=1e-3)


def test_limits_report(tmp_path: Path) -> None:
    result = run(tmp_path, "G0 X-20 Y10\nG3 X20 Y10 I20 J0 F600\n")  # a half circle below Y10: lowest at Y-10
    axes = result.limits["axes"]
    assert axes["x"]["min"] == pytest.approx(-20.0) and axes["x"]["lower"] == -500.0
    assert axes["x"]["margin"] == pytest.approx(480.0)
    assert axes["y"]["min"] == pytest.approx(-10.0) and axes["y"]["max"] == pytest.approx(10.0)
    assert result.limits["joints"]["y"]["max"] == pytest.approx(axes["y"]["max"])


def test_json_has_the_estimate(tmp_path: Path) -> None:
    job = tmp_path / "job.nc"
    job.write_text("G0 X10\r\nG1 Y10 F600\r\nG4 P1\r\nM30\r\n", newline="")
    result = invoke("run", str(job), "--json", "--ini", str(machine(tmp_path)), "--feed-override", "50")
    assert result.exit_code == 0, result.stderr
    import json

    estimate = json.loads(result.stdout)["estimate"]
    assert set(estimate) == {"seconds", "rapid_seconds", "feed_seconds", "dwell_seconds", "distance", "per_tool"}
    assert estimate["distance"] == {"rapid": 10.0, "feed": 10.0}
    assert estimate["feed_seconds"] == pytest.approx(rest_to_rest(10.0, 5.0))
    assert estimate["seconds"] == pytest.approx(estimate["rapid_seconds"] + estimate["feed_seconds"] + 1.0)


def test_bad_override_is_a_usage_error(tmp_path: Path) -> None:
    job = tmp_path / "job.nc"
    job.write_text("G0 X1\n")
    result = invoke("run", str(job), "--rapid-override", "150")
    assert result.exit_code == 2 and "--rapid-override" in result.stderr


SLOW_PLUGIN = '''
from edingcnc_lang.kinematics import KinematicsPlugin

class Slow(KinematicsPlugin):
    """Joints = position, but the plug-in knows the machine may only do 10 mm/s and 100 mm/s^2."""
    def inverse(self, pos, tool_length=0.0):
        return tuple(pos)

    def forward(self, joints, tool_length=0.0):
        return tuple(joints)

    def inverse_max_feed(self, start, end, tool_length=0.0):
        return (10.0,) * 6, (100.0,) * 6
'''


def test_python_plugin_inverse_max_feed_slows_the_move(tmp_path: Path) -> None:
    (tmp_path / "slow.py").write_text(SLOW_PLUGIN)
    ini = machine(tmp_path)
    ini.write_text(ini.read_text() + "[KINEMATICS]\r\nkinematicsDLLName = slow.dll\r\n", newline="")
    result = run(tmp_path, "KIN ON\nG1 X100 F3000\nKIN OFF\nG1 X0\n", ini=ini)
    assert result.estimate.seconds == pytest.approx(rest_to_rest(100.0, 10.0, 100.0) + rest_to_rest(100.0, 50.0))


def test_summary_line_on_a_terminal(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    from edingcnc_lang.cli import progress

    monkeypatch.setattr(progress, "wanted", lambda quiet: not quiet)  # as if stderr were a terminal
    job = tmp_path / "job.nc"
    job.write_text("G1 X500 F3000\nG4 P3600\nG1 X0\n")
    result = invoke("run", str(job), "--ini", str(machine(tmp_path)))
    assert result.exit_code == 0, result.stderr
    assert result.stderr.strip().splitlines()[-1] == "2 moves, 1 h 0 min 20 s, 1.0 m"
    assert invoke("run", str(job), "--quiet").stderr == ""


@pytest.mark.parametrize(("seconds", "text"), [(7.26, "7.3 s"), (59.96, "1 min 0 s"), (4325.4, "1 h 12 min 5 s")])
def test_durations_read_like_a_clock(seconds: float, text: str) -> None:
    from edingcnc_lang.motion.planner.estimate import format_duration

    assert format_duration(seconds) == text


def test_the_estimate_example(tmp_path: Path) -> None:
    folder = Path(__file__).resolve().parents[2] / "examples" / "estimate"
    options = {"ini": folder / "cnc.ini"}
    base = run_string((folder / "job.nc").read_text(encoding="latin-1"), RunOptions(**options)).estimate
    faster = run_string((folder / "job.nc").read_text(encoding="latin-1"),
                        RunOptions(**options, feed_override=150.0)).estimate
    assert set(base.per_tool) == {1, 2} and base.dwell_seconds == 2.0
    assert sum(share.seconds for share in base.per_tool.values()) == pytest.approx(base.seconds)
    assert faster.rapid_seconds == pytest.approx(base.rapid_seconds)
    assert base.feed_seconds / 1.5 < faster.feed_seconds < base.feed_seconds  # acceleration does not scale


def test_g64active_0_starts_in_exact_stop(tmp_path: Path) -> None:
    ini = machine(tmp_path, interpreter="g64Active = 0\r\n")
    job = "G1 X10 F3000\nX20\n"
    result = run(tmp_path, job, ini=ini)
    assert result.estimate.seconds == pytest.approx(2 * rest_to_rest(10.0, 50.0))
    assert "G61" in result.modal
    assert run(tmp_path, "G64\n" + job, ini=ini).estimate.seconds == pytest.approx(rest_to_rest(20.0, 50.0))
