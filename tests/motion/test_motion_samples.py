"""Joint trajectories: sample spacing and times, rapids at the joints' speed, the .csv/.npz files, the trace."""
from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest
from motion_helpers import DELTA_HOME, delta_machine, joints, read_csv

from edingcnc_lang.motion.sinks import SAMPLES_COLUMNS

SCALAR_COREXY = '''
from edingcnc_lang.kinematics import KinematicsPlugin

class ScalarCoreXY(KinematicsPlugin):
    """Only the scalar functions: the motion stage falls back to one call per sample."""
    def inverse(self, pos, tool_length=0.0):
        x, y, z, a, b, c = pos
        return (x + y, x - y, z, a, b, c)

    def forward(self, joints, tool_length=0.0):
        jx, jy, z, a, b, c = joints
        return ((jx + jy) / 2, (jx - jy) / 2, z, a, b, c)
'''


def test_feed_move_is_sampled_every_interpolation_time(run_job, tmp_path: Path) -> None:  # type: ignore[no-untyped-def]
    samples = tmp_path / "s.csv"
    outcome = run_job("G1 X10 F600\n", None, "--samples", str(samples))  # 10 mm/s, 10,000 mm/s^2: 1.001 s
    assert outcome.code == 0, outcome.err
    header, rows = read_csv(samples)
    assert header == list(SAMPLES_COLUMNS)
    data = np.array(rows)
    assert len(data) == 201                                            # 200 ticks, then the end at rest
    np.testing.assert_allclose(data[:200, 0], np.arange(1, 201) * 0.005)
    assert data[-1, 0] == pytest.approx(1.001) and data[-1, 1] == 10.0
    cruise = data[:200]                                                # speeding up takes 0.001 s, 0.005 mm
    np.testing.assert_allclose(cruise[:, 1], 10.0 * cruise[:, 0] - 0.005, atol=1e-12)
    np.testing.assert_allclose(cruise[:, 14], 10.0)                    # v: the feed
    np.testing.assert_array_equal(data[:, 7:13], data[:, 1:7])         # trivial: joints = position


def test_interpolation_time_comes_from_the_ini(run_job, tmp_path: Path) -> None:  # type: ignore[no-untyped-def]
    samples = tmp_path / "s.csv"
    outcome = run_job("G1 X1 F60\nG4 P0.5\nG1 X2\n", {**joints(), "TRAJECTORY": {"interpolationTime": 0.01}},
                      "--samples", str(samples))
    assert outcome.code == 0, outcome.err
    t = np.array(read_csv(samples)[1])[:, 0]
    move = 1.0 + 1.0 / 5000.0                                            # L/v + v/a
    np.testing.assert_allclose(t[:100], np.arange(1, 101) * 0.01)      # on the global 100 Hz grid
    second = t[t > move + 0.5]                                          # the dwell adds its time
    assert second[0] == pytest.approx(1.51) and second[-1] == pytest.approx(2 * move + 0.5)
    np.testing.assert_allclose(np.diff(second[:-1]), 0.01)


def test_rapids_run_at_the_slowest_joints_max_velocity(run_job, tmp_path: Path) -> None:  # type: ignore[no-untyped-def]
    sections = joints(velocity=100.0)
    sections["JOINT_1"]["maxVelocity"] = 25.0
    samples = tmp_path / "s.csv"
    outcome = run_job("G0 X100 Y50\n", sections, "--samples", str(samples))
    assert outcome.code == 0, outcome.err
    data = np.array(read_csv(samples)[1])
    assert data[-1, 0] == pytest.approx(2.0 + 50 / 5000)             # Y: 50 mm at 25 mm/s, plus v/a
    assert np.diff(data[:, 2]).max() == pytest.approx(25 * 0.005)


