"""One move record: every stage keeps every field of a move it does not own, alone or in a batch.

A stage changes what it owns (the pose stages the start, end and arc; cutter compensation also
the kind and feed of the corners it adds; height compensation the start and end) and hands the
rest on as it came: the spindle speed, constant surface speed, synchronisation, caller, file and
line.  The runs at the end are the two defects that dropped those fields.
"""
from __future__ import annotations

import math
from dataclasses import fields
from random import Random
from pathlib import Path

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from stage_helpers import LOOPS, Recorder, pose

from edingcnc_lang import RunOptions, run_file, run_string
from edingcnc_lang.canon import PLANES, Arc, Batch, Event, Move
from edingcnc_lang.events import CutterCompEvent, RotationEvent, ScalingEvent, ZhcEvent
from edingcnc_lang.config.machine_config import MachineConfig
from edingcnc_lang.errors import MachineError
from edingcnc_lang.config.heightmap import HeightMap
from edingcnc_lang.canon import Css
from edingcnc_lang.pipeline import STAGES
from edingcnc_lang.pipeline import comp_runs
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
    Rotation: RotationEvent("job.nc", 1, True, (1.0, 2.0), 30.0),
    Scaling: ScalingEvent("job.nc", 1, True, (2.0, 2.0, 1.0), (0.0, 0.0)),
    CutterCompensation: CutterCompEvent("job.nc", 1, "left", 0.5, "XY"),
    HeightCompensation: ZhcEvent("job.nc", 1, True, SURFACE),
}
KEPT = [f.name for f in fields(Move)]


def test_every_stage_of_the_pipeline_is_covered() -> None:
    assert set(STAGES) == set(OWNS)


coordinate = st.integers(-20, 20).map(float)
spindles = st.tuples(st.sampled_from([0.0, 600.0, 12000.0]),
                     st.sampled_from([None, Css(20000.0, 3000.0, 0.0, 0.0)]),
                     st.sampled_from([0.0, 1.5]), st.sampled_from([0, 7]))
moves = st.lists(st.tuples(st.sampled_from(["linear", "linear", "rapid", "arc"]), coordinate, coordinate, coordinate,
                           st.sampled_from([100.0, 2500.0])), min_size=1, max_size=8)


