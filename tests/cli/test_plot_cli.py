"""``ecnc plot`` and ``ecnc view`` as a user runs them: files written where expected, exit codes."""
from __future__ import annotations

import re
import shutil
import subprocess
import sys
from pathlib import Path

import pytest

from tests.cli_runner import invoke
from tests.plot.jobs import SQUARE, write

pytestmark = pytest.mark.slow  # the whole module (pyproject's slow marker)

pytest.importorskip("matplotlib")

ROOT = Path(__file__).resolve().parents[2]


def test_plot_writes_job_png_beside_the_job_and_prints_it(tmp_path: Path) -> None:
    job = write(tmp_path, "square.nc", SQUARE, newline="\r\n")
    result = invoke("plot", job)
    assert result.exit_code == 0, result.output
    assert result.stdout.strip() == str(tmp_path / "square.png")
    assert (tmp_path / "square.png").read_bytes().startswith(b"\x89PNG")


@pytest.mark.parametrize("name, magic", [("p.svg", b"<?xml"), ("p.pdf", b"%PDF")])
def test_plot_format_by_extension_and_options(tmp_path: Path, name: str, magic: bytes) -> None:
    job = write(tmp_path, "square.nc", SQUARE)
    result = invoke("plot", job, "-o", tmp_path / name, "--view", "iso", "--color", "kind")
    assert result.exit_code == 0, result.output
    assert (tmp_path / name).read_bytes().startswith(magic)


def test_plot_with_the_machine_of_an_ini_and_joints(tmp_path: Path) -> None:
    result = invoke("plot", ROOT / "examples/delta/job.nc", "--ini", ROOT / "examples/delta/cnc.ini",
                    "--joints", "-o", tmp_path / "delta.png")
    assert result.exit_code == 0, result.output
    assert "carriages at" in result.stderr  # the job's msg, as ecnc run shows it
    assert (tmp_path / "delta.png").stat().st_size > 10_000


def test_a_runtime_error_still_gives_the_picture_and_exit_70(tmp_path: Path) -> None:
    job = write(tmp_path, "bad.nc", "G0 X5\nG1 X10 F100\nG1 X[1/0]\n")
    result = invoke("plot", job)
    assert result.exit_code == 70
    assert (tmp_path / "bad.png").exists()
    assert f"{job}:3" in result.stderr and "Traceback" not in result.output


def test_a_syntax_error_writes_nothing_and_exits_65(tmp_path: Path) -> None:
    job = write(tmp_path, "broken.nc", "G0 X5\nG1 X[1\n")
    for command in ("plot", "view"):
        result = invoke(command, job)
        assert result.exit_code == 65, result.output
        assert f"{job}:2:" in result.stderr
    assert not list(tmp_path.glob("broken.*[gl]"))


def test_usage_errors_name_the_option(tmp_path: Path) -> None:
    job = write(tmp_path, "square.nc", SQUARE)
    result = invoke("plot", job, "-o", tmp_path / "p.jpg")
    assert result.exit_code == 2 and "p.jpg" in result.stderr and ".png" in result.stderr
    result = invoke("plot", job, "--view", "bottom")
    assert result.exit_code == 2 and "--view" in result.stderr
    result = invoke("view", job, "--lines", "9:3")
    assert result.exit_code == 2 and "--lines" in result.stderr
    assert invoke("plot", tmp_path / "missing.nc").exit_code == 2


def test_view_writes_one_html_file(tmp_path: Path) -> None:
    job = write(tmp_path, "square.nc", SQUARE)
    result = invoke("view", job, "--lines", "5:9", "--max-moves", "100")
    assert result.exit_code == 0, result.output
    page = tmp_path / "square.html"
    assert result.stdout.strip() == str(page)
    text = page.read_text(encoding="utf-8")
    assert text.startswith("<!DOCTYPE html>") and '"moves":5' in text


def test_view_lines_that_make_no_moves_is_an_error(tmp_path: Path) -> None:
    job = write(tmp_path, "square.nc", SQUARE)
    result = invoke("view", job, "--lines", "1:2")
    assert result.exit_code == 70 and f"{job}: error: lines 1 to 2 make no moves" in result.stderr


