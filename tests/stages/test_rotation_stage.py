"""The G68 rotation stage alone: programmed moves in, turned moves out."""
from __future__ import annotations

import pytest
from stage_helpers import Recorder, batch, line, pose

from edingcnc_lang.canon import Arc, Move
from edingcnc_lang.events import RotationEvent
from edingcnc_lang.config.machine_config import MachineConfig
from edingcnc_lang.errors import MachineError
from edingcnc_lang.pipeline.rotation import Rotation

CONFIG = MachineConfig.default()


def turned(angle: float, pivot: tuple[float, float] = (0.0, 0.0)) -> tuple[Recorder, Rotation]:
    sink = Recorder()
    stage = Rotation(sink, CONFIG)
    stage.event(RotationEvent("job.nc", 1, True, pivot, angle))
    return sink, stage


def test_moves_and_arc_centres_turn_about_the_pivot() -> None:
    sink, stage = turned(90.0, (5.0, 5.0))
    stage.move(line(5, 5, 10, 5, 2))
    stage.move(Move("arc", "job.nc", 3, pose(10, 5), pose(5, 10), 100.0, Arc((5.0, 5.0), "XY", 1)))
    first, arc = sink.moves()
    assert first.end == pytest.approx(pose(5, 10)) and arc.end == pytest.approx(pose(0, 5))
    assert arc.arc is not None and arc.arc.center == pytest.approx((5.0, 5.0)) and arc.arc.turn == 1


def test_arcs_outside_the_xy_plane_are_refused() -> None:
    _, stage = turned(30.0)
    with pytest.raises(MachineError, match="XZ plane"):
        stage.move(Move("arc", "job.nc", 4, pose(), pose(2), 100.0, Arc((1.0, 0.0), "XZ", 1)))


def test_bulk_moves_turn_while_on_and_pass_whole_after_g69() -> None:
    sink, stage = turned(180.0)
    stage.move_batch(batch(pose(), ("linear", 2, pose(1, 2), 100.0)))
    assert sink.moves()[-1].end == pytest.approx(pose(-1, -2))
    stage.event(RotationEvent("job.nc", 3, False))
    stage.move_batch(batch(pose(1, 2), ("linear", 4, pose(3, 3), 100.0)))
    assert sink.moves()[-1].start == pytest.approx(pose(-1, -2))  # starts where the tool really was
    stage.move_batch(batch(pose(3, 3), ("linear", 5, pose(4, 4), 100.0)))
    assert sink.log[-1][0] == "batch"


def test_kinematics_answers_in_the_programmed_frame() -> None:
    _, stage = turned(90.0)
    stage.move(line(0, 0, 1, 0, 2))  # really at (0, 1)
    assert stage.kinematics("ON", (), pose(1, 0), "job.nc", 3) == pytest.approx(pose(1, 0))
