"""Every kinematics run from a job: switching, homing, #5150, the joints and the user output."""
from __future__ import annotations

import math
from pathlib import Path

import pytest
from motion_helpers import DELTA_HOME, HOME, delta_machine, ini_text, joints

from edingcnc_lang.runner import RunOptions, run_file

CYLINDER = {"aAxisCalibratedCilinderRadius": 10.0}
DEG_PER_MM = 180.0 / (math.pi * 10.0)


def test_seed_delta_homes_to_0_0_200_through_the_cli(run_job) -> None:  # type: ignore[no-untyped-def]
    outcome = run_job(DELTA_HOME, delta_machine(userOutputStartVariable=1000, userOutputNumVariables=3))
    assert outcome.code == 0, outcome.err
    assert outcome.pose("machine") == pytest.approx([0, 0, 200, 0, 0, 0], abs=1e-6)
    assert outcome.pose("joints") == [HOME, HOME, HOME, 0.0, 0.0, 0.0]
    assert outcome.json["kinematics"] == {"name": "deltakins", "type": 4, "active": True}
    assert [outcome.var(1000 + i) for i in range(3)] == pytest.approx([HOME] * 3, abs=1e-9)
    assert outcome.var(5150) == 4.0


def test_seed_delta_homes_to_0_0_200_through_run_file(tmp_path: Path) -> None:
    (tmp_path / "cnc.ini").write_text(ini_text(delta_machine()), newline="")
    (tmp_path / "home.nc").write_text(DELTA_HOME + "G1 Z150 F600\n")
    result = run_file(tmp_path / "home.nc", RunOptions(ini=tmp_path / "cnc.ini"))
    assert result.machine == pytest.approx((0, 0, 150, 0, 0, 0), abs=1e-6)
    below = math.sqrt(250**2 - 125**2) + 150   # every carriage the same height above the effector
    assert result.joints == pytest.approx((below,) * 3 + (0, 0, 0), abs=1e-6)


def test_delta_moves_and_user_output_are_the_end_joints(run_job) -> None:  # type: ignore[no-untyped-def]
    outcome = run_job(DELTA_HOME + "G1 X0 Y50 Z150 F1200\n",
                      delta_machine(userOutputStartVariable=1000, userOutputNumVariables=4))
    assert outcome.code == 0, outcome.err
    jx = 150 + math.sqrt(250**2 - 75**2)  # tower X is at (0, 125)
    assert outcome.pose("joints")[0] == pytest.approx(jx)
    assert [outcome.var(1000 + i) for i in range(4)] == [*outcome.pose("joints")[:3], 0.0]


def test_rotatekins_rotates_xy_about_the_switch_on_point(run_job) -> None:  # type: ignore[no-untyped-def]
    sections = {**joints(), "KINEMATICS": {"kinematicsDLLName": "rotatekins", "userOutputStartVariable": 1000,
                                           "userOutputNumVariables": 3}}
    outcome = run_job("G0 X200 Y150\nKIN ON\nG1 X250 F1200\nG0 C90\n#1 = #5150\n", sections)
    assert outcome.code == 0, outcome.err
    assert outcome.pose("machine") == [250, 150, 0, 0, 0, 90]
    assert outcome.pose("joints") == pytest.approx([200, 200, 0, 0, 0, 0])
    assert [outcome.var(n) for n in (1000, 1001, 1002)] == [200.0, 150.0, 90.0]
    assert outcome.var(1) == 3.0


def test_rotatekins_ctrl_sets_the_point_and_angle_without_moving(run_job) -> None:  # type: ignore[no-untyped-def]
    sections = {**joints(), "KINEMATICS": {"kinematicsDLLName": "rotatekins.dll"}}
    outcome = run_job("G0 X10\nKIN ON\nKIN CTRL 11 0 0\nKIN CTRL 12 90\n", sections)
    assert outcome.code == 0, outcome.err
    assert outcome.pose("joints") == [10, 0, 0, 0, 0, 0]                 # nothing moved
    assert outcome.pose("machine") == pytest.approx([0, -10, 0, 0, 0, 90])  # the same joints seen rotated


def test_unknown_control_id_is_an_error_naming_the_line(run_job) -> None:  # type: ignore[no-untyped-def]
    outcome = run_job("G0 X10\nKIN CTRL 40 1 2\n", {**joints(), "KINEMATICS": {"kinematicsDLLName": "rotatekins"}})
    assert outcome.code == 70
    assert "job.nc:2:1: error: kinematics rotatekins: control 40 returned -1" in outcome.err


