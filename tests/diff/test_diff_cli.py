"""``ecnc diff`` and ``ecnc view --diff`` as a script sees them: exit codes, streams, files written."""
from __future__ import annotations

import json
import re
from pathlib import Path

import pytest

from tests.cli_runner import invoke
from tests.plot.test_browser import CHROMIUM, chromium, console

ROOT = Path(__file__).resolve().parents[2]
OLD = ROOT / "examples" / "pocket.nc"
CASES = Path(__file__).resolve().parent / "cases"


def test_same_is_exit_0_with_a_one_line_verdict() -> None:
    result = invoke("diff", OLD, CASES / "reformatted.nc")
    assert result.exit_code == 0, result.output
    assert "same: nothing the machine does differs beyond 0.001 mm" in result.stdout
    assert result.stderr == ""  # the jobs' messages are not repeated


def test_differs_is_exit_1_with_old_and_new_lines() -> None:
    result = invoke("diff", OLD, CASES / "feed.nc")
    assert result.exit_code == 1
    assert "feed 1200 -> 1500 mm/min, 23 moves" in result.stdout
    assert re.search(r"OLD +\d+: G1 X65 F1200", result.stdout)
    assert re.search(r"NEW +\d+: G1 X65 F1500", result.stdout)


@pytest.mark.slow
def test_a_coarser_tolerance_makes_the_moved_contour_the_same() -> None:
    assert invoke("diff", OLD, CASES / "moved.nc", "--tolerance", "0.06").exit_code == 0
    assert invoke("diff", OLD, CASES / "moved.nc", "--tolerance", "0.04").exit_code == 1


def test_lists_are_bounded_and_what_is_left_out_is_counted(tmp_path: Path) -> None:
    text = OLD.read_text(encoding="latin-1")
    changed = tmp_path / "feeds.nc"  # every feed word changed: several separate runs of moves
    changed.write_text(re.sub(r"F(\d+)", lambda m: f"F{int(m.group(1)) + 7}", text), encoding="latin-1")
    doc = json.loads(invoke("diff", OLD, changed, "--json", "--limit", "1").stdout)
    assert len(doc["feeds"]) == 1 and doc["left_out"]["feeds"] >= 2


@pytest.mark.parametrize(("args", "code"), [
    (("missing.nc", OLD), 2),
    ((OLD, CASES / "feed.nc", "--tolerance", "0"), 2),
    ((OLD, CASES / "feed.nc", "-o", "diff.gif"), 2),
])
def test_usage_errors_are_exit_2(args: tuple[object, ...], code: int, tmp_path: Path, monkeypatch) -> None:
    monkeypatch.chdir(tmp_path)
    assert invoke("diff", *args).exit_code == code


def test_a_syntax_error_is_65_and_a_run_error_70(tmp_path: Path) -> None:
    bad = tmp_path / "bad.nc"
    bad.write_text("G1 X10 F100\nG1 X(1\nM30\n", encoding="ascii")
    result = invoke("diff", OLD, bad)
    assert result.exit_code == 65 and f"{bad}:2:" in result.stderr
    failing = tmp_path / "fails.nc"
    failing.write_text("G1 X10 F100\nG2 X20 Y0 R1\nM30\n", encoding="ascii")  # radius too small for the chord
    result = invoke("diff", failing, OLD)
    assert result.exit_code == 70 and f"{failing}:2:" in result.stderr


def test_the_json_has_the_issues_shape() -> None:
    doc = json.loads(invoke("diff", OLD, CASES / "moved.nc", "--json").stdout)
    for key, kind in (("same", bool), ("max_deviation", float), ("deviations", list), ("feeds", list),
                      ("spindle", list), ("tools", dict), ("time", dict), ("rapids", list)):
        assert isinstance(doc[key], kind), key
    assert set(doc["tools"]) >= {"old", "new"} and set(doc["time"]) == {"old", "new"}
    assert set(doc["deviations"][0]) >= {"old_line", "new_line", "distance", "tool"}


