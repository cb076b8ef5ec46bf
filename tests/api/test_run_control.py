"""Controlling a run from the embedding program: cancel, callbacks that raise, the move stream,
and the state it can read (docs/api.md, "Control of a run")."""
from __future__ import annotations

import threading
from pathlib import Path

import pytest

from edingcnc_lang import (
    CallbackError,
    Cancelled,
    Host,
    Move,
    Pose,
    Run,
    RunOptions,
    result_of,
    run_file,
    run_string,
)

JOB = "G21 G90 F1000\n" + "".join(f"G1 X{i % 50} Y{i % 7}\n" for i in range(1, 3001)) + "M30\n"


@pytest.fixture
def job(tmp_path: Path) -> Path:
    path = tmp_path / "job.nc"
    path.write_text(JOB, encoding="utf-8")
    return path


@pytest.mark.parametrize("plan", [True, False])
def test_a_callback_that_raises_stops_the_run_where_it_raised_with_the_partial_result(job: Path, plan: bool) -> None:
    seen: list[Move] = []

    def on_move(move: Move, joints: Pose) -> None:
        if len(seen) == 1000:
            raise ZeroDivisionError("boom")
        seen.append(move)

    with pytest.raises(CallbackError) as info:
        run_file(job, RunOptions(on_move=on_move, plan=plan))
    err = info.value
    assert isinstance(err.__cause__, ZeroDivisionError)
    assert err.code == "R803" and "on_move raised ZeroDivisionError: boom" in err.message
    result = result_of(err)
    assert result is not None
    # the run is a batch ahead of nothing: it counts exactly the moves whose callback returned
    assert result.moves == len(seen) == 1000
    assert err.location is not None and err.location.line == 1002  # the 1001st move's line
    assert result.position[:2] == seen[-1].end[:2]


def test_cancel_from_a_callback_ends_with_cancelled_and_what_the_callbacks_saw(job: Path) -> None:
    seen: list[Move] = []

    def on_move(move: Move, joints: Pose) -> None:
        seen.append(move)
        if len(seen) == 500:
            run.cancel()

    run = Run(RunOptions(on_move=on_move))
    with pytest.raises(Cancelled) as info:
        run.execute_file(job)
    assert info.value.code == "R802" and info.value.exit_code == 130
    result = result_of(info.value)
    assert result is not None and result.moves == len(seen) == 500


def test_cancel_from_another_thread_stops_a_run_without_callbacks() -> None:
    started = threading.Event()
    run = Run(RunOptions(max_steps=None, plan=False, host=Host(message=lambda *args: started.set())))
    # an endless loop with no moves: only the statement check can stop it
    job = 'msg "go"\nWhile [1]\n#1 = [#1 + 1]\nEndWhile\n'
    def press_stop() -> None:
        started.wait(60)
        run.cancel()

    timer = threading.Thread(target=press_stop)
    timer.start()
    with pytest.raises(Cancelled) as info:
        run.execute_text(job)
    timer.join()
    assert result_of(info.value) is not None


def test_an_event_callback_and_a_host_callback_that_raise_are_callback_errors() -> None:
    def on_event(event: object) -> None:
        raise KeyError("x")

    with pytest.raises(CallbackError) as info:
        run_string("G0 X1\nM3 S1000\nG0 X2\nM30\n", RunOptions(on_event=on_event))
    assert info.value.location is not None and info.value.location.line == 2
    assert result_of(info.value) is not None

    def probe(start: Pose, target: Pose) -> Pose | None:
        return 1 / 0  # type: ignore[return-value]

    with pytest.raises(CallbackError) as probed:
        run_string("G38.2 Z-10 F100\nM30\n", RunOptions(host=Host(probe=probe)))
    assert "the host's probe callback raised ZeroDivisionError" in probed.value.message
    assert isinstance(probed.value.__cause__, ZeroDivisionError)
    assert probed.value.location is not None and probed.value.location.line == 1


def test_the_move_stream_gives_every_move_in_order_and_the_result(job: Path) -> None:
    stream = Run(RunOptions()).moves(job, buffer=16)
    lines = [move.line for move in stream]
    assert lines == list(range(2, 3002))
    assert stream.result is not None and stream.result.moves == 3000


def test_leaving_the_stream_early_cancels_the_run(job: Path) -> None:
    with Run(RunOptions()).moves(job, buffer=8) as stream:
        for count, _move in enumerate(stream, 1):
            if count == 100:
                break
    assert stream.result is not None
    assert 100 <= stream.result.moves <= 100 + 8 + 1  # what was made: at most the buffer ahead


def test_an_error_in_the_stream_is_raised_after_the_moves_before_it() -> None:
    path_text = "G1 X1 F100\nG1 X2\n#1 = [1 / 0]\nM30\n"
    run = Run(RunOptions())
    import tempfile

    with tempfile.TemporaryDirectory() as folder:
        job = Path(folder) / "j.nc"
        job.write_text(path_text, encoding="utf-8")
        got: list[int] = []
        with pytest.raises(Exception) as info:
            for move in run.moves(job):
                got.append(move.line)
    assert got == [1, 2]
    assert getattr(info.value, "code", None) == "R813"


def test_parameters_holds_every_parameter_written_or_not_read_only() -> None:
    result = run_string("#100 = 5\nM30\n", RunOptions(variables={4050: 7}))
    assert result.parameters[4050] == 7 and result.parameters[100] == 5
    assert 4050 not in result.variables  # written by the run: only #100
    assert result.parameters[5001] == result.position[0]
    assert len(result.parameters) == 5999 and 6000 not in result.parameters
    with pytest.raises(TypeError):
        result.parameters[1] = 2  # type: ignore[index]


def test_run_options_take_file_names_as_strings(tmp_path: Path) -> None:
    ini = tmp_path / "cnc.ini"
    ini.write_text("[TOOLS]\n", encoding="utf-8")
    options = RunOptions(ini=str(ini), trace=str(tmp_path / "t.csv"))
    assert options.ini == ini and isinstance(options.trace, Path)
    run_string("G0 X1\nM30\n", options)
    assert (tmp_path / "t.csv").exists()


def test_a_callback_reads_the_machine_through_the_runs_read_only_view() -> None:
    seen: list[tuple[int, float, float]] = []

    def on_move(move: Move, joints: Pose) -> None:
        seen.append((run.view.line, run.view.variable(100), run.view.variable(5001)))

    run = Run(RunOptions(on_move=on_move))
    run.execute_text("#100 = 3\nG0 X4\n#100 = 5\nG0 X7\nM30\n")
    # inside on_move the machine is still where the move starts (its end is move.end)
    assert seen == [(2, 3.0, 0.0), (4, 5.0, 4.0)]
    assert not hasattr(run.view, "params")  # a view, not the machine
