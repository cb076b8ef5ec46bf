"""Bounded memory for pictures and samples (issue 28, item 4): a plot draws at most the viewer's
budget of moves (300,000 moves took 2.2 GB in matplotlib), a joint plot at most MAX_CURVE_POINTS
samples per joint; kins check --samples and kins plot --resolution have limits (1e9 and 1e6 asked
for tens of GB)."""
from __future__ import annotations

import json
from pathlib import Path

import numpy as np
import pytest

from edingcnc_lang.syntax.input_limits import MAX_CHECK_SAMPLES, MAX_ENVELOPE_RESOLUTION
from edingcnc_lang.plot.toolpath import record_job
from tests.cli_runner import invoke

pytest.importorskip("matplotlib")


def job(tmp_path: Path, moves: int) -> Path:
    path = tmp_path / "j.nc"
    lines = ["G0 X0 Y0"] + [f"G1 X{i % 97} Y{(i // 97) % 89} F1000" if i % 3 else f"G2 X{i % 97} Y{(i // 97) % 89} R-200"
                            for i in range(1, moves + 1)]
    path.write_text("\n".join(lines) + "\nM30\n")
    return path


def test_a_long_job_is_thinned_before_it_is_drawn(tmp_path: Path) -> None:
    from edingcnc_lang.plot.render import thinned

    path = record_job(job(tmp_path, 600))
    drawn = thinned(path, 100)
    assert len(drawn) <= 200 < len(path)
    assert np.array_equal(drawn.ends[-1], path.ends[-1])  # the shape still ends where the job does
    assert np.allclose(drawn.starts[1:], drawn.ends[:-1])  # one connected path, no gaps
    assert thinned(path, 1000) is path


def test_plot_of_a_long_job_still_writes_its_picture(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    from edingcnc_lang.plot import viewer

    monkeypatch.setattr(viewer, "MAX_MOVES", 50)
    out = tmp_path / "j.png"
    result = invoke("plot", job(tmp_path, 300), "-o", out)
    assert result.exit_code == 0 and out.stat().st_size > 0


def test_a_joint_plot_draws_a_bounded_number_of_samples(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    from edingcnc_lang.plot import joints

    drawn: list[int] = []
    monkeypatch.setattr(joints, "MAX_CURVE_POINTS", 100)
    from matplotlib.axes import Axes

    plot = Axes.plot
    monkeypatch.setattr(Axes, "plot", lambda self, x, *a, **k: (drawn.append(len(x)), plot(self, x, *a, **k))[1])
    out = tmp_path / "j.png"
    assert invoke("plot", job(tmp_path, 30), "--joints", "-o", out).exit_code == 0
    assert drawn and max(drawn) <= 100


@pytest.mark.parametrize(("args", "limit"), [(["check", "trivial", "--samples", "1000000000"], MAX_CHECK_SAMPLES),
                                             (["plot", "trivial", "-o", "x.png", "--resolution", "1000000"],
                                              MAX_ENVELOPE_RESOLUTION)])
def test_kins_workloads_have_a_limit(args: list[str], limit: int) -> None:
    result = invoke("kins", *args)
    assert result.exit_code == 2 and f"{limit}" in result.stderr


def test_running_out_of_memory_is_an_error_not_a_traceback(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    from edingcnc_lang import runner

    def exhausted(*_args: object, **_kwargs: object) -> None:
        raise MemoryError

    monkeypatch.setattr(runner.Run, "execute_file", exhausted)
    result = invoke("run", job(tmp_path, 3), "--json")
    assert result.exit_code == 70 and "out of memory" in result.stderr
    assert json.loads(result.stdout)["error"]["message"].startswith("out of memory")
