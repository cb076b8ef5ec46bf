"""The scaling stage alone: programmed moves in, scaled moves out."""
from __future__ import annotations

import pytest
from stage_helpers import Recorder, batch, line, pose

from edingcnc_lang.canon import Arc, Move
from edingcnc_lang.events import ScalingEvent
from edingcnc_lang.config.machine_config import MachineConfig
from edingcnc_lang.errors import MachineError
from edingcnc_lang.pipeline.scaling import Scaling

CONFIG = MachineConfig.default()


def scaled(factors: tuple[float, float, float], center: tuple[float, float] = (0.0, 0.0)) -> tuple[Recorder, Scaling]:
    sink = Recorder()
    stage = Scaling(sink, CONFIG)
    stage.move(line(0, 0, 10, 10, 1))  # before G51: where the machine really is
    stage.event(ScalingEvent("job.nc", 2, True, factors, center))
    return sink, stage


def test_uniform_factor_about_a_centre_and_z_unscaled() -> None:
    sink, stage = scaled((2.0, 2.0, 1.0), (5.0, 5.0))
    stage.move(Move("linear", "job.nc", 3, pose(10, 10), pose(20, 10, -3), 100.0))
    moved = sink.moves()[-1]
    assert moved.start == pose(10, 10) and moved.end == pose(35, 15, -3)  # starts where it was: no jump


def test_arcs_scale_under_uniform_factors_and_mirror_reverses_them() -> None:
    sink, stage = scaled((2.0, 2.0, 1.0))
    arc = Move("arc", "job.nc", 3, pose(10, 10), pose(20, 20), 100.0, Arc((10.0, 20.0), "XY", -1))
    stage.move(arc)
    assert sink.moves()[-1].arc == Arc((20.0, 40.0), "XY", -1)
    sink, stage = scaled((-1.0, 1.0, 1.0))
    stage.move(arc)
    assert sink.moves()[-1].arc == Arc((-10.0, 20.0), "XY", 1)


@pytest.mark.parametrize(("factors", "plane"), [((2.0, 1.0, 1.0), "XY"), ((2.0, 2.0, 1.0), "XZ")])
def test_arcs_under_unequal_factors_are_refused_at_their_line(factors: tuple[float, float, float],
                                                              plane: str) -> None:
    _, stage = scaled(factors)
    with pytest.raises(MachineError, match="different factors") as err:
        stage.move(Move("arc", "job.nc", 9, pose(10, 10), pose(20, 10), 100.0, Arc((15.0, 10.0), plane, 1)))
    assert err.value.location is not None and err.value.location.line == 9


def test_after_g50_the_next_move_starts_where_the_machine_is() -> None:
    sink, stage = scaled((2.0, 2.0, 1.0))
    stage.move(line(10, 10, 20, 20, 3))
    stage.event(ScalingEvent("job.nc", 4, False))
    stage.move_batch(batch(pose(20, 20), ("linear", 5, pose(0, 0), 100.0)))
    last = sink.moves()[-1]
    assert last.start == pose(40, 40) and last.end == pose(0, 0)


def test_bulk_moves_pass_whole_while_off() -> None:
    sink = Recorder()
    Scaling(sink, CONFIG).move_batch(batch(pose(), ("linear", 1, pose(1), 100.0)))
    assert sink.log[0][0] == "batch"
