"""The recorder takes a batch of moves at once from its columns (``Recorder.write_batch``): its rows and
events must be the very numbers it records when it hears the same run move by move (``on_timed_move``),
for straight moves, arcs in a batch, a tool change, the spindle, moves made in a sub and jobs whose
moves were made in another file."""
from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from edingcnc_lang.canon import Batch
from edingcnc_lang.diff.record import Recorder, Recording, record
from edingcnc_lang.runner import Run, RunOptions

COLUMNS = ("kinds", "tools", "lines", "feeds", "spindles", "times", "starts", "ends", "frames")


def _zigzag(count: int) -> list[str]:
    lines = []
    for k in range(count):
        x = 40.0 if k % 2 else 0.0
        lines.append(f"G1 X{x:.3f} Y{k * 0.5:.3f}" if k % 7 != 3 else f"G{2 + k % 2} X{x:.3f} Y{k * 0.5:.3f} R25")
    return lines


JOBS = {
    "straight and arcs": ["G21 G90 G17 F1200", "T1 M6", "S8000 M3", "G0 Z2", "G1 Z-1 F300", *_zigzag(400),
                          "G0 Z10", "M5", "M30"],
    "a sub's moves": ["G21 G90 F900", "M3 S5000", "GoSub pass", "G0 X0 Y0", "GoSub pass", "M30",
                      "Sub pass", *_zigzag(60), "G0 Z5", "EndSub"],
    "two tools, coolant, a dwell": ["G21 G90 F1500", "T1 M6", "M3 S6000", "M8", *_zigzag(120), "G4 P0.5",
                                    "T2 M6", "M4 S3000", *_zigzag(90), "M9", "M5", "M30"],
}


class _Counting(Recorder):
    """A recorder that counts the batches it was handed whole."""

    batches = 0

    def write_batch(self, batch: Batch, times, speeds) -> None:  # type: ignore[no-untyped-def]
        self.batches += 1
        super().write_batch(batch, times, speeds)


def _move_by_move(job: Path) -> Recording:
    recorder = Recorder(str(job))
    run = Run(RunOptions(on_timed_move=lambda move, joints, timing: recorder.move(move, joints, None, timing),
                         on_event=recorder.event, plan=True))
    return recorder.recording(str(job), run.execute_file(job))


@pytest.mark.parametrize("name", sorted(JOBS))
def test_a_batch_records_the_rows_of_its_moves(tmp_path: Path, name: str) -> None:
    job = tmp_path / "job.nc"
    job.write_text("\n".join(JOBS[name]) + "\n", encoding="utf-8")
    counting = _Counting(str(job))
    Run(RunOptions(sinks=(counting,), plan=True)).execute_file(job)
    assert counting.batches > 0  # the batch form was used, not only single moves
    batched, single = record(job, RunOptions()), _move_by_move(job)
    assert len(batched) == len(single) > 100
    for column in COLUMNS:
        a, b = getattr(batched, column), getattr(single, column)
        assert a.dtype == b.dtype and np.array_equal(a, b) and a.tobytes() == b.tobytes(), column
    assert batched.events == single.events
    assert np.any(batched.frames[:, 0] >= 0) == any("R25" in line for line in JOBS[name])
