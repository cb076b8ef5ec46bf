"""The recorded toolpath: tools per move, arcs as arcs, bounds, errors kept, line ranges."""
from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest

from edingcnc_lang import RunOptions
from edingcnc_lang.errors import EcncError
from edingcnc_lang.plot.toolpath import KINDS, record_job
from tests.plot.jobs import CIRCLE, SQUARE, TWO_TOOLS, write

ROOT = Path(__file__).resolve().parents[2]


def test_moves_carry_the_tool_in_the_spindle(tmp_path: Path) -> None:
    path = record_job(write(tmp_path, "two.nc", TWO_TOOLS))
    feeds = path.kinds == KINDS.index("linear")
    assert path.tools[feeds].tolist() == [1, 1, 2, 2]
    assert path.lines[feeds].tolist() == [4, 5, 9, 10]


def test_an_arc_is_sampled_on_its_circle(tmp_path: Path) -> None:
    path = record_job(write(tmp_path, "circle.nc", CIRCLE))
    arc = next(i for i in range(len(path)) if i in path.arcs)
    points = path.move_points(arc)
    radii = np.hypot(points[:, 0] - 40.0, points[:, 1] - 40.0)
    assert np.allclose(radii, 30.0, atol=1e-9)
    assert len(points) >= 120  # a full turn, 3 degrees a chord
    chord = np.hypot(*np.diff(points[:, :2], axis=0).T).max()
    assert chord <= 30.0 * math.radians(3.0) + 1e-9


def test_bounds_are_those_of_the_cut_not_of_the_rapids(tmp_path: Path) -> None:
    path = record_job(write(tmp_path, "circle.nc", CIRCLE))
    lower, upper = path.bounds()
    assert np.allclose(lower, [10.0, 10.0, -1.0]) and np.allclose(upper, [70.0, 70.0, 2.0])
    lower, upper = path.bounds(feed_only=False)
    assert np.allclose(lower[:2], [0.0, 0.0])


def test_polylines_split_where_style_changes_and_cover_every_move(tmp_path: Path) -> None:
    path = record_job(write(tmp_path, "square.nc", SQUARE))
    lines = list(path.polylines())
    owners = np.concatenate([line.moves for line in lines])
    assert sorted(set(owners.tolist())) == list(range(len(path)))
    feed = next(line for line in lines if line.kind == KINDS.index("linear"))
    assert np.allclose(feed.points[:, :2], [[10, 10], [10, 10], [60, 10], [60, 60], [10, 60], [10, 10]])


def test_a_runtime_error_keeps_the_path_so_far(tmp_path: Path) -> None:
    job = write(tmp_path, "bad.nc", "G0 X5\nG1 X10 F100\nerrmsg \"stop here\"\nG1 X20\n")
    path = record_job(job)
    assert path.error is not None and "stop here" in path.error.format()
    assert path.ends[-1, 0] == 10.0


def test_a_syntax_error_is_raised_as_nothing_ran(tmp_path: Path) -> None:
    with pytest.raises(EcncError) as caught:
        record_job(write(tmp_path, "broken.nc", "G1 X(1\n"))
    assert caught.value.exit_code == 65


def test_select_lines_keeps_moves_of_those_job_lines_with_their_subs(tmp_path: Path) -> None:
    path = record_job(write(tmp_path, "two.nc", TWO_TOOLS))
    part = path.select_lines(8, 10)
    assert part.lines.tolist() == [8, 9, 10] and len(part.starts) == 3


def test_machine_limits_come_from_the_ini_and_not_from_the_wide_defaults() -> None:
    """A delta's travel is its [KINEMATICS] Cartesian box, not its carriages' 0..420 mm."""
    path = record_job(ROOT / "examples/delta/job.nc", RunOptions(ini=ROOT / "examples/delta/cnc.ini"))
    assert path.limits is not None and path.kinematics.startswith("deltakins")
    assert path.limits[0].tolist() == [-400.0, -400.0, 0.0] and path.limits[1].tolist() == [400.0, 400.0, 200.0]
    assert record_job(ROOT / "examples/pocket.nc").limits is None  # no ini: nothing to draw


def test_a_job_without_moves_gives_an_empty_path(tmp_path: Path) -> None:
    path = record_job(write(tmp_path, "empty.nc", "(nothing to cut)\nM30\n"))
    assert len(path) == 0 and path.starts.shape == (0, 6) and path.bounds() is None
    assert list(path.polylines()) == []


