"""``ecnc test``, ``ecnc sim``, ``ecnc diff`` and the small defects of the third hostile probe (issue
43, items 2 to 6): every number and name from a TOML file or an option goes through the input
limits (a clear error, never a traceback); ``test -j`` ends its workers at once on SIGTERM and
reports a worker that died as its file's failure; a piped diff input is read once."""
from __future__ import annotations

import json
import os
import signal
import subprocess
import sys
import time
from pathlib import Path

import pytest

from tests.cli_runner import invoke

JOB = "G0 X10 Y15\nG1 Z-1 F300\nG1 X30\nG0 Z5\nM30\n"
STOCK = "0,0,-10,40,30,0"
DIGITS_400 = "9" * 400


def _clean(result: object, code: int, message: str) -> None:
    output = result.output  # type: ignore[attr-defined]
    assert result.exit_code == code, output  # type: ignore[attr-defined]
    assert "Traceback" not in output and message in output, output


# --------------------------------------------------------------------------- ecnc test: the TOML file

@pytest.mark.parametrize("body, message", [
    (f'vars = {{ "{DIGITS_400}" = 1 }}', "is not a parameter number"),
    ('vars = { "\u00b2" = 1 }', "is not a parameter number"),
    ('vars = { "\u0665\u0660\u0660\u0668" = 1 }', "is not a parameter number"),  # Arabic-Indic 5008
    ('expect.vars = { "\uff15\uff10\uff10\uff18" = 1 }', "is not a parameter number"),  # full-width
    (f'vars = {{ "4000" = {DIGITS_400} }}', "is not a number"),
    (f'expect.position = {{ x = {{ approx = 1, tol = {DIGITS_400} }} }}', "is not a number"),
    (f'forbid.outside = [0, 0, 0, 1, 1, {DIGITS_400}]', "is not a number"),
    (f'probe = [{{ z = -{DIGITS_400} }}]', "is not a number"),
    (f"max_steps = {'9' * 30}", "max_steps must be a whole number"),
    ("x = " + "[" * 5000 + "]" * 5000, "nested more than"),
    ("x = " + "{ a = " * 3000 + "1" + " }" * 3000, "nested more than"),
])
def test_test_file_values_go_through_the_input_limits(tmp_path: Path, body: str, message: str) -> None:
    (tmp_path / "test_a.toml").write_text(f'[[test]]\nname = "t"\njob = "M30"\n{body}\n', encoding="utf-8")
    _clean(invoke("test", tmp_path / "test_a.toml"), 65, message)


def test_a_test_file_that_is_not_utf8_names_its_line(tmp_path: Path) -> None:
    (tmp_path / "test_a.toml").write_bytes(b'[[test]]\nname = "t\xff"\njob = "M30"\n')
    _clean(invoke("test", tmp_path / "test_a.toml"), 65, "test_a.toml:2: error: a TOML file must be UTF-8")


@pytest.mark.parametrize("expression, message", [
    ("(" * 100_000 + "a" + ")" * 100_000, "the nesting limit"),
    ("not " * 100_000 + "a", "the nesting limit"),
    (" or ".join(["zqzq"] * 50_000), "no test matches"),  # long but flat: fine
])
def test_deep_k_expressions_are_usage_errors(tmp_path: Path, expression: str, message: str) -> None:
    (tmp_path / "test_a.toml").write_text('[[test]]\nname = "t"\njob = "M30"\n')
    _clean(invoke("test", tmp_path / "test_a.toml", "-k", expression), 2, message)


def test_jobs_take_ascii_digits_and_a_bounded_count(tmp_path: Path) -> None:
    (tmp_path / "test_a.toml").write_text('[[test]]\nname = "t"\njob = "M30"\n')
    _clean(invoke("test", tmp_path / "test_a.toml", "-j", "\u0662"), 2, "is not a whole number")
    _clean(invoke("test", tmp_path / "test_a.toml", "-j", "1000000"), 2, "--jobs")


# --------------------------------------------------------------------------- ecnc test -j

