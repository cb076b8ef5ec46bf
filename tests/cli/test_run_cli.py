"""``ecnc run``: exit codes, messages on stderr, the --json document, the --trace CSV, options,
and bad input of every kind ending in a clear message (never a traceback)."""
from __future__ import annotations

import csv
import json
import subprocess
import sys
from pathlib import Path

import pytest

from tests.cli_runner import Result, invoke

ROOT = Path(__file__).resolve().parent.parent.parent
DATA = ROOT / "tests" / "interpreter" / "data"
EMPTY_MACRO = DATA / "empty_macro.cnc"
TRACE_HEADER = ["line", "kind", "x", "y", "z", "a", "b", "c", "jx", "jy", "jz", "ja", "jb", "jc"]


def write(folder: Path, name: str, text: str) -> Path:
    path = folder / name
    path.write_text(text)
    return path


def ecnc(*args: object) -> Result:
    return invoke("run", *args)


def run_job(tmp_path: Path, source: str, *args: object, macro: Path | None = EMPTY_MACRO) -> Result:
    job = write(tmp_path, "job.nc", source)
    return ecnc(job, *(["--macro", macro] if macro else []), *args)


def trace_rows(path: Path) -> list[list[str]]:
    with open(path, newline="") as handle:
        rows = list(csv.reader(handle))
    if rows:
        assert rows[0][:len(TRACE_HEADER)] == TRACE_HEADER
    return rows[1:]


# ------------------------------------------------------------------ exit codes and messages

def test_ok_run_prints_nothing_and_exits_0(tmp_path: Path) -> None:
    result = run_job(tmp_path, "G0 X1\nG1 Y2 F100\nM30\n")
    assert (result.exit_code, result.stdout, result.stderr) == (0, "", "")


def test_messages_go_to_stderr_with_file_and_line(tmp_path: Path) -> None:
    result = run_job(tmp_path, 'G0 X1.5\nmsg "at "#5001\nwarnmsg "check the clamp"\n(MSG from a comment)\n')
    job = tmp_path / "job.nc"
    assert result.exit_code == 0 and result.stdout == ""
    assert result.stderr.splitlines() == [f"{job}:2: msg: at 1.5", f"{job}:3: warning: check the clamp",
                                          f"{job}:4: msg: from a comment"]


def test_errmsg_exits_70_and_prints_its_text_once(tmp_path: Path) -> None:
    result = run_job(tmp_path, 'G0 X1\nerrmsg "spindle not ready"\nG0 X2\n')
    assert result.exit_code == 70
    assert result.stderr.count("spindle not ready") == 1
    assert f"{tmp_path / 'job.nc'}:2: error: spindle not ready" in result.stderr


def test_runtime_error_exits_70_with_path_line_col(tmp_path: Path) -> None:
    result = run_job(tmp_path, "G0 X1\n#1 = [2 / 0]\n")
    assert result.exit_code == 70
    assert result.stderr.startswith(f"{tmp_path / 'job.nc'}:2:7: error: division by zero")


def test_syntax_error_exits_65_and_runs_nothing(tmp_path: Path) -> None:
    trace = tmp_path / "t.csv"
    result = run_job(tmp_path, 'msg "before"\nG0 X1\nG0 X[1\nG1 X2\n', "--trace", trace)
    assert result.exit_code == 65
    assert "before" not in result.stderr
    assert f"{tmp_path / 'job.nc'}:3:5: error: unclosed '['" in result.stderr
    assert not trace.exists() or trace_rows(trace) == []


def test_a_macro_line_that_does_not_parse_is_a_warning_until_the_run_reaches_it(tmp_path: Path) -> None:
    macro = write(tmp_path, "macro.cnc", ";@unit mm\nSub m101\n  G0 Y[#25\nEndSub\n")
    trace = tmp_path / "t.csv"
    result = run_job(tmp_path, "G0 X1\nM101 Y3\n", "--trace", trace, macro=macro)
    assert result.exit_code == 65
    assert result.stderr.count(f"{macro}:3:7: warning:") == 1  # listed once, at load
    assert f"{macro}:3:7: error:" in result.stderr  # the same message when M101 reaches it
    assert len(trace_rows(trace)) == 1  # G0 X1 ran first


def test_strict_makes_a_macro_syntax_error_stop_the_run_before_anything_moves(tmp_path: Path) -> None:
    macro = write(tmp_path, "macro.cnc", ";@unit mm\nSub m101\n  G0 Y[#25\nEndSub\n")
    trace = tmp_path / "t.csv"
    result = run_job(tmp_path, "G0 X1\nM101 Y3\n", "--trace", trace, "--strict", macro=macro)
    assert result.exit_code == 65
    assert f"{macro}:3:7: error:" in result.stderr
    assert not trace.exists() or trace_rows(trace) == []


