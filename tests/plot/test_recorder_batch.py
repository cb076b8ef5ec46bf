"""The plot recorder's batch form (``Recorder.write_batch``: a batch's columns at once) records what its moves
one at a time record (``Recorder.move``): the same toolpath, column for column, on the examples (a pocket with
arcs and tool changes, a lathe job with its work offsets, a rotated job)."""
from __future__ import annotations

from collections.abc import Sequence
from pathlib import Path

import numpy as np
import pytest

from edingcnc_lang import Batch, RunOptions
from edingcnc_lang.motion.sinks import Timing
from edingcnc_lang.plot import toolpath
from edingcnc_lang.plot.toolpath import Recorder, Toolpath, record_job

ROOT = Path(__file__).resolve().parents[2]
JOBS = [("examples/pocket.nc", None), ("examples/lathe/shaft.nc", "examples/lathe/cnc.ini"),
        ("examples/rotate/job.nc", "examples/rotate/cnc.ini"), ("zigzag", None)]
# bench_plot.py's kind of job: a zigzag with every tenth move an R arc, rapids, a tool change halfway, G91 runs
ZIGZAG = ("G21 G90 G17 F2000\nG0 X0 Y0 Z2\nG1 Z-1\n"
          + "".join(f"G1 X{k % 7 * 3} Y{k * 0.5:.1f}\n" if k % 10 else f"G2 X{k % 7 * 3} Y{k * 0.5:.1f} R40\n"
                    for k in range(1, 120))
          + "G0 Z5\nT2 M6\nG91\n" + "G1 X1 Y-0.5\n" * 40 + "G90 G0 Z5\nGoSub square\nM30\n"
          + "Sub square\n" + "".join(f"G1 X{x} Y{y}\n" for x, y in ((0, 0), (10, 0), (10, 10), (0, 10)) * 5)
          + "EndSub\n")


def _one_by_one(self: Recorder, batch: Batch, times: Sequence[float], speeds: Sequence[float]) -> None:
    for move, t0, t1, speed in zip(batch.moves(), times, times[1:], speeds):
        self.move(move, move.end, None, Timing(t0, t1, speed))


def _record(job: str, ini: str | None, folder: Path) -> Toolpath:
    if job == "zigzag":
        (folder / "zigzag.nc").write_text(ZIGZAG, encoding="ascii")
        return record_job(folder / "zigzag.nc")
    return record_job(ROOT / job, RunOptions(ini=ROOT / ini if ini else None))


@pytest.mark.parametrize(("job", "ini"), JOBS)
def test_the_batch_form_records_what_the_moves_one_by_one_record(job: str, ini: str | None, tmp_path: Path,
                                                                 monkeypatch: pytest.MonkeyPatch) -> None:
    fast = _record(job, ini, tmp_path)
    monkeypatch.setattr(toolpath.Recorder, "write_batch", _one_by_one)
    slow = _record(job, ini, tmp_path)
    assert len(fast) == len(slow) > 10 and fast.error is None
    for name in ("kinds", "tools", "lines", "callers", "files", "feeds", "times", "speeds", "starts", "ends",
                 "joints", "offsets"):
        a, b = getattr(fast, name), getattr(slow, name)
        assert (a is None and b is None) or (a.dtype == b.dtype and np.array_equal(a, b)), name
    assert fast.arcs == slow.arcs and fast.paths == slow.paths


def test_a_batch_reaches_the_recorder(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    """(The test above compares something: the pocket's plain lines come as batches.)"""
    sizes: list[int] = []
    original = Recorder.write_batch

    def counting(self: Recorder, batch: Batch, times: Sequence[float], speeds: Sequence[float]) -> None:
        sizes.append(len(batch))
        original(self, batch, times, speeds)
    monkeypatch.setattr(Recorder, "write_batch", counting)
    _record("zigzag", None, tmp_path)
    assert sizes and max(sizes) > 100
