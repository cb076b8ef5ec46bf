"""Removed volumes against closed forms: the sweep is right for each tool shape, straight and round.

The field samples each cell at its centre, so a cell on the edge of the cut counts whole or not at
all: the error is at most half a cell across the outline of the cut, times the depth.  Each
tolerance below is that bound, ``perimeter * resolution / 2 * depth``.
"""
from __future__ import annotations

import math

import pytest

from edingcnc_lang.sim import Tool

from .jobs import cut

R = 0.1  # mm cells
GROOVE = "G0 Z5\nG0 X10 Y15\nG1 Z-{depth} F300\nG1 X30 F1000\nG0 Z5"


def bound(perimeter: float, depth: float) -> float:
    return perimeter * R / 2.0 * depth


def test_flat_end_pocket_is_a_box_with_round_corners(tmp_path):
    # a 6 mm end mill around a 20 x 10 rectangle, 2 mm deep, then the middle cleared: a 26 x 16 pocket
    body = "G0 Z5\nG0 X10 Y10\nG1 Z-2 F300\nX30 F1000\nY20\nX10\nY10\nY12\nX30\nY15\nX10\nY18\nX30\nG0 Z5"
    result = cut(tmp_path, body, Tool(0, "flat", 6.0))
    expected = 2.0 * (26 * 16 - (4 - math.pi) * 9)  # the corners are quarter circles of the tool
    assert result.stock.removed_volume == pytest.approx(expected, abs=bound(2 * (26 + 16), 2.0))
    assert result.findings == []


def test_ball_end_groove_is_a_circular_segment_with_spherical_caps(tmp_path):
    result = cut(tmp_path, GROOVE.format(depth=1), Tool(0, "ball", 6.0))
    segment = 9 * math.acos(2 / 3) - 2 * math.sqrt(5)  # circle r 3 cut 2 from its centre
    cap = math.pi * 1 * (3 * 3 - 1) / 3                # the two half caps at the ends make one
    width = 2 * math.sqrt(5)
    assert result.stock.removed_volume == pytest.approx(20 * segment + cap, abs=bound(2 * 20 + math.pi * width, 1))


def test_vee_engraving_is_a_triangle_with_half_cones(tmp_path):
    result = cut(tmp_path, GROOVE.format(depth=1.5), Tool(0, "vee", 10.0, angle=60.0))
    half_width = 1.5 * math.tan(math.radians(30))
    expected = 20 * 1.5 * half_width + math.pi * half_width ** 2 * 1.5 / 3
    assert result.stock.removed_volume == pytest.approx(expected, abs=bound(40 + 2 * math.pi * half_width, 1.5))


def test_bull_nose_groove(tmp_path):
    # corner radius 1 on a 6 mm tool, 1 mm deep: flat 4 mm + two quarter circles across; the ends
    # make one solid of revolution of the tool's profile
    result = cut(tmp_path, GROOVE.format(depth=1), Tool(0, "bull", 6.0, corner_radius=1.0))
    section = 4 + math.pi / 2
    revolved = 4 * math.pi + 2 * math.pi * (1 / 3 + math.pi / 2)
    assert result.stock.removed_volume == pytest.approx(20 * section + revolved, abs=bound(40 + 6 * math.pi, 1))


@pytest.mark.parametrize("plane", ["G17 G2 X10 Y15 I10 J0", "G17 G3 X10 Y15 I10 J0"])
def test_full_circle_arc_is_an_annulus(tmp_path, plane):
    body = f"G0 Z5\nG0 X10 Y15\nG1 Z-1 F300\n{plane}\nG0 Z5"
    result = cut(tmp_path, body, Tool(0, "flat", 6.0))
    expected = math.pi * (13 ** 2 - 7 ** 2)
    assert result.stock.removed_volume == pytest.approx(expected, abs=bound(2 * math.pi * 20, 1))


def test_helix_down_ends_at_its_depth(tmp_path):
    # two turns of a helix from Z0 to Z-2 around (20, 15): the centre column stays, the floor is at -2
    body = "G0 Z5\nG0 X25 Y15\nG1 Z0 F300\nG2 X25 Y15 Z-2 I-5 J0 L2\nG2 X25 Y15 I-5 J0\nG0 Z5"
    result = cut(tmp_path, body, Tool(0, "flat", 4.0))
    stock = result.stock
    column = stock.top[round(15 / R), round(20 / R)]
    ring = stock.top[round(15 / R), round(25 / R)]
    assert column == pytest.approx(0.0)
    assert ring == pytest.approx(-2.0, abs=1e-4)
    assert stock.removed_volume == pytest.approx(2 * math.pi * (7 ** 2 - 3 ** 2), abs=bound(2 * math.pi * 10, 2))


def test_nothing_is_cut_above_the_stock_or_off_its_side(tmp_path):
    result = cut(tmp_path, "G0 Z5\nG0 X10 Y10\nG1 X30 Y20 Z0.5 F300\nG0 X-10\nG1 Z-3\nG1 Y-5", Tool(0, "flat", 6.0))
    assert result.stock.removed_volume == 0.0


def test_arcs_in_the_xz_plane_dip_where_the_circle_does(tmp_path):
    # a half circle of radius 10 in XZ from X10 to X30 about X20 Z0: one direction goes down through
    # Z-10 under X20, the other up through Z10 (cutting nothing)
    cuts = []
    for code in ("G2", "G3"):
        body = f"G0 X10 Y15 Z5\nG1 Z0 F300\nG18 {code} X30 Z0 I10 K0\nG17\nG0 Z50"
        stock = cut(tmp_path, body, Tool(0, "ball", 2.0), box=(0, 0, -20, 40, 30, 0)).stock
        cuts.append((stock.removed_volume, float(stock.top[round(15 / R), round(20 / R)])))
    (low_volume, low_z), (high_volume, high_z) = sorted(cuts, key=lambda c: c[1])
    # the ball's tip at the bottom of the circle, up to the chords' quarter cell (and the cell's
    # centre 0.05 mm off the axis: 0.0013 mm up the ball)
    assert low_z == pytest.approx(-10.0, abs=R / 4 + 0.002)
    assert high_volume == 0.0 and high_z == 0.0
