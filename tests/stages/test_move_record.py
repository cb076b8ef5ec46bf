"""One move record: every stage keeps every field of a move it does not own, alone or in a batch.

A stage changes what it owns (the pose stages the start, end and arc; cutter compensation also
the kind and feed of the corners it adds; height compensation the start and end) and hands the
rest on as it came: the spindle speed, constant surface speed, synchronisation, caller, file and
line.  The runs at the end are the two defects that dropped those fields.
"""
from __future__ import annotations

from dataclasses import fields
from pathlib import Path

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from stage_helpers import Recorder, pose

from edingcnc_lang import RunOptions, run_file, run_string
from edingcnc_lang.canon import Batch, Event, Move
from edingcnc_lang.config.machine_config import MachineConfig
from edingcnc_lang.errors import MachineError
from edingcnc_lang.config.heightmap import HeightMap
from edingcnc_lang.canon import Css
from edingcnc_lang.pipeline import STAGES
from edingcnc_lang.pipeline.base import Stage
from edingcnc_lang.pipeline.cutter_comp import CutterCompensation
from edingcnc_lang.pipeline.height_comp import HeightCompensation
from edingcnc_lang.pipeline.rotation import Rotation
from edingcnc_lang.pipeline.scaling import Scaling

CONFIG = MachineConfig.default()
SURFACE = HeightMap((0.0, 10.0, 20.0), (0.0, 10.0), ((0.0, 1.0, 2.0), (0.5, 1.5, 2.5)))
# What each stage owns (may change); every other field of Move must arrive as it was programmed.
OWNS = {Rotation: {"start", "end", "arc"}, Scaling: {"start", "end", "arc"},
        CutterCompensation: {"start", "end", "arc", "kind", "feed"}, HeightCompensation: {"start", "end"}}
SWITCH_ON = {
    Rotation: Event("rotation", "job.nc", 1, {"on": True, "pivot": (1.0, 2.0), "angle": 30.0}),
    Scaling: Event("scaling", "job.nc", 1, {"on": True, "factors": (2.0, 2.0, 1.0), "center": (0.0, 0.0)}),
    CutterCompensation: Event("cutter_comp", "job.nc", 1, {"side": "left", "radius": 0.5, "plane": "XY"}),
    HeightCompensation: Event("zhc", "job.nc", 1, {"on": True, "map": SURFACE}),
}
KEPT = [f.name for f in fields(Move)]


def test_every_stage_of_the_pipeline_is_covered() -> None:
    assert set(STAGES) == set(OWNS)


coordinate = st.integers(-20, 20).map(float)
spindles = st.tuples(st.sampled_from([0.0, 600.0, 12000.0]),
                     st.sampled_from([None, Css(20000.0, 3000.0, 0.0, 0.0)]),
                     st.sampled_from([0.0, 1.5]), st.sampled_from([0, 7]))
moves = st.lists(st.tuples(st.sampled_from(["linear", "linear", "rapid"]), coordinate, coordinate, coordinate,
                           st.sampled_from([100.0, 2500.0])), min_size=1, max_size=8)


def _programmed(items: list[tuple[str, float, float, float, float]], spindle: tuple) -> list[Move]:  # type: ignore[type-arg]
    rpm, css, sync, caller = spindle
    start, made = pose(), []
    for number, (kind, x, y, z, feed) in enumerate(items, 2):
        end = pose(x, y, z)
        made.append(Move(kind, "job.nc", number, start, end, feed if kind == "linear" else 0.0, None,
                         css.rpm(x) if css is not None else rpm, css, sync, caller))
        start = end
    return made


def _through(factory: type[Stage], send: object) -> list[Move]:
    sink = Recorder()
    stage = factory(sink, CONFIG)  # type: ignore[arg-type]
    stage.event(SWITCH_ON[factory])  # type: ignore[index]
    try:
        send(stage)  # type: ignore[operator]
        stage.flush()
    except MachineError:  # a corner compensation refuses (gouging): what came out before still counts
        pass
    return sink.moves()


def _assert_kept(factory: type[Stage], programmed: list[Move], out: list[Move]) -> None:
    by_line = {move.line: move for move in programmed}
    assert out or factory is CutterCompensation
    for move in out:
        source = by_line[move.line]
        for name in KEPT:
            if name not in OWNS[factory]:
                assert getattr(move, name) == getattr(source, name), (factory.__name__, name)


@pytest.mark.parametrize("factory", list(OWNS), ids=lambda f: f.__name__)
@settings(max_examples=40, deadline=None)
@given(items=moves, spindle=spindles)
def test_a_stage_keeps_every_field_it_does_not_own(factory: type[Stage], items: list, spindle: tuple) -> None:  # type: ignore[type-arg]
    programmed = _programmed(items, spindle)

    def one_by_one(stage: Stage) -> None:
        for move in programmed:
            stage.move(move)

    _assert_kept(factory, programmed, _through(factory, one_by_one))


@pytest.mark.parametrize("factory", list(OWNS), ids=lambda f: f.__name__)
@settings(max_examples=40, deadline=None)
@given(items=moves, spindle=spindles)
def test_a_stage_keeps_every_field_of_a_batch_it_does_not_own(factory: type[Stage], items: list,
                                                                spindle: tuple) -> None:  # type: ignore[type-arg]
    rpm, css, sync, caller = spindle
    programmed = _programmed(items, spindle)
    batch = Batch("job.nc", pose(), [m.kind for m in programmed], [m.line for m in programmed],
                  [m.end for m in programmed], [m.feed for m in programmed], rpm if css is None else 0.0, css,
                  sync, caller)
    assert list(batch.moves()) == programmed  # the array form of the very same records
    _assert_kept(factory, programmed, _through(factory, lambda stage: stage.straight_moves(batch)))


def test_a_single_move_is_a_batch_of_one() -> None:
    move = Move("linear", "job.nc", 3, pose(), pose(1, 2), 500.0, None, 800.0, None, 0.0, 9)
    assert list(Batch.of(move).moves()) == [move]
    assert list(Batch.of(move).tail(1).moves()) == [] and Batch.of(move).head(1) == Batch.of(move)


# --------------------------------------------------------------------------- the two defects

def test_moves_from_a_file_carry_the_spindle_speed_as_from_a_string(tmp_path: Path) -> None:
    text = "M3 S1000\nG1 X10 F100\nX20\nG0 Z5\nM5\nG1 X0\n"
    job = tmp_path / "job.nc"
    job.write_text(text)
    from_file: list[Move] = []
    from_string: list[Move] = []
    run_file(job, RunOptions(on_move=lambda move, _joints: from_file.append(move)))
    run_string(text, RunOptions(on_move=lambda move, _joints: from_string.append(move)), path=str(job))
    assert [m.spindle for m in from_file] == [1000.0, 1000.0, 1000.0, 0.0]
    assert from_file == from_string


@pytest.mark.parametrize("turned", ["", "G68 X0 Y0 R30\n", "G51 P2\n"])
def test_a_rigid_tap_ignores_the_feed_override_under_g68_and_g51(turned: str) -> None:
    # 10 mm down and back at 1 mm per revolution and 600 rpm: 2 s, whatever the feed override says
    result = run_string(f"M3 S600\n{turned}G33.1 Z-10 K1\n", RunOptions(feed_override=50))
    assert result.estimate is not None
    assert result.estimate.to_json()["seconds"] == pytest.approx(2.0, abs=0.01)
