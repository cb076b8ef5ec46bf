"""The arcs of a batch as one table: each row the very frame the arc's own geometry gives, and the
vectorised circle test deciding as ``machine.geometry.circle_within`` does, arc by arc."""
from __future__ import annotations

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from edingcnc_lang.canon import Arc
from edingcnc_lang.kinematics.trajectory import arc_geometry
from edingcnc_lang.machine.geometry import circle_within
from edingcnc_lang.motion.arc_table import ArcTable
from edingcnc_lang.motion.reach import frame_extremes, table_beyond

values = st.one_of(st.floats(-200, 200), st.sampled_from([0.0, -0.0, 10.0, -10.0]))
poses = st.tuples(*[values] * 6)
arcs = st.builds(Arc, st.tuples(values, values), st.sampled_from(["XY", "XZ", "YZ"]), st.sampled_from([1, -1]),
                 st.sampled_from([0, 0, 1, 2]))


@pytest.mark.slow
@settings(max_examples=200, deadline=None)
@given(poses, st.lists(st.tuples(poses, st.none() | arcs), min_size=1, max_size=10),
       st.tuples(*[values] * 6), st.tuples(*[values] * 6))
def test_each_row_is_the_arcs_frame_and_the_circle_test_is_the_scalar_one(
        start: tuple[float, ...], moves: list[tuple[tuple[float, ...], Arc | None]],
        low: tuple[float, ...], high: tuple[float, ...]) -> None:
    ends, arcs_of = [end for end, _ in moves], [arc for _, arc in moves]
    table = ArcTable.of(start, ends, arcs_of)
    expected = [(index, arc_geometry(ends[index - 1] if index else start, ends[index], arc).frame)
                for index, arc in enumerate(arcs_of) if arc is not None]
    assert table.index.tolist() == [index for index, _ in expected]
    assert [repr(table.frame(k)) for k in range(len(table))] == [repr(frame) for _, frame in expected]
    within = [circle_within(f.center, max(f.r0, f.r1), (f.u, f.v), low, high) for _, f in expected]
    assert table.circle_within(low, high).tolist() == within


@pytest.mark.slow
@settings(max_examples=300, deadline=None)
@given(poses, st.lists(st.tuples(poses, st.none() | arcs), min_size=1, max_size=10),
       st.tuples(*[values] * 6), st.tuples(*[values] * 6))
def test_the_tables_extremes_are_each_arcs_frame_extremes(
        start: tuple[float, ...], moves: list[tuple[tuple[float, ...], Arc | None]],
        low: tuple[float, ...], high: tuple[float, ...]) -> None:
    """The vectorised extremes (the limits report's, the limit check's) are the very points
    ``frame_extremes`` gives arc by arc, the same bits, and the limit check decides as it did."""
    import numpy as np

    ends, arcs_of = [end for end, _ in moves], [arc for _, arc in moves]
    table = ArcTable.of(start, ends, arcs_of)
    moves_of = table.index.tolist()
    expected = sorted(repr(tuple(point)) for k in range(len(table)) if not table.circle_within(low, high)[k]
                      for point in frame_extremes(table.frame(k), ends[moves_of[k]]))
    points = table.extremes(np.array(ends, dtype=float).T, low, high)
    assert sorted(repr(tuple(row)) for row in points.tolist()) == expected
    one_by_one = any(not low[axis] <= value <= high[axis] for k in range(len(table))
                     if not table.circle_within(low, high)[k]
                     for point in frame_extremes(table.frame(k), ends[moves_of[k]]) for axis, value in enumerate(point))
    assert table_beyond(table, ends, low, high) == one_by_one


def test_a_window_keeps_its_arcs_in_order_as_moves_come_and_go() -> None:
    """The planner's bookkeeping: tables joined in order, the arcs of the first moves, and what is left
    (counted from there) when they are done."""
    arc = Arc((5.0, 0.0), "XY", -1)
    start, ends = (0.0,) * 6, [(10.0, 0.0, 0.0, 0.0, 0.0, 0.0), (20.0, 0.0, 0.0, 0.0, 0.0, 0.0)]
    first = ArcTable.of(start, ends, [arc, None])                 # an arc, then a straight move
    second = ArcTable.of(ends[-1], [(30.0, 0.0, 0.0, 0.0, 0.0, 0.0)], [Arc((25.0, 0.0), "XY", 1)]).shifted(2)
    window = ArcTable.joined([first, second])
    assert window.index.tolist() == [0, 2]
    assert window.before(2).index.tolist() == [0] and window.before(3) is window
    assert window.after(1).index.tolist() == [1] and len(window.after(3)) == 0
    assert window.column("sweep").tolist() == [-3.141592653589793, 3.141592653589793]
    assert window.column("u").dtype.kind == "i" and len(ArcTable.joined([])) == 0
