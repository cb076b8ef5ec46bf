"""ecnc parse --json writes the tree statement by statement (issue 17), byte for byte what json.dumps gives."""
from __future__ import annotations

import json
import os
import threading
from pathlib import Path

import pytest

from edingcnc_lang.syntax.parser import parse_file
from edingcnc_lang.syntax.serialize import to_data
from tests.cli_runner import invoke

ROOT = Path(__file__).resolve().parents[2]


@pytest.mark.parametrize("name", ["examples/pocket.nc", "stdlib/macro.cnc", "examples/delta/job.nc", "empty"])
@pytest.mark.parametrize("spans", [True, False])
def test_streamed_json_is_the_whole_trees_json(tmp_path: Path, name: str, spans: bool) -> None:
    path = ROOT / name if name != "empty" else tmp_path / "empty.nc"
    if name == "empty":
        path.write_text(";@unit mm\n")
    result = invoke("parse", "--json", path, *([] if spans else ["--no-spans"]))
    assert result.exit_code == 0, result.stderr
    assert result.stdout == json.dumps(to_data(parse_file(path), with_spans=spans), indent=1) + "\n"


def test_a_syntax_error_anywhere_prints_only_the_error_record(tmp_path: Path) -> None:
    job = tmp_path / "job.nc"
    job.write_text("G0 X1\n" * 100 + "G1 X[\n")
    result = invoke("parse", "--json", job)
    assert result.exit_code == 65
    assert list(json.loads(result.stdout)) == ["error"]  # no half-written tree before it


def _whole_text_refused(*args: object, **kwargs: object) -> None:
    raise AssertionError("standard input was read whole instead of streamed")


@pytest.mark.parametrize("command", [["parse", "-"], ["parse", "-", "--json"], ["run", "-", "--json"], ["lint", "-"]])
def test_standard_input_streams_like_a_file(tmp_path: Path, monkeypatch: pytest.MonkeyPatch,
                                            command: list[str]) -> None:
    """A million-line job on stdin took 2 GB when read whole; copied to a temporary file it streams."""
    import tempfile

    import edingcnc_lang.syntax.parser
    import edingcnc_lang.runner

    job = ROOT / "examples/pocket.nc"
    from_file = invoke(*[job if arg == "-" else arg for arg in command])
    monkeypatch.setattr(edingcnc_lang.syntax.parser, "parse_text", _whole_text_refused)
    monkeypatch.setattr(edingcnc_lang.runner.Run, "execute_text", _whole_text_refused)
    monkeypatch.setattr(tempfile, "tempdir", str(tmp_path))
    from_stdin = invoke(*command, input=job.read_bytes())
    assert from_stdin.exit_code == from_file.exit_code == 0, from_stdin.stderr
    assert from_stdin.stdout == from_file.stdout.replace(json.dumps(str(job)), json.dumps("<stdin>"))
    assert list(tmp_path.iterdir()) == []  # the copy is gone


@pytest.mark.skipif(not hasattr(os, "mkfifo"), reason="no FIFOs here")
@pytest.mark.parametrize("command", [["run", "{job}", "--json"], ["parse", "{job}", "--json"]])
def test_a_fifo_job_is_read_whole_though_it_can_be_read_only_once(tmp_path: Path, command: list[str]) -> None:
    """ecnc run <(generate-job): checked, then run, from one copy (reading the FIFO twice ran nothing)."""
    job = ROOT / "examples/pocket.nc"
    fifo = tmp_path / "job.nc"
    os.mkfifo(fifo)
    writer = threading.Thread(target=fifo.write_bytes, args=(job.read_bytes(),))
    writer.start()
    from_fifo = invoke(*[arg.format(job=fifo) for arg in command])
    writer.join()
    from_file = invoke(*[arg.format(job=job) for arg in command])
    assert from_fifo.exit_code == from_file.exit_code == 0, from_fifo.stderr
    assert from_fifo.stdout == from_file.stdout.replace(json.dumps(str(job)), json.dumps(str(fifo)))


def test_a_full_temporary_folder_is_named_not_standard_output(monkeypatch: pytest.MonkeyPatch) -> None:
    import errno
    import shutil

    def full(*args: object) -> None:
        raise OSError(errno.ENOSPC, "No space left on device")

    monkeypatch.setattr(shutil, "copyfileobj", full)
    result = invoke("run", "-", input="G0 X1\n")
    assert result.exit_code == 70
    assert "stdin.nc: error: No space left on device" in result.stderr and "standard output" not in result.stderr


@pytest.mark.skipif(not hasattr(os, "mkfifo"), reason="no FIFOs here")
def test_a_piped_jobs_run_error_names_the_column_without_reading_the_pipe_again(tmp_path: Path) -> None:
    """The column of an error found after the interpreter comes from the copy that ran (the pipe
    itself, opened again, hung; standard input had no column)."""
    job = "G0 X1\nG68 R30\nG18\n  G2 X1 Z1 R5 F100\n"
    fifo = tmp_path / "gen.nc"
    os.mkfifo(fifo)
    writer = threading.Thread(target=fifo.write_text, args=(job,))
    writer.start()
    from_fifo = invoke("run", fifo)
    writer.join()
    from_stdin = invoke("run", "-", input=job)
    assert from_fifo.exit_code == from_stdin.exit_code == 70
    assert from_fifo.stderr.startswith(f"{fifo}:4:3: error: an arc in the XZ plane cannot be turned by G68")
    assert from_stdin.stderr.startswith("<stdin>:4:3: error: an arc in the XZ plane cannot be turned by G68")


@pytest.mark.skipif(not hasattr(os, "kill"), reason="no signals here")
def test_sigterm_removes_the_copy_of_a_piped_job(tmp_path: Path) -> None:
    """``kill`` or ``timeout`` on ``ecnc run -`` unwinds like Ctrl-C: the job's copy is removed, exit 143."""
    import signal
    import subprocess
    import sys
    import time

    env = {**os.environ, "TMPDIR": str(tmp_path)}
    proc = subprocess.Popen([sys.executable, "-m", "edingcnc_lang", "run", "-"], stdin=subprocess.PIPE,
                            stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, env=env)
    assert proc.stdin is not None
    proc.stdin.write(b"G0 X1\n")
    proc.stdin.flush()  # stdin stays open: ecnc is still copying the job when the signal comes
    for _ in range(600):
        if list(tmp_path.glob("ecnc-stdin-*/stdin.nc")):
            break
        time.sleep(0.05)
    assert list(tmp_path.glob("ecnc-stdin-*/stdin.nc")), "the copy was never made"
    proc.send_signal(signal.SIGTERM)
    assert proc.wait(timeout=30) == 143
    proc.stdin.close()
    assert list(tmp_path.glob("ecnc-stdin-*")) == []