@pytest.mark.skipif(shutil.which("ecnc") is None, reason="the ecnc script is not installed")
def test_plot_as_a_real_process(tmp_path: Path) -> None:
    job = write(tmp_path, "square.nc", SQUARE)
    done = subprocess.run([sys.executable, "-m", "edingcnc_lang", "plot", str(job), "-o", str(tmp_path / "s.png")],
                          capture_output=True, text=True, timeout=120)
    assert done.returncode == 0, done.stderr
    assert (tmp_path / "s.png").exists()


@pytest.mark.parametrize("command, name", [("plot", "p.png"), ("view", "v.html")])
def test_a_missing_output_folder_is_told_before_the_job_runs(tmp_path: Path, command: str, name: str) -> None:
    job = write(tmp_path, "square.nc", 'msg "the job started"\n' + SQUARE)
    result = invoke(command, job, "-o", tmp_path / "missing" / name)
    assert result.exit_code == 70 and "folder" in result.stderr and "does not exist" in result.stderr
    assert "the job started" not in result.stderr


def test_the_override_knobs_of_ecnc_run_change_the_viewers_estimate(tmp_path: Path) -> None:
    job = write(tmp_path, "square.nc", SQUARE)
    seconds = []
    for args in ((), ("--feed-override", "50")):
        out = tmp_path / f"v{len(args)}.html"
        assert invoke("view", job, "-o", out, *args).exit_code == 0
        seconds.append(float(re.search(r'"seconds":([0-9.e+-]+)', out.read_text(encoding="utf-8")).group(1)))
    assert seconds[1] > 1.5 * seconds[0]  # the cut at half the feed takes about twice as long
    assert invoke("plot", job, "--rapid-override", "150").exit_code == 2  # at most 100, as for ecnc run


def test_plot_and_kins_plot_tell_a_wrong_picture_name_alike_before_any_work(tmp_path: Path) -> None:
    job = write(tmp_path, "square.nc", SQUARE)
    said = []
    for args in (("plot", job), ("plot", job, "--joints"), ("kins", "plot", "deltakins")):
        out = tmp_path / "p.jpg"
        result = invoke(*args, "-o", out)
        assert result.exit_code == 2 and not out.exists()
        said.append(result.stderr.strip())
    assert len(set(said)) == 1 and said[0].endswith(
        f"error: cannot write {tmp_path / 'p.jpg'}: the extension names the picture format, one of "
        ".png, .svg, .pdf (not .jpg)")


@pytest.mark.skipif(not hasattr(__import__("os"), "mkfifo"), reason="no FIFOs here")
@pytest.mark.parametrize("command, out", [("plot", "p.png"), ("view", "p.html")])
def test_a_piped_job_is_drawn_whole_and_needs_an_output_name(tmp_path: Path, command: str, out: str) -> None:
    """ecnc plot <(generate-job): drawn from one copy (reading the pipe twice drew an empty picture)."""
    import os
    import threading

    fifo = tmp_path / "gen.nc"
    os.mkfifo(fifo)
    refused = invoke(command, fifo)  # nothing is read: the pipe's writer is never started
    assert refused.exit_code == 2 and "is a pipe, not a file: name the file to write with -o FILE" in refused.stderr
    writer = threading.Thread(target=fifo.write_text, args=(SQUARE,))
    writer.start()
    result = invoke(command, fifo, "-o", tmp_path / out)
    writer.join()
    assert result.exit_code == 0, result.stderr
    text = (tmp_path / out).read_bytes()
    from_file = invoke(command, write(tmp_path, "square.nc", SQUARE), "-o", tmp_path / ("f" + out))
    assert from_file.exit_code == 0
    if command == "view":  # the program lines beside the picture come from the copy that ran
        assert b"G1 X60 F1000" in text and b"G1 X60 F1000" in (tmp_path / ("f" + out)).read_bytes()
    assert len(text) > 1000
