"""Plug-ins and hosts cannot corrupt output or escape the error path (issue 28, item 5): a Python
plug-in that raises, returns the wrong shape, exits or prints is an error naming it (exit 70), and
its print() or an Exec'd program's output never reaches a --json document; host callbacks that
answer with the wrong type are errors at the job's line."""
from __future__ import annotations

import json
from pathlib import Path

import pytest

from edingcnc_lang.errors import EcncError
from edingcnc_lang.host import DialogAnswer, Host
from edingcnc_lang.runner import RunOptions, run_string
from tests.cli_runner import invoke

BODIES = {
    "raise": 'raise RuntimeError("boom")', "none": "return None", "zero": "return 1 / 0",
    "recurse": "return deep(0)", "exit": "raise SystemExit(3)", "tuple2": "return (1.0, 2.0)",
    "generator": "return (v for v in pos)", "base": 'raise Odd("b")',
}


def plugin(tmp_path: Path, kind: str) -> Path:
    path = tmp_path / f"p_{kind}.py"
    path.write_text(f"""from edingcnc_lang.kinematics.base import KinematicsPlugin
print("printed while loading")
class Odd(BaseException):
    pass
def deep(n):
    return deep(n + 1)
class P(KinematicsPlugin):
    KIN_TYPE = 1
    def inverse(self, pos, tool_length=0.0):
        print("printed by inverse")
        {BODIES[kind]}
    def forward(self, joints, tool_length=0.0):
        return tuple(joints)
""")
    return path


@pytest.mark.parametrize("kind", BODIES)
def test_kins_inverse_reports_a_broken_plugin(tmp_path: Path, kind: str) -> None:
    result = invoke("kins", "inverse", plugin(tmp_path, kind), "1", "2", "3")
    assert result.exit_code == 70, result.output
    assert result.stdout == "" and "kinematics plug-in" in result.stderr and "Traceback" not in result.output


@pytest.mark.parametrize("kind", BODIES)
def test_run_json_stays_one_document_whatever_the_plugin_does(tmp_path: Path, kind: str) -> None:
    ini = tmp_path / "cnc.ini"
    ini.write_text(f"[KINEMATICS]\nkinematicsDLLName = {plugin(tmp_path, kind).name}\n")
    job = tmp_path / "j.nc"
    job.write_text("KIN ON\nG1 X1 F100\nM30\n")
    result = invoke("run", job, "--ini", ini, "--json")
    assert result.exit_code == 70
    assert json.loads(result.stdout)["error"]["kind"] == "plugin"
    assert "printed by inverse" in result.stderr


def test_a_plugins_print_goes_to_stderr_when_it_works(tmp_path: Path) -> None:
    path = tmp_path / "ok.py"
    path.write_text(plugin(tmp_path, "none").read_text().replace("return None", "return tuple(pos)"))
    result = invoke("kins", "inverse", path, "1", "2", "3")
    assert result.exit_code == 0 and json.loads(result.stdout)["jx"] == 1.0
    assert "printed by inverse" in result.stderr


def test_exec_output_does_not_reach_stdout(tmp_path: Path) -> None:
    job = tmp_path / "j.nc"
    job.write_text('Exec "echo" "hello"\nM30\n')
    result = invoke("run", job, "--allow-exec", "--json")
    assert result.exit_code == 0 and json.loads(result.stdout)


@pytest.mark.parametrize(("host", "job"), [
    (Host(probe=lambda start, goal: (1.0, 2.0)), "G38.2 Z-5 F100\n"),
    (Host(probe=lambda start, goal: (*goal[:3], 45.0, 0.0, 0.0)), "G38.2 Z-5 F100\n"),
    (Host(probe=lambda start, goal: (0.0, 0.0, float("nan"), 0.0, 0.0, 0.0)), "G38.2 Z-5 F100\n"),
    (Host(read_input=lambda port: "high"), "M56 P1\n"),
    (Host(dialog=lambda title, fields: True), 'dlgmsg "x"\n'),
])
def test_a_host_callback_answering_the_wrong_type_is_an_error_at_the_jobs_line(host: Host, job: str) -> None:
    with pytest.raises(EcncError, match="the host's") as err:
        run_string("G0 X0\n" + job, RunOptions(host=host))
    assert err.value.location is not None and err.value.location.line == 2


def test_well_behaved_callbacks_still_work() -> None:
    host = Host(probe=lambda start, goal: (*goal[:2], -2.0, *goal[3:]), read_input=lambda port: True,
                dialog=lambda title, fields: DialogAnswer())
    assert run_string("G38.2 Z-5 F100\nM56 P1\ndlgmsg \"x\"\nM30\n", RunOptions(host=host)).error is None
