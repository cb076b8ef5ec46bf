"""The command line itself: help and version, usage errors (exit 2) on every command, how
arguments are read, and the exit status of ``python -m edingcnc_lang`` and the ``ecnc`` script."""
from __future__ import annotations

import json
import os
import subprocess
import sys
from pathlib import Path

import pytest

import edingcnc_lang
from edingcnc_lang import speedups
import edingcnc_lang.runner
from tests.cli_runner import invoke

COMMANDS = [[], ["run"], ["parse"], ["lint"], ["kins"], ["kins", "list"], ["kins", "inverse"], ["kins", "forward"],
            ["kins", "build"], ["kins", "check"], ["kins", "compare"], ["kins", "plot"]]


@pytest.fixture
def job(tmp_path: Path) -> Path:
    path = tmp_path / "job.nc"
    path.write_text("G0 X1\nG1 X5 F0\n")
    return path


def test_version() -> None:
    result = invoke("--version")
    assert (result.exit_code, result.stdout, result.stderr) == (
        0, f"ecnc, version {edingcnc_lang.__version__} ({speedups.CORE} core)\n", "")


@pytest.mark.parametrize("command", COMMANDS, ids=lambda c: " ".join(["ecnc", *c]))
@pytest.mark.parametrize("flag", ["-h", "--help"])
def test_help_on_every_level(command: list[str], flag: str) -> None:
    result = invoke(*command, flag)
    assert result.exit_code == 0 and result.stderr == ""
    assert result.stdout.startswith(" ".join(["usage: ecnc", *command]))


@pytest.mark.parametrize(("command", "names"), [([], ["kins", "lint", "parse", "run"]),
                                                (["kins"], ["list", "inverse", "forward", "build", "check",
                                                            "compare", "plot"])])
def test_a_group_alone_prints_its_help_as_a_usage_error(command: list[str], names: list[str]) -> None:
    result = invoke(*command)
    assert result.exit_code == 2 and result.stdout == ""
    assert result.stderr.startswith(" ".join(["usage: ecnc", *command]))
    assert all(f"\n  {name} " in result.stderr for name in names)


@pytest.mark.parametrize(("command", "arguments"), [
    ([], []), (["run"], ["{job}"]), (["parse"], ["{job}"]), (["lint"], ["{job}"]), (["kins", "list"], []),
    (["kins", "inverse"], ["trivial", "1", "2", "3"]), (["kins", "forward"], ["trivial", "1", "2", "3"]),
    (["kins", "build"], ["{job}"]),
], ids=["ecnc", "run", "parse", "lint", "kins list", "kins inverse", "kins forward", "kins build"])
def test_an_unknown_option_is_a_usage_error_of_that_command(command: list[str], arguments: list[str],
                                                            job: Path) -> None:
    result = invoke(*command, *(a.format(job=job) for a in arguments), "--xyzzy")
    assert (result.exit_code, result.stdout) == (2, "")
    assert result.stderr.startswith(" ".join(["usage: ecnc", *command]))
    assert result.stderr.endswith(": error: unrecognized arguments: --xyzzy\n")


@pytest.mark.parametrize("command", [
    ["run", "{missing}"], ["run", "{job}", "--ini", "{missing}"], ["run", "{job}", "--macro", "{missing}"],
    ["run", "{job}", "--user-macro", "{missing}"], ["parse", "{missing}"], ["lint", "{missing}"],
    ["lint", "{job}", "--macro", "{missing}"], ["lint", "--ini", "{missing}"],
    ["kins", "inverse", "trivial", "--ini", "{missing}", "1", "2", "3"], ["kins", "build", "{missing}"],
], ids=" ".join)
def test_a_missing_input_file_is_a_usage_error_naming_it(command: list[str], job: Path, tmp_path: Path) -> None:
    missing = tmp_path / "no-such-file.nc"
    result = invoke(*(a.format(job=job, missing=missing) for a in command))
    assert (result.exit_code, result.stdout) == (2, "")
    assert result.stderr.startswith(f"usage: ecnc {command[0]}")
    assert ": error: argument " in result.stderr and f"'{missing}' does not exist" in result.stderr


def test_a_folder_where_a_file_belongs_is_a_usage_error(tmp_path: Path) -> None:
    result = invoke("run", tmp_path)
    assert result.exit_code == 2
    assert f"argument JOB: '{tmp_path}' is a folder, not a file" in result.stderr


