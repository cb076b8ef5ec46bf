"""``ecnc kins check|compare|plot`` from the shell: exit codes, text and JSON reports, usage errors."""
from __future__ import annotations

import json
import subprocess
import sys
from pathlib import Path

import pytest

from tests.cli_runner import invoke

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
    ("1,2,3", "--box takes X0 X1 Y0 Y1 Z0 Z1"),
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
