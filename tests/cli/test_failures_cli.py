"""How every failure ends: the JSON ``error`` object with ``--json``, Ctrl-C (exit 130 naming the
line), and standard streams that are closed or full (a message, never a traceback)."""
from __future__ import annotations

import json
import os
import signal
import subprocess
import sys
import time
from pathlib import Path

import pytest

import edingcnc_lang.cli.options
from edingcnc_lang import speedups
from tests.cli_runner import invoke

pytestmark = pytest.mark.slow  # the whole module (pyproject's slow marker)

ECNC = [sys.executable, "-m", "edingcnc_lang"]


def write(folder: Path, name: str, text: str) -> Path:
    path = folder / name
    path.write_text(text)
    return path


@pytest.mark.parametrize(("source", "kind", "line", "column", "code"), [
    ("G0 X1\nG0 X[1\n", "syntax", 2, 5, 65),
    ("G0 X1\n#1 = [2 / 0]\n", "runtime", 2, 7, 70),
    ('G0 X1\nerrmsg "stop"\n', "errmsg", 2, 1, 70),
])
def test_json_failures_carry_an_error_object(tmp_path: Path, source: str, kind: str, line: int,
                                             column: int | None, code: int) -> None:
    job = write(tmp_path, "job.nc", source)
    result = invoke("run", "--json", job)
    assert result.exit_code == code
    error = json.loads(result.stdout)["error"]
    assert (error["kind"], error["file"], error["line"], error["column"]) == (kind, str(job), line, column)
    assert error["message"] and error["text"].startswith(f"{job}:{line}")


def test_a_run_that_started_still_reports_its_state_with_the_error(tmp_path: Path) -> None:
    job = write(tmp_path, "job.nc", "G0 X4\n#1 = [2 / 0]\n")
    doc = json.loads(invoke("run", "--json", job).stdout)
    assert doc["position"]["x"] == 4.0 and doc["error"]["message"].startswith("division by zero")


def test_a_configuration_error_is_a_json_error_too(tmp_path: Path) -> None:
    job = write(tmp_path, "job.nc", "G0 X1\n")
    ini = write(tmp_path, "cnc.ini", "[KINEMATICS]\nkinematicsDLLName = no_such_kins.dll\n")
    result = invoke("run", "--json", "--ini", ini, job)
    assert result.exit_code == 70
    assert json.loads(result.stdout)["error"]["kind"] in ("plugin", "configuration")


def test_a_limit_of_zero_is_a_configuration_error_naming_its_key(tmp_path: Path) -> None:
    job = write(tmp_path, "job.nc", "G0 X1\nG1 X5 F100\nM30\n")
    ini = write(tmp_path, "cnc.ini", "[JOINT_0]\nname = X\nmaxVelocity = 0\nmaxAcceleration = 1000\n")
    result = invoke("run", "--ini", ini, job)
    assert result.exit_code == 70
    assert result.stderr.startswith(f"{ini}:3: error: maxVelocity = 0 in [JOINT_0] must be 1e-06 to 1e+09")
    lint = invoke("lint", "--format", "json", "--ini", ini, job)
    assert [(d["line"], d["code"]) for d in json.loads(lint.stdout)] == [(3, "C701")]


def test_a_usage_error_with_json_is_a_json_error(tmp_path: Path) -> None:
    result = invoke("run", "--json", tmp_path / "missing.nc")
    assert result.exit_code == 2 and result.stderr.startswith("usage: ecnc run")
    assert json.loads(result.stdout)["error"]["kind"] == "usage"


