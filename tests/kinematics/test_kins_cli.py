"""``ecnc kins ...`` run in-process."""
from __future__ import annotations

import json
import math
import shutil
from pathlib import Path

import pytest

from tests.cli_runner import invoke

DELTA_INI = "[KINEMATICS]\r\nkinematicsDLLName = deltakins.dll\r\nlinDeltaRadius = 100.000000\r\nlinDeltaArmLength = 200.0\r\n"


def run(*args: str) -> tuple[int, str, str]:
    result = invoke("kins", *args)  # an exception (a traceback) fails the test
    return result.exit_code, result.stdout, result.stderr


def test_list() -> None:
    code, out, _ = run("list")
    assert code == 0
    assert "deltakins\t4\t" in out and "trivial\t1\tTRIVIAL 1.0" in out
    listed = json.loads(run("list", "--json")[1])
    assert {"name": "corexy", "type": 5, "version": "COREXY 1.0"} in listed


def test_inverse_accepts_negative_numbers_and_prints_exact_json() -> None:
    code, out, _ = run("inverse", "corexy", "-5", "0.1", "-2.5e-3")
    assert code == 0
    assert json.loads(out) == {"jx": -4.9, "jy": -5.1, "jz": -0.0025, "ja": 0.0, "jb": 0.0, "jc": 0.0}
    assert '"jx": -4.9,' in out                                       # repr, not rounded


def test_rotatekins_is_switched_on_at_the_origin() -> None:
    _, out, _ = run("inverse", "rotatekins", "10", "0", "0", "0", "0", "90")
    joints = json.loads(out)
    assert joints["jx"] == pytest.approx(0.0, abs=1e-12) and joints["jy"] == pytest.approx(10.0)


def test_forward_with_ini(tmp_path: Path) -> None:
    ini = tmp_path / "cnc.ini"
    ini.write_bytes(DELTA_INI.encode())
    home = math.sqrt(200.0**2 - 100.0**2) + 50.0
    code, out, _ = run("forward", "deltakins", "--ini", str(ini), str(home), str(home), str(home), "-1")
    assert code == 0
    pos = json.loads(out)
    assert (pos["x"], pos["y"], pos["z"], pos["a"]) == pytest.approx((0.0, 0.0, 50.0, -1.0), abs=1e-9)


def test_unreachable_exits_70() -> None:
    code, out, err = run("inverse", "deltakins", "0", "-400", "0")
    assert (code, out) == (70, "")
    assert err.startswith("error: X0 Y-400 Z0 is out of reach of the delta robot")
    assert "Traceback" not in err


def test_unknown_plugin_exits_70() -> None:
    code, _, err = run("inverse", "nosuchkins.dll", "1", "2", "3")
    assert code == 70 and "error: kinematics plug-in 'nosuchkins.dll' not found" in err


@pytest.mark.parametrize("args", [("inverse", "trivial", "1", "2"), ("forward", "trivial", *"1234567"),
                                  ("inverse", "trivial", "1", "x", "3"), ("inverse",), ("frobnicate",)])
def test_usage_errors_exit_2(args: tuple[str, ...]) -> None:
    assert run(*args)[0] == 2


@pytest.mark.slow
def test_build_and_use(tmp_path: Path) -> None:
    if shutil.which("cc") is None:
        pytest.skip("no C compiler (cc) on PATH")
    source = tmp_path / "rotatekins.c"
    source.write_text((Path(__file__).resolve().parents[2] / "kins" / "c" / "rotatekins.c").read_text())
    code, out, _ = run("build", str(source), "-o", str(tmp_path / "rk.so"))
    assert code == 0 and out.strip() == str(tmp_path / "rk.so")
    _, out, _ = run("inverse", str(tmp_path / "rk.so"), "10", "0", "0", "0", "0", "-90")
    assert json.loads(out)["jy"] == pytest.approx(-10.0)


def test_build_failure_exits_70(tmp_path: Path) -> None:
    source = tmp_path / "bad.c"
    source.write_text("this is not C")
    code, _, err = run("build", str(source), "--cc", "no-such-cc")
    assert code == 70 and "cannot run the C compiler 'no-such-cc'" in err