def _ecnc(*args: object, cwd: Path) -> subprocess.Popen[str]:
    return subprocess.Popen([sys.executable, "-m", "edingcnc_lang", *map(str, args)], cwd=cwd, text=True,
                            stdout=subprocess.PIPE, stderr=subprocess.PIPE)


@pytest.mark.slow
@pytest.mark.skipif(not hasattr(signal, "SIGTERM") or os.name == "nt", reason="POSIX signals")
def test_sigterm_ends_test_j_at_once_with_143(tmp_path: Path) -> None:
    (tmp_path / "test_a.toml").write_text('[[test]]\nname = "quick"\njob = "M30"\n')
    (tmp_path / "test_b.toml").write_text(f'[[test]]\nname = "endless"\nmax_steps = {10**15}\n'
                                          'job = "While [1]\\nEndWhile"\n')
    process = _ecnc("test", "-j", "2", "test_a.toml", "test_b.toml", cwd=tmp_path)
    assert process.stdout is not None
    assert process.stdout.readline().startswith("PASS")  # the quick file is done: the workers run
    time.sleep(0.5)
    started = time.monotonic()
    process.send_signal(signal.SIGTERM)
    assert process.wait(timeout=20) == 143
    assert time.monotonic() - started < 10  # not when the endless test ends (never)
    assert "Traceback" not in process.stderr.read() if process.stderr else True


@pytest.mark.slow
def test_a_worker_that_dies_is_its_files_failure(tmp_path: Path) -> None:
    (tmp_path / "killer.py").write_text("import os, signal\nos.kill(os.getpid(), signal.SIGKILL)\n")
    (tmp_path / "kill.ini").write_bytes(b"[KINEMATICS]\r\nkinematicsDLLName = killer.py\r\n")
    (tmp_path / "test_a.toml").write_text('[[test]]\nname = "dies"\nini = "kill.ini"\njob = "G0 X1\\nM30"\n')
    for name in ("test_b.toml", "test_c.toml"):
        (tmp_path / name).write_text('[[test]]\nname = "fine"\njob = "#4000 = 2\\nM30"\n'
                                     'expect.vars = { "4000" = 2 }\n')
    process = _ecnc("test", "-j", "2", "test_a.toml", "test_b.toml", "test_c.toml", cwd=tmp_path)
    out, err = process.communicate(timeout=120)
    assert process.returncode == 1, err
    assert "Traceback" not in err and "BrokenProcessPool" not in out + err
    lines = out.splitlines()
    assert lines[0].startswith("FAIL test_a.toml:1: dies: the process running this test file ended abruptly")
    assert lines[1:] == ["PASS test_b.toml:1: fine", "PASS test_c.toml:1: fine", "2 passed, 1 failed"]


# --------------------------------------------------------------------------- ecnc sim: stock and tools

@pytest.fixture
def job(tmp_path: Path) -> Path:
    path = tmp_path / "job.nc"
    path.write_text(JOB)
    return path


@pytest.mark.parametrize("stock, message", [
    ("0,0,-5,1e308,1e308,0", "beyond 1e+09 mm"),
    ("-1e308,0,-5,1e308,10,0", "beyond 1e+09 mm"),
    ("0,0,-5,1e9,1e9,0", "too many"),
    ("0,0,-5,10,10,\u0660", "is not six numbers"),
])
def test_stock_extremes_are_usage_errors(job: Path, stock: str, message: str) -> None:
    _clean(invoke("sim", job, "--stock", stock), 2, message)


@pytest.mark.parametrize("text, message", [
    ('[tool."\u00b2"]\ndiameter = 3\n', "the tool number must be a whole number"),
    ('[tool."\u0661"]\ndiameter = 3\n', "the tool number must be a whole number"),
    (f'[tool."{DIGITS_400}"]\ndiameter = 3\n', "the tool number must be a whole number"),
    (f"[tool.1]\ndiameter = {DIGITS_400}\n", "diameter must be a positive number"),
    ("[tool.1]\ndiameter = 1e200\n", "diameter must be a positive number"),
    ("[tool.1]\ndiameter = 3\nflute_length = 1e-300\n", "flute_length must be a positive number"),
    ('[tool.1]\nshape = "vee"\ndiameter = 3\nangle = 1e-300\n', "angle must be from 1"),
    ('[tool.1]\nshape = "vee"\ndiameter = 3\nangle = 180\n', "angle must be from 1"),
    ("x = " + "[" * 5000 + "]" * 5000 + "\n", "nested more than"),
])
def test_tools_file_extremes_are_usage_errors(job: Path, tmp_path: Path, text: str, message: str) -> None:
    (tmp_path / "t.toml").write_text(text, encoding="utf-8")
    _clean(invoke("sim", job, "--stock", STOCK, "--tools", tmp_path / "t.toml"), 2, message)


