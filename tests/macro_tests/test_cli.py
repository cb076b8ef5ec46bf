"""``ecnc test``: a line per test, the count line, exit codes, -k, -x, -j, --junit, --cov-report."""
from __future__ import annotations

import json
import xml.etree.ElementTree as ET
from pathlib import Path

import pytest

from tests.cli_runner import invoke

TESTS = """[[test]]
name = "sets one"
job = "#1 = 1\\nM30\\n"
expect.vars = { "1" = 1 }

[[test]]
name = "wrong on purpose"
job = "#1 = 1\\nG0 Z-1\\nM30\\n"
expect.vars = { "1" = 2 }
forbid.rapid_below_z = 0

[[test]]
name = "sets two"
job = "#2 = 2\\nM30\\n"
expect.vars = { "2" = 2 }
"""


@pytest.fixture
def folder(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> Path:
    (tmp_path / "sub").mkdir()
    (tmp_path / "sub" / "test_a.toml").write_text(TESTS)
    (tmp_path / "sub" / "test_b.toml").write_text('[[test]]\nname = "b passes"\njob = "M30\\n"\n')
    (tmp_path / "notes.toml").write_text("not = [a test file")  # not test_*.toml: never read
    monkeypatch.chdir(tmp_path)
    return tmp_path


def test_a_line_per_test_then_the_count(folder: Path) -> None:
    result = invoke("test")
    assert result.exit_code == 1
    assert result.stdout.splitlines() == [
        "PASS sub/test_a.toml:1: sets one",
        "FAIL sub/test_a.toml:6: wrong on purpose: #1: expected 2, got 1; "
        "forbid.rapid_below_z: the rapid at <job>:2 ends at work Z-1, below Z0",
        "PASS sub/test_a.toml:12: sets two",
        "PASS sub/test_b.toml:1: b passes",
        "3 passed, 1 failed"]


def test_k_selects_and_x_stops_at_the_first_failure(folder: Path) -> None:
    assert invoke("test", "-k", "sets and not two").stdout.splitlines() == [
        "PASS sub/test_a.toml:1: sets one", "1 passed, 0 failed"]
    assert invoke("test", "sub/test_b.toml").exit_code == 0
    stopped = invoke("test", "-x", ".")
    assert stopped.exit_code == 1 and stopped.stdout.splitlines()[-1] == "1 passed, 1 failed"


@pytest.mark.slow
def test_j_runs_files_in_parallel_with_the_same_report(folder: Path) -> None:
    assert invoke("test", "-j", "2").stdout == invoke("test").stdout


def test_junit_xml_has_a_testcase_per_test(folder: Path) -> None:
    invoke("test", "--junit", "out/results.xml")
    root = ET.parse(folder / "out" / "results.xml").getroot()
    cases = root.findall(".//testcase")
    assert [c.get("name") for c in cases] == ["sets one", "wrong on purpose", "sets two", "b passes"]
    assert cases[0].get("classname") == "sub.test_a"
    (failure,) = root.findall(".//failure")
    assert failure.get("message") == "#1: expected 2, got 1"
    assert failure.text and "forbid.rapid_below_z" in failure.text


def test_coverage_reports(folder: Path) -> None:
    (folder / "m.cnc").write_text("Sub a\n  #1 = 1\nEndSub\nSub b\n  #2 = 1\nEndSub\n")
    (folder / "test_m.toml").write_text('[[test]]\nname = "a"\nmacro = "m.cnc"\njob = "GoSub a\\nM30\\n"\n')
    result = invoke("test", "test_m.toml", "--cov")
    assert result.exit_code == 0
    # line 5 is sub b's, which no test ran: named as a sub, not as a line
    assert result.stdout.splitlines()[1:] == ["1 passed, 0 failed", "m.cnc: lines 1/2 (50%), branches 0/0 (-)",
                                              "  subs no test ran: b"]
    result = invoke("test", "test_m.toml", "--cov-report", "json:cov.json", "--cov-report", "html:cov")
    assert json.loads((folder / "cov.json").read_text())["files"]["m.cnc"]["subs_never_run"] == ["b"]
    assert "coverage pages: cov/index.html" in result.stdout and (folder / "cov" / "index.html").is_file()


def test_a_test_file_that_does_not_load_is_exit_65_without_a_traceback(folder: Path) -> None:
    (folder / "sub" / "test_c.toml").write_text('[[test]]\nname = "c"\njob = "M30"\nexpect.vars = { "5008" = "two" }\n')
    result = invoke("test")
    assert result.exit_code == 65 and result.stdout == ""
    assert result.stderr == "sub/test_c.toml:4: error: expect.vars #5008: 'two' is not a number\n"


@pytest.mark.parametrize(("args", "message"), [
    (("-k", "sets and"), "-k 'sets and': the expression ends too early"),
    (("-k", "nothing"), "no test matches -k 'nothing'"),
    (("--cov-report", "xml"), "--cov-report 'xml': write term, json:FILE, html:DIR, lcov:FILE or cobertura:FILE"),
    (("--cov-report", "json"), "--cov-report 'json': write term, json:FILE, html:DIR, lcov:FILE or cobertura:FILE"),
    (("missing",), "'missing' does not exist"),
    (("notes.toml", "-j", "-1"), "-1 is not in the range"),
])
def test_usage_errors_are_exit_2(folder: Path, args: tuple[str, ...], message: str) -> None:
    result = invoke("test", *args)
    assert result.exit_code == 2 and message in result.stderr


def test_no_test_files_is_a_usage_error(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.chdir(tmp_path)
    result = invoke("test")
    assert result.exit_code == 2 and "no test_*.toml files in ." in result.stderr


def test_control_characters_in_a_name_are_shown_escaped(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.chdir(tmp_path)
    (tmp_path / "test_esc.toml").write_text('[[test]]\nname = "clear\\u001b[2J"\njob = "M30\\n"\n')
    assert invoke("test").stdout.splitlines()[0] == "PASS test_esc.toml:1: clear\\x1b[2J"


def test_ctrl_c_stops_every_test_with_exit_130(folder: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    from edingcnc_lang.runner import Run

    def interrupted(self: Run, macros: object) -> None:
        raise KeyboardInterrupt

    monkeypatch.setattr(Run, "start", interrupted)
    result = invoke("test")
    assert result.exit_code == 130 and result.stdout == "" and "interrupted (Ctrl-C)" in result.stderr


def test_junit_to_standard_output_is_refused(folder: Path) -> None:
    result = invoke("test", "--junit", "-")
    assert result.exit_code == 2 and "--junit needs a file" in result.stderr
