"""The pipeline's plumbing: plain stages pass everything through; a look-ahead stage holds one move,
queues events behind it and flushes on stops, kinematics, the end of the run and errors."""
from __future__ import annotations

from collections.abc import Iterable
from dataclasses import replace
from pathlib import Path

import pytest
from stage_helpers import Recorder, batch, line, pose

from edingcnc_lang import runner
from edingcnc_lang.canon import Event, Move
from edingcnc_lang.events import CoolantEvent, EndEvent, MsgEvent, PauseEvent, SpindleEvent
from edingcnc_lang.config.machine_config import MachineConfig
from edingcnc_lang.errors import MachineError
from edingcnc_lang.runner import RunOptions, run_string
from edingcnc_lang.pipeline import LookaheadStage, Pipeline, Stage

CONFIG = MachineConfig.default()
EMPTY_MACRO = Path(__file__).parent.parent / "interpreter" / "data" / "empty_macro.cnc"


class Successor(LookaheadStage):
    """Tags each move's path with the line of the move that followed it ('-' when flushed alone)."""

    def release(self, held: Move, following: Move | None) -> Iterable[Move]:
        return (replace(held, path=f"then {following.line if following else '-'}"),)


class Idle(Successor):
    @property
    def active(self) -> bool:
        return False


def test_a_plain_stage_passes_everything_through() -> None:
    sink = Recorder()
    stage = Stage(sink, CONFIG)
    stage.move(line(0, 0, 1, 0))
    stage.move_batch(batch(pose(1), ("linear", 2, pose(2), 100.0)))
    stage.event(CoolantEvent("job.nc", 3, 8))
    assert stage.kinematics("ON", (), pose(5), "job.nc", 4) == pose(5)
    stage.flush()
    assert [entry[0] for entry in sink.log] == ["move", "batch", "event", "kinematics"]


def test_lookahead_releases_each_move_when_the_next_arrives() -> None:
    sink = Recorder()
    stage = Successor(sink, CONFIG)
    stage.move(line(0, 0, 1, 0, 1))
    assert sink.log == []
    stage.move(line(1, 0, 1, 1, 2))
    stage.move(line(1, 1, 0, 1, 3))
    stage.flush()
    stage.flush()  # nothing left: a second flush emits nothing
    assert [(m.line, m.path) for m in sink.moves()] == [(1, "then 2"), (2, "then 3"), (3, "then -")]


def test_events_queue_behind_the_held_move_in_program_order() -> None:
    sink = Recorder()
    stage = Successor(sink, CONFIG)
    stage.event(SpindleEvent("job.nc", 1, 3, 1000.0, 1000.0))  # nothing held: straight through
    stage.move(line(0, 0, 1, 0, 2))
    stage.event(CoolantEvent("job.nc", 3, 8))
    stage.event(MsgEvent("job.nc", 4, "hello"))
    assert sink.log == [("event", "spindle")]
    stage.move(line(1, 0, 2, 0, 5))
    assert [e[1] if e[0] == "event" else e[1].line for e in sink.log] == ["spindle", 2, "coolant", "msg"]


@pytest.mark.parametrize("stop", [EndEvent("job.nc", 2, 30), PauseEvent("job.nc", 2, 0)])
def test_program_stops_flush(stop: Event) -> None:
    sink = Recorder()
    stage = Successor(sink, CONFIG)
    stage.move(line(0, 0, 1, 0, 1))
    stage.event(stop)
    assert [e[0] for e in sink.log] == ["move", "event"]
    assert sink.moves()[0].path == "then -"


def test_kinematics_flushes_first() -> None:
    sink = Recorder()
    stage = Successor(sink, CONFIG)
    stage.move(line(0, 0, 1, 0, 1))
    stage.kinematics("OFF", (), pose(1), "job.nc", 2)
    assert [e[0] for e in sink.log] == ["move", "kinematics"]


def test_bulk_moves_pass_an_idle_stage_whole_and_split_through_an_active_one() -> None:
    moves = batch(pose(), ("linear", 2, pose(1), 100.0), ("rapid", 3, pose(1, 1), 0.0))
    idle_sink, active_sink = Recorder(), Recorder()
    Idle(idle_sink, CONFIG).move_batch(moves)
    assert idle_sink.log == [("batch", moves)]
    active = Successor(active_sink, CONFIG)
    active.move_batch(moves)
    active.flush()
    moves = active_sink.moves()
    assert [(m.kind, m.start, m.end, m.feed, m.path) for m in moves] == [
        ("linear", pose(), pose(1), 100.0, "then 3"), ("rapid", pose(1), pose(1, 1), 0.0, "then -")]


def test_the_pipeline_chains_first_to_last_and_flushes_first_stage_first() -> None:
    sink = Recorder()
    pipeline = Pipeline([Successor, Successor], sink, CONFIG)
    first, second = pipeline.stages
    assert pipeline.head is first and first.next is second and second.next is sink
    pipeline.head.move(line(0, 0, 1, 0, 1))
    pipeline.head.move(line(1, 0, 2, 0, 2))
    pipeline.flush()
    assert [m.path for m in sink.moves()] == ["then 2", "then -"]  # the second stage saw "then 2" as a path


def test_no_stages_means_the_interpreter_talks_to_the_sink() -> None:
    sink = Recorder()
    assert Pipeline([], sink, CONFIG).head is sink


def _run(monkeypatch: pytest.MonkeyPatch, text: str) -> list[tuple[str, int]]:
    monkeypatch.setattr(runner, "STAGES", (Successor,))
    stream: list[tuple[str, int]] = []
    options = RunOptions(macro=EMPTY_MACRO, on_move=lambda move, joints: stream.append((move.path, move.line)),
                         on_event=lambda event: stream.append((event.kind, event.line)))
    try:
        run_string(text, options, path="job.nc")
    except MachineError:
        stream.append(("error", 0))
    return stream


def test_a_run_flushes_at_the_end_of_the_file(monkeypatch: pytest.MonkeyPatch) -> None:
    assert _run(monkeypatch, "G1 X1 F100\nM8\nG1 X2\n") == [("then 3", 1), ("coolant", 2), ("then -", 3)]


def test_a_failed_run_emits_the_held_move_before_the_error(monkeypatch: pytest.MonkeyPatch) -> None:
    stream = _run(monkeypatch, "G1 X1 F100\nG1 X2\nG2 X3\n")  # the arc has no centre
    assert stream == [("then 2", 1), ("then -", 2), ("error", 0)]


def test_m30_flushes_before_the_end_event(monkeypatch: pytest.MonkeyPatch) -> None:
    # M30 switches the overrides on (M48, manual 3.7.1) before it ends
    assert _run(monkeypatch, "G1 X1 F100\nM30\n") == [("then -", 1), ("override", 2), ("end", 2)]