def test_a_tools_file_that_is_not_utf8_is_a_usage_error(job: Path, tmp_path: Path) -> None:
    (tmp_path / "t.toml").write_bytes(b"[tool.1]\ndiameter = 3\n# \xff\xfe\n")
    _clean(invoke("sim", job, "--stock", STOCK, "--tools", tmp_path / "t.toml"), 2, "must be UTF-8")


def test_sim_options_take_ascii_digits_only(job: Path) -> None:
    _clean(invoke("sim", job, "--stock", STOCK, "--tool", "\u0661"), 2, "is not a tool number")
    _clean(invoke("sim", job, "--stock", STOCK, "--resolution", "\uff11"), 2, "is not a number")


@pytest.mark.parametrize("option", ["--stock-stl", "--compare-stl"])
def test_nan_triangles_are_refused_by_both_stl_options(job: Path, tmp_path: Path, option: str) -> None:
    np = pytest.importorskip("numpy")
    from edingcnc_lang.sim.stl import write_stl

    good = np.array([[[0, 0, -5], [40, 0, -5], [40, 30, 0]], [[0, 0, -5], [40, 30, 0], [0, 30, 0]]], dtype=float)
    bad = good.copy()
    bad[1, 1, 2] = np.nan
    write_stl(tmp_path / "good.stl", [good])
    write_stl(tmp_path / "bad.stl", [bad])
    stock = ["--stock", STOCK] if option == "--compare-stl" else []
    _clean(invoke("sim", job, *stock, option, tmp_path / "bad.stl"), 2, "not a number")


# --------------------------------------------------------------------------- ecnc diff: a pipe read once

@pytest.mark.skipif(os.name == "nt", reason="FIFOs")
def test_diff_reads_a_pipe_once(job: Path, tmp_path: Path) -> None:
    fifo = tmp_path / "pipe.nc"
    os.mkfifo(fifo)
    writer = subprocess.Popen(["sh", "-c", f'cat "{job}" > "{fifo}"'])
    try:
        result = invoke("diff", job, fifo, "--json")
    finally:
        writer.wait(timeout=30)
    assert result.exit_code == 0, result.output
    assert json.loads(result.stdout)["same"] is True


# --------------------------------------------------------------------------- small defects

def test_run_json_times_a_crawling_feed(tmp_path: Path) -> None:
    (tmp_path / "slow.nc").write_text("G1 X1 F0." + "0" * 170 + "1\nM30\n")
    result = invoke("run", "--json", tmp_path / "slow.nc")
    assert result.exit_code == 0, result.output
    assert json.loads(result.stdout)["estimate"]["seconds"] == pytest.approx(6e172)


def test_mdi_columns_of_an_expression_line_are_the_typed_ones() -> None:
    from edingcnc_lang.errors import EcncError
    from edingcnc_lang.mdi import MdiSession

    session = MdiSession()
    for text, column in (("1/0", 1), ("  SQRT[-1]", 3), ("#5001 + [1/0]", 10)):
        with pytest.raises(EcncError) as caught:
            session.execute(text)
        assert caught.value.location is not None and caught.value.location.col == column, text


def test_a_job_named_like_a_placeholder_keeps_its_name_in_the_page_title(tmp_path: Path) -> None:
    job = tmp_path / "{{data}}.nc"
    job.write_text(JOB)
    result = invoke("view", job, "-o", tmp_path / "v.html")
    assert result.exit_code == 0, result.output
    page = (tmp_path / "v.html").read_text(encoding="utf-8")
    assert "<title>{{data}}.nc \u2014 ecnc view</title>" in page
