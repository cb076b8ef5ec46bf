"""The first hour (docs/quickstart.md): a run says what it assumed, the machine is set up from the
command line, and looking at a job changes nothing beside it."""
from __future__ import annotations

import json
from pathlib import Path

import pytest

from tests.cli_runner import ASSUMING, invoke

ROOT = Path(__file__).resolve().parents[2]
PROBE_JOB = 'G21 G90\nG38.2 Z-50 F100\nmsg "length "#5063\nM30\n'


def write(folder: Path, name: str, text: str) -> Path:
    path = folder / name
    path.write_text(text, encoding="utf-8")
    return path


def test_a_run_without_an_ini_says_once_what_it_assumed_on_stderr_and_in_json(tmp_path: Path) -> None:
    job = write(tmp_path, "job.nc", PROBE_JOB)
    result = invoke("run", job, "--json", assumptions=True)
    lines = result.stderr.splitlines()
    assert lines[0].startswith(ASSUMING + "no cnc.ini given: a built-in 6-axis mill")
    assert lines[1].startswith(ASSUMING + "no macro file given or named by the ini: the packaged macro.cnc")
    assert lines[2] == (f"{job}:2: note: the probe is simulated: G38.2 trips at its target, so a measured length "
                        "is the target's (give --probe-at Z or --probe-surface FILE)")
    assert sum(line.count("probe is simulated") for line in lines) == 1
    document = json.loads(result.stdout)  # stdout is the JSON document alone
    assert [a["what"] for a in document["assumptions"]] == ["machine", "macro", "probe"]
    assert document["assumptions"][2]["line"] == 2


def test_q_silences_the_assumptions_and_an_ini_and_a_macro_leave_none(tmp_path: Path) -> None:
    job = write(tmp_path, "job.nc", "G0 X1\nM30\n")
    assert invoke("run", "-q", job, assumptions=True).stderr == ""
    ini = write(tmp_path, "cnc.ini", "[TOOLS]\n")
    macro = write(tmp_path, "macro.cnc", "Sub unused\nEndSub\n")
    result = invoke("run", job, "--ini", ini, "--macro", macro, "--json", assumptions=True)
    assert result.stderr == "" and json.loads(result.stdout)["assumptions"] == []


def test_probe_at_makes_a_tool_length_macro_measure_a_real_height(tmp_path: Path) -> None:
    job = write(tmp_path, "job.nc", PROBE_JOB)
    assert "length -50" in invoke("run", job).stderr
    result = invoke("run", job, "--probe-at", "-12.5", assumptions=True)
    assert "length -12.5" in result.stderr and "probe is simulated" not in result.stderr


def test_variables_offsets_and_tools_from_the_command_line(tmp_path: Path) -> None:
    job = write(tmp_path, "job.nc", 'msg #4520" "#5221" "#5223" "#5403" "#5503" "#5008\nG0 X0\nM30\n')
    result = invoke("run", job, "--var", "4520=1", "--offset", "G54=100,50,-20", "--tool", "3=42.5,6",
                    "--tool", "3", "--json")
    document = json.loads(result.stdout)
    assert document["messages"][0]["text"] == "1 100 -20 42.5 6 3"
    assert document["machine"]["x"] == 100  # G0 X0 in G54 is machine X100


@pytest.mark.parametrize(("option", "message"), [
    ("--var=5001=3", "#5001 is a read-only system variable: the machine sets it"),
    ("--var=7000=1", "#7000 is not a parameter"),
    ("--offset=G60=1,2", "'G60' is not a work offset"),
    ("--tool=100=5", "T100: tools are T1..T99"),
    ("--var=4520=abc", "#4520: 'abc' is not a plain decimal number"),
])
def test_a_set_up_value_that_cannot_be_is_a_usage_error_with_the_reason(tmp_path: Path, option: str,
                                                                      message: str) -> None:
    job = write(tmp_path, "job.nc", "G0 X1\n")
    result = invoke("run", job, option)
    assert result.exit_code == 2 and message in result.stderr, result.stderr


@pytest.mark.parametrize("command", [["run"], ["plot", "-o", "{out}.png"], ["view", "-o", "{out}.html"],
                                     ["sim", "--stock", "-10,-10,-5,10,10,0"], ["diff", "{job}"]])