@pytest.mark.parametrize("args", [
    ["missing.nc"], ["{job}", "--answer", "maybe"], ["{job}", "--max-steps", "0"], ["{job}", "--save-vars"],
    ["{job}", "--log-dir", "{job}"], ["{job}", "--macro", "missing.cnc"], ["{job}", "--bogus"],
    ["{dir}"],
])
def test_usage_errors_exit_2(tmp_path: Path, args: list[str]) -> None:
    job = write(tmp_path, "job.nc", "G0 X1\n")
    result = ecnc(*(a.format(job=job, dir=tmp_path) for a in args))
    assert result.exit_code == 2, result.output
    assert "Traceback" not in result.output


def test_subprocess_exit_codes_and_streams(tmp_path: Path) -> None:
    ok = write(tmp_path, "ok.nc", 'msg "hi"\nG0 X1\n')
    bad = write(tmp_path, "bad.nc", "G0 X[1\n")
    stop = write(tmp_path, "stop.nc", 'errmsg "no"\n')

    def run(job: Path) -> subprocess.CompletedProcess[str]:
        return subprocess.run([sys.executable, "-m", "edingcnc_lang", "run", "-q", str(job), "--macro", str(EMPTY_MACRO)],
                              check=False, capture_output=True, text=True, cwd=tmp_path)

    results = [run(job) for job in (ok, bad, stop)]
    assert [r.returncode for r in results] == [0, 65, 70]
    assert [r.stdout for r in results] == ["", "", ""]
    assert results[0].stderr == f"{ok}:1: msg: hi\n"
    assert results[2].stderr == f"{stop}:1: error: no\n"


# ------------------------------------------------------------------ --json

def test_json_document_keys_types_and_values(tmp_path: Path) -> None:
    result = run_job(tmp_path, 'G10 L2 P1 X10\nG0 X0.5 Y0.25\n#1000 = [1/3]\nmsg "done"\nT3 M6\nG91\n', "--json")
    assert result.exit_code == 0 and result.stderr == ""
    doc = json.loads(result.stdout)
    for key in ("position", "machine", "joints"):
        assert list(doc[key]) == ["x", "y", "z", "a", "b", "c"]
        assert all(type(v) is float for v in doc[key].values())
    assert doc["position"]["x"] == 0.5 and doc["position"]["y"] == 0.25
    assert doc["machine"]["x"] == 10.5 and doc["joints"]["x"] == 10.5
    assert doc["variables"]["1000"] == 1 / 3           # repr-exact
    assert doc["variables"]["5221"] == 10.0
    assert all(isinstance(k, str) for k in doc["variables"])
    assert doc["messages"] == [{"kind": "msg", "text": "done", "file": str(tmp_path / "job.nc"), "line": 4}]
    assert doc["kinematics"] == {"name": "trivial", "type": 1, "active": False}
    assert (doc["tool"], doc["moves"]) == (3, 1)
    assert doc["modal"] == ["G0", "G17", "G21", "G40", "G49", "G54", "G64", "G80", "G91", "G94", "G98"]


def test_json_numbers_round_trip_exactly(tmp_path: Path) -> None:
    result = run_job(tmp_path, "G1 X[0.1 + 0.2] Y[2 ** 0.5] F100\n#100 = [10 / 3]\n", "--json")
    doc = json.loads(result.stdout)
    assert doc["position"]["x"] == 0.1 + 0.2
    assert doc["position"]["y"] == 2 ** 0.5
    assert doc["variables"]["100"] == 10 / 3
    assert repr(0.1 + 0.2) in result.stdout


def test_json_collects_messages_instead_of_printing_them(tmp_path: Path) -> None:
    result = run_job(tmp_path, 'msg "a"\nwarnmsg "b"\n', "--json")
    assert result.stderr == ""
    assert [(m["kind"], m["text"], m["line"]) for m in json.loads(result.stdout)["messages"]] == [
        ("msg", "a", 1), ("warn", "b", 2)]


def test_json_after_a_runtime_error_still_reports_the_state(tmp_path: Path) -> None:
    result = run_job(tmp_path, 'G0 X4\nerrmsg "stop"\n', "--json")
    assert result.exit_code == 70
    doc = json.loads(result.stdout)
    assert doc["position"]["x"] == 4.0
    assert doc["messages"][-1]["kind"] == "error" and doc["messages"][-1]["text"] == "stop"