def test_every_move_carries_the_planners_timing(tmp_path: Path) -> None:
    path = record_job(write(tmp_path, "square.nc", SQUARE))
    start, end = path.times[:, 0], path.times[:, 1]
    assert (end >= start).all() and np.allclose(start[1:], end[:-1])  # back to back, in order
    assert path.seconds == pytest.approx(end[-1])
    feeds = path.kinds == KINDS.index("linear")
    assert (path.speeds[feeds] > 0).all() and (path.speeds[feeds] <= path.feeds[feeds] + 1e-6).all()


def test_callbacks_already_in_the_options_still_get_every_move(tmp_path: Path) -> None:
    seen: list[tuple[int, float]] = []
    events: list[str] = []
    options = RunOptions(on_timed_move=lambda move, joints, timing: seen.append((move.line, timing.end)),
                         on_event=lambda event: events.append(event.kind))
    path = record_job(write(tmp_path, "square.nc", SQUARE), options)
    assert [line for line, _ in seen] == path.lines.tolist() and "tool_change" in events


SUB_IN_JOB = "G0 X0 Y0\nGoSub sq\nG0 Z5\nGoSub sq\nM30\nSub sq\n G1 X10 F500\n G1 Y10\nEndSub\n"


def test_a_subs_moves_count_with_the_gosub_line_also_when_the_sub_is_in_the_job(tmp_path: Path) -> None:
    path = record_job(write(tmp_path, "sqj2.nc", SUB_IN_JOB, newline="\r\n"))
    assert path.select_lines(2, 2).lines.tolist() == [7, 8]
    assert path.select_lines(3, 3).lines.tolist() == [3]
    assert path.select_lines(4, 4).lines.tolist() == [7, 8]
    assert path.select_lines(6, 9).lines.tolist() == []  # the sub's own lines make no moves of the job


def test_a_macro_subs_moves_count_with_the_line_that_called_it(tmp_path: Path) -> None:
    job = write(tmp_path, "job.nc", "G0 X0 Y0\nGoSub sq\nG0 Z5\nGoSub sq\nM30\n")
    macro = write(tmp_path, "sq.cnc", "Sub sq\n G1 X10 F500\n G1 Y10\n G1 X0\nEndSub\n")
    path = record_job(job, RunOptions(user_macro=macro))
    assert len(path.select_lines(1, 1)) == 1
    part = path.select_lines(2, 3)
    assert part.lines.tolist() == [2, 3, 4, 3] and part.callers.tolist() == [2, 2, 2, 0]


def test_the_work_zero_is_the_coordinate_systems_origin_under_rotation_and_scaling(tmp_path: Path) -> None:
    rotated = write(tmp_path, "rot.nc", "G21 G17 G90\nG0 X0 Y0 Z5\nG68 X0 Y0 R90\nG1 X10 F1000\nG1 Y5\n")
    assert record_job(rotated).work_zero == (0.0, 0.0, 0.0)
    scaled = write(tmp_path, "scale.nc", "G10 L2 P1 X20 Y10 Z-3\nG54 G0 X0 Y0\nG51 X5 Y5 P2\nG1 X10 F500\n")
    assert record_job(scaled).work_zero == pytest.approx((20.0, 10.0, -3.0))


def test_the_caller_survives_cutter_compensation_rotation_and_a_tool_change_sub(tmp_path: Path) -> None:
    """Moves rebuilt by the comp and rotation stages, and the change_tool sub's, keep their job line."""
    job = write(tmp_path, "comp.nc", "G0 X0 Y0 Z5\nT1 M6\nGoSub prof\nM30\n"
                "Sub prof\n G68 X0 Y0 R30\n G41 D1 G1 X10 Y0 F500\n G1 X20\n G1 Y10\n G40 G1 X30\n G69\nEndSub\n")
    path = record_job(job)
    assert path.error is None
    own = path.files == path.paths.index(str(job))
    assert set(path.callers[own & (path.lines >= 7)].tolist()) == {3}
    assert set(path.callers[~own].tolist()) == {2}  # the change_tool sub of the macro file, called by T1 M6
    assert len(path.select_lines(3, 3)) == int((own & (path.lines >= 7)).sum())