def _programmed(items: list[tuple[str, float, float, float, float]], spindle: tuple) -> list[Move]:  # type: ignore[type-arg]
    """The moves, an arc as a half circle in XY (a helix when Z changes) or, where it would not move in XY,
    a feed move."""
    rpm, css, sync, caller = spindle
    start, made = pose(), []
    for number, (kind, x, y, z, feed) in enumerate(items, 2):
        end = pose(x, y, z)
        arc = None
        if kind == "arc" and (x, y) != start[:2]:
            arc = Arc(((start[0] + x) / 2.0, (start[1] + y) / 2.0), "XY", 1 if number % 2 else -1)
        kind = "linear" if kind == "arc" and arc is None else kind
        made.append(Move(kind, "job.nc", number, start, end, feed if kind != "rapid" else 0.0, arc,
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


@pytest.mark.slow
@pytest.mark.parametrize("factory", list(OWNS), ids=lambda f: f.__name__)
@settings(max_examples=40, deadline=None)
@given(items=moves, spindle=spindles)
def test_a_stage_keeps_every_field_it_does_not_own(factory: type[Stage], items: list, spindle: tuple) -> None:  # type: ignore[type-arg]
    programmed = _programmed(items, spindle)

    def one_by_one(stage: Stage) -> None:
        for move in programmed:
            stage.move(move)

    _assert_kept(factory, programmed, _through(factory, one_by_one))


@pytest.mark.slow
@pytest.mark.parametrize("factory", list(OWNS), ids=lambda f: f.__name__)
@settings(max_examples=40, deadline=None)
@given(items=moves, spindle=spindles)
def test_a_stage_keeps_every_field_of_a_batch_it_does_not_own(factory: type[Stage], items: list,
                                                                spindle: tuple) -> None:  # type: ignore[type-arg]
    rpm, css, sync, caller = spindle
    programmed = _programmed(items, spindle)
    arcs = [m.arc for m in programmed]
    batch = Batch("job.nc", pose(), [m.kind for m in programmed], [m.line for m in programmed],
                  [m.end for m in programmed], [m.feed for m in programmed], rpm if css is None else 0.0, css,
                  sync, caller, None if arcs == [None] * len(arcs) else arcs)
    assert list(batch.moves()) == programmed  # the array form of the very same records
    _assert_kept(factory, programmed, _through(factory, lambda stage: stage.move_batch(batch)))


# --------------------------------------------------------------------------- compensation in batches
# A contour as a random walk: each step turns by some angle (straight on, inside and outside corners,
# folds back) and goes some length; length 0 is a plunge (no motion in the plane).
compensations = st.tuples(st.sampled_from(["left", "right"]), st.sampled_from([0.25, 1.0, 3.0]),
                          st.sampled_from(["XY", "XY", "XZ", "YZ"]))


def _step(rng: Random) -> tuple[str, float, float, float]:
    roll = rng.random()
    turn = (rng.uniform(-1.2, 1.2) if roll < 0.7 else rng.uniform(-0.06, 0.06) if roll < 0.85
            else rng.choice([0.0, 1e-9, 2.6, -2.6, math.pi]))
    roll = rng.random()
    length = rng.uniform(2.0, 12.0) if roll < 0.85 else rng.uniform(0.2, 2.0) if roll < 0.95 else 0.0
    return rng.choice(["linear", "linear", "linear", "rapid"]), turn, length, rng.choice([0.0, 0.0, -1.0])


def _walk(items: list, spindle: tuple, plane: str) -> list[Move]:  # type: ignore[type-arg]
    rpm, css, sync, caller = spindle
    first, second, normal = PLANES[plane]
    heading, point, depth = 0.3, [0.0, 0.0], 0.0
    start, made = pose(), []
    for number, (kind, turn, length, dz) in enumerate(items, 2):
        heading += turn
        point = [point[0] + length * math.cos(heading), point[1] + length * math.sin(heading)]
        depth += dz if length == 0.0 else 0.0
        end = [0.0] * 6
        end[first], end[second], end[normal] = point[0], point[1], depth
        made.append(Move(kind, "job.nc", number, start, tuple(end), 500.0 if kind == "linear" else 0.0, None,
                         css.rpm(end[0]) if css is not None else rpm, css, sync, caller))
        start = tuple(end)
    return made


def _compensated(programmed: list[Move], comp: tuple[str, float, str], send: object) -> tuple:  # type: ignore[type-arg]
    side, radius, plane = comp
    sink = Recorder()
    stage = CutterCompensation(sink, CONFIG)  # type: ignore[arg-type]
    stage.event(CutterCompEvent("job.nc", 1, side, radius, plane))
    error = None
    try:
        send(stage)  # type: ignore[operator]
        stage.event(CutterCompEvent("job.nc", 99, "off"))
        stage.flush()
    except MachineError as err:
        error = err.format()
    return sink.moves(), error


@pytest.mark.slow
@pytest.mark.parametrize("loop", LOOPS)
@settings(max_examples=150, deadline=None)
@given(rng=st.randoms(use_true_random=False), count=st.integers(1, 80), spindle=spindles, comp=compensations,
       cuts=st.lists(st.integers(1, 79), max_size=4))
def test_compensation_in_batches_gives_the_moves_of_compensation_move_by_move(
        loop: object, rng: Random, count: int, spindle: tuple, comp: tuple, cuts: list[int]) -> None:  # type: ignore[type-arg]
    """Runs of corners in one loop (comp_runs, in Python and compiled) give the very moves, bit for bit, and
    the same refusals; the batches are cut anywhere (the interpreter's batches end at any line)."""
    programmed = _walk([_step(rng) for _ in range(count)], spindle, comp[2])
    rpm, css, sync, caller = spindle

    def one_by_one(stage: Stage) -> None:
        for move in programmed:
            stage.move(move)

    def in_batches(stage: Stage) -> None:
        bounds = sorted({0, len(programmed), *(cut for cut in cuts if cut < len(programmed))})
        for low, high in zip(bounds, bounds[1:]):
            part = programmed[low:high]
            stage.move_batch(Batch("job.nc", part[0].start, [m.kind for m in part], [m.line for m in part],
                                       [m.end for m in part], [m.feed for m in part], rpm if css is None else 0.0,
                                       css, sync, caller))

    alone = _compensated(programmed, comp, one_by_one)
    with pytest.MonkeyPatch.context() as patch:
        patch.setattr(comp_runs, "LINES", loop)
        batched = _compensated(programmed, comp, in_batches)
    assert batched == alone


def test_a_long_contour_goes_on_in_batches_and_gives_the_moves_one_by_one() -> None:
    """A 200-segment spiral (straight on, then inside corners) leaves the stage as one batch."""
    items = [("linear", 0.01, 5.0, 0.0)] * 100 + [("linear", 0.3, 4.0, 0.0)] * 100
    programmed = _walk(items, (1000.0, None, 0.0, 0), "XY")
    batch = Batch("job.nc", pose(), [m.kind for m in programmed], [m.line for m in programmed],
                  [m.end for m in programmed], [m.feed for m in programmed], 1000.0)
    alone = _compensated(programmed, ("left", 1.0, "XY"), lambda stage: [stage.move(m) for m in programmed])
    sink = Recorder()
    stage = CutterCompensation(sink, CONFIG)  # type: ignore[arg-type]
    stage.event(CutterCompEvent("job.nc", 1, "left", 1.0, "XY"))
    stage.move_batch(batch)
    assert [(kind, len(what)) for kind, what in sink.log[1:]] == [("batch", 199)]  # the last one held back
    stage.event(CutterCompEvent("job.nc", 99, "off"))
    stage.flush()
    assert (sink.moves(), None) == alone


@pytest.mark.parametrize("move", [Move("linear", "job.nc", 3, pose(), pose(1, 2), 500.0, None, 800.0, None, 0.0, 9),
                                  Move("arc", "job.nc", 4, pose(), pose(2), 300.0, Arc((1.0, 0.0), "XY", -1),
                                       Css(20000.0, 3000.0, 0.0, 0.0).rpm(2.0), Css(20000.0, 3000.0, 0.0, 0.0))])
def test_a_single_move_is_a_batch_of_one(move: Move) -> None:
    assert list(Batch.of(move).moves()) == [move]
    assert list(Batch.of(move).tail(1).moves()) == [] and Batch.of(move).head(1) == Batch.of(move)


def test_the_arcs_column_is_cut_with_the_others() -> None:
    arc = Arc((1.0, 0.0), "XY", 1)
    batch = Batch("job.nc", pose(), ["linear", "arc", "rapid"], [1, 2, 3], [pose(0, 1), pose(2, 1), pose(5)],
                  [100.0, 100.0, 0.0], arcs=[None, arc, None])
    assert [m.arc for m in batch.head(2).moves()] == [None, arc]
    assert [m.arc for m in batch.tail(1).moves()] == [arc, None] and batch.tail(1).start == pose(0, 1)
    assert list(batch.head(2).moves()) + list(batch.tail(2).moves()) == list(batch.moves())


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