def test_json_lengths_stay_in_mm_after_g20(tmp_path: Path) -> None:
    doc = json.loads(run_job(tmp_path, "G20\nG0 X1 Y0.5\n", "--json").stdout)
    assert doc["position"]["x"] == 25.4 and doc["machine"]["y"] == 12.7
    assert "G20" in doc["modal"]


# ------------------------------------------------------------------ --trace

def test_trace_rows_for_moves_subs_and_cycles(tmp_path: Path) -> None:
    trace = tmp_path / "trace.csv"
    source = "G0 X1\nGoSub park\nG81 X5 Z-2 R1 F100\nM30\nSub park\n  G0 Z5\n  G1 X0.1 F200\nEndSub\n"
    result = run_job(tmp_path, source, "--trace", trace)
    assert result.exit_code == 0
    rows = [r[:5] + r[8:11] for r in trace_rows(trace)]
    assert rows == [
        ["1", "rapid", "1.0", "0.0", "0.0", "1.0", "0.0", "0.0"],
        ["6", "rapid", "1.0", "0.0", "5.0", "1.0", "0.0", "5.0"],      # inside Sub park
        ["7", "linear", "0.1", "0.0", "5.0", "0.1", "0.0", "5.0"],
        ["3", "rapid", "5.0", "0.0", "5.0", "5.0", "0.0", "5.0"],      # the canned cycle, every move
        ["3", "rapid", "5.0", "0.0", "1.0", "5.0", "0.0", "1.0"],
        ["3", "linear", "5.0", "0.0", "-2.0", "5.0", "0.0", "-2.0"],
        ["3", "rapid", "5.0", "0.0", "5.0", "5.0", "0.0", "5.0"],
    ]


def test_trace_lines_of_moves_in_macro_subs_are_the_subs_lines(tmp_path: Path) -> None:
    macro = write(tmp_path, "macro.cnc", ";@unit mm\n; park\nSub m101\n  G0 Y[#25]\n  G0 Z[#26]\nEndSub\n")
    trace = tmp_path / "t.csv"
    result = run_job(tmp_path, "G0 X1\nM101 Y3 Z4\n", "--trace", trace, macro=macro)
    assert result.exit_code == 0
    assert [(r[0], r[1], r[3], r[4]) for r in trace_rows(trace)] == [
        ("1", "rapid", "0.0", "0.0"), ("4", "rapid", "3.0", "0.0"), ("5", "rapid", "3.0", "4.0")]


def test_trace_kinds_for_arcs_probes_and_g28(tmp_path: Path) -> None:
    trace = tmp_path / "t.csv"
    source = "G0 X10 Z5\nG2 X0 Y10 I-10 F100\nG38.2 Z-5 F50\n#5161 = 1\nG28\n"
    assert run_job(tmp_path, source, "--trace", trace).exit_code == 0
    # the probe, then its back-off (manual p. 25)
    assert [r[1] for r in trace_rows(trace)] == ["rapid", "arc", "probe", "probe", "rapid", "rapid"]


def test_trace_numbers_are_repr_exact(tmp_path: Path) -> None:
    trace = tmp_path / "t.csv"
    run_job(tmp_path, "G0 X[1/3] Y[0.1 + 0.2]\n", "--trace", trace)
    row = trace_rows(trace)[0]
    assert (float(row[2]), float(row[3])) == (1 / 3, 0.1 + 0.2)


# ------------------------------------------------------------------ options

def test_answers_in_order(tmp_path: Path) -> None:
    source = ('#27 = 1\n#28 = 2\ndlgmsg "One" "a" 27\n#100 = #5398\ndlgmsg "Two" "b" 28\n#101 = #5398\n'
              'dlgmsg "Three" "a" 27 "b" 28\n#102 = #5398\n')
    result = run_job(tmp_path, source, "--json", "--answer", "ok:#27=5", "--answer", "cancel")
    v = json.loads(result.stdout)["variables"]
    assert (v["27"], v["28"], v["100"], v["101"], v["102"]) == (5.0, 2.0, 1.0, -1.0, 1.0)


@pytest.mark.parametrize("answer", ["ok:#27=1e400", "ok:#27=nan", "ok:#27=-inf"])
def test_a_non_finite_answer_is_a_usage_error(tmp_path: Path, answer: str) -> None:
    result = run_job(tmp_path, 'dlgmsg "Maße" "Breite" 27 "Höhe" 28\nmsg "b=" #27\n', "--answer", answer)
    assert result.exit_code == 2 and "not a finite number" in result.stderr and "Traceback" not in result.output


