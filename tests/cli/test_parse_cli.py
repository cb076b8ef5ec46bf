"""``ecnc parse``: exit codes and output formats of the public contract."""
from __future__ import annotations

import json
import subprocess
import sys
from pathlib import Path

from tests.cli_runner import invoke


def test_parse_ok_prints_nothing_and_exits_0(tmp_path: Path) -> None:
    job = tmp_path / "job.nc"
    job.write_text("G0 X1\n")
    result = invoke("parse", job)
    assert result.exit_code == 0
    assert result.output == ""


def test_parse_json_dumps_the_ast(tmp_path: Path) -> None:
    job = tmp_path / "job.nc"
    job.write_text("G1 X[#1 + 2]\n")
    result = invoke("parse", "--json", job)
    data = json.loads(result.output)
    word = data["body"][0]["words"][1]
    assert word["letter"] == "X"
    assert word["value"]["type"] == "Binary"
    assert word["span"] == [1, 4, 1, 13]


def test_syntax_errors_exit_65_with_every_error_on_stderr(tmp_path: Path) -> None:
    job = tmp_path / "job.nc"
    job.write_text("G0 X10+5\nG0 X1\nEndIf\n")
    result = subprocess.run([sys.executable, "-m", "edingcnc_lang", "parse", str(job)],
                            check=False, capture_output=True, text=True)
    assert result.returncode == 65
    assert result.stdout == ""
    assert f"{job}:1:4: error: expression needs brackets: X10+5" in result.stderr
    assert f"{job}:3:1: error: EndIf without If" in result.stderr
    assert "Traceback" not in result.stderr


def test_missing_file_is_a_usage_error(tmp_path: Path) -> None:
    result = invoke("parse", tmp_path / "nope.nc")
    assert result.exit_code == 2
