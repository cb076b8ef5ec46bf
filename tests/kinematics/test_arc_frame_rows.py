"""``arc_frame_rows`` (a batch's arc frames, ``arc_frame``'s steps inlined) gives each arc the very numbers
``arc_geometry(...).frame`` gives it, on either core's ``arc_frame``: the Python one is compared here."""
from __future__ import annotations

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from edingcnc_lang.canon import Arc
from edingcnc_lang.kinematics.trajectory import ARC_ROW, arc_frame, arc_frame_rows, arc_geometry

coordinates = st.one_of(st.floats(-1e4, 1e4), st.sampled_from([0.0, -0.0, 5.0, -5.0, 1e-9]))
poses = st.tuples(*[coordinates] * 6)
arcs = st.one_of(st.none(), st.builds(Arc, st.tuples(coordinates, coordinates), st.sampled_from(["XY", "XZ", "YZ"]),
                                      st.sampled_from([1, -1]), st.sampled_from([0, 0, 1, 3])))


@settings(max_examples=300, deadline=None)
@given(poses, st.lists(st.tuples(poses, arcs), max_size=8))
def test_the_rows_are_each_arcs_frame(start: tuple[float, ...], moves: list[tuple[tuple[float, ...], Arc | None]]) -> None:
    ends = [end for end, _ in moves]
    rows = arc_frame_rows(start, ends, [arc for _, arc in moves])
    expected: list[float] = []
    previous = start
    for index, (end, arc) in enumerate(moves):
        if arc is not None:
            path = arc_geometry(previous, end, arc)
            assert path.center is not None
            frame = arc_frame(path.start, path.end, path.center, path.normal, path.turns, path.full_circle_epsilon)
            expected += (float(index), float(frame.u), float(frame.v), *frame.center, frame.r0, frame.r1,
                         frame.start_angle, frame.sweep, frame.linear)
        previous = end
    assert repr(rows) == repr(expected)
    assert len(rows) == ARC_ROW * sum(arc is not None for _, arc in moves)


def test_an_arc_without_a_direction_is_refused_as_arc_sweep_refuses_it() -> None:
    start = (0.0,) * 6
    with pytest.raises(ValueError, match="turns must be non-zero"):
        arc_frame_rows(start, [(1.0, 1.0, 0.0, 0.0, 0.0, 0.0)], [Arc((1.0, 0.0), "XY", 0)])