def test_an_infinite_ini_variable_is_a_located_config_error(tmp_path: Path) -> None:
    ini = tmp_path / "cnc.ini"
    ini.write_text("[VARIABLES]\r\n#4002 = 1e999\r\n")
    result = run_job(tmp_path, 'msg "v=" #4002\n', "--ini", ini)
    assert result.exit_code == 70 and result.stderr.startswith(f"{ini}:2: error: #4002 in [VARIABLES]")


def test_max_steps(tmp_path: Path) -> None:
    result = run_job(tmp_path, "While [1]\n  G4 P0.1\nEndWhile\n", "--max-steps", "100")
    assert result.exit_code == 70
    assert "step budget of 100" in result.stderr and "--max-steps" in result.stderr


def test_no_simulation_clears_5380(tmp_path: Path) -> None:
    source = "#100 = #5380\n"
    assert json.loads(run_job(tmp_path, source, "--json").stdout)["variables"]["100"] == 1.0
    assert json.loads(run_job(tmp_path, source, "--json", "--no-simulation").stdout)["variables"]["100"] == 0.0


def test_block_delete(tmp_path: Path) -> None:
    source = "G0 X1\n/G0 X2\n"
    assert json.loads(run_job(tmp_path, source, "--json").stdout)["position"]["x"] == 2.0
    assert json.loads(run_job(tmp_path, source, "--json", "--block-delete").stdout)["position"]["x"] == 1.0


def test_log_dir_option(tmp_path: Path) -> None:
    logs = tmp_path / "logs"
    logs.mkdir()
    result = run_job(tmp_path, 'logfile "..\\..\\x.txt" 0\nlogmsg "hello"\n', "--log-dir", logs)
    assert result.exit_code == 0
    assert (logs / "x.txt").read_text() == "hello\n"
    assert not (tmp_path / "x.txt").exists()


def test_allow_exec(tmp_path: Path) -> None:
    flag = tmp_path / "ran"
    refused = run_job(tmp_path, f"Exec touch {flag}\n")
    assert refused.exit_code == 0 and not flag.exists() and "--allow-exec" in refused.stderr
    assert run_job(tmp_path, f"Exec touch {flag}\n", "--allow-exec").exit_code == 0
    assert flag.exists()


def test_save_vars(tmp_path: Path) -> None:
    ini = tmp_path / "cnc.ini"
    ini.write_bytes((DATA / "machine.ini").read_bytes())
    assert run_job(tmp_path, "#4001 = 99\n", "--ini", ini, "--save-vars").exit_code == 0
    assert b"#4001 = 99.000000\r\n" in ini.read_bytes()


def test_user_macro_option_wins_over_macro(tmp_path: Path) -> None:
    result = run_job(tmp_path, "GoSub shared\n", "--json", "--user-macro", DATA / "macros" / "user_macro.cnc",
                     macro=DATA / "macros" / "main_macro.cnc")
    assert json.loads(result.stdout)["variables"]["300"] == 2.0


def test_default_macro_is_the_packaged_one(tmp_path: Path) -> None:
    result = run_job(tmp_path, "GoSub user_8\n", macro=None)
    assert result.exit_code == 0
    assert "Spindle and coolant off, Z up" in result.stderr


# ------------------------------------------------------------------ never a traceback

BAD_JOBS = [
    "G0 X10+5\n", "EndIf\n", "Sub a\nSub b\nEndSub\n", "G0 X1 G1 Y2\n", "#0 = 1\n", "#1 = #6000\n", "G2 X1 F100\n",
    "G38.2 Z0.1 F10\n", "T100 M6\n", "M3 S-1\n", "GoSub nowhere\n", "#5001 = 1\n", "G81 X1 Z1 R0 F1\n",
    "G10 L2 P12 X1\n", "G53 G2 X1 R1\n", 'dlgmsg "t" "a" #1\n', "G0 X#[0-1]\n", "While [1]\nEndWhile\n",
    "G0 X[1/0]\n", "%\nG0 X1\n%\n", "\x00\x01\x02\n", "IF [1] AND [2]\nENDIF\n", "G43 H-1\n",
    "G4 P-1\n", 'logfile "" 0\n', "G[12.34]\n", "M[1.5]\n", "M6 T[1/3]\n",
]