def test_a_machine_changed_for_new_only(tmp_path: Path) -> None:
    """--ini-new: the same job on a machine with a tenth of the acceleration takes longer, and only that."""
    ini = Path("/work/shared/samples/cnc.ini")
    if not ini.exists():
        pytest.skip("no sample cnc.ini")
    slow = tmp_path / "slow.ini"
    slow.write_text(re.sub(r"maxAcceleration = [\d.]+", "maxAcceleration = 100.000000",
                           ini.read_text(encoding="latin-1")), encoding="latin-1")
    doc = json.loads(invoke("diff", OLD, OLD, "--ini", ini, "--ini-new", slow, "--json").stdout)
    assert doc["same"] is False and doc["deviations"] == doc["feeds"] == []
    assert doc["time"]["new"] > doc["time"]["old"]


@pytest.mark.slow
@pytest.mark.parametrize("suffix", [".png", ".svg"])
def test_the_picture_is_written(suffix: str, tmp_path: Path) -> None:
    pytest.importorskip("matplotlib")
    out = tmp_path / f"diff{suffix}"
    result = invoke("diff", OLD, CASES / "leadin.nc", "-o", out)
    assert result.exit_code == 1 and out.stat().st_size > 10_000
    assert f"picture: {out}" in result.stdout
    if suffix == ".svg":
        from edingcnc_lang.diff.style import KINDS

        page = out.read_text(encoding="utf-8")
        assert KINDS["moved"][1] in page and "NEW, unchanged" in page  # the legend names each kind drawn


def test_the_picture_with_the_parts(tmp_path: Path) -> None:
    pytest.importorskip("matplotlib")
    out = tmp_path / "parts.svg"
    result = invoke("diff", OLD, CASES / "rapid.nc", "--stock", "0,0,-20,100,60,0", "-o", out)
    assert result.exit_code == 1 and "parts differ" in out.read_text(encoding="utf-8")


def test_view_diff_holds_both_jobs(tmp_path: Path) -> None:
    out = tmp_path / "both.html"
    assert invoke("view", "--diff", OLD, CASES / "moved.nc", "-o", out).exit_code == 0
    page = out.read_text(encoding="utf-8")
    assert page.count('id="job-data"') == 1 and page.count('id="job-data-old"') == 1
    changes = json.loads(page.split('id="diff-data">')[1].split("</script>")[0])
    [moved] = changes["changes"]  # the contour moved 0.05 mm, as ecnc diff finds it
    assert moved["what"] == "moved" and moved["new"] and moved["color"] == changes["kinds"]["moved"][0]
    assert "{{other}}" not in page
    plain = tmp_path / "one.html"
    invoke("view", OLD, "-o", plain)
    assert 'id="job-data-old"' not in plain.read_text(encoding="utf-8").replace('getElementById("job-data-old")', "")


@pytest.mark.slow
@pytest.mark.skipif(CHROMIUM is None, reason="Chromium is not installed")
@pytest.mark.parametrize(("fragment", "title"), [("", "NEW: "), ("#job=old", "OLD: ")])
def test_view_diff_toggles_in_the_browser(fragment: str, title: str, tmp_path: Path) -> None:
    out = tmp_path / "both.html"
    invoke("view", "--diff", OLD, CASES / "leadin.nc", "-o", out)
    log = chromium(out, tmp_path / "profile", "--dump-dom", fragment=fragment)
    assert console(log) == [], console(log)
    assert re.search(rf'<h1 id="title">{title}', log)
    assert 'id="diff-toggle"' in log and 'data-ready="1"' in log
    assert '<ol id="changes">' in log and "path moved by up to 0.3 mm" in log  # the list of changes, each a link


def test_a_job_that_makes_no_moves(tmp_path: Path) -> None:
    empty = tmp_path / "empty.nc"
    empty.write_text("G21 G90\nM30\n", encoding="ascii")
    assert invoke("diff", empty, empty).exit_code == 0
    result = invoke("diff", OLD, empty, "--json")
    doc = json.loads(result.stdout)  # valid JSON: no Infinity
    assert result.exit_code == 1 and doc["max_deviation"] is None
    assert doc["deviations"] and all(c["what"] == "removed" and c["distance"] is None for c in doc["deviations"])
    assert "the other job makes no moves" in invoke("diff", empty, OLD).stdout