def test_ctrl_c_in_a_run_names_the_line(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    def interrupt(kind: str, text: str, path: str, line: int) -> None:
        raise KeyboardInterrupt

    monkeypatch.setattr(edingcnc_lang.cli.options, "print_message", interrupt)
    job = write(tmp_path, "job.nc", 'G0 X1\nG0 X2\nmsg "here"\nG0 X3\n')
    result = invoke("run", job)
    assert (result.exit_code, result.stderr) == (130, f"{job}:3:1: error: interrupted (Ctrl-C)\n")


def test_ctrl_c_while_the_job_is_checked_names_the_job(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    """A long job is read through before its first move: Ctrl-C then says so, naming the job."""
    def interrupted(*_args: object, **_kwargs: object) -> None:
        raise KeyboardInterrupt

    monkeypatch.setattr(edingcnc_lang.runner, "check_file", interrupted)
    job = write(tmp_path, "job.nc", "G0 X1\n")
    result = invoke("run", job)
    assert (result.exit_code, result.stderr) == (
        130, f"{job}: error: interrupted (Ctrl-C) while checking the job, before its first move\n")
    error = json.loads(invoke("run", "--json", job).stdout)["error"]
    assert (error["kind"], error["file"]) == ("interrupted", str(job))


def test_a_real_sigint_ends_a_long_run_with_130(tmp_path: Path) -> None:
    job = write(tmp_path, "loop.nc", "#1 = 0\nWhile [1]\n  #1 = [#1 + 1]\nEndWhile\n")
    # Ctrl-C as a user's terminal sends it, even where the tests run with SIGINT ignored (a shell's
    # background job), which a child would inherit
    process = subprocess.Popen([*ECNC, "run", str(job), "--json"], stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                               preexec_fn=lambda: signal.signal(signal.SIGINT, signal.SIG_DFL))
    time.sleep(4)  # started and looping: the loop runs for minutes; a Ctrl-C inside Python's own start-up is not ours
    process.send_signal(signal.SIGINT)
    stdout, stderr = process.communicate(timeout=60)
    assert process.returncode == 130 and b"Traceback" not in stderr
    assert json.loads(stdout)["error"]["kind"] == "interrupted"


def _shell(command: str, cwd: Path) -> subprocess.CompletedProcess[str]:
    ecnc = " ".join(ECNC)
    return subprocess.run(["sh", "-c", command.replace("ecnc", ecnc, 1)], capture_output=True, text=True,
                          cwd=cwd, check=False, env={**os.environ, "PYTHONPATH": str(Path.cwd())})


def test_version_works_with_stderr_closed(tmp_path: Path) -> None:
    result = _shell("ecnc --version 2>&-", tmp_path)
    assert (result.returncode, result.stdout) == (0, f"ecnc, version 0.1.0 ({speedups.CORE} core)\n")


@pytest.mark.skipif(not Path("/dev/full").exists(), reason="no /dev/full")
@pytest.mark.parametrize(("command", "code"), [("ecnc run job.nc", 0), ("ecnc run bad.nc", 65), ("ecnc lint bad.nc", 1),
                                               ("ecnc run job.nc --bogus", 2), ("ecnc --version", 0)])
def test_a_full_stderr_keeps_the_exit_code(tmp_path: Path, command: str, code: int) -> None:
    write(tmp_path, "job.nc", 'G0 X1\nmsg "to stderr"\n')  # the message is the first write to fail
    write(tmp_path, "bad.nc", "G0 X[1\n")
    result = _shell(f"{command} 2> /dev/full", tmp_path)
    assert result.returncode == code  # as with 2>&-: there is no one left to tell


@pytest.mark.parametrize("command", ["ecnc run -q --json job.nc >&-", "ecnc lsp < /dev/null >&-"])
def test_closed_stdout_is_a_write_error_not_a_traceback(tmp_path: Path, command: str) -> None:
    write(tmp_path, "job.nc", "G0 X1\n")
    result = _shell(command, tmp_path)
    assert result.returncode == 70
    assert result.stderr == "error: cannot write standard output: Bad file descriptor\n"  # not 'fileno'


@pytest.mark.skipif(not Path("/dev/full").exists(), reason="no /dev/full")
def test_a_full_stdout_is_a_write_error_not_a_traceback(tmp_path: Path) -> None:
    write(tmp_path, "job.nc", "G0 X1\n")
    result = _shell("ecnc run -q --json job.nc > /dev/full", tmp_path)
    assert result.returncode == 70
    assert result.stderr == "error: cannot write standard output: No space left on device\n"


def test_a_trace_that_cannot_be_written_names_the_file(tmp_path: Path) -> None:
    write(tmp_path, "job.nc", "G0 X1\n")
    result = _shell("ecnc run -q job.nc --trace /dev/full", tmp_path)
    assert result.returncode == 70 and "/dev/full" in result.stderr and "Traceback" not in result.stderr


@pytest.mark.skipif(not Path("/dev/full").exists(), reason="no /dev/full")
def test_an_events_file_that_cannot_be_written_names_the_file(tmp_path: Path) -> None:
    write(tmp_path, "job.nc", "G0 X1\nM3 S1000\nG1 X2 F100\n")
    result = _shell("ecnc run -q job.nc --events /dev/full", tmp_path)
    assert result.returncode == 70
    assert result.stderr == "error: cannot write /dev/full: No space left on device\n"


def test_samples_with_another_extension_is_a_usage_error(tmp_path: Path) -> None:
    write(tmp_path, "job.nc", "G0 X1\n")
    result = _shell("ecnc run job.nc --samples out.xyz", tmp_path)
    assert result.returncode == 2 and not (tmp_path / "out.xyz").exists()
    assert ("ecnc run: error: --samples out.xyz: the samples file must end in .csv or .npz "
            "(or be - for CSV on standard output)") in result.stderr


def test_errors_with_stderr_closed_keep_their_exit_code(tmp_path: Path) -> None:
    write(tmp_path, "bad.nc", "G0 X[1\n")
    result = _shell("ecnc run bad.nc 2>&-", tmp_path)
    assert (result.returncode, result.stdout) == (65, "")


def test_a_closed_stdin_reads_as_empty(tmp_path: Path) -> None:
    assert _shell("ecnc mdi <&-", tmp_path).returncode == 0
    result = _shell("ecnc run --json - <&-", tmp_path)
    assert result.returncode == 0 and json.loads(result.stdout)["moves"] == 0


def test_trace_to_standard_output(tmp_path: Path) -> None:
    write(tmp_path, "job.nc", "G0 X1\nG1 Y2 F100\n")
    result = _shell("ecnc run job.nc --trace -", tmp_path)
    assert result.returncode == 0
    rows = result.stdout.splitlines()
    assert rows[0].startswith("line,kind,x,y,z") and [r.split(",")[:2] for r in rows[1:]] == [["1", "rapid"],
                                                                                              ["2", "linear"]]
    assert _shell("ecnc run -q job.nc --trace - > /dev/full", tmp_path).stderr == (
        "error: cannot write standard output: No space left on device\n")


def test_only_one_output_on_standard_output(tmp_path: Path) -> None:
    job = write(tmp_path, "job.nc", "G0 X1\n")
    result = invoke("run", job, "--json", "--trace", "-")
    assert result.exit_code == 2 and "not --json and --trace -" in result.stderr


@pytest.mark.parametrize("option", ["--trace", "--events", "--samples"])
def test_a_closed_pipe_on_standard_output_ends_quietly_with_exit_1(tmp_path: Path, option: str) -> None:
    # far more rows than a pipe buffers, so the writes go on after the reader is gone (`ecnc ... | head -1`)
    job = write(tmp_path, "big.nc", "#1 = 0\nWhile [#1 < 20000]\n  G1 X[#1 MOD 100] Y[#1 MOD 7] F3000\n"
                                     "  #1 = [#1 + 1]\nEndWhile\n")
    process = subprocess.Popen([*ECNC, "run", "-q", str(job), option, "-"], stdout=subprocess.PIPE,
                               stderr=subprocess.PIPE, cwd=tmp_path,
                               env={**os.environ, "PYTHONPATH": str(Path.cwd())})
    assert process.stdout is not None and process.stderr is not None
    assert process.stdout.readline()
    process.stdout.close()
    stderr = process.stderr.read().decode()
    assert (process.wait(timeout=120), stderr) == (1, "")


def test_control_bytes_of_the_job_are_escaped_in_errors_messages_and_findings(tmp_path: Path) -> None:
    job = tmp_path / "esc.nc"
    job.write_bytes(b'G0 X\x1b]0;HACKED\x07\x1b[2J\n')
    messages = tmp_path / "msg.nc"
    messages.write_bytes(b'msg "a\x1b[2Jb\x00"\n')
    run, lint, said = invoke("run", job), invoke("lint", job), invoke("run", messages)
    for output in (run.stderr, lint.stdout + lint.stderr, said.stderr):
        assert "\x1b" not in output and "\x07" not in output and "\x00" not in output
    assert f"{messages}:1: msg: a\\x1b[2Jb\\x00" in said.stderr
    source, caret = run.stderr.splitlines()[-2:]
    assert source == "    G0 X\\x1b]0;HACKED\\x07\\x1b[2J" and caret.index("^") == source.index("]")
    assert "G0 X\\x1b]0;HACKED" in lint.stdout + lint.stderr
    tabbed = tmp_path / "tab.nc"
    tabbed.write_text("\tG0 X]\n")
    assert invoke("run", tabbed).stderr.splitlines()[-2:] == ["    \tG0 X]", "    \t    ^"]