def test_every_command_that_runs_a_job_takes_the_same_set_up_options(tmp_path: Path, command: list[str]) -> None:
    pytest.importorskip("matplotlib") if command[0] == "plot" else None
    job = write(tmp_path, "job.nc", "G21 G90\nT3 M6\nG0 X1 Y1\nG1 Z-1 F100\nG0 Z5\nM30\n")
    ini = write(tmp_path, "cnc.ini", "[TOOLS]\n")
    common = ["-q", "-v", "--ini", ini, "--macro", write(tmp_path, "m.cnc", "Sub change_tool\nEndSub\n"),
              "--answer", "ok", "--var", "4520=1", "--offset", "G54=0,0,0", "--tool", "3=40,6", "--probe-at", "-5"]
    args = [part.format(out=tmp_path / "out", job=job) for part in command]
    result = invoke(args[0], job, *args[1:], *common)
    assert result.exit_code in (0, 1), result.output
    assert "ecnc: assuming" not in result.stderr


def test_mdi_takes_them_too(tmp_path: Path) -> None:
    result = invoke("mdi", "-q", "--var", "4520=7", input="#4520\n")
    assert result.exit_code == 0 and "7" in result.stdout


def _folder(folder: Path) -> dict[str, tuple[int, bytes]]:
    return {p.name: (p.stat().st_mtime_ns, p.read_bytes()) for p in folder.iterdir() if p.is_file()}


@pytest.mark.parametrize("command", [["plot", "-o", "{out}.png"], ["view", "-o", "{out}.html"],
                                     ["sim", "--stock", "-10,-10,-5,10,10,0"], ["diff", "{job}"]])
def test_looking_at_a_job_changes_nothing_beside_it(tmp_path: Path, command: list[str]) -> None:
    if command[0] == "plot":
        pytest.importorskip("matplotlib")
    folder = tmp_path / "job"
    folder.mkdir()
    # a Vectric post's log line, and a job that reads back what it wrote
    job = write(folder, "job.nc", 'logfile "job.log" 1\nlogmsg "started"\nG0 X1\nZHCINIT 10 2 2\nZHCS heights.txt\n'
                                  "ZHCL heights.txt\nM30\n")
    write(folder, "job.log", "the user's own log\n")
    before = _folder(folder)
    args = [part.format(out=tmp_path / "out", job=job) for part in command]
    result = invoke(args[0], job, *args[1:])
    assert result.exit_code in (0, 1), result.output
    assert _folder(folder) == before


def test_a_run_writes_the_jobs_log_and_log_dir_makes_its_folder(tmp_path: Path) -> None:
    job = write(tmp_path, "job.nc", 'logfile "job.log" 1\nlogmsg "started"\nM30\n')
    logs = tmp_path / "new" / "logs"
    assert invoke("run", job, "--log-dir", logs).exit_code == 0
    assert (logs / "job.log").read_text(encoding="utf-8") == "started\n"


def test_test_takes_q(tmp_path: Path) -> None:
    write(tmp_path, "macro.cnc", "Sub two\n#1 = 2\nEndSub\n")
    write(tmp_path, "test_two.toml", '[defaults]\nmacro = "macro.cnc"\n'
                                     '[[test]]\nname = "two"\njob = "GoSub two"\nexpect.vars = { 1 = 2 }\n'
                                     '[[test]]\nname = "three"\njob = "GoSub two"\nexpect.vars = { 1 = 3 }\n')
    result = invoke("test", "-q", tmp_path)
    assert "PASS" not in result.stdout and "FAIL" in result.stdout and "1 passed, 1 failed" in result.stdout


def test_v_says_what_the_run_uses_that_was_given(tmp_path: Path) -> None:
    job = write(tmp_path, "job.nc", "G0 X1\nM30\n")
    ini = ROOT / "examples" / "lathe" / "cnc.ini"
    lines = invoke("run", "-v", job, "--ini", ini, assumptions=True).stderr.splitlines()
    assert lines[0].startswith(f"ecnc: using {ini}: a lathe, X as a diameter, travel X ")
    assert lines[1].startswith("ecnc: using macro files, in lookup order: ") and lines[1].endswith("macro.cnc")
    assert invoke("run", "-v", "-q", job, "--ini", ini, assumptions=True).stderr == ""


def test_a_dialog_nobody_answered_is_an_assumption_at_its_line(tmp_path: Path) -> None:
    job = write(tmp_path, "job.nc", 'dlgmsg "Setup" "depth" 100\ndlgmsg "Again" "depth" 100\nM30\n')
    document = json.loads(invoke("run", job, "--json", "--answer", "ok:#100=5").stdout)
    dialogs = [a for a in document["assumptions"] if a["what"] == "dialog"]
    assert [(a["line"], a["text"]) for a in dialogs] == [
        (2, "the dialog 'Again' was answered OK with its values unchanged (no answer given: --answer)")]
