"""The built wheel carries the grammars, the stdlib macro file and the shipped kinematics.

A packaging regression (package data left out of the wheel) would pass every
in-repo test, so this builds the wheel and uses it from a folder outside the repo.
"""
from __future__ import annotations

import os
import subprocess
import sys
import zipfile
from pathlib import Path

import pytest

pytestmark = pytest.mark.slow  # the whole module (pyproject's slow marker)

ROOT = Path(__file__).resolve().parents[2]

CHECK = """
import edingcnc_lang, sys
from pathlib import Path
assert Path(edingcnc_lang.__file__).resolve().is_relative_to(Path(sys.argv[1]).resolve()), edingcnc_lang.__file__
from edingcnc_lang.syntax.parser import parse_file
from importlib import resources
program = parse_file("job.nc")
assert len(program.body) == 2, program
macro = resources.files("edingcnc_lang.stdlib") / "macro.cnc"
assert "change_tool" in parse_file(str(macro)).subs
print("ok")
"""


def test_wheel_works_outside_the_repository(tmp_path: Path) -> None:
    wheels = tmp_path / "wheels"
    subprocess.run([sys.executable, "-m", "pip", "wheel", "--no-deps", "-q", "-w", str(wheels), str(ROOT)],
                   check=True, capture_output=True)
    wheel = next(wheels.glob("edingcnc_lang-*.whl"))
    names = set(zipfile.ZipFile(wheel).namelist())
    for needed in ("edingcnc_lang/syntax/grammar/gcode.lark", "edingcnc_lang/syntax/grammar/macro.lark",
                   "edingcnc_lang/stdlib/macro.cnc", "edingcnc_lang/kins/rotatekins.py",
                   "edingcnc_lang/kins/c/rotatekins.c", "edingcnc_lang/knowledge/gm.py",
                   "edingcnc_lang/lsp/server.py"):
        assert needed in names, needed
    unpacked = tmp_path / "site"
    zipfile.ZipFile(wheel).extractall(unpacked)
    work = tmp_path / "elsewhere"
    work.mkdir()
    (work / "job.nc").write_text("G0 X1\nIf [#1 == 0]\n  G1 Y2 F100\nEndIf\n")
    env = {**os.environ, "PYTHONPATH": str(unpacked)}
    result = subprocess.run([sys.executable, "-c", CHECK, str(unpacked)], cwd=work, env=env,
                            capture_output=True, text=True)
    assert result.returncode == 0, result.stderr
    assert result.stdout.strip() == "ok"
