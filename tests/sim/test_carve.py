"""The compiled sweep (``_sweep.carve``) cuts the same height field as the numpy reference.

Random straight moves (short and long, vertical, climbing and plunging, in and out of the stock,
or one after another as a finishing pass makes them) of random flat, ball, bull nose and vee cutters, some with a shank that reaches the material or
moves with the spindle off (chunks that may be findings, which numpy keeps), are swept both ways
on the same stock; the fields must be equal cell for cell (the C repeats numpy's operations in
numpy's precision, so no tolerance is needed) and the findings the same.
"""
from __future__ import annotations

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from edingcnc_lang.sim import Stock, Tool
from edingcnc_lang.sim import sweep as sweep_module
from edingcnc_lang.sim.sweep import NONE, RAPID, SPINDLE_OFF, Segments, sweep

pytestmark = pytest.mark.skipif(sweep_module.CARVE is None,
                                reason="the compiled sweep is not built (or ECNC_PURE_PYTHON)")

coordinate = st.floats(-4.0, 24.0, allow_nan=False)
height = st.floats(-7.0, 3.0, allow_nan=False)
point = st.tuples(coordinate, coordinate, height)
move = st.one_of(st.tuples(point, point),
                 point.map(lambda p: (p, (p[0], p[1], p[2] - 2.0))),            # a plunge
                 st.tuples(point, st.floats(-3.0, 3.0)).map(lambda pd: (pd[0], (pd[0][0] + pd[1], pd[0][1], pd[0][2]))))
# a finishing pass: consecutive short segments, each reaching cells the ones before it cut
step = st.tuples(st.floats(-0.4, 0.4), st.floats(-0.4, 0.4), st.floats(-0.2, 0.2))
passes = st.tuples(point, st.lists(step, min_size=1, max_size=150)).map(
    lambda ps: [tuple(p) for p in np.cumsum(np.array([ps[0], *ps[1]]), axis=0)]).map(
    lambda pts: list(zip(pts[:-1], pts[1:])))
tools = st.one_of(
    st.builds(lambda d: Tool(0, "flat", d), st.floats(0.2, 8.0)),
    st.builds(lambda d: Tool(0, "ball", d), st.floats(0.2, 8.0)),
    st.builds(lambda d, c: Tool(0, "bull", d, corner_radius=c * d / 2.0), st.floats(0.5, 8.0), st.floats(0.05, 1.0)),
    st.builds(lambda d, a: Tool(0, "vee", d, angle=a), st.floats(0.5, 8.0), st.floats(20.0, 170.0)))


def _cut(stock: Stock, tool: Tool, segs: Segments, compiled: bool) -> tuple:
    field = Stock(stock.x0, stock.y0, stock.resolution, stock.bottom, stock.height, stock.top.copy())
    with pytest.MonkeyPatch.context() as patch:
        if not compiled:
            patch.setattr(sweep_module, "CARVE", None)
        hits = sweep(field, tool, segs, 0.5 * tool.diameter, field.height)
    return field.top, hits


@settings(max_examples=150)
@given(moves=st.one_of(st.lists(move, min_size=1, max_size=40), passes), tool=tools, resolution=st.sampled_from([0.1, 0.25, 0.37]),
       codes=st.one_of(st.just([NONE] * 150),  # all quiet: the compiled sweep cuts every chunk
                      st.lists(st.sampled_from([NONE] * 6 + [RAPID, SPINDLE_OFF]), min_size=150, max_size=150)),
       flutes=st.one_of(st.none(), st.floats(0.5, 6.0)))
def test_compiled_sweep_cuts_the_reference_field(moves, tool, resolution, codes, flutes):
    if flutes is not None:
        tool = Tool(0, tool.shape, tool.diameter, tool.corner_radius, tool.angle, flute_length=flutes)
    stock = Stock.box((0.0, 0.0, -5.0), (20.0, 15.0, 0.0), resolution)
    stock.top[:, : stock.shape[1] // 3] = -1.5  # a step, so some cells are already lower
    ends = np.array(moves, dtype=float)
    segs = Segments(ends[:, 0].copy(), ends[:, 1].copy(), np.arange(len(moves)), np.array(codes[:len(moves)], np.int8))
    reference, expected = _cut(stock, tool, segs, False)
    compiled, found = _cut(stock, tool, segs, True)
    assert np.array_equal(compiled, reference), np.argwhere(compiled != reference)[:5]
    for name in ("move", "code", "depth", "where"):
        assert np.array_equal(getattr(found, name), getattr(expected, name))


def test_a_finishing_pass_is_carved_in_c(monkeypatch):
    # a chunk with nothing to find goes to the compiled core; the field is the reference's
    calls = []
    carve = sweep_module.CARVE
    monkeypatch.setattr(sweep_module, "CARVE", lambda *args: calls.append(len(args[1])) or carve(*args))
    xs = np.linspace(0.0, 20.0, 201)
    a = np.column_stack((xs[:-1], np.full(200, 7.0), -1.0 - 0.01 * xs[:-1]))
    b = np.column_stack((xs[1:], np.full(200, 7.0), -1.0 - 0.01 * xs[1:]))
    segs = Segments(a, b, np.arange(200), np.zeros(200, np.int8))
    stock = Stock.box((0.0, 0.0, -5.0), (20.0, 15.0, 0.0), 0.1)
    compiled, _ = _cut(stock, Tool(0, "ball", 6.0), segs, True)
    reference, _ = _cut(stock, Tool(0, "ball", 6.0), segs, False)
    assert sum(calls) == 200 and np.array_equal(compiled, reference)
