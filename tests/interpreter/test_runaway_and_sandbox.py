"""Issue 17: the log-file sandbox (no symlink, hard link, FIFO or NUL escapes it), the default run
budget, and an M-code sub reaching itself again."""
from __future__ import annotations

import os
from pathlib import Path

import pytest

from edingcnc_lang.syntax import input_limits as limits
from edingcnc_lang.errors import MachineError
from edingcnc_lang.config.heightmap import HeightMap, ProbeAt
from edingcnc_lang.host import Host
from edingcnc_lang.runner import RunOptions, run_string
from tests.cli_runner import invoke


def error_of(source: str, **options: object) -> MachineError:
    with pytest.raises(MachineError) as caught:
        run_string(source, RunOptions(**options), path="job.nc")  # type: ignore[arg-type]
    return caught.value


@pytest.fixture()
def logs(tmp_path: Path) -> Path:
    folder = tmp_path / "logs"
    folder.mkdir()
    (tmp_path / "outside.txt").write_text("precious\n")
    return folder


def test_a_symlink_in_the_log_folder_is_refused_and_its_target_kept(logs: Path) -> None:
    (logs / "a.txt").symlink_to(logs.parent / "outside.txt")
    for source, line in (('logfile "a.txt" 0\n', 1), ('logfile "a.txt"\nlogmsg "x"\n', 2)):
        err = error_of(source, log_dir=logs)
        assert err.format().startswith(f"job.nc:{line}:1: error: cannot write the log file {logs / 'a.txt'}: "
                                       "it is a symbolic link")
    assert (logs.parent / "outside.txt").read_text() == "precious\n"


def test_a_hard_link_in_the_log_folder_is_refused_and_left_whole(logs: Path) -> None:
    os.link(logs.parent / "outside.txt", logs / "h.txt")
    assert "not a plain file of its own" in error_of('logfile "h.txt" 0\n', log_dir=logs).message
    assert (logs.parent / "outside.txt").read_text() == "precious\n"


def test_a_fifo_in_the_log_folder_is_an_error_not_a_hang(logs: Path) -> None:
    os.mkfifo(logs / "f.txt")
    assert error_of('logfile "f.txt"\nlogmsg "x"\n', log_dir=logs).location.line == 2  # type: ignore[union-attr]


