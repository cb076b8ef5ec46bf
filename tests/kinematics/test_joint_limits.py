"""Issue 21 item 8: ``kins check`` and ``kins plot`` honour the ini's joint limits, as a run does.

A SCARA whose shoulder turns -90..90 and elbow 0..150 degrees reaches less than its arms could:
the envelope showed reachable what the run refuses.
"""
from __future__ import annotations

import shutil
from pathlib import Path

import numpy as np
import pytest

from edingcnc_lang.kinematics.workbench import CheckOptions, check_plugin
from edingcnc_lang.kinematics.workbench.check import load_plugin, read_machine
from edingcnc_lang.kinematics.workbench.calls import Status, call_each
from tests.cli_runner import invoke

pytestmark = pytest.mark.slow  # the whole module (pyproject's slow marker)

SCARA = Path(__file__).resolve().parent / "scara"
QUICK = dict(samples=600, segments=80, speed=False)
BEHIND = (-100.0, -200.0, -50.0, 0.0, 0.0, 0.0)  # the arms reach it, the shoulder would be at -158 degrees


def test_a_pose_beyond_a_joint_limit_is_not_reached() -> None:
    machine = read_machine(str(SCARA / "cnc.ini"))
    kins = load_plugin("scara.py", machine)
    out = call_each(kins.inverse, np.array([BEHIND, (300.0, 0.0, -50.0, 0, 0, 0)]), machine.joint_limits)
    assert out.status.tolist() == [Status.JOINT_LIMIT, Status.OK]
    assert out.messages[Status.JOINT_LIMIT].startswith("joint X would be at -157.5")
    assert "outside its limits [-90, 90] ([JOINT_0])" in out.messages[Status.JOINT_LIMIT]
    assert call_each(kins.inverse, np.array([BEHIND])).status.tolist() == [Status.OK]  # no limits: reached


def test_the_run_refuses_that_pose_too(tmp_path: Path) -> None:
    (tmp_path / "job.nc").write_text("KIN ON\nG1 X{} Y{} Z{} F1000\n".format(*BEHIND[:3]))
    result = invoke("run", "--ini", SCARA / "cnc.ini", tmp_path / "job.nc")
    assert result.exit_code == 70 and "joint X" in result.stderr


def test_kins_check_counts_only_what_the_joints_allow(tmp_path: Path) -> None:
    limited = check_plugin("scara.py", CheckOptions(ini=str(SCARA / "cnc.ini"), **QUICK))
    assert limited.ok, limited.format()
    domain = next(s for s in limited.sections if s.name == "domain")
    assert 0.3 < domain.figures["beyond_joint_limits_fraction"] < 0.5
    assert "the ini's joint limits do not allow" in domain.summary
    # the same machine without [JOINT_n] sections: the arms' whole reach, and the shoulder's wrap at -X is found
    shutil.copy(SCARA / "scara.py", tmp_path / "scara.py")
    text = (SCARA / "cnc.ini").read_text()
    (tmp_path / "cnc.ini").write_text(text[text.index("[KINEMATICS]"):])
    free = check_plugin("scara.py", CheckOptions(ini=str(tmp_path / "cnc.ini"), **QUICK))
    free_domain = next(s for s in free.sections if s.name == "domain")
    assert free_domain.figures["reachable_fraction"] > domain.figures["reachable_fraction"] + 0.3
    assert "K202" in {f.code for f in free.findings}  # beyond the limits: never driven there, so not in `limited`


def test_kins_plot_shows_the_joint_limits(tmp_path: Path) -> None:
    result = invoke("kins", "plot", "--ini", SCARA / "cnc.ini", "-o", tmp_path / "scara.svg", "scara.py")
    assert result.exit_code == 0, result.stderr
    svg = (tmp_path / "scara.svg").read_text()
    assert "beyond the joint limits" in svg
