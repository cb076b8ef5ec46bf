"""``ecnc test --junit FILE`` as CI test-report viewers read it: well-formed whatever the names hold,
``<failure>``/``<error>``/``<skipped>`` told apart, timestamp, hostname and the job's messages;
read back with junitparser (a third-party reader) besides the strict expat parser."""
from __future__ import annotations

import re
import socket
import xml.etree.ElementTree as ET
from pathlib import Path

import pytest

from tests.cli_runner import invoke

TESTS = r'''[[test]]
name = "bell \u0007 and escape \u001b[31m red & <b>\"quoted\"</b>"
job = "msg \"hello \u0001 there\"\n#1 = 1\nM30\n"
expect.vars = { "1" = 1 }

[[test]]
name = "a check that does not hold"
job = "msg \"working\"\n#1 = 1\nM30\n"
expect.vars = { "1" = 2 }

[[test]]
name = "a run that stops"
job = "G0 X[1/0]\nM30\n"

[[test]]
name = "an expected error is a pass"
job = "G0 X[1/0]\nM30\n"
expect.error = "division by zero"
'''


@pytest.fixture
def folder(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> Path:
    (tmp_path / "test_odd.toml").write_text(TESTS, encoding="utf-8")
    (tmp_path / "test_zz.toml").write_text('[[test]]\nname = "later"\njob = "M30\\n"\n', encoding="utf-8")
    monkeypatch.chdir(tmp_path)
    return tmp_path


def report(folder: Path, *args: str) -> tuple[str, ET.Element]:
    result = invoke("test", "--junit", "out.xml", *args)
    assert result.exit_code == 1, result.output
    text = (folder / "out.xml").read_text(encoding="utf-8")
    return text, ET.fromstring(text.encode("utf-8"))  # expat: any character XML 1.0 forbids is an error


def test_control_characters_are_shown_not_written(folder: Path) -> None:
    text, root = report(folder)
    assert not re.search("[\x00-\x08\x0b\x0c\x0e-\x1f]", text)
    first = root.find(".//testcase")
    assert first is not None
    assert first.get("name") == 'bell \\x07 and escape \\x1b[31m red & <b>"quoted"</b>'
    assert first.findtext("system-out") == "msg: hello \\x01 there"


def test_failure_error_and_pass_are_told_apart_with_counts(folder: Path) -> None:
    _, root = report(folder)
    suite = root.find("testsuite[@name='test_odd.toml']")
    assert suite is not None
    cases = {c.get("name"): c for c in suite.findall("testcase")}
    failing = cases["a check that does not hold"]
    assert [e.tag for e in failing] == ["failure", "system-out"]
    assert failing[0].get("message") == "#1: expected 2, got 1" and failing.findtext("system-out") == "msg: working"
    stopped = cases["a run that stops"]
    assert [e.tag for e in stopped] == ["error"] and "the run stopped" in (stopped[0].get("message") or "")
    assert list(cases["an expected error is a pass"]) == []
    assert {k: suite.get(k) for k in ("tests", "failures", "errors", "skipped")} == {
        "tests": "4", "failures": "1", "errors": "1", "skipped": "0"}
    assert suite.get("hostname") == socket.gethostname()
    assert re.fullmatch(r"\d{4}-\d\d-\d\dT\d\d:\d\d:\d\d", suite.get("timestamp") or "")
    assert {k: root.get(k) for k in ("tests", "failures", "errors", "skipped")} == {
        "tests": "5", "failures": "1", "errors": "1", "skipped": "0"}


def test_tests_left_out_by_x_are_skipped(folder: Path) -> None:
    _, root = report(folder, "-x")
    skipped = [c.get("name") for c in root.iter("testcase") if c.find("skipped") is not None]
    assert skipped == ["a run that stops", "an expected error is a pass", "later"]
    assert root.get("skipped") == "3" and root.get("tests") == "5"


def test_junitparser_reads_it(folder: Path) -> None:
    junitparser = pytest.importorskip("junitparser")
    report(folder, "-x")
    xml = junitparser.JUnitXml.fromfile(str(folder / "out.xml"))
    seen = {}
    for suite in xml:
        for case in suite:
            seen[case.name] = [type(r).__name__ for r in case.result]
    assert seen["a check that does not hold"] == ["Failure"]
    assert seen["later"] == ["Skipped"] and seen["bell \\x07 and escape \\x1b[31m red & <b>\"quoted\"</b>"] == []
    suite = next(iter(xml))
    assert (suite.tests, suite.failures, suite.errors, suite.skipped) == (4, 1, 0, 2)
    assert next(iter(suite)).system_out == "msg: hello \\x01 there"