def test_delta_rapid_is_timed_on_its_joints(run_job, tmp_path: Path) -> None:  # type: ignore[no-untyped-def]
    samples = tmp_path / "s.csv"
    outcome = run_job(DELTA_HOME + "G0 X60 Y0 Z40\n", delta_machine(), "--samples", str(samples))  # long enough to cruise
    assert outcome.code == 0, outcome.err
    data = np.array(read_csv(samples)[1])
    rapid = data[data[:, 7] != data[:, 1]]                            # after KIN ON: joints differ
    speed = np.abs(np.diff(rapid[:, 7:10], axis=0)).max(axis=0) / 0.005
    assert speed.max() == pytest.approx(200.0, rel=0.01)               # the fastest joint at maxVelocity


def test_npz_holds_the_same_columns(run_job, tmp_path: Path) -> None:  # type: ignore[no-untyped-def]
    csv_file, npz_file = tmp_path / "s.csv", tmp_path / "s.npz"
    job = DELTA_HOME + "G1 X10 Y10 Z150 F3000\nG2 X10 Y-10 R20\n"
    assert run_job(job, delta_machine(), "--samples", str(csv_file)).code == 0
    assert run_job(job, delta_machine(), "--samples", str(npz_file)).code == 0
    with np.load(npz_file) as npz:
        assert sorted(npz.files) == sorted(SAMPLES_COLUMNS)
        stacked = np.column_stack([npz[name] for name in SAMPLES_COLUMNS])
    np.testing.assert_array_equal(stacked, np.array(read_csv(csv_file)[1]))
    assert (np.diff(stacked[:, 0]) > 0).all()


def test_trace_joints_are_the_last_sample_of_each_move(run_job, tmp_path: Path) -> None:  # type: ignore[no-untyped-def]
    trace, samples = tmp_path / "t.csv", tmp_path / "s.csv"
    outcome = run_job(DELTA_HOME + "G1 X10 Y10 Z150 F3000\nG3 X-10 Y10 R10\n", delta_machine(),
                      "--trace", str(trace), "--samples", str(samples))
    assert outcome.code == 0, outcome.err
    _, moves = read_csv(trace)
    data = np.array(read_csv(samples)[1])
    for move in moves[-1:]:                                          # it ends at rest: its end point is a sample
        row = data[np.all(np.isclose(data[:, 1:7], move[2:8], atol=1e-12), axis=1)][-1]
        assert list(row[7:13]) == move[8:14]
    arc = data[data[:, 0] > moves[-2][-1]]                               # after the G1 ends (trace column t)
    np.testing.assert_allclose(np.hypot(arc[:, 1], arc[:, 2] - 10), 10.0)   # the arc, sampled on its circle


def test_scalar_plugin_gives_the_vectorised_result(run_job, tmp_path: Path) -> None:  # type: ignore[no-untyped-def]
    (tmp_path / "scalar_corexy.py").write_text(SCALAR_COREXY)
    job = "KIN ON\nG1 X10 Y4 F600\nG2 X20 Y4 R5\n"
    first, second = tmp_path / "a.csv", tmp_path / "b.csv"
    assert run_job(job, {**joints(), "KINEMATICS": {"kinematicsDLLName": "scalar_corexy.dll"}},
                   "--samples", str(first)).code == 0
    assert run_job(job, {**joints(), "KINEMATICS": {"kinematicsDLLName": "corexy"}},
                   "--samples", str(second)).code == 0
    np.testing.assert_allclose(np.array(read_csv(first)[1]), np.array(read_csv(second)[1]), rtol=0, atol=1e-12)


def test_full_circle_is_sampled_all_the_way_round(run_job, tmp_path: Path) -> None:  # type: ignore[no-untyped-def]
    samples = tmp_path / "s.csv"
    outcome = run_job("G0 X10\nG2 X10 Y0 I-10 J0 F600\n", None, "--samples", str(samples))
    assert outcome.code == 0, outcome.err
    data = np.array(read_csv(samples)[1])
    circle = data[data[:, 0] > data[data[:, 1] == 10.0][0, 0]]
    assert circle[-1, 0] - circle[0, 0] == pytest.approx(2 * math.pi, abs=0.006)  # 62.8 mm at 10 mm/s
    assert circle[:, 1].min() == pytest.approx(-10.0, abs=1e-3)
