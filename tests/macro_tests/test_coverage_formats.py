"""``--cov-report lcov:FILE`` and ``cobertura:FILE``: checked against the LCOV record grammar and the
Cobertura coverage-04 structure, and read back by third-party readers (lcov_cobertura, pycobertura)."""
from __future__ import annotations

import re
import xml.etree.ElementTree as ET
from pathlib import Path

import pytest

from tests.cli_runner import invoke
from tests.macro_tests.test_coverage import MACRO

# geninfo(1)'s tracefile records (the ones a record of ours may hold), each as its grammar
LCOV_RECORD = re.compile(r"TN:.*|SF:.+|FN:\d+,[^,\n]+|FNDA:\d+,[^,\n]+|FNF:\d+|FNH:\d+|BRDA:\d+,\d+,\d+,(\d+|-)"
                         r"|BRF:\d+|BRH:\d+|DA:\d+,\d+|LF:\d+|LH:\d+|end_of_record")


@pytest.fixture
def project(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> Path:
    (tmp_path / "macros dir").mkdir()
    (tmp_path / "macros dir" / "macro.cnc").write_text(MACRO)
    (tmp_path / "test_m.toml").write_text('[[test]]\nname = "a"\nmacro = "macros dir/macro.cnc"\n'
                                          'job = "#1 = 1\\nGoSub a\\nM30\\n"\n')
    monkeypatch.chdir(tmp_path)
    result = invoke("test", "--cov-report", "lcov:out/cov.info", "--cov-report", "cobertura:out/cov.xml")
    assert result.exit_code == 0, result.output
    return tmp_path


def parse_lcov(text: str) -> dict[str, dict[str, list[str]]]:
    """Tracefile -> {SF: {record kind: [values]}}, failing on any line outside the grammar."""
    files: dict[str, dict[str, list[str]]] = {}
    current: dict[str, list[str]] | None = None
    for line in text.splitlines():
        assert LCOV_RECORD.fullmatch(line), line
        kind, _, value = line.partition(":")
        if kind == "SF":
            assert current is None
            current = files.setdefault(value, {})
        elif kind == "end_of_record":
            current = None
        elif kind != "TN":
            assert current is not None
            current.setdefault(kind, []).append(value)
    assert current is None
    return files


def test_lcov_follows_the_grammar_with_lines_branches_and_subs(project: Path) -> None:
    files = parse_lcov((project / "out" / "cov.info").read_text())
    record = files["macros dir/macro.cnc"]  # relative to the project
    assert record["DA"] == ["2,1", "4,1", "5,1", "7,0", "9,1", "10,1", "11,0", "15,0"]
    assert (record["LF"], record["LH"]) == (["8"], ["5"])
    assert record["BRDA"] == ["4,0,0,1", "4,0,1,0", "10,1,0,0", "10,1,1,1"]
    assert (record["BRF"], record["BRH"]) == (["4"], ["2"])
    assert record["FN"] == ["3,a", "14,never"] and record["FNDA"] == ["1,a", "0,never"]
    assert (record["FNF"], record["FNH"]) == (["2"], ["1"])


def test_cobertura_has_the_dtd_structure_and_figures(project: Path) -> None:
    text = (project / "out" / "cov.xml").read_text()
    assert '<!DOCTYPE coverage SYSTEM "http://cobertura.sourceforge.net/xml/coverage-04.dtd">' in text
    root = ET.fromstring(text)
    required = {"coverage": {"line-rate", "branch-rate", "lines-covered", "lines-valid", "branches-covered",
                             "branches-valid", "complexity", "version", "timestamp"},
                "package": {"name", "line-rate", "branch-rate", "complexity"},
                "class": {"name", "filename", "line-rate", "branch-rate", "complexity"},
                "method": {"name", "signature", "line-rate", "branch-rate"}, "line": {"number", "hits"}}
    for element in root.iter():
        assert required.get(element.tag, set()) <= set(element.attrib), element.tag
    assert [child.tag for child in root] == ["sources", "packages"]
    assert Path(root.findtext("sources/source") or "") == project
    (cls,) = root.iter("class")
    assert cls.get("filename") == "macros dir/macro.cnc" and [c.tag for c in cls] == ["methods", "lines"]
    lines = {int(line.get("number", 0)): line.attrib for line in cls.findall("lines/line")}
    assert sorted(lines) == [2, 4, 5, 7, 9, 10, 11, 15] and lines[7]["hits"] == "0"
    assert lines[4]["condition-coverage"] == "50% (1/2)" and lines[4]["branch"] == "true"
    assert (root.get("lines-covered"), root.get("lines-valid"), root.get("branches-covered")) == ("5", "8", "2")
    assert float(root.get("line-rate", 0)) == pytest.approx(5 / 8)


def test_third_party_readers_agree(project: Path) -> None:
    lcov_cobertura = pytest.importorskip("lcov_cobertura")
    converted = ET.fromstring(lcov_cobertura.LcovCobertura(
        (project / "out" / "cov.info").read_text(), base_dir=str(project)).convert())
    ours = ET.fromstring((project / "out" / "cov.xml").read_text())
    for key in ("lines-covered", "lines-valid", "branches-covered", "branches-valid"):
        assert converted.get(key) == ours.get(key), key
    pycobertura = pytest.importorskip("pycobertura")
    read = pycobertura.Cobertura(str(project / "out" / "cov.xml"))
    assert read.files() == ["macros dir/macro.cnc"]
    assert read.line_rate() == pytest.approx(5 / 8) and read.branch_rate() == pytest.approx(2 / 4)
    hit, missed = read.hit_statements("macros dir/macro.cnc"), read.missed_statements("macros dir/macro.cnc")
    assert sorted(hit + missed) == [2, 4, 5, 7, 9, 10, 11, 15] and missed == [4, 7, 10, 11, 15]  # partial: 4, 10
