"""A run that skips the planner (``RunOptions(plan=False)``, ``ecnc run`` with no output that reads
time) does everything else exactly as a planned run: same moves and events in the same order, same
final state, same errors; only the estimate and the limits report are missing (None)."""
from __future__ import annotations

from dataclasses import asdict
from pathlib import Path
from typing import Any

import pytest

from edingcnc_lang import RunOptions, run_file
from edingcnc_lang.errors import EcncError

ROOT = Path(__file__).resolve().parents[2]
JOB = """G21 G90 G17 F600
G0 X1 Y1
M48 ; feed override on
M50 P50 ; at 50 %
G1 X10 Y2
G2 X20 Y2 I5 J0
G4 P0.5
T2 M6
G91 G1 X-3 Z-1
G90 G61
G1 X0 Y0
msg "done"
M30
"""


def _run(job: Path, plan: bool, ini: Path | None = None) -> tuple[list[Any], dict[str, Any]]:
    seen: list[Any] = []
    options = RunOptions(ini=ini, plan=plan, on_move=lambda move, joints: seen.append((move, joints)),
                         on_event=lambda event: seen.append(event))
    result = asdict(run_file(job, options))
    assert (result.pop("estimate") is None, result.pop("limits") is None) == (not plan, not plan)
    return seen, result


@pytest.mark.parametrize("example", [None, "rotate", "delta", "tanknife"])
def test_an_unplanned_run_does_the_same_as_a_planned_one(tmp_path: Path, example: str | None) -> None:
    if example is None:
        job, ini = tmp_path / "job.nc", None
        job.write_text(JOB)
    else:
        job, ini = ROOT / "examples" / example / "job.nc", ROOT / "examples" / example / "cnc.ini"
    planned, unplanned = _run(job, True, ini), _run(job, False, ini)
    assert planned[0] and planned == unplanned


def test_an_unplanned_run_fails_the_same_way(tmp_path: Path) -> None:
    job = tmp_path / "job.nc"
    job.write_text("G0 X1\nG1 X5 F100\nG0 X150\nM30\n")
    ini = tmp_path / "cnc.ini"
    ini.write_text("[JOINT_0]\r\npositiveLimit = 100\r\nnegativeLimit = -100\r\n")
    errors = []
    for plan in (True, False):
        with pytest.raises(EcncError) as info:
            run_file(job, RunOptions(ini=ini, plan=plan))
        errors.append((info.value.format(), info.value.result.moves))  # type: ignore[attr-defined]
    assert errors[0] == errors[1] and errors[0][0].startswith(f"{job}:3:")


def test_outputs_that_read_time_plan_even_when_told_not_to(tmp_path: Path) -> None:
    job = tmp_path / "job.nc"
    job.write_text(JOB)
    times: list[float] = []
    result = run_file(job, RunOptions(plan=False, on_timed_move=lambda move, joints, timing: times.append(timing.end)))
    assert result.estimate is not None and result.estimate.seconds == pytest.approx(times[-1])
    assert times == sorted(times) and times[-1] > 0.5  # the dwell alone takes 0.5 s
    assert result.limits
