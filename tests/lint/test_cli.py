"""``ecnc lint`` on the command line: every output format, the options and the exit codes."""
from __future__ import annotations

import json
from pathlib import Path

import pytest

from edingcnc_lang.codes import CODES
from tests.cli_runner import Result, invoke


def run(*args: str | Path) -> Result:
    return invoke("lint", *args)


@pytest.fixture
def job(tmp_path: Path) -> Path:
    path = tmp_path / "job.nc"
    path.write_text("G0 X1\nG1 X5 F0\nG38.2 Z-1 F10\nIf [#5067 == 1]\nEndIf\nM30\n")
    return path


def test_text_shows_location_code_message_source_and_caret(job: Path) -> None:
    result = run(job)
    assert result.exit_code == 1
    lines = result.output.splitlines()
    assert lines[0] == f"{job}:2:7: G503 F0 on a G1 move: give a feed rate above 0 (EdingCNC G1516: incorrect feed rate)"
    assert lines[1] == "    G1 X5 F0"
    assert lines[2] == "          ^"
    assert lines[3].startswith(f"{job}:3:1: G504 ")


def test_no_source_prints_one_line_per_finding(job: Path) -> None:
    result = run(job, "--no-source")
    assert result.output.splitlines() == [
        f"{job}:2:7: G503 F0 on a G1 move: give a feed rate above 0 (EdingCNC G1516: incorrect feed rate)",
        (f"{job}:3:1: G504 G38.2 runs while the job is rendered too: wrap it in If [#5397 == 0] ... EndIf "
         "(not while rendering), or If [[#5380 == 0] and [#5397 == 0]] (nor in simulation)"),
    ]


def test_json_is_an_array_of_findings(job: Path) -> None:
    result = run(job, "--format", "json")
    assert result.exit_code == 1
    data = json.loads(result.output)
    assert [(d["line"], d["col"], d["code"], d["severity"]) for d in data] == [
        (2, 7, "G503", "error"), (3, 1, "G504", "warning")]
    assert set(data[0]) == {"path", "line", "col", "code", "severity", "message"}
    assert data[0]["path"] == str(job)


def test_github_annotations(job: Path) -> None:
    result = run(job, "--format", "github")
    lines = result.output.splitlines()
    assert lines[0].startswith(f"::error file={job},line=2,col=7,title=G503::F0 on a G1 move")
    assert lines[1].startswith(f"::warning file={job},line=3,col=1,title=G504::G38.2 runs")


def test_github_escapes_newlines_and_property_separators(tmp_path: Path) -> None:
    odd = tmp_path / "a,b.nc"
    odd.write_text("G1 X1 F0\n")
    result = run(odd, "--format", "github")
    assert "file=" + str(odd).replace(",", "%2C") + ",line=1" in result.output


def test_sarif_has_rules_from_the_registry_and_results(job: Path) -> None:
    result = run(job, "--format", "sarif")
    log = json.loads(result.output)
    assert log["version"] == "2.1.0"
    run_ = log["runs"][0]
    rules = run_["tool"]["driver"]["rules"]
    assert [r["id"] for r in rules] == list(CODES)
    first = run_["results"][0]
    assert first["ruleId"] == "G503" and first["level"] == "error"
    assert rules[first["ruleIndex"]]["id"] == "G503"
    region = first["locations"][0]["physicalLocation"]["region"]
    assert region == {"startLine": 2, "startColumn": 7}
    assert run_["results"][1]["level"] == "warning"


def test_clean_file_exits_0_with_no_output(tmp_path: Path) -> None:
    clean = tmp_path / "clean.nc"
    clean.write_text("G0 X1\nM30\n")
    for fmt in ("text", "github"):
        result = run(clean, "--format", fmt)
        assert (result.exit_code, result.output.strip()) == (0, "")
    assert json.loads(run(clean, "--format", "json").output) == []
    assert json.loads(run(clean, "--format", "sarif").output)["runs"][0]["results"] == []


def test_warnings_alone_exit_1(tmp_path: Path) -> None:
    path = tmp_path / "w.nc"
    path.write_text("G0 X[#100]\n")
    result = run(path, "--format", "json")
    assert result.exit_code == 1
    assert [d["code"] for d in json.loads(result.output)] == ["V302"]


def test_syntax_errors_are_findings_exit_1(tmp_path: Path) -> None:
    path = tmp_path / "s.nc"
    path.write_text("G0 X1\nG0 X10+5\n")
    result = run(path, "--no-source")
    assert result.exit_code == 1
    assert result.output.startswith(f"{path}:2:4: E105 expression needs brackets")


@pytest.mark.parametrize("args", [
    ["--bogus"],                       # unknown option
    ["does-not-exist.nc"],             # missing path
    [],                                # nothing to lint
    ["--select", "Q9"],                # unknown code
    ["--ignore", "G999"],              # unknown code
    ["--format", "xml"],               # unknown format
])
def test_usage_errors_exit_2(args: list[str], job: Path) -> None:
    extra = [str(job)] if args and args[0] in ("--select", "--ignore", "--format") else []
    result = run(*args, *extra)
    assert result.exit_code == 2, result.output


def test_select_and_ignore_take_codes_and_prefixes(job: Path) -> None:
    def codes(*args: str) -> list[str]:
        return [d["code"] for d in json.loads(run(job, "--format", "json", *args).output)]

    assert codes("--select", "G503") == ["G503"]
    assert codes("--select", "g5") == ["G503", "G504"]
    assert codes("--ignore", "G504") == ["G503"]
    assert codes("--select", "G5", "--ignore", "G503,V") == ["G504"]
    assert run(job, "--ignore", "G5").exit_code == 0



