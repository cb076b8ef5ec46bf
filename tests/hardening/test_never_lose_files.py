"""The user's files are never lost (issue 28, item 6): an output that is an input is refused
before anything is written; a job cannot write the run's own files; a UTF-16 cnc.ini is read and
written back in its own encoding; an in-place rewrite reserves its room before it overwrites;
two runs cannot write one output at once."""
from __future__ import annotations

import errno
import os
from pathlib import Path

import pytest

from edingcnc_lang.config import ini as ini_module
from edingcnc_lang.config.machine_config import load_config
from edingcnc_lang.errors import ConfigError, EcncError, UsageFailure
from edingcnc_lang.runner import Run, RunOptions, run_string
from tests.cli_runner import invoke

JOB = "G0 X1\nG1 X2 F100\nM30\n"


@pytest.fixture()
def job(tmp_path: Path) -> Path:
    path = tmp_path / "j.nc"
    path.write_text(JOB)
    return path


@pytest.fixture()
def ini(tmp_path: Path) -> Path:
    path = tmp_path / "cnc.ini"
    path.write_bytes(b"[VARIABLES]\r\n#4000 = 1.000000\r\n")
    return path


# --------------------------------------------------------------------------- outputs that are inputs

@pytest.mark.parametrize("option", ["--trace", "--events", "--samples"])
def test_run_refuses_an_output_that_is_the_job(job: Path, option: str) -> None:
    target = job.with_suffix(".csv") if option == "--samples" else job
    if option == "--samples":
        os.link(job, target)  # the same file under a name --samples accepts
    result = invoke("run", job, option, target)
    assert result.exit_code == 2, result.output
    assert "is also an input" in result.stderr and "Traceback" not in result.output
    assert job.read_text() == JOB


def test_run_refuses_the_ini_and_macro_files_as_outputs(job: Path, ini: Path, tmp_path: Path) -> None:
    before = ini.read_bytes()
    result = invoke("run", job, "--ini", ini, "--trace", ini)
    assert result.exit_code == 2 and "is also an input" in result.stderr
    assert ini.read_bytes() == before
    macro = tmp_path / "macro.cnc"
    macro.write_text("Sub x\nEndSub\n")
    result = invoke("run", job, "--macro", macro, "--events", macro)
    assert result.exit_code == 2 and macro.read_text() == "Sub x\nEndSub\n"


def test_a_hard_link_or_another_spelling_of_the_job_is_the_job(job: Path, tmp_path: Path) -> None:
    other = tmp_path / "sub"
    other.mkdir()
    os.link(job, other / "x.csv")
    assert invoke("run", job, "--trace", other / "x.csv").exit_code == 2
    assert invoke("run", job, "--trace", tmp_path / "sub" / ".." / "j.nc").exit_code == 2
    assert job.read_text() == JOB


def test_two_outputs_in_one_file_are_refused(job: Path, tmp_path: Path) -> None:
    out = tmp_path / "out.csv"
    result = invoke("run", job, "--trace", out, "--samples", out)
    assert result.exit_code == 2 and "twice" in result.stderr


@pytest.mark.parametrize("command", ["view", "plot"])
def test_view_and_plot_refuse_to_write_over_the_job(job: Path, command: str) -> None:
    if command == "plot":
        pytest.importorskip("matplotlib")
    result = invoke(command, job, "-o", job)
    assert result.exit_code == 2 and "is also an input" in result.stderr, result.output
    assert job.read_text() == JOB


def test_the_api_refuses_too(job: Path) -> None:
    with pytest.raises(UsageFailure, match="is also an input"):
        Run(RunOptions(trace=job)).execute_file(job)
    assert job.read_text() == JOB


def test_an_ordinary_output_is_still_written(job: Path, tmp_path: Path) -> None:
    out = tmp_path / "t.csv"
    assert invoke("run", job, "--trace", out).exit_code == 0
    assert len(out.read_text().splitlines()) == 3


# --------------------------------------------------------------------------- two runs, one output

def test_an_output_another_run_is_writing_is_refused(job: Path, tmp_path: Path) -> None:
    pytest.importorskip("fcntl")
    out = tmp_path / "t.csv"
    first = Run(RunOptions(trace=out))
    first.open_outputs()  # the first run holds its trace open (as while it runs)
    try:
        with pytest.raises(EcncError, match="another run is writing it"):
            Run(RunOptions(trace=out)).execute_file(job)
    finally:
        first.motion.close()
    assert invoke("run", job, "--trace", out).exit_code == 0  # free again once the first closed it


