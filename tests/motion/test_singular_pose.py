"""A move that starts at a singular pose (a SCARA's arm fully stretched) is timed at a crawl, never
at zero acceleration: the estimate was NaN and `ecnc plot --joints` ended in a traceback."""
from __future__ import annotations

import math
from pathlib import Path

import pytest

from edingcnc_lang import RunOptions, run_string
from tests.cli_runner import invoke

pytestmark = pytest.mark.slow  # the whole module (pyproject's slow marker)

INI = Path(__file__).resolve().parent.parent / "kinematics" / "scara" / "cnc.ini"
JOB = "KIN ON\nG1 X200 Y0 F1000\nG1 X150 Y50\nM30\n"  # KIN ON at joints 0, 0: the arm stretched to X350


def test_the_estimate_is_finite_and_slow_off_the_singular_pose() -> None:
    result = run_string(JOB, RunOptions(ini=INI))
    assert result.estimate is not None
    seconds = result.estimate.seconds
    assert math.isfinite(seconds) and seconds > 150 / (1000 / 60)  # slower than the feed: a crawl


def test_the_joint_plot_draws(tmp_path: Path) -> None:
    job = tmp_path / "sc.nc"
    job.write_text(JOB)
    result = invoke("plot", job, "--ini", INI, "--joints", "-o", tmp_path / "sc.png")
    assert result.exit_code == 0, result.output
    assert (tmp_path / "sc.png").stat().st_size > 0
