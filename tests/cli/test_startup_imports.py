"""Start-up cost: what a short run and ``ecnc --help`` import.

numpy (~100 ms) and lark (~50 ms) dominate the start of a three-line job.  The motion planner
times moves with numpy, so it runs only when an output reads time (``--json``, the trace, samples,
events, the summary line on a terminal, ``on_timed_move``; the API plans by default): a plain
``ecnc run`` of a job that moves loads no numpy, nor does a job that only computes (a macro test,
a variables job), and ``ecnc --help`` loads neither.  Each check runs in a fresh interpreter,
because this test process has imported everything already.
"""
from __future__ import annotations

import json
import math
import os
import subprocess
import sys
from pathlib import Path

import pytest

pytestmark = pytest.mark.slow  # the whole module (pyproject's slow marker)

ROOT = Path(__file__).resolve().parents[2]

RUN_TRIVIAL_JOB = """
import sys
from pathlib import Path
from edingcnc_lang import RunOptions, run_file
result = run_file(sys.argv[1], RunOptions(trace=Path(sys.argv[2])))
print(result.machine, result.moves, 'numpy' in sys.modules)
"""


def _python(*args: str) -> subprocess.CompletedProcess[str]:
    return subprocess.run([sys.executable, *args], capture_output=True, text=True, check=True, cwd=ROOT)


def _imported_modules(importtime_log: str) -> set[str]:
    """Module names from ``-X importtime`` lines (``import time: self | cumulative | name``)."""
    return {line.rsplit("|", 1)[1].strip() for line in importtime_log.splitlines()
            if line.startswith("import time:") and "|" in line}


def test_a_job_that_does_not_move_does_not_import_numpy(tmp_path: Path) -> None:
    job = tmp_path / "compute.nc"
    job.write_text("#1 = 2\nIf [#1 > 1]\n  #2 = [#1 * 3]\nEndIf\nM30\n")
    out = _python("-c", RUN_TRIVIAL_JOB, str(job), str(tmp_path / "trace.csv")).stdout.split()
    assert out == ["(0.0,", "0.0,", "0.0,", "0.0,", "0.0,", "0.0)", "0", "False"]
    assert len((tmp_path / "trace.csv").read_text().splitlines()) == 1  # the header only


MOVING_JOB = "G0 X1\nG1 X5 F100\nG2 X7 Y0 I1 J0\nG0 Z2\nM30\n"

RUN_UNPLANNED = """
import sys
from edingcnc_lang import RunOptions, run_file
moves = []
result = run_file(sys.argv[1], RunOptions(plan=False, on_move=lambda move, joints: moves.append(move.line)))
print(moves, result.estimate, result.limits, 'numpy' in sys.modules)
"""


def test_a_plain_run_of_a_job_that_moves_does_not_import_numpy(tmp_path: Path) -> None:
    job = tmp_path / "moves.nc"
    job.write_text(MOVING_JOB)
    result = _python("-X", "importtime", "-m", "edingcnc_lang", "run", str(job))
    modules = _imported_modules(result.stderr)
    assert "edingcnc_lang.motion.stage" in modules  # the job really ran
    assert not {"numpy", "edingcnc_lang.motion.planner.profile", "edingcnc_lang.motion.planner.segments"} & modules


@pytest.mark.parametrize("core", ["compiled", "python"])
def test_a_plain_run_of_a_compensated_contour_does_not_import_numpy(tmp_path: Path, core: str) -> None:
    # compensation's runs of corners need no numpy on either core, however long the contour (10,000 segments:
    # more than compensation once took one at a time before it loaded numpy for them)
    job = tmp_path / "contour.nc"
    job.write_text("G0 X60 Y0\nG41.1 D2\nG1 X40 Y0 F500\n"
                   + "".join(f"X{40 * math.cos(k / 50):.3f} Y{40 * math.sin(k / 50):.3f}\n" for k in range(1, 10_000))
                   + "G40\nG1 X0 Y0\nM30\n")
    code = ("import sys; from edingcnc_lang.cli import run_command_line\n"
            "code = run_command_line(['run', sys.argv[1]])\n"
            "print(code, 'numpy' in sys.modules)")
    env = {**os.environ, "ECNC_PURE_PYTHON": "1" if core == "python" else ""}
    done = subprocess.run([sys.executable, "-c", code, str(job)], capture_output=True, text=True, cwd=ROOT, env=env)
    loaded = done.stdout.splitlines()[-1]
    assert loaded == "0 False"  # the job ran, and numpy was not loaded