@pytest.mark.skipif(not os.path.exists(os.devnull) or os.name != "posix", reason="needs /dev/zero")
@pytest.mark.parametrize("command", [["run", "/dev/zero"], ["parse", "/dev/zero"], ["lint", "/dev/zero"],
                                     ["run", "{job}", "--ini", "/dev/zero"], ["run", "{job}", "--macro", "/dev/zero"],
                                     ["run", "{job}", "--probe-surface", "/dev/zero"], ["mdi", "--ini", "/dev/zero"]])
def test_a_device_as_an_input_file_is_a_usage_error_not_a_hang(command: list[str], job: Path) -> None:
    result = invoke(*(a.format(job=job) for a in command))  # /dev/zero never ends: reading it would hang
    assert (result.exit_code, result.stdout) == (2, "")
    assert "'/dev/zero' is a device, not a file" in result.stderr


def test_log_dir_must_be_an_existing_folder(job: Path) -> None:
    result = invoke("run", job, "--log-dir", job)
    assert result.exit_code == 2
    assert f"argument --log-dir: '{job}' is a file, not a folder" in result.stderr


@pytest.mark.parametrize(("args", "message"), [
    (["--max-steps", "0"], "argument --max-steps: 0 is less than 1"),
    (["--max-steps", "x"], "argument --max-steps: 'x' is not a whole number"),
    (["--answer", "maybe"], "argument --answer: answer 'maybe': expected ok, cancel or ok:#N=V,..."),
    (["--save-vars"], "error: --save-vars needs --ini (the file to write the variables to)"),
])
def test_run_option_errors_say_what_is_wrong(job: Path, args: list[str], message: str) -> None:
    result = invoke("run", job, *args)
    assert result.exit_code == 2
    assert result.stderr.startswith("usage: ecnc run") and message in result.stderr


def test_an_unknown_lint_code_points_to_list_codes(job: Path) -> None:
    result = invoke("lint", job, "--select", "E,Q9")
    assert result.exit_code == 2
    assert "argument --select: no code starts with Q9 (see --list-codes)" in result.stderr


@pytest.mark.parametrize("coords", [["-5", "1", "2"], ["-.5", "-2.5e-3", "1E3"]])
def test_negative_numbers_are_coordinates(coords: list[str]) -> None:
    result = invoke("kins", "inverse", "trivial", *coords)
    assert result.exit_code == 0, result.stderr
    assert list(json.loads(result.stdout).values()) == [float(c) for c in coords] + [0.0, 0.0, 0.0]


@pytest.mark.parametrize("value", ["-inf", "nan", "1e999"])
def test_a_coordinate_must_be_finite(value: str) -> None:
    """Read as a value (not an unknown option), then refused: the answer would not be valid JSON."""
    result = invoke("kins", "inverse", "trivial", value, "0", "0")
    assert (result.exit_code, result.stdout) == (2, "")
    assert "X must be a finite number" in result.stderr


def test_options_may_stand_between_arguments(job: Path, tmp_path: Path) -> None:
    other = tmp_path / "other.nc"
    other.write_text("G1 X1 F0\n")
    result = invoke("lint", job, "--format", "json", other, "--select", "G503")
    assert [d["path"] for d in json.loads(result.stdout)] == [str(job), str(other)]
    ini = tmp_path / "cnc.ini"
    ini.write_text("[KINEMATICS]\n")
    result = invoke("kins", "forward", "trivial", "1", "--ini", ini, "-2", "3")
    assert json.loads(result.stdout) == {"x": 1.0, "y": -2.0, "z": 3.0, "a": 0.0, "b": 0.0, "c": 0.0}