def test_a_logmsg_in_a_runaway_loop_stops_at_the_log_limit(logs: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    from edingcnc_lang.machine import messages

    monkeypatch.setattr(messages, "MAX_LOG_BYTES", 1000)  # 64 MB in a real run
    err = error_of('#1 = 0\nWhile [1]\n  logmsg "pass "#1\n  #1 = [#1 + 1]\nEndWhile\n', log_dir=logs)
    assert err.location.line == 3 and "the most a run may write" in err.message  # type: ignore[union-attr]
    assert 950 < (logs / "log.txt").stat().st_size <= 1000


@pytest.mark.parametrize(("name", "message"), [
    ("a\0b.txt", "logfile 'a\\x00b.txt': a file name cannot hold control characters"),
    ("a" * 300 + ".txt", "File name too long"),
])
def test_bad_log_names_are_errors_at_the_jobs_line(logs: Path, name: str, message: str) -> None:
    err = error_of(f'G0 X1\nlogfile "{name}" 0\n', log_dir=logs)
    assert (err.location.line, message in err.message) == (2, True)  # type: ignore[union-attr]


def test_runs_have_a_default_budget(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    assert RunOptions().max_steps == limits.DEFAULT_MAX_STEPS == 100_000_000
    monkeypatch.setattr(limits, "DEFAULT_MAX_STEPS", 5000)  # what the CLI reads when --max-steps is absent
    for source in ("While [1]\nEndWhile\n", "G0 Z5\nG81 X0 Y0 Z-1 R1 F100 L1000000000\n"):
        job = tmp_path / "job.nc"
        job.write_text(source)
        result = invoke("run", job)
        assert result.exit_code == 70
        assert "step budget of 5,000 steps exhausted" in result.stderr
        assert "raise it with --max-steps N" in result.stderr


def test_an_m_code_without_a_built_in_reaching_its_own_sub_again_is_an_error() -> None:
    source = "M101\nM30\nSub m101\n  GoSub helper\nEndSub\nSub helper\n  M101\nEndSub\n"
    err = error_of(source)
    assert err.format().splitlines() == [
        "job.nc:7:3: error: M101 inside Sub m101, which is already running: M101 has no built-in action to "
        "run instead; write GoSub m101 if the recursion is meant",
        "  in Sub helper, called from job.nc:4", "  in Sub m101, called from job.nc:1"]


def test_an_m_code_with_a_built_in_runs_it_inside_its_own_sub() -> None:
    result = run_string("M3 S100\nM30\nSub m3\n  GoSub helper\nEndSub\nSub helper\n  M3\nEndSub\n")
    assert (result.error, result.ended_by) == (None, "M30")


def test_a_repeat_count_past_the_budget_fails_at_once() -> None:
    err = error_of("G0 Z5\nG81 X1 Y1 Z-1 R1 F100 L[10**300]\n")  # the default budget: no minutes of drilling
    assert err.location.line == 2 and "step budget of 100,000,000 steps exhausted" in err.message  # type: ignore[union-attr]


def test_a_move_of_more_samples_than_the_limit_is_an_error_not_gigabytes(tmp_path: Path) -> None:
    err = error_of("G0 X10\nG1 X100000 F1\n", samples=tmp_path / "s.csv")  # 1.2e9 samples at 200 Hz
    assert err.location.line == 2  # type: ignore[union-attr]
    assert f"a move may have at most {limits.MAX_MOVE_SAMPLES:,}" in err.message


ZHCS_JOB = "ZHCINIT 10 1 1\nG0 Z5\nG38.2 Z-5 F100\nZHCADDPOINT\nZHCS {name}\nM30\n"


def zhc_error(logs: Path, name: str, save: bool) -> MachineError:
    surface = HeightMap((0.0, 10.0), (0.0, 10.0), ((0.0, 0.0), (0.0, 0.0)))  # flat, for the probe to touch
    source = ZHCS_JOB.format(name=name) if save else f"ZHCL {name}\nM30\n"
    return error_of(source, log_dir=logs, host=Host(probe=ProbeAt(surface)))


@pytest.mark.parametrize("save", [True, False], ids=["ZHCS", "ZHCL"])
@pytest.mark.parametrize(("make", "reason"), [
    (lambda logs: (logs / "t.txt").symlink_to(logs.parent / "outside.txt"), "it is a symbolic link"),
    (lambda logs: os.link(logs.parent / "outside.txt", logs / "t.txt"), "it is not a plain file of its own"),
])
def test_zhcs_and_zhcl_refuse_links_like_logfile(logs: Path, make, reason: str, save: bool) -> None:  # type: ignore[no-untyped-def]
    make(logs)
    err = zhc_error(logs, "t.txt", save)
    verb = "write" if save else "read"
    assert err.format().startswith(f"job.nc:{5 if save else 1}:1: error: cannot {verb} the height table "
                                   f"{logs / 't.txt'}: {reason}")
    assert (logs.parent / "outside.txt").read_text() == "precious\n"


@pytest.mark.parametrize("save", [True, False], ids=["ZHCS", "ZHCL"])
def test_zhcs_and_zhcl_on_a_fifo_are_errors_not_hangs(logs: Path, save: bool) -> None:
    os.mkfifo(logs / "f.txt")
    assert zhc_error(logs, "f.txt", save).location.line == (5 if save else 1)  # type: ignore[union-attr]


@pytest.mark.parametrize("save", [True, False], ids=["ZHCS", "ZHCL"])
def test_zhc_file_names_with_control_characters_are_errors(logs: Path, save: bool) -> None:
    err = zhc_error(logs, "a\0b.txt", save)
    assert "a file name cannot hold control characters" in err.message
