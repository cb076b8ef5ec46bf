"""The pytest plugin: test_*.toml files become pytest items, and Python tests get the ``ecnc`` fixture.

pytest runs in a child process on a folder of its own, with the plugin loaded by name as the
``pytest11`` entry point loads it once the package is installed.
"""
from __future__ import annotations

import subprocess
import sys
from pathlib import Path

import pytest

pytestmark = pytest.mark.slow  # the whole module (pyproject's slow marker)

TOML = """[[test]]
name = "passes"
job = "#1 = 1\\nM30\\n"
expect.vars = { "1" = 1 }

[[test]]
name = "fails"
job = "#1 = 1\\nM30\\n"
expect.vars = { "1" = 2 }
"""

PYTHON = '''
def test_fixture_runs_a_macro(ecnc):
    result = ecnc.run(job="G0 Z10\\nGoSub user_1\\nM30\\n", simulation=False, probe=[{"z": -3}],
                      vars={4000: 20, 4001: 100, 4002: 5})
    assert result.position["z"] == 10 and result.var(5067) == 1

def test_fixture_judges_expect(ecnc):
    ecnc.run(job="M30\\n", expect={"vars": {5008: 2}})
'''


def pytest_in(folder: Path, *args: str) -> subprocess.CompletedProcess[str]:
    return subprocess.run([sys.executable, "-m", "pytest", "-p", "edingcnc_lang.testing.pytest_plugin",
                           "-p", "no:cacheprovider", "-p", "no:hypothesispytest", "-q", "-rf", *args], cwd=folder, capture_output=True,
                          text=True, timeout=120)


def test_toml_tests_and_the_fixture_under_pytest(tmp_path: Path) -> None:
    (tmp_path / "test_macro.toml").write_text(TOML)
    (tmp_path / "test_fixture.py").write_text(PYTHON)
    (tmp_path / "pyproject.toml").write_text("[tool.x]\nnot_a = 'test'\n")
    (tmp_path / "settings.toml").write_text("broken = [")  # not test_*.toml: never read
    (tmp_path / "test_data.toml").write_text("broken = [")  # no [[test]] table: some other project's data
    done = pytest_in(tmp_path, "-p", "no:ecnc")
    out = done.stdout
    assert done.returncode == 1, out + done.stderr
    assert "2 failed, 2 passed" in out
    assert "FAIL test_macro.toml:6: fails: #1: expected 2, got 1" in out  # the text ecnc test prints
    assert "FAILED test_fixture.py::test_fixture_judges_expect" in out and "\n#5008: expected 2, got 0\n" in out
    assert "Traceback" not in out


def test_a_broken_test_file_is_a_collection_error_naming_its_line(tmp_path: Path) -> None:
    (tmp_path / "test_broken.toml").write_text('[[test]]\nname = "x"\njob = "M30"\nfoo = 1\n')
    done = pytest_in(tmp_path, "-p", "no:ecnc")
    assert done.returncode == 2
    assert "test_broken.toml:4: error: unknown key 'foo'" in done.stdout