def test_a_retired_code_is_still_accepted_and_explained(tmp_path: Path) -> None:
    """G505 (a #5067 check after G38.2) is retired: a probe that does not touch is a run error, so
    a G38.2 with no check reports nothing, and scripts naming the code keep working."""
    job = tmp_path / "probe.nc"
    job.write_text("If [[#5380 == 0] and [#5397 == 0]]\n    G38.2 Z-5 F100\nEndIf\nG38.2 Z-5 F100 ; noqa: G504,G505\n")
    assert run(job).exit_code == 0
    assert run(job, "--select", "G505").exit_code == 0
    assert run(job, "--ignore", "G505,G504").exit_code == 0
    explained = run("--explain", "G505")
    assert explained.exit_code == 0 and "G505: retired" in explained.output and "run error" in explained.output
    assert "G505" not in run("--list-codes").output

def test_list_codes_prints_every_code_with_severity() -> None:
    result = run("--list-codes")
    assert result.exit_code == 0
    lines = result.output.splitlines()
    assert len(lines) == len(CODES)
    assert "G503  error    feed rate 0 on a feed or probe move (EdingCNC G1516)" in lines
    assert any(line.startswith("V302  warning") for line in lines)


def test_macro_option_resolves_gosub(tmp_path: Path) -> None:
    job = tmp_path / "job.nc"
    job.write_text("GoSub Park\nM30\n")
    lib = tmp_path / "lib" / "mine.cnc"
    lib.parent.mkdir()
    lib.write_text(";@unit mm\nSub park\n    G53 G0 Z0\nEndSub\n")
    assert run(job, "--select", "S208").exit_code == 1
    assert run(job, "--macro", lib).exit_code == 0
    assert run(job, "--user-macro", lib).exit_code == 0


def test_macro_beside_the_job_is_found_case_insensitively(tmp_path: Path) -> None:
    job = tmp_path / "job.nc"
    job.write_text("GoSub park\nM30\n")
    (tmp_path / "MACRO.CNC").write_text(";@unit mm\nSub PARK\nEndSub\n")
    assert run(job).exit_code == 0


def test_folders_are_walked_for_source_suffixes_only(tmp_path: Path) -> None:
    (tmp_path / "sub").mkdir()
    (tmp_path / "sub" / "a.ngc").write_text("G1 X1 F0\n")
    (tmp_path / "b.TAP").write_text("G1 X1 F0\n")
    (tmp_path / "notes.md").write_text("G1 X1 F0\n")
    data = json.loads(run(tmp_path, "--format", "json").output)
    assert sorted(Path(d["path"]).name for d in data) == ["a.ngc", "b.TAP"]


def test_ini_is_checked_and_its_user_outputs_count_as_written(tmp_path: Path) -> None:
    job = tmp_path / "job.nc"
    job.write_text("G0 X[#3000]\n")
    ini = tmp_path / "cnc.ini"
    ini.write_text("[KINEMATICS]\nuserOutputStartVariable = 3000\nuserOutputNumVariables = 2\n")
    assert run(job, "--select", "V302").exit_code == 1
    assert run(job, "--ini", ini).exit_code == 0
    ini.write_text("[KINEMATICS]\nuserOutputStartVariable = 5000\nuserOutputNumVariables = 2\n")
    result = run(job, "--ini", ini, "--format", "json", "--select", "C")
    assert [(d["path"], d["line"], d["code"]) for d in json.loads(result.output)] == [(str(ini), 2, "C700")]


def test_the_garbage_collector_is_paused_only_while_linting(job: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    import gc

    from edingcnc_lang.lint import driver

    seen: list[bool] = []
    real = driver.lint_paths

    def spy(*args: object, **kwargs: object) -> object:
        seen.append(gc.isenabled())
        return real(*args, **kwargs)  # type: ignore[arg-type]

    monkeypatch.setattr("edingcnc_lang.lint.parallel.lint_paths", spy)  # what the CLI calls with -j 1
    assert gc.isenabled()
    assert run(job).exit_code == 1
    assert seen == [False]  # big acyclic trees: the collector would only waste time on them
    assert gc.isenabled()  # and an embedding program gets it back as it was


def test_an_unknown_gosub_names_the_files_that_were_searched(tmp_path: Path) -> None:
    (tmp_path / "macro.cnc").write_text(";@unit mm\nSub a\n    GoSub nothere\nEndSub\n")
    (tmp_path / "user_macro.cnc").write_text(";@unit mm\nSub b\nEndSub\n")
    job = tmp_path / "job.nc"
    job.write_text("GoSub a\nGoSub zz\nM30\n")
    lone = tmp_path / "lone" / "job.nc"
    lone.parent.mkdir()
    lone.write_text("GoSub zz\nM30\n")
    result = run(tmp_path / "macro.cnc", job, lone, "--select", "S208", "--no-source")
    assert result.exit_code == 1
    assert "job.nc:2:1: S208 GoSub zz: no Sub zz in this file or macro.cnc or user_macro.cnc" in result.output
    assert "macro.cnc:3:5: S208 GoSub nothere: no Sub nothere in this file or user_macro.cnc" in result.output
    assert ("S208 GoSub zz: no Sub zz in this file or its macro files "
            "(--macro/--user-macro, or macro.cnc beside it)") in result.output
