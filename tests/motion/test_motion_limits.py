"""Limits: a violation stops the run with exit 70 and `PATH:LINE: error:` naming the joint and the value."""
from __future__ import annotations

import json
import math
from pathlib import Path

import numpy as np
import pytest
from motion_helpers import DELTA_HOME, delta_machine, joints, read_csv

SAMPLE_LIMITS = joints((0.0, 400.0), 100.0, 1000.0)
ROTATE = {**joints((0.0, 400.0), 100.0, 1000.0),
          "KINEMATICS": {"kinematicsDLLName": "rotatekins", "maxVelocityC": 3600, "maxAccelerationC": 1e6,
                         **{f"{side}Limit{axis}": sign * 500 for side, sign in (("positive", 1), ("negative", -1))
                            for axis in "XYZABC"}}}
SLOW_XY = {**ROTATE, **{f"JOINT_{i}": {"negativeLimit": -500, "positiveLimit": 500, "maxVelocity": 100,
                                       "maxAcceleration": 50} for i in range(2)}}


def assert_error(outcome, line: int, *parts: str) -> None:  # type: ignore[no-untyped-def]
    assert outcome.code == 70, outcome.err
    first = outcome.err.strip().splitlines()[0]
    assert f"job.nc:{line}:1: error: " in first, first
    for part in parts:
        assert part in first, first


@pytest.mark.parametrize("samples", [False, True])
def test_trivial_end_point_outside_the_joint_limits(run_job, tmp_path: Path, samples: bool) -> None:  # type: ignore[no-untyped-def]
    options = ("--samples", str(tmp_path / "s.csv")) if samples else ()
    outcome = run_job("G0 X10 Y10\nG1 X450.5 F1000\n", SAMPLE_LIMITS, *options)
    assert_error(outcome, 2, "joint X would reach 450.5000", "[0, 400]", "[JOINT_0]")


@pytest.mark.parametrize("samples", [False, True])
def test_trivial_arc_extreme_outside_the_limits(run_job, tmp_path: Path, samples: bool) -> None:  # type: ignore[no-untyped-def]
    # from (10, 50) to (10, 10) clockwise about (10, 30): the arc bulges to X = 30 ... and the other way to X = -10
    options = ("--samples", str(tmp_path / "s.csv")) if samples else ()
    assert run_job("G0 X10 Y50\nG2 X10 Y10 I0 J-20 F1000\n", SAMPLE_LIMITS, *options).code == 0
    outcome = run_job("G0 X10 Y50\nG3 X10 Y10 I0 J-20 F1000\n", SAMPLE_LIMITS, *options)
    assert_error(outcome, 2, "joint X would reach -10.0000")


def test_a_spiral_arc_is_checked_at_its_larger_radius_as_the_limits_report_shows_it(run_job) -> None:  # type: ignore[no-untyped-def]
    # start radius 10, end radius 10.0015 (within the 0.002 mm tolerance): the top is at Y 10.0015, past
    # the limit of 10.001 that the start radius alone would keep
    limits = {**joints((-1000.0, 1000.0)), "JOINT_1": {"negativeLimit": -20, "positiveLimit": 10.001}}
    outcome = run_job("G0 X0 Y0\nG2 X20.0015 Y0 I10 J0 F500\n", limits)
    assert_error(outcome, 2, "joint Y would reach 10.0015")
    limits["JOINT_1"]["positiveLimit"] = 10.002
    outcome = run_job("G0 X0 Y0\nG2 X20.0015 Y0 I10 J0 F500\n", limits, "--json")
    assert outcome.code == 0, outcome.err
    assert json.loads(outcome.out)["limits"]["joints"]["y"]["max"] == pytest.approx(10.0015, abs=1e-12)


def test_kinematics_moves_a_joint_out_of_its_limits(run_job) -> None:  # type: ignore[no-untyped-def]
    outcome = run_job("G0 X10 Y10\nKIN ON\nG1 X50 F6000\nG0 C180\n", ROTATE)
    assert_error(outcome, 4, "joint X would reach -0.", "[JOINT_0]")