def test_an_unplanned_api_run_reports_moves_but_no_estimate(tmp_path: Path) -> None:
    job = tmp_path / "moves.nc"
    job.write_text(MOVING_JOB)
    assert _python("-c", RUN_UNPLANNED, str(job)).stdout.split() == ["[1,", "2,", "3,", "4]", "None", "None", "False"]


def _planned_seconds(output: str, stdout: str) -> float:
    """The job's planned duration as each output tells it."""
    if output == "--json":
        return float(json.loads(stdout)["estimate"]["seconds"])
    if output == "--trace":
        return float(stdout.splitlines()[-1].rsplit(",", 1)[1])  # the t column of the last move
    return max(json.loads(line).get("t", 0.0) for line in stdout.splitlines())


@pytest.mark.parametrize("output", ["--json", "--trace", "--events"])
def test_outputs_that_read_time_still_plan(tmp_path: Path, output: str) -> None:
    job = tmp_path / "moves.nc"
    job.write_text(MOVING_JOB)
    args = [output] if output == "--json" else [output, "-"]
    result = _python("-X", "importtime", "-m", "edingcnc_lang", "run", str(job), *args)
    assert "numpy" in _imported_modules(result.stderr)
    assert _planned_seconds(output, result.stdout) > 2.4  # 4 mm at 100 mm/min alone take 2.4 s


def test_samples_still_load_numpy(tmp_path: Path) -> None:
    job = tmp_path / "one.nc"
    job.write_text("G1 X1 F600\n")
    samples = tmp_path / "samples.csv"
    _python("-m", "edingcnc_lang", "run", str(job), "--samples", str(samples))
    rows = samples.read_text().splitlines()
    assert rows[0].startswith("t,x,y,z") and rows[-1].split(",")[1] == "1.0"  # the move ends at rest, sampled


@pytest.mark.parametrize("args", [["--help"], ["run", "--help"], ["kins", "--help"]])
def test_help_imports_neither_numpy_nor_lark(args: list[str]) -> None:
    result = _python("-X", "importtime", "-m", "edingcnc_lang", *args)
    assert result.stdout.startswith("usage: ecnc")
    modules = _imported_modules(result.stderr)
    assert "click" in modules  # the log is really there
    assert not {"numpy", "lark"} & modules


def test_lazy_package_names_resolve() -> None:
    import edingcnc_lang
    import edingcnc_lang.kinematics

    for package in (edingcnc_lang, edingcnc_lang.kinematics):
        for name in package.__all__:
            assert getattr(package, name) is not None, name
        with pytest.raises(AttributeError):
            package.no_such_name  # noqa: B018 - the lookup itself is the test
    assert edingcnc_lang.run_file.__module__ == "edingcnc_lang.runner"


def test_lint_format_names_match_the_formats() -> None:
    from edingcnc_lang.cli.lint_cmd import FORMAT_NAMES
    from edingcnc_lang.lint.formats import FORMATS

    assert sorted(FORMAT_NAMES) == sorted(FORMATS)


def test_a_lint_on_one_process_loads_only_what_it_uses(tmp_path: Path) -> None:
    """``ecnc lint`` of a macro file: no process pool, numpy, planner, ini or TOML reader, json;
    those load when asked for (``-j``, a run, ``--ini``, an ``ecnc.toml``, ``--format json``)."""
    job = tmp_path / "macro.cnc"
    job.write_text(";@unit mm\nSub user_1\n    #1 = [#2 + 1]\n    G1 X[#1] F100\nEndSub\n")
    result = subprocess.run([sys.executable, "-X", "importtime", "-m", "edingcnc_lang", "lint", str(job)],
                            capture_output=True, text=True, cwd=tmp_path)
    assert result.returncode == 0, result.stdout
    modules = _imported_modules(result.stderr)
    assert "edingcnc_lang.lint.rules_gm" in modules  # the rules really ran
    assert not {"numpy", "lark", "multiprocessing", "concurrent.futures", "tomllib", "json",
                "edingcnc_lang.config.machine_config", "edingcnc_lang.config.ini",
                "edingcnc_lang.kinematics", "edingcnc_lang.motion.planner"} & modules