def test_build_of_a_source_missing_a_required_function_fails(tmp_path: Path) -> None:
    if shutil.which("cc") is None:
        pytest.skip("no C compiler (cc) on PATH")
    source = tmp_path / "partial.c"
    text = (Path(__file__).resolve().parents[2] / "kins" / "c" / "rotatekins.c").read_text()
    source.write_text(text.replace("KinematicsForward(", "KinematicsForwardX("))
    code, out, err = run("build", str(source), "-o", str(tmp_path / "partial.so"))
    assert (code, out) == (70, "")
    assert "does not export KinematicsForward: a kinematics plug-in must define every function" in err


@pytest.mark.slow
def test_a_compiled_plugin_named_by_bare_file_name_loads_from_the_current_folder(
        tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    if shutil.which("cc") is None:
        pytest.skip("no C compiler (cc) on PATH")
    source = tmp_path / "polar.c"
    source.write_text((Path(__file__).resolve().parents[2] / "kins" / "c" / "rotatekins.c").read_text())
    assert run("build", str(source))[0] == 0
    monkeypatch.chdir(tmp_path)  # "polar.so" alone: the dynamic loader would search the system's folders
    code, out, err = run("inverse", "polar.so", "10", "0", "0", "0", "0", "-90")
    assert code == 0, err
    assert json.loads(out)["jy"] == pytest.approx(-10.0)


GAIN_PLUGIN = r"""
#include <math.h>
#include <string.h>
#include "edingcnc_kins.h"
static double gain = 1.0;
int KINS_CALL KinematicsControl(int id, KIN_CONTROLDATA *data)
{
    if (id == ECNC_KIN_CONTROL_ID_SETTING && strcmp(data->cData, "gain") == 0 && !isnan(data->dData[8])) {
        gain = data->dData[8];
        return 0;
    }
    return id >= CNC_KIN_CONTROL_ID_OPEN && id <= CNC_KIN_CONTROL_ID_ON ? 0 : -1;
}
int KINS_CALL KinematicsInverse(CNC_CART_DOUBLE p, CNC_JOINT_DOUBLE *j, const CNC_KINEMATICS_INVERSE_FLAGS *a,
                                CNC_KINEMATICS_FORWARD_FLAGS *b, double t)
{
    j->jx = gain * p.x; j->jy = p.y; j->jz = p.z; j->ja = p.a; j->jb = p.b; j->jc = p.c;
    return 0;
}
int KINS_CALL KinematicsForward(CNC_JOINT_DOUBLE j, CNC_CART_DOUBLE *p, const CNC_KINEMATICS_FORWARD_FLAGS *a,
                                CNC_KINEMATICS_INVERSE_FLAGS *b, double t)
{
    p->x = j.jx / gain; p->y = j.jy; p->z = j.jz; p->a = j.ja; p->b = j.jb; p->c = j.jc;
    return 0;
}
CNC_KINEMATICS_TYPE KINS_CALL KinematicsType(void) { return CNC_KINEMATICS_TYPE_CUSTOM_1; }
char *KINS_CALL KinematicsVersion(void) { return "GAIN 1.0"; }
"""


@pytest.mark.slow
def test_a_compiled_plugin_receives_its_ini_settings_at_load(tmp_path: Path) -> None:
    if shutil.which("cc") is None:
        pytest.skip("no C compiler (cc) on PATH")
    source = tmp_path / "gain.c"
    source.write_text(GAIN_PLUGIN)
    assert run("build", str(source))[0] == 0, run("build", str(source))
    ini = tmp_path / "cnc.ini"
    ini.write_text("[KINEMATICS]\r\nkinematicsDLLName = gain.dll\r\nGain = 2.5\r\nnote = text\r\n")
    code, out, err = run("inverse", "gain", "--ini", str(ini), "4", "1", "0")
    assert code == 0, err
    assert json.loads(out)["jx"] == 10.0


def test_list_with_an_ini_adds_the_plugin_it_names(tmp_path: Path) -> None:
    ini = tmp_path / "cnc.ini"
    ini.write_text(DELTA_INI)
    code, out, _ = run("list", "--ini", str(ini))
    assert code == 0 and out.splitlines()[-1] == "deltakins.dll\t4\tEDINGCNC-LANG LINEAR DELTA 1.0"
    ini.write_text("[KINEMATICS]\r\nkinematicsDLLName = missing.dll\r\n")
    last = json.loads(run("list", "--json", "--ini", str(ini))[1])[-1]
    assert (last["name"], last["type"]) == ("missing.dll", 0) and "failed to load" in last["version"]
    ini.write_text("[TRAJECTORY]\r\n")
    code, _, err = run("list", "--ini", str(ini))
    assert code == 2 and "names no kinematics plug-in" in err