# --------------------------------------------------------------------------- what a job may write

@pytest.mark.parametrize("line", ['logfile "cnc.ini" 0', 'logfile "j.nc" 0', 'logfile "macro.cnc" 1\nlogmsg "x"',
                                  "ZHCINIT 10 2 2\nZHCS j.nc", 'logfile "t.csv" 1\nlogmsg "x"'])
def test_a_job_cannot_write_the_runs_own_files(tmp_path: Path, ini: Path, line: str) -> None:
    macro = tmp_path / "macro.cnc"
    macro.write_text("Sub x\nEndSub\n")
    job = tmp_path / "j.nc"
    job.write_text(line + "\nM30\n")
    files = {path: path.read_bytes() for path in (ini, macro, job)}
    result = invoke("run", job, "--ini", ini, "--macro", macro, "--trace", tmp_path / "t.csv")
    assert result.exit_code == 70, result.output
    assert "a file this run reads or writes" in result.stderr
    assert {path: path.read_bytes() for path in files} == files


def test_other_log_files_are_still_written(tmp_path: Path) -> None:
    job = tmp_path / "j.nc"
    job.write_text('logfile "out.txt" 0\nlogmsg "hi"\nM30\n')
    assert invoke("run", job).exit_code == 0
    assert (tmp_path / "out.txt").read_text() == "hi\n"


# --------------------------------------------------------------------------- UTF-16 ini

@pytest.mark.parametrize("codec", ["utf-16", "utf-16-le", "utf-16-be"])
def test_a_utf16_ini_is_read_and_written_back_in_its_own_encoding(tmp_path: Path, codec: str) -> None:
    path = tmp_path / "cnc.ini"
    text = "[VARIABLES]\r\n#4000 = 1.000000\r\n#4001 = 7\r\n[KINEMATICS]\r\n; Grüße\r\n"
    path.write_bytes(text.encode(codec))
    config = load_config(path)
    assert config.variables[4001] == 7.0
    run_string("#4000 = 5\n#4002 = 3\n", RunOptions(ini=path, save_vars=True))
    raw = path.read_bytes()
    assert raw.startswith(text.encode(codec)[:2])  # the BOM (or the first character) as it was
    written = raw.decode("utf-16" if codec == "utf-16" else codec)
    assert "#4000 = 5.000000\r\n" in written and "#4002 = 3.000000" in written and "Grüße" in written
    assert load_config(path).variables[4002] == 3.0


def test_lint_reads_a_utf16_ini(tmp_path: Path) -> None:
    path = tmp_path / "cnc.ini"
    path.write_bytes("[INTERPRETER]\r\nfullCircleThetaEpsilon = abc\r\n".encode("utf-16"))
    assert invoke("lint", path).exit_code != 0


def test_an_undecodable_utf16_ini_is_refused(tmp_path: Path) -> None:
    path = tmp_path / "cnc.ini"
    path.write_bytes(b"\xff\xfe[\x00V\x00\x00\xd8")  # a lone surrogate
    with pytest.raises(ConfigError, match="UTF-16"):
        load_config(path)


# --------------------------------------------------------------------------- in-place rewrite on a full disk

def test_an_in_place_rewrite_that_finds_no_room_leaves_the_file_whole(ini: Path,
                                                                     monkeypatch: pytest.MonkeyPatch) -> None:
    os.link(ini, ini.parent / "link.ini")
    before = ini.read_bytes()

    def full(fd: int, offset: int, length: int) -> None:
        raise OSError(errno.ENOSPC, os.strerror(errno.ENOSPC))

    monkeypatch.setattr(ini_module, "_reserve", full)
    with pytest.raises(ConfigError, match="No space left"):
        run_string("".join(f"#{n} = {n}\n" for n in range(4000, 4070)), RunOptions(ini=ini, save_vars=True))
    assert ini.read_bytes() == before


def test_kins_build_refuses_to_write_over_its_source(tmp_path: Path) -> None:
    source = tmp_path / "k.c"
    source.write_text("int x;\n")
    result = invoke("kins", "build", source, "-o", source)
    assert result.exit_code == 2 and "is also an input" in result.stderr
    assert source.read_text() == "int x;\n"