def test_cartesian_limits_apply_with_kinematics_on(run_job) -> None:  # type: ignore[no-untyped-def]
    sections = {**ROTATE, "KINEMATICS": {**ROTATE["KINEMATICS"], "positiveLimitC": 45}}
    outcome = run_job("G0 X100 Y100\nKIN ON\nG0 C30\nG0 C60\n", sections)
    assert_error(outcome, 4, "C would reach 4", "outside the Cartesian limits [-500, 45] of [KINEMATICS]")


def test_delta_out_of_reach(run_job) -> None:  # type: ignore[no-untyped-def]
    outcome = run_job(DELTA_HOME + "G1 X0 Y-200 Z0 F3000\n", delta_machine())
    assert_error(outcome, 6, "out of reach of the delta robot", "the arm of joint X is too short")


def test_delta_safety_radius(run_job) -> None:  # type: ignore[no-untyped-def]
    outcome = run_job(DELTA_HOME + "G1 X30 Y0 Z100 F3000\nG1 X60\n", delta_machine(linDeltaSafetyRadius=50))
    assert_error(outcome, 7, "X50", "beyond linDeltaSafetyRadius = 50")


def test_joint_velocity_above_its_maximum_slows_the_move(run_job, tmp_path: Path) -> None:  # type: ignore[no-untyped-def]
    samples = tmp_path / "s.csv"
    outcome = run_job(DELTA_HOME + "G1 X50 Y0 Z100 F60000\n", delta_machine(), "--samples", str(samples))
    assert outcome.code == 0, outcome.err                              # 1000 mm/s asked: the joints set the pace
    data = np.array(read_csv(samples)[1])
    move = data[data[:, 1] > 0.0]                                       # homing keeps X at 0
    speed = np.abs(np.diff(move[:, 7:10], axis=0) / np.diff(move[:, 0])[:, None])
    assert speed.max() <= 200.0 * 1.01
    assert move[:, 13].max() < 1000.0                                   # the path ran slower than F


def test_feed_slows_down_for_the_joints_acceleration(run_job, tmp_path: Path) -> None:  # type: ignore[no-untyped-def]
    # C turns the XY plane: at F3094 joint X/Y would go round a 100 mm circle at 0.9 rad/s -> 81 mm/s^2
    samples = tmp_path / "s.csv"
    outcome = run_job("KIN ON\nG0 X100\nG1 C90 F3094\n", SLOW_XY, "--samples", str(samples))
    assert outcome.code == 0, outcome.err
    data = np.array(read_csv(samples)[1])
    turn = data[data[:, 6] > 0]
    duration = turn[-1, 0] - turn[0, 0] + 0.005
    # the circle may use sqrt(3)/2 of the joints' 50 mm/s^2 (speeding up gets the rest): at most this fast
    speed = 3094 / 60 * math.sqrt(50 * math.sqrt(3) / 2 / 81)
    assert duration > 90 / speed
    velocity = np.diff(turn[:, 7]) / np.diff(turn[:, 0])
    acceleration = np.abs(np.diff(velocity[:-1]) / 0.005)
    assert acceleration.max() <= 50 * 1.01


def test_rapids_never_exceed_the_joints(run_job) -> None:  # type: ignore[no-untyped-def]
    outcome = run_job("KIN ON\nG0 X100\nG0 C360\n", SLOW_XY)
    assert outcome.code == 0, outcome.err


def test_ordinary_job_on_the_sample_machine_has_no_false_alarms(run_job, tmp_path: Path) -> None:  # type: ignore[no-untyped-def]
    job = ("G0 X100 Y100 Z-5\nG1 X150 F3000\nG2 X160 Y110 R10\nG1 Y150\nG3 X150 Y160 R10\n"
           "G2 X150 Y160 I-0.5 J0\nG1 X100\nG1 Y100\nG0 Z0\n")
    sections = {**joints((-1000, 1000), 100.0, 1000.0), "KINEMATICS": {"kinematicsDLLName": "corexy"}}
    for prefix in ("", "KIN ON\n"):
        outcome = run_job(prefix + job, sections, "--samples", str(tmp_path / "s.npz"))
        assert outcome.code == 0, outcome.err
