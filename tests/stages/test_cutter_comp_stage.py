"""The cutter compensation stage alone: programmed moves in, compensated moves out."""
from __future__ import annotations

import math

import pytest
from stage_helpers import Recorder, batch, line, pose

from edingcnc_lang.canon import Arc, Move
from edingcnc_lang.events import CoolantEvent, CutterCompEvent, EndEvent
from edingcnc_lang.config.machine_config import MachineConfig
from edingcnc_lang.errors import MachineError
from edingcnc_lang.pipeline.cutter_comp import CutterCompensation

CONFIG = MachineConfig.default()


def comp_on(stage: CutterCompensation, side: str, radius: float, plane: str = "XY") -> None:
    stage.event(CutterCompEvent("job.nc", 1, side, radius, plane))


def entered(side: str, radius: float) -> tuple[Recorder, CutterCompensation]:
    """A stage with compensation on, fed the entry move (-10, 0) -> (0, 0) on line 2."""
    sink = Recorder()
    stage = CutterCompensation(sink, CONFIG)
    comp_on(stage, side, radius)
    stage.move(line(-10, 0, 0, 0, 2))
    return sink, stage


def ends(sink: Recorder) -> list[tuple[str, int, tuple[float, float]]]:
    return [(m.kind, m.line, (round(m.end[0], 4) + 0.0, round(m.end[1], 4) + 0.0)) for m in sink.moves()]


def square(stage: CutterCompensation) -> None:
    """Entry from (-10, -10), then a 20 mm square counter-clockwise from the origin, then G40 and exit."""
    stage.move(line(-10, -10, 0, 0, 2))
    stage.move(line(0, 0, 20, 0, 3))
    stage.move(line(20, 0, 20, 20, 4))
    stage.move(line(20, 20, 0, 20, 5))
    stage.move(line(0, 20, 0, 0, 6))
    stage.event(CutterCompEvent("job.nc", 7, "off"))
    stage.move(line(0, 0, -10, -10, 8))


def test_outside_corners_get_arcs_round_the_corner_point_inside_ones_are_cut_back() -> None:
    sink = Recorder()
    stage = CutterCompensation(sink, CONFIG)
    comp_on(stage, "right", 2.0)  # counter-clockwise with the tool on the right: outside
    square(stage)
    assert ends(sink) == [  # the entry's corner turns towards the tool: cut back, not rounded
        ("linear", 2, (0.8284, -2.0)), ("linear", 3, (20.0, -2.0)),
        ("arc", 4, (22.0, 0.0)), ("linear", 4, (22.0, 20.0)), ("arc", 5, (20.0, 22.0)), ("linear", 5, (0.0, 22.0)),
        ("arc", 6, (-2.0, 20.0)), ("linear", 6, (-2.0, 0.0)), ("linear", 8, (-10.0, -10.0))]
    corner = sink.moves()[2]
    assert corner.arc == Arc((20.0, 0.0), "XY", 1, 0) and corner.start == sink.moves()[1].end


def test_inside_corners_are_cut_back_to_the_intersection_of_both_sides() -> None:
    sink = Recorder()
    stage = CutterCompensation(sink, CONFIG)
    comp_on(stage, "left", 2.0)  # counter-clockwise with the tool on the left: inside
    square(stage)
    assert ends(sink) == [  # the entry's corner turns away from the tool: rounded
        ("linear", 2, (-1.4142, 1.4142)), ("arc", 3, (0.0, 2.0)), ("linear", 3, (18.0, 2.0)),
        ("linear", 4, (18.0, 18.0)), ("linear", 5, (2.0, 18.0)), ("linear", 6, (2.0, 0.0)), ("linear", 8, (-10.0, -10.0))]
    moves = sink.moves()
    assert all(a.end == b.start for a, b in zip(moves, moves[1:]))  # each move starts where the last ended


def test_a_move_is_held_until_the_next_one_and_events_wait_behind_it() -> None:
    sink, stage = entered("left", 1.0)
    stage.event(CoolantEvent("job.nc", 3, 8))
    assert [e[0] for e in sink.log] == ["event"]  # only the cutter_comp event so far
    stage.move(line(0, 0, 10, 0, 4))
    assert [e[1] if e[0] == "event" else list(e[1].lines) for e in sink.log[1:]] == [[2], "coolant"]


def test_compensated_move_batch_go_on_as_one_batch_with_their_spindle() -> None:
    sink, stage = entered("left", 1.0)
    moves = [line(0, 0, 10, 0, 4), line(10, 0, 20, 1, 5), line(20, 1, 30, 3, 6)]
    stage.move_batch(batch(pose(), *[(m.kind, m.line, m.end, m.feed) for m in moves]))
    kinds = [entry[0] for entry in sink.log]
    assert kinds.count("batch") == 1 and "move" not in kinds
    stage.flush()
    assert [m.line for m in sink.moves()] == [2, 4, 5, 6]


def test_the_bulk_path_passes_whole_while_compensation_is_off() -> None:
    sink = Recorder()
    CutterCompensation(sink, CONFIG).move_batch(batch(pose(), ("linear", 1, pose(1), 100.0)))
    assert sink.log[0][0] == "batch"


def test_a_radius_of_zero_compensates_nothing() -> None:
    sink = Recorder()
    stage = CutterCompensation(sink, CONFIG)
    comp_on(stage, "left", 0.0)
    stage.move(line(0, 0, 1, 0))
    assert ends(sink) == [("linear", 1, (1.0, 0.0))]


def test_a_negative_radius_swaps_the_side() -> None:
    sink, stage = entered("left", -2.0)
    stage.flush()
    assert ends(sink) == [("linear", 2, (0.0, -2.0))]  # on the right of a move along +X


def test_entry_shorter_than_the_radius_is_refused_at_its_line() -> None:
    stage = CutterCompensation(Recorder(), CONFIG)
    comp_on(stage, "left", 3.0)
    with pytest.raises(MachineError, match="entry move") as err:
        stage.move(line(0, 0, 2, 0, 7))
    assert err.value.location is not None and err.value.location.line == 7


def test_a_tool_too_big_for_a_concave_arc_is_refused() -> None:
    _, stage = entered("right", 3.0)
    arc = Move("arc", "job.nc", 3, pose(), pose(4), 100.0, Arc((2.0, 0.0), "XY", -1))
    with pytest.raises(MachineError, match="does not fit inside the arc"):
        stage.move(arc)


def test_the_move_after_g40_must_be_straight() -> None:
    _, stage = entered("left", 1.0)
    stage.event(CutterCompEvent("job.nc", 3, "off"))
    with pytest.raises(MachineError, match="after G40"):
        stage.move(Move("arc", "job.nc", 4, pose(), pose(10), 100.0, Arc((5.0, 0.0), "XY", 1)))


def test_the_xz_plane_compensates_in_z_and_x() -> None:
    sink = Recorder()
    stage = CutterCompensation(sink, CONFIG)
    comp_on(stage, "left", 1.0, plane="XZ")
    stage.move(Move("linear", "job.nc", 2, pose(10, 0, 10), pose(10, 0, 0), 100.0))  # along -Z
    stage.flush()
    end = sink.moves()[0].end
    assert (end[0], end[2]) == pytest.approx((9.0, 0.0))  # left of -Z seen in the (Z, X) frame is -X


def test_program_end_flushes_and_ends_compensation() -> None:
    sink, stage = entered("left", 1.0)
    stage.event(EndEvent("job.nc", 3, 30))
    assert [e[0] for e in sink.log] == ["event", "batch", "event"] and not stage.side
    assert math.isclose(sink.moves()[0].end[1], 1.0)
