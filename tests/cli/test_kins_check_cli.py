"""``ecnc kins check|compare|plot`` from the shell: exit codes, text and JSON reports, usage errors."""
from __future__ import annotations

import json
import subprocess
import sys
from pathlib import Path

import pytest

from tests.cli_runner import invoke

pytestmark = pytest.mark.slow  # the whole module (pyproject's slow marker)

ROOT = Path(__file__).resolve().parents[2]
BROKEN = ROOT / "tests" / "kinematics" / "broken"
QUICK = ("--samples", "400", "--no-speed")


def test_shipped_plugin_passes_with_exit_0() -> None:
    result = invoke("kins", "check", "deltakins", "--ini", ROOT / "examples/delta/cnc.ini", *QUICK)
    assert result.exit_code == 0, result.output
    assert "workspace (cnc.ini [KINEMATICS] limits): X -400..400  Y -400..400  Z 0..200" in result.stdout
    assert result.stdout.rstrip().endswith("result: no findings")


def test_broken_plugin_exits_1_with_the_finding_and_its_poses() -> None:
    result = invoke("kins", "check", BROKEN / "wrapping_angle.py", "--box", "-100,-10,-50,50,0,10", *QUICK)
    assert result.exit_code == 1
    assert "K202 continuity: joint jC wraps by 360 (1 turn)" in result.stdout
    assert "    at X" in result.stdout and "    and X" in result.stdout


def test_json_report() -> None:
    result = invoke("kins", "check", BROKEN / "nan_corner.py", "--json", "--seed", "3", *QUICK)
    report = json.loads(result.stdout)
    assert result.exit_code == 1 and report["ok"] is False and report["seed"] == 3
    [finding] = report["findings"]
    assert finding["code"] == "K401" and "nan" in finding["joints"]  # NaN written as a string: valid JSON


@pytest.mark.parametrize("box, message", [
    ("1,2,3", "--box takes X0,X1,Y0,Y1,Z0,Z1 and optionally A0,A1,B0,B1,C0,C1 (6 to 12 numbers, got 3)"),
    ("a,b,c,d,e,f", "--box: not a list of numbers"),
])
def test_bad_box_is_a_usage_error(box: str, message: str) -> None:
    result = invoke("kins", "check", "trivial", "--box", box)
    assert result.exit_code == 2 and message in result.stderr and "Traceback" not in result.output


def test_unknown_plugin_is_exit_70() -> None:
    result = invoke("kins", "check", "no_such_kins", *QUICK)
    assert result.exit_code == 70 and "not found" in result.stderr


def test_compare_exits_1_when_the_plugins_differ() -> None:
    same = invoke("kins", "compare", "corexy", "corexy", *QUICK[:2])
    assert same.exit_code == 0 and "result: the same within the tolerance" in same.stdout
    differ = invoke("kins", "compare", BROKEN / "scaled_forward.py", "trivial", "--json", *QUICK[:2])
    data = json.loads(differ.stdout)
    assert differ.exit_code == 1 and data["ok"] is False
    assert next(d for d in data["forward"] if d["name"] == "X")["largest"] == pytest.approx(1.0)


def test_plot_writes_the_picture(tmp_path: Path) -> None:
    pytest.importorskip("matplotlib")
    out = tmp_path / "delta.png"
    result = invoke("kins", "plot", "deltakins", "-o", out, "--box", "-150 150 -150 150 -50 100", "--resolution", "12")
    assert result.exit_code == 0, result.output
    assert out.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
    bad = invoke("kins", "plot", "deltakins", "-o", tmp_path / "delta.txt")
    assert bad.exit_code == 2 and ".png, .svg, .pdf (not .txt)" in bad.stderr


@pytest.mark.skipif(not (ROOT / "kins/c/rotatekins.c").exists(), reason="source checkout only")
def test_a_crashing_compiled_plugin_does_not_take_ecnc_down(tmp_path: Path) -> None:
    """A true subprocess run: the C library segfaults, ecnc reports it and exits 1."""
    import shutil

    if shutil.which("cc") is None:
        pytest.skip("no C compiler (cc)")
    so = tmp_path / "crash_corner.so"
    build = subprocess.run([sys.executable, "-m", "edingcnc_lang", "kins", "build", BROKEN / "crash_corner.c",
                            "-o", so], capture_output=True, text=True, check=False)
    assert build.returncode == 0, build.stderr
    done = subprocess.run([sys.executable, "-m", "edingcnc_lang", "kins", "check", so, *QUICK],
                          capture_output=True, text=True, check=False, timeout=120)
    assert done.returncode == 1, done.stderr
    assert "K602 compiled: KinematicsInverse crashed the process (SIGSEGV)" in done.stdout
    assert "at X100 Y100" in done.stdout


def test_kins_inverse_refuses_nan_from_a_plugin() -> None:
    result = invoke("kins", "inverse", BROKEN / "nan_corner.py", "100", "100", "0")
    assert result.exit_code == 70 and result.stdout == ""
    assert "inverse returned a value that is not a finite number (jx=100.0 jy=100.0 jz=nan" in result.stderr
    assert "KinematicsDomainError" in result.stderr


def test_a_plugin_that_calls_sys_exit_at_import_is_a_plugin_error(tmp_path: Path) -> None:
    boom = tmp_path / "boom.py"
    boom.write_text("raise SystemExit(3)\n")
    result = invoke("kins", "check", boom, *QUICK)
    assert result.exit_code == 70
    assert f"kinematics plug-in {boom}: importing it failed: SystemExit: 3" in result.stderr


def test_a_plugin_that_calls_sys_exit_in_inverse_is_a_k402_finding(tmp_path: Path) -> None:
    quits = tmp_path / "quits.py"
    quits.write_text("import sys\n"
                     "from edingcnc_lang.kinematics.builtin import TrivialKinematics\n\n\n"
                     "class Quits(TrivialKinematics):\n"
                     "    def inverse(self, pos, tool_length=0.0):\n"
                     "        if pos[0] > 50:\n"
                     "            sys.exit(4)\n"
                     "        return super().inverse(pos, tool_length)\n\n\n"
                     "KINEMATICS = Quits\n")
    result = invoke("kins", "check", quits, "--box=-100,100,-100,100,0,10", *QUICK)
    assert result.exit_code == 1, result.output
    assert "K402 domain: inverse raised" in result.stdout and "SystemExit: 4" in result.stdout


def test_cartesian_limits_come_from_load_config_and_a_bad_one_names_its_line(tmp_path: Path) -> None:
    ini = tmp_path / "cnc.ini"
    ini.write_text("[KINEMATICS]\npositiveLimitX = 50\nnegativeLimitX = -50\npositiveLimitY = 40\n"
                   "negativeLimitY = -40\npositiveLimitZ = 10\nnegativeLimitZ = 0\n")
    good = invoke("kins", "check", "trivial", "--ini", ini, *QUICK)
    assert good.exit_code == 0, good.output
    assert "workspace (cnc.ini [KINEMATICS] limits): X -50..50  Y -40..40  Z 0..10" in good.stdout
    ini.write_text(ini.read_text().replace("positiveLimitY = 40", "positiveLimitY = 4o"))
    bad = invoke("kins", "check", "trivial", "--ini", ini, *QUICK)
    assert bad.exit_code == 70
    assert bad.stderr == f"{ini}:4: error: positiveLimitY in [KINEMATICS]: expected a number, got '4o'\n"
