"""``RunOptions.on_batch``: the moves made in bulk as their ``Batch`` (the array form of ``on_move``'s records),
``on_move`` for the moves made singly; a raise makes none of the batch (docs/api.md, "Control of a run")."""
from __future__ import annotations

from pathlib import Path

import pytest

from edingcnc_lang import Batch, CallbackError, EcncError, Move, Pose, Run, RunOptions, result_of, run_file

# plain lines (one batch), arcs among them, a canned cycle's holes, a home move, a tool change, a probe
JOB = ("G21 G90 G17 F600\nG0 X0 Y0 Z5\nG1 Z-1\n" + "".join(f"G1 X{k} Y{k % 3}\n" for k in range(1, 40))
       + "G2 X41 Y0 I1 J0\nG3 X43 Y0 R1\nG1 X44\nG28\nG0 Z5\nG81 X10 Y10 Z-2 R1\nX20\nX30 Y5\nG80\n"
       + "G38.2 Z-3 F100\nG1 X50 Y50 F900\nM30\n")


@pytest.fixture
def job(tmp_path: Path) -> Path:
    """The job as a file (a job's plain lines are read in bulk from a file)."""
    path = tmp_path / "job.nc"
    path.write_text(JOB, encoding="utf-8")
    return path


def test_the_batches_and_the_single_moves_are_the_moves_on_move_alone_hears(job: Path) -> None:
    alone: list[tuple[Move, Pose]] = []
    run_file(job, RunOptions(on_move=lambda move, joints: alone.append((move, joints))))
    heard: list[tuple[Move, Pose]] = []
    batches: list[Batch] = []

    def on_batch(batch: Batch) -> None:
        batches.append(batch)
        heard.extend((move, move.end) for move in batch.moves())

    result = run_file(job, RunOptions(on_move=lambda move, joints: heard.append((move, joints)), on_batch=on_batch))
    assert heard == alone and result.moves == len(alone)
    assert len(batches) >= 2 and any(batch.arcs is not None for batch in batches)
    assert max(len(batch) for batch in batches) >= 40  # the plain lines, one batch
    singles = len(alone) - sum(len(batch) for batch in batches)
    assert singles >= 2 and "probe" not in {move.kind for batch in batches for move in batch.moves()}


def test_a_batch_callback_that_raises_makes_none_of_the_batch(job: Path) -> None:
    singles: list[Move] = []

    def on_batch(batch: Batch) -> None:
        if len(batch) > 10:
            raise ZeroDivisionError("boom")

    with pytest.raises(CallbackError) as info:
        run_file(job, RunOptions(on_move=lambda move, joints: singles.append(move), on_batch=on_batch))
    err = info.value
    assert err.code == "R803" and "on_batch raised ZeroDivisionError: boom" in err.message
    assert isinstance(err.__cause__, ZeroDivisionError)
    result = result_of(err)
    assert result is not None
    assert err.location is not None and err.location.line == 2  # the batch's first move: G0 X0 Y0 Z5
    assert result.moves == 0 and result.position[:3] == (0.0, 0.0, 0.0)


def test_cancel_from_a_batch_callback_stops_before_the_next_move(job: Path) -> None:
    made: list[int] = []

    def on_batch(batch: Batch) -> None:
        made.append(len(batch))
        run.cancel()
    run = Run(RunOptions(on_batch=on_batch))
    with pytest.raises(EcncError) as info:
        run.execute_file(job)
    result = result_of(info.value)
    assert len(made) == 1 and result is not None and result.moves == made[0]


def test_on_batch_with_on_timed_move_is_refused() -> None:
    with pytest.raises(EcncError, match="on_batch hears the moves as the machine makes them"):
        Run(RunOptions(on_batch=lambda batch: None, on_timed_move=lambda move, joints, timing: None))


def test_the_move_stream_gives_every_move_with_a_batch_callback_too(job: Path) -> None:
    batched: list[int] = []
    singles: list[int] = []
    stream = Run(RunOptions(on_batch=lambda batch: batched.append(len(batch)),
                            on_move=lambda move, joints: singles.append(move.line))).moves(job, buffer=16)
    lines = [move.line for move in stream]
    alone = [move.line for move in Run(RunOptions()).moves(job, buffer=16)]
    assert lines == alone and sum(batched) + len(singles) == len(lines) and batched and singles