def test_after_a_double_dash_everything_is_an_argument(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.chdir(tmp_path)
    Path("-x.nc").write_text("G0 G1 X1\nM30\n")
    assert invoke("parse", "--", "-x.nc").exit_code == 0
    linted = invoke("lint", "--no-source", "--", "-x.nc")
    assert linted.exit_code == 1
    assert linted.stdout.startswith("-x.nc:1:4: G500 G0 and G1 are both in the motion group")
    ran = invoke("run", "--json", "--", "-x.nc")
    assert ran.exit_code == 70 and "same modal group" in ran.stderr


@pytest.mark.parametrize("abbreviation", ["--no", "--js", "--max"])
def test_options_must_be_spelt_out(job: Path, abbreviation: str) -> None:
    result = invoke("run", job, abbreviation)
    assert result.exit_code == 2 and f"unrecognized arguments: {abbreviation}" in result.stderr


@pytest.mark.slow
def test_text_the_console_cannot_show_is_escaped_not_a_traceback(tmp_path: Path) -> None:
    job = tmp_path / "uni.nc"
    job.write_text("G0 G1 X1 ; caf\u00e9\n", encoding="utf-8")
    result = subprocess.run([sys.executable, "-m", "edingcnc_lang", "lint", str(job)], capture_output=True,
                            env={**os.environ, "PYTHONIOENCODING": "ascii"}, check=False)
    assert (result.returncode, result.stderr) == (1, b"")
    assert b"    G0 G1 X1 ; caf\\xe9\n" in result.stdout


def test_blocks_nested_past_the_limit_are_a_syntax_error_not_a_traceback(tmp_path: Path) -> None:
    deep = tmp_path / "deep.nc"
    deep.write_text("If [1]\n" * 3000 + "G0 X1\n" + "EndIf\n" * 3000)
    for command in (("parse",), ("parse", "--json")):
        result = invoke(*command, deep)
        assert result.exit_code == 65
        assert result.stderr.startswith(f"{deep}:51:1: error: blocks nested more than 50 deep")
    assert invoke("parse", deep).stdout == ""
    assert json.loads(result.stdout)["error"]["kind"] == "syntax"


def test_ctrl_c_outside_a_run_exits_130(job: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    def interrupted(*_args: object) -> None:
        raise KeyboardInterrupt

    monkeypatch.setattr(edingcnc_lang.runner.Run, "execute_file", interrupted)
    result = invoke("run", job)
    assert (result.exit_code, result.stdout, result.stderr) == (130, "", "\nerror: interrupted (Ctrl-C)\n")
    result = invoke("run", "--json", job)
    assert result.exit_code == 130 and json.loads(result.stdout)["error"]["kind"] == "interrupted"


@pytest.mark.slow
def test_a_closed_pipe_ends_quietly(tmp_path: Path) -> None:
    big = tmp_path / "big.nc"
    big.write_text("G1 X[#1 + 2] Y3 F100\n" * 2000)  # far more JSON than a pipe holds
    process = subprocess.Popen([sys.executable, "-m", "edingcnc_lang", "parse", "--json", str(big)],
                               stdout=subprocess.PIPE, stderr=subprocess.PIPE)
    assert process.stdout is not None and process.stderr is not None
    process.stdout.close()
    stderr = process.stderr.read()
    assert (process.wait(), stderr) == (1, b"")


@pytest.mark.slow
def test_the_program_ends_at_once_with_all_its_output(tmp_path: Path) -> None:
    """``entry()`` skips the interpreter's teardown: what was written must be complete anyway."""
    job = tmp_path / "big.nc"
    job.write_text("G1 X[#1 + 2] Y3 F100\n" * 3000 + "errmsg \"stop\"\n")
    trace = tmp_path / "trace.csv"
    done = subprocess.run([sys.executable, "-m", "edingcnc_lang", "run", str(job), "--json", "--trace", str(trace)],
                          capture_output=True, check=False)
    assert done.returncode == 70 and json.loads(done.stdout)["messages"][-1]["text"] == "stop"
    assert len(trace.read_text().splitlines()) == 3001  # header and every move, flushed and closed
    parsed = subprocess.run([sys.executable, "-m", "edingcnc_lang", "parse", "--json", str(job)],
                            capture_output=True, check=False)
    assert (parsed.returncode, parsed.stdout.decode()) == (0, invoke("parse", "--json", job).stdout)


@pytest.mark.slow
@pytest.mark.parametrize("program", [[sys.executable, "-m", "edingcnc_lang"],
                                     [str(Path(sys.executable).parent / "ecnc")]],
                         ids=["python -m edingcnc_lang", "ecnc script"])
def test_exit_status_of_the_programs(program: list[str], tmp_path: Path) -> None:
    if not Path(program[0]).exists():
        pytest.skip("the ecnc script is not installed beside this Python")
    bad = tmp_path / "bad.nc"
    bad.write_text("G0 X[1\n")

    def status(*args: str) -> int:
        return subprocess.run([*program, *args], check=False, capture_output=True, cwd=tmp_path).returncode

    assert [status("--version"), status(), status("run", "missing.nc"), status("parse", str(bad))] == [0, 2, 2, 65]


@pytest.mark.parametrize(("args", "message"), [
    (["rn"], "ecnc: error: unknown command 'rn' (did you mean run?)"),
    (["kins", "inverce"], "ecnc kins: error: unknown command 'inverce' (did you mean inverse?)"),
    (["run", "{job}", "--jsn"], "ecnc run: error: unrecognized arguments: --jsn (did you mean --json"),
    # an abbreviation is refused, and answered with the options it would abbreviate
    (["run", "{job}", "--no"], "ecnc run: error: unrecognized arguments: --no (did you mean --no-simulation?)"),
    (["run", "{job}", "--jso"], "ecnc run: error: unrecognized arguments: --jso (did you mean --json?)"),
])
def test_a_mistyped_command_or_option_gets_a_suggestion(args: list[str], message: str, job: Path) -> None:
    result = invoke(*(a.format(job=job) for a in args))
    assert (result.exit_code, result.stdout) == (2, "")
    assert message in result.stderr


def test_an_option_without_its_value_names_the_command(job: Path) -> None:
    result = invoke("run", job, "--trace")
    assert result.exit_code == 2
    assert result.stderr.startswith("usage: ecnc run [OPTIONS] JOB\necnc run: error: ")
    assert "--trace" in result.stderr


def test_a_dash_reads_standard_input() -> None:
    latin1 = "G0 X1 (caf\u00e9)\r\nG1 X2 F100\r\nmsg \"done\"\r\n".encode("latin-1").decode("latin-1")
    ran = invoke("run", "--json", "-", input=latin1)
    assert ran.exit_code == 0 and json.loads(ran.stdout)["messages"][0]["file"] == "<stdin>"
    parsed = invoke("parse", "-", input="G0 X[1\n")
    assert parsed.exit_code == 65 and parsed.stderr.startswith("<stdin>:1:5: error: unclosed '['")
    linted = invoke("lint", "--no-source", "-", input="G0 G1 X1\n")
    assert linted.exit_code == 1 and linted.stdout.startswith("<stdin>:1:4: G500 ")


def test_a_dash_after_double_dash_is_still_standard_input() -> None:
    assert invoke("parse", "--", "-", input="G0 X1\n").exit_code == 0


@pytest.mark.parametrize("codec", ["utf-16-le", "utf-16-be"])
def test_a_windows_unicode_job_is_decoded_as_utf16(tmp_path: Path, codec: str) -> None:
    """Notepad's "Unicode" (UTF-16 with its BOM, CRLF): run, lint and standard input read the text."""
    text = "(Maße in mm)\r\nG0 X10 Y5\r\nmsg \"Höhe \" #5001\r\nG1 X20 F100\r\n"
    data = ("\ufeff" + text).encode(codec)
    job = tmp_path / "unicode.nc"
    job.write_bytes(data)
    ran = json.loads(invoke("run", "--json", job).stdout)
    assert ran["position"]["x"] == 20.0 and ran["messages"][0]["text"] == "Höhe 10"
    assert invoke("lint", job).exit_code == 0
    piped = invoke("run", "-", input=data)
    assert piped.exit_code == 0 and "<stdin>:3: msg: Höhe 10" in piped.stderr


def test_the_ecnc_program_runs_openblas_on_one_thread_unless_told(monkeypatch: pytest.MonkeyPatch) -> None:
    """numpy's BLAS thread pool only costs a run CPU time (issue 42); a user's own setting is kept."""
    from edingcnc_lang.cli import _one_blas_thread

    monkeypatch.delenv("OPENBLAS_NUM_THREADS", raising=False)
    _one_blas_thread()
    assert os.environ["OPENBLAS_NUM_THREADS"] == "1"
    monkeypatch.setenv("OPENBLAS_NUM_THREADS", "4")
    _one_blas_thread()
    assert os.environ["OPENBLAS_NUM_THREADS"] == "4"