@pytest.mark.parametrize("source", BAD_JOBS, ids=[repr(s)[:30] for s in BAD_JOBS])
def test_bad_jobs_give_a_message_and_no_traceback(tmp_path: Path, source: str) -> None:
    result = run_job(tmp_path, source, "--max-steps", "1000")
    assert "Traceback" not in result.output
    assert result.exit_code in (0, 65, 70)
    if result.exit_code:
        assert ": error: " in result.stderr


def test_binary_garbage_is_a_syntax_error(tmp_path: Path) -> None:
    job = tmp_path / "job.nc"
    job.write_bytes(bytes(range(256)) * 4)
    result = ecnc(job, "--macro", EMPTY_MACRO)
    assert result.exit_code == 65
    assert "Traceback" not in result.output and ": error: " in result.stderr


@pytest.mark.parametrize("ini_text", [
    "[TRAJECTORY]\ninterpolationTime = abc\n",
    "[TRAJECTORY]\ninterpolationTime = 0\n",
    "[KINEMATICS]\nkinematicsDLLName = nosuchkins.dll\n",
    "[JOINT_0]\npositiveLimit = 5\nnegativeLimit = 0\n",
])
def test_bad_configuration_exits_70_with_a_message(tmp_path: Path, ini_text: str) -> None:
    ini = write(tmp_path, "cnc.ini", ini_text)
    result = run_job(tmp_path, "G0 X10\n", "--ini", ini)
    assert result.exit_code == 70
    assert "error: " in result.stderr and "Traceback" not in result.output


@pytest.mark.parametrize("trace", ["{tmp}/missing/deeper/t.csv", "/proc/ecnc-test.csv"])
def test_unwritable_trace_is_a_clear_error(tmp_path: Path, trace: str) -> None:
    result = run_job(tmp_path, "G0 X1\n", "--trace", trace.format(tmp=tmp_path))
    assert result.exit_code in (2, 70)
    assert "error" in result.output.lower() and "Traceback" not in result.output


KNOWN_CRASHES = [  # each of these once ended in a Python traceback
    pytest.param('dlgmsg "t" "a" 99999\n', id="dlgmsg field #99999"),
    pytest.param("GetToolInfo first 6000\n", id="GetToolInfo into #6000"),
    pytest.param('logfile ".." 0\nlogmsg "x"\n', id="logfile .."),
]


@pytest.mark.parametrize("source", KNOWN_CRASHES)
def test_inputs_that_crashed_give_a_message(tmp_path: Path, source: str) -> None:
    logs = tmp_path / "logs"
    logs.mkdir()
    result = run_job(tmp_path, source, "--log-dir", logs)
    assert result.exit_code == 70
    assert "error:" in result.output and "Traceback" not in result.output


# ------------------------------------------------------------------ examples

@pytest.mark.parametrize(("example", "options", "moves"), [
    ("pocket.nc", [], True), ("dialog_setup.nc", [], True),
    ("probe_corner.nc", [], False),                      # the simulation guard skips the probing
    ("probe_corner.nc", ["--no-simulation"], True),
])
def test_examples_run(example: str, options: list[str], moves: bool) -> None:
    result = ecnc(ROOT / "examples" / example, "--json", *options)
    assert result.exit_code == 0, result.stderr
    assert (json.loads(result.stdout)["moves"] > 0) == moves


def test_pocket_example_from_a_subprocess(tmp_path: Path) -> None:
    trace = tmp_path / "pocket.csv"
    result = subprocess.run([sys.executable, "-m", "edingcnc_lang", "run", str(ROOT / "examples" / "pocket.nc"),
                             "--trace", str(trace)], check=False, capture_output=True, text=True)
    assert result.returncode == 0, result.stderr
    rows = trace_rows(trace)
    kinds = {r[1] for r in rows}
    assert {"rapid", "linear", "arc"} <= kinds
    assert "Traceback" not in result.stderr


def test_trace_file_column_tells_macro_rows_from_job_rows(tmp_path: Path) -> None:
    macro = write(tmp_path, "my, macro.cnc", "Sub park\n  G0 Z5\nEndSub\n")
    job = write(tmp_path, "job.nc", "G0 X1\nGoSub park\nG0 X2\n")
    trace = tmp_path / "trace.csv"
    assert ecnc(job, "--macro", macro, "--trace", trace).exit_code == 0
    with open(trace, newline="") as handle:
        rows = list(csv.reader(handle))
    assert rows[0][len(TRACE_HEADER)] == "file"
    assert [(r[0], r[len(TRACE_HEADER)]) for r in rows[1:]] == [("1", str(job)), ("2", str(macro)), ("3", str(job))]
