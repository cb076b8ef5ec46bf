"""Coverage of macro files: lines, If/Else and While branches, subs no test ran; the three reports."""
from __future__ import annotations

import json
from pathlib import Path

from edingcnc_lang.testing.coverage import CoverageData, shape_of, summarise
from edingcnc_lang.testing.reports import coverage_json, coverage_term, ranges, write_coverage_html
from edingcnc_lang.testing.session import run_file_cases
from edingcnc_lang.testing.spec import from_mapping

MACRO = """; a macro
#4000 = 1
Sub a
  If [#1 == 1]
    msg "one"
  Else
    msg "other"
  EndIf
  #2 = 0
  While [#2 < #3]
    #2 = [#2 + 1]
  EndWhile
EndSub
Sub never
  M5
EndSub
this line is prose between subs
"""


def macro(tmp_path: Path) -> Path:
    path = tmp_path / "macro.cnc"
    path.write_bytes(MACRO.replace("\n", "\r\n").encode("latin-1"))  # as a controller's file often is
    return path


def covered(tmp_path: Path, *jobs: str) -> CoverageData:
    cases = [from_mapping({"job": job, "macro": str(macro(tmp_path))}, tmp_path) for job in jobs]
    results, data = run_file_cases(cases, stop_first=False, coverage=True)
    assert all(r.passed for r in results) and data is not None
    return data


def test_what_a_macro_file_could_run_comes_from_parsing_it(tmp_path: Path) -> None:
    shape = shape_of(str(macro(tmp_path)))
    assert sorted(shape.lines) == [2, 4, 5, 7, 9, 10, 11, 15]  # no Sub/Else/End lines, no prose
    assert shape.branches == ((4, True, "then"), (4, False, "else"), (10, True, "enter"), (10, False, "leave"))
    assert shape.subs == {"a": ("a", 3), "never": ("never", 14)}


def test_lines_branches_and_subs_of_one_test(tmp_path: Path) -> None:
    (cov,) = summarise(covered(tmp_path, "#1 = 1\nGoSub a\nM30\n"))
    assert cov.lines_total == 8 and sorted(cov.lines_hit) == [2, 4, 5, 9, 10] and cov.missed == (7, 11, 15)
    assert (cov.branches_total, cov.branches_hit) == (4, 2)
    assert cov.branches_missed == ((4, "else"), (10, "enter"))
    assert cov.subs_never_run == ("never",)


def test_coverage_adds_up_over_tests_and_the_json_has_the_issues_shape(tmp_path: Path) -> None:
    files = summarise(covered(tmp_path, "#1 = 1\nGoSub a\nM30\n", "#3 = 2\nGoSub a\nM30\n"))
    document = json.loads(coverage_json(files))
    (entry,) = document["files"].values()
    assert entry["lines"] == {"total": 8, "hit": 7, "missed": [15]}
    assert {k: entry["branches"][k] for k in ("total", "hit")} == {"total": 4, "hit": 4}
    assert entry["subs_never_run"] == ["never"]
    term = coverage_term(files)
    assert "lines 7/8 (88%), branches 4/4 (100%)" in term and "lines not run" not in term  # 15 is in `never`
    assert "subs no test ran: never" in term


def test_the_lines_not_run_are_grouped_by_the_sub_they_are_in(tmp_path: Path) -> None:
    path = tmp_path / "g.cnc"
    path.write_text("Sub a\n#1 = 1\nIf [#1 == 2]\n#2 = 1\nEndIf\nEndSub\n"
                    "Sub b\n#3 = 1\nIf [#3 == 2]\n#4 = 1\n#5 = 1\nEndIf\nEndSub\n")
    cases = [from_mapping({"job": "GoSub a\nGoSub b\nM30\n", "macro": str(path)}, tmp_path)]
    _results, data = run_file_cases(cases, stop_first=False, coverage=True)
    assert data is not None
    files = summarise(data)
    assert files[0].missed_by_sub() == [("a", (4,)), ("b", (10, 11))]
    assert "  lines not run in a: 4\n  lines not run in b: 10-11" in coverage_term(files)


def test_the_html_page_colours_each_line(tmp_path: Path) -> None:
    files = summarise(covered(tmp_path, "#1 = 1\nGoSub a\nM30\n"))
    index = write_coverage_html(files, tmp_path / "html")
    assert "macro.cnc" in index.read_text()
    (page,) = [p for p in index.parent.iterdir() if p.name != "index.html"]
    html = page.read_text()
    assert '<tr class="hit"><td class="n">5</td>' in html
    assert '<tr class="missed"><td class="n">7</td>' in html
    assert '<tr class="partial" title="branch not taken: else"><td class="n">4</td>' in html
    assert '<tr class=""><td class="n">1</td><td><pre>; a macro</pre>' in html


def test_ranges_fold_runs_of_lines() -> None:
    assert ranges([9, 3, 4, 5, 12, 13]) == "3-5, 9, 12-13" and ranges([]) == ""
