"""A plug-in that fails to load or raises stops the run with exit 70 and a message naming it, never a traceback."""
from __future__ import annotations

from pathlib import Path

import pytest
from motion_helpers import joints

PLUGIN = '''
from edingcnc_lang.kinematics import KinematicsPlugin

class Broken(KinematicsPlugin):
    VERSION = "BROKEN 1"

    def __init__(self, settings):
        super().__init__(settings)
        if self.setting("failIn", 0) == 1:
            raise RuntimeError("no licence")

    def inverse(self, pos, tool_length=0.0):
        if self.setting("failIn", 0) == 2 and pos[0] > 5:
            raise ZeroDivisionError("bad maths")
        return pos

    def forward(self, joints, tool_length=0.0):
        return joints

    def control(self, control_id, data):
        if control_id == 12 and self.setting("failIn", 0) == 3:
            raise KeyError("control")
        return super().control(control_id, data)

    def user_output(self):
        return [1.0, "x"] if self.setting("failIn", 0) == 4 else [7.0]
'''
VECTOR = '''
import numpy as np
from edingcnc_lang.kinematics import KinematicsPlugin

class Wrong(KinematicsPlugin):
    def inverse(self, pos, tool_length=0.0):
        return pos

    def forward(self, joints, tool_length=0.0):
        return joints

    def inverse_many(self, pos, tool_length=0.0):
        return np.full((len(pos), 6), np.nan) if self.setting("nan", 0) else pos[:, :3]
'''


def plugin_machine(tmp_path: Path, source: str, **settings: object) -> dict[str, dict[str, object]]:
    (tmp_path / "mykins.py").write_text(source)
    return {**joints(), "KINEMATICS": {"kinematicsDLLName": "mykins.dll", "userOutputStartVariable": 500,
                                       "userOutputNumVariables": 2, **settings}}


@pytest.mark.parametrize(("fail", "job", "line", "message"), [
    (1, "G0 X1\n", None, ": constructing it failed: RuntimeError: no licence"),
    (2, "KIN ON\nG1 X10 F600\n", 2, " failed: ZeroDivisionError: bad maths"),
    (3, "KIN ON\nKIN CTRL 12 1\n", 2, " failed: KeyError: 'control'"),
    (4, "KIN ON\n", 1, " failed: ValueError: could not convert string to float"),
])
def test_plugin_that_raises(run_job, tmp_path: Path, fail: int, job: str, line: int | None,
                            message: str) -> None:  # type: ignore[no-untyped-def]
    outcome = run_job(job, plugin_machine(tmp_path, PLUGIN, failIn=fail))
    assert outcome.code == 70
    where = f"job.nc:{line}:1: error: " if line else "error: "
    assert f"{where}kinematics plug-in " in outcome.err and f"mykins.py{message}" in outcome.err


def test_plugin_user_output_is_padded_with_zeros(run_job, tmp_path: Path) -> None:  # type: ignore[no-untyped-def]
    outcome = run_job("KIN ON\nG1 X10 F600\n", plugin_machine(tmp_path, PLUGIN))
    assert outcome.code == 0, outcome.err
    assert (outcome.var(500), outcome.var(501)) == (7.0, 0.0)


def test_plugin_that_does_not_import(run_job, tmp_path: Path) -> None:  # type: ignore[no-untyped-def]
    outcome = run_job("G0 X1\n", plugin_machine(tmp_path, "def broken(:\n"))
    assert outcome.code == 70
    assert "mykins.py: importing it failed: SyntaxError" in outcome.err


def test_missing_plugin(run_job) -> None:  # type: ignore[no-untyped-def]
    outcome = run_job("G0 X1\n", {**joints(), "KINEMATICS": {"kinematicsDLLName": "nowhere.dll"}})
    assert outcome.code == 70
    assert "kinematics plug-in 'nowhere.dll' not found" in outcome.err


@pytest.mark.parametrize(("nan", "message"), [(0, "inverse_many returned shape (1, 3), expected (1, 6)"),
                                              (1, "inverse_many returned a joint that is not a finite number")])
def test_plugin_batch_result_is_checked(run_job, tmp_path: Path, nan: int, message: str) -> None:  # type: ignore[no-untyped-def]
    outcome = run_job("KIN ON\n", plugin_machine(tmp_path, VECTOR, nan=nan))
    assert outcome.code == 70
    assert "job.nc:1:1: error: kinematics plug-in " in outcome.err
    assert f"mykins.py failed: ValueError: {message}" in outcome.err


def test_an_unbuilt_c_plugin_says_how_to_build_it(tmp_path) -> None:
    from tests.cli_runner import invoke

    (tmp_path / "mykins.c").write_text("/* source only */\n")
    ini = tmp_path / "cnc.ini"
    ini.write_text("[KINEMATICS]\nkinematicsDLLName = mykins.dll\n")
    job = tmp_path / "job.nc"
    job.write_text("G0 X1\n")
    result = invoke("run", "--ini", ini, job)
    assert result.exit_code == 70
    assert "build it first with `ecnc kins build" in result.output
