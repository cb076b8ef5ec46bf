"""The height-map model: bilinear heights, grid crossings, the ZHC table file, probe surfaces."""
from __future__ import annotations

from pathlib import Path

import pytest
from hypothesis import given
from hypothesis import strategies as st

from edingcnc_lang.config.heightmap import HeightMap, HeightMapError, ProbeAt, ZhcTable, read_surface

TILTED = HeightMap((0.0, 10.0, 20.0), (0.0, 10.0), ((0.0, 1.0, 2.0), (0.5, 1.5, 2.5)))  # z = x/10 + y/20


@pytest.mark.parametrize("x, y, z", [(0, 0, 0.0), (5, 0, 0.5), (15, 5, 1.75), (20, 10, 2.5),
                                     (-5, -5, 0.0), (30, 20, 2.5), (25, 5, 2.25)])
def test_bilinear_height_clamped_outside(x: float, y: float, z: float) -> None:
    assert TILTED.height(x, y) == pytest.approx(z)


@given(st.floats(0, 20), st.floats(0, 10))
def test_a_plane_is_reproduced_exactly(x: float, y: float) -> None:
    assert TILTED.height(x, y) == pytest.approx(x / 10 + y / 20, abs=1e-12)


def test_crossings_are_the_grid_lines_a_move_crosses_in_order() -> None:
    assert TILTED.crossings((-5, 5), (25, 5)) == pytest.approx([1 / 6, 0.5, 5 / 6])
    assert TILTED.crossings((5, 5), (5, 6)) == []
    assert TILTED.crossings((0, 0), (20, 10)) == pytest.approx([0.5])  # through a node: one split


def test_zhc_table_fills_the_node_nearest_each_probe_and_round_trips(tmp_path: Path) -> None:
    table = ZhcTable.empty(3, 2, 0.0, 0.0, 10.0, 10.0)
    serpentine = [(0, 0), (10, 0), (20, 0), (20, 10), (10, 10), (0, 10)]
    for x, y in serpentine:
        assert table.add(x + 0.2, y - 0.3, x / 100 + y / 1000) is not None
    assert table.add(50, 0, 1.0) is None  # off the grid
    assert table.complete()
    path = tmp_path / "zHeightCompTable.txt"
    table.save(path)
    text = path.read_text()
    assert text.splitlines()[:3] == ["; ecnc ZHC height table", "nx 3", "ny 2"]
    loaded = ZhcTable.load(path)
    assert loaded.height_map().height(15, 5) == pytest.approx(table.height_map().height(15, 5))
    assert "6 measured" in loaded.statistics() and "range 0.2100" in loaded.statistics()


@pytest.mark.parametrize("text, message", [
    ("nx 2\nny 1\nx0 0\ny0 0\ndx 1\n", "lacks dy"),
    ("nx 2\nny 1\nx0 0\ny0 0\ndx 1\ndy 1\n1 2 3\n", "3 heights on this row"),
    ("nx 2\nny 2\nx0 0\ny0 0\ndx 1\ndy 1\n1 2\n", "1 rows of heights"),
    ("nx 2\nny 1\nx0 0\ny0 0\ndx 1\ndy 1\n1 abc\n", "'abc' is not a number"),
    # hostile headers (a job archive may ship the table): checked before the grid is allocated
    ("nx 1e308\nny 2\nx0 0\ny0 0\ndx 1\ndy 1\n1 2\n", "at most 100,000 points"),  # was OverflowError
    ("nx 100000\nny 100000\nx0 0\ny0 0\ndx 1\ndy 1\n1 2\n", "at most 100,000 points"),  # was 80 GB
    ("nx nan\nny 1\nx0 0\ny0 0\ndx 1\ndy 1\n1 2\n", "nX, nY whole numbers"),  # was ValueError
    ("nx 2.5\nny 1\nx0 0\ny0 0\ndx 1\ndy 1\n1 2\n", "nX, nY whole numbers"),
    ("nx 2\nny 1\nx0 0\ny0 0\ndx 0\ndy 1\n1 2\n", "grid sizes must be above 0"),
    ("nx 2\nny 1\nx0 nan\ny0 0\ndx 1\ndy 1\n1 2\n", "x0 and y0 must be numbers"),
])
def test_a_broken_table_file_is_an_error_naming_the_file(tmp_path: Path, text: str, message: str) -> None:
    path = tmp_path / "t.txt"
    path.write_text(text)
    with pytest.raises(HeightMapError) as info:
        ZhcTable.load(path)
    assert message in info.value.message and str(path) in info.value.format()


def test_surface_csv_with_header_comments_and_crlf(tmp_path: Path) -> None:
    path = tmp_path / "surface.csv"
    path.write_bytes(b"x,y,z\r\n# probed 2026-01-01\r\n0,0,0\r\n10,0,1\r\n0,10,0.5\r\n10,10,1.5\r\n")
    surface = read_surface(path)
    assert surface.height(5, 5) == pytest.approx(0.75)


@pytest.mark.parametrize("text, message", [
    ("0,0,0\n10,0,1\n0,10,2\n", "no height at x=10 y=10"),
    ("0,0\n", "expected x,y,z"),
    ("", "no points"),
])
def test_a_surface_that_is_not_a_full_grid_is_refused(tmp_path: Path, text: str, message: str) -> None:
    path = tmp_path / "s.csv"
    path.write_text(text)
    with pytest.raises(HeightMapError, match=message):
        read_surface(path)


def test_probe_trips_where_it_meets_the_surface() -> None:
    probe = ProbeAt(TILTED)
    trip = probe((15.0, 5.0, 10.0, 0, 0, 0), (15.0, 5.0, -10.0, 0, 0, 0))
    assert trip is not None and trip[2] == pytest.approx(1.75, abs=1e-9)
    assert probe((15.0, 5.0, 10.0, 0, 0, 0), (15.0, 5.0, 5.0, 0, 0, 0)) is None  # stops above it
    sideways = probe((-5.0, 5.0, 1.0, 0, 0, 0), (25.0, 5.0, 1.0, 0, 0, 0))  # runs into the rising surface
    assert sideways is not None and sideways[0] == pytest.approx(7.5, abs=1e-9)