def test_compiled_plugin_named_by_path_runs_a_job(run_job, compiled_rotatekins: Path) -> None:  # type: ignore[no-untyped-def]
    sections = {**joints(), "KINEMATICS": {"kinematicsDLLName": str(compiled_rotatekins),
                                           "userOutputStartVariable": 1000, "userOutputNumVariables": 3}}
    outcome = run_job("G0 X200 Y150\nKIN ON\nG1 X250 F1200\nG0 C90\n#1 = #5150\n", sections)
    assert outcome.code == 0, outcome.err
    assert outcome.pose("joints") == pytest.approx([200, 200, 0, 0, 0, 0])
    assert [outcome.var(n) for n in (1, 1000, 1001, 1002)] == [3.0, 200.0, 150.0, 90.0]
    assert outcome.json["kinematics"]["name"] == "rotatekins"


def test_corexy_named_in_the_ini(run_job) -> None:  # type: ignore[no-untyped-def]
    outcome = run_job("KIN ON\nG1 X10 Y4 F600\n", {**joints(), "KINEMATICS": {"kinematicsDLLName": "CoreXY.dll"}})
    assert outcome.code == 0, outcome.err
    assert outcome.pose("joints") == [14, 6, 0, 0, 0, 0]
    assert outcome.var(5150) == 5.0


@pytest.mark.parametrize(("mode", "job", "expected"), [
    ("Y2A", "G1 Y15.707963267948966 Z-1 F600", [5, 0, -1, 90, 0, 0]),
    ("X2A", "G1 X15.707963267948966 F600", [0, 0, 0, 90, 0, 0]),
    ("X2XA", "G1 X7 Z-1 F600", [7, 0, -1, 7, 0, 0]),
    ("Y2YA", "G1 Y-3 F600", [5, -3, 0, -3, 0, 0]),
    ("Z2C", "G1 Z-4 F600", [5, 0, 0, 0, 0, -4]),
    ("Z2ZC", "G1 Z-4 F600", [5, 0, -4, 0, 0, -4]),
    ("Y2YAZ2ZC", "G1 Y2 Z-4 F600", [5, 2, -4, 2, 0, -4]),
])
def test_kin_mappings(run_job, mode: str, job: str, expected: list[float]) -> None:  # type: ignore[no-untyped-def]
    start = "G0 X5\n" if mode not in ("X2A", "X2XA") else ""
    outcome = run_job(f"{start}KIN {mode}\n#1 = #5150\n{job}\nKIN OFF\n#2 = #5150\n",
                      {**joints(), "KINEMATICS": CYLINDER})
    assert outcome.code == 0, outcome.err
    assert outcome.pose("joints") == pytest.approx(expected)
    assert (outcome.var(1), outcome.var(2)) == (2.0, 1.0)


def test_y2a_wraps_about_the_work_zero(run_job) -> None:  # type: ignore[no-untyped-def]
    outcome = run_job("G10 L2 P1 Y20\nG54 G0 X0 Y0\nKIN Y2A\nG1 Y-5 F600\n", {**joints(), "KINEMATICS": CYLINDER})
    assert outcome.code == 0, outcome.err
    assert outcome.pose("joints") == pytest.approx([0, 20, 0, -5 * DEG_PER_MM, 0, 0])


def test_y2a_without_a_radius_is_an_error(run_job) -> None:  # type: ignore[no-untyped-def]
    outcome = run_job("G0 X1\nKIN Y2A\n", joints())
    assert outcome.code == 70
    assert "job.nc:2:1: error:" in outcome.err and "aAxisCalibratedCilinderRadius" in outcome.err


def test_switching_never_makes_a_joint_jump(run_job) -> None:  # type: ignore[no-untyped-def]
    outcome = run_job("G0 Z-3\nG0 C5\nKIN Z2ZC\n", {**joints(), "KINEMATICS": CYLINDER})
    assert outcome.code == 70
    assert "job.nc:3:1: error: KIN Z2ZC would make joint C jump from 5.0000 to -3.0000" in outcome.err


def test_homing_switches_kinematics_off_until_kin_on(run_job) -> None:  # type: ignore[no-untyped-def]
    sections = {**joints(), "KINEMATICS": {"kinematicsDLLName": "rotatekins"}}
    outcome = run_job("G0 X10\nKIN ON\nG0 C90\nhome x\n", sections)
    assert outcome.code == 0, outcome.err
    assert outcome.json["kinematics"]["active"] is False
    assert outcome.pose("joints") == outcome.pose("machine") == pytest.approx([0, 0, 0, 0, 0, 0], abs=1e-12)


def test_bend_knife_offsets_the_joints_with_depth(run_job) -> None:  # type: ignore[no-untyped-def]
    sections = {**joints(), "INTERPRETER": {"tanknifeBendingAngle": 90, "tanknifeZhi": 0.0, "tanknifeZlo": -2.0}}
    outcome = run_job("G0 X10 Y10 Z5 C0\ntanknife on\nG1 Z-1 F300\nG1 Z-5\n", sections)
    assert outcome.code == 0, outcome.err
    assert outcome.pose("machine") == [10, 10, -5, 0, 0, 0]
    assert outcome.pose("joints") == pytest.approx([10, 12, -5, 0, 0, 0])  # C 0 + 90 degrees: +Y, clamped at 2
