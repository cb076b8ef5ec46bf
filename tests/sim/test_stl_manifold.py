"""The STL of the cut stock is a closed, manifold solid whatever was cut: through the stock's edge,
a through-hole, nothing left at all. Checked on the file as written, with our own edge count and
with trimesh (an independent mesh library), and its volume against the simulation's."""
from __future__ import annotations

from collections import Counter
from pathlib import Path

import numpy as np
import pytest

from edingcnc_lang.sim import Stock, Tool
from edingcnc_lang.sim.stl import read_stl, stock_from_stl, stock_mesh, write_stl

from .jobs import cut
from .test_stl import mesh_volume

EDGE_SLOT = "G0 X-5 Y10\nG1 Z-3 F300\nG1 X45\nG0 Z5"            # across the whole stock, 3 deep
THROUGH_HOLE = "G0 X20 Y15\nG1 Z-12 F300\nG0 Z5"                   # a plunge through the 10 mm stock
EDGE_THROUGH = "G0 X-5 Y0\nG1 Z-12 F300\nG1 X20\nG0 Z5"             # a through-slot along the front edge
BOX = (0, 0, -10, 40, 30, 0)


def check_closed(triangles: np.ndarray) -> None:
    """Every edge is met by exactly two triangles, once each way round, and no triangle is flat."""
    rounded = [tuple(map(tuple, tri)) for tri in triangles.round(5)]
    directed: Counter[tuple[tuple[float, ...], tuple[float, ...]]] = Counter()
    for tri in rounded:
        for k in range(3):
            directed[(tri[k], tri[(k + 1) % 3])] += 1
    assert max(directed.values()) == 1, "an edge used twice in the same direction"
    assert all((b, a) in directed for a, b in directed), "an edge with one triangle: the mesh is open"
    areas = np.linalg.norm(np.cross(triangles[:, 1] - triangles[:, 0], triangles[:, 2] - triangles[:, 0]), axis=1)
    assert areas.min() > 1e-9


def with_trimesh(path: Path, volume: float) -> None:
    trimesh = pytest.importorskip("trimesh")
    mesh = trimesh.load_mesh(str(path), process=True)
    assert mesh.is_watertight and mesh.is_winding_consistent and mesh.is_volume
    assert mesh.volume == pytest.approx(volume, rel=1e-6)


@pytest.mark.parametrize("body", [EDGE_SLOT, THROUGH_HOLE, EDGE_THROUGH], ids=["edge slot", "through hole", "edge through"])
@pytest.mark.parametrize("band", [256, 7])
def test_cut_stock_is_a_closed_manifold_solid(tmp_path: Path, body: str, band: int) -> None:
    result = cut(tmp_path, body, Tool(0, "flat", 6.0), box=BOX, resolution=0.5)
    path = tmp_path / "cut.stl"
    write_stl(path, stock_mesh(result.stock, band))
    triangles = read_stl(path)
    check_closed(triangles)
    volume = mesh_volume(triangles)
    with_trimesh(path, volume)
    # the mesh runs through the cell centres; the simulation sums the cells' columns: they differ by
    # the slopes between centres, and at an opening by the half cell the cut at the midpoints leaves out
    assert volume == pytest.approx(result.stock.remaining_volume, rel=0.01)
    assert volume < result.stock.initial_volume


def test_a_through_hole_is_an_opening_not_a_skin(tmp_path: Path) -> None:
    result = cut(tmp_path, THROUGH_HOLE, Tool(0, "flat", 6.0), box=BOX, resolution=0.5)
    triangles = read_stl_of(tmp_path, result.stock)
    centre = np.array([20.0, 15.0])
    distance = np.linalg.norm(triangles.mean(axis=1)[:, :2] - centre, axis=1)
    flat = np.abs(np.cross(triangles[:, 1] - triangles[:, 0], triangles[:, 2] - triangles[:, 0])[:, 2]) > 1e-9
    assert not (flat & (distance < 2.5)).any()  # inside the 6 mm hole no face lies flat, top or bottom
    assert (~flat & (distance < 3.5)).any()  # the hole's walls stand around it
    trimesh = pytest.importorskip("trimesh")
    mesh = trimesh.load_mesh(str(tmp_path / "cut.stl"))
    assert mesh.euler_number == 0  # a solid with one hole through it (a torus): genus 1


def read_stl_of(folder: Path, stock: Stock) -> np.ndarray:
    write_stl(folder / "cut.stl", stock_mesh(stock))
    return read_stl(folder / "cut.stl")


def test_nothing_left_is_an_empty_mesh_and_islands_stay_apart(tmp_path: Path) -> None:
    stock = Stock.box((0, 0, -5), (10, 10, 0), 0.5)
    stock.top[:] = -5.0
    assert sum(len(part) for part in stock_mesh(stock)) == 0  # (read_stl refuses an empty mesh as an input)
    stock.top[4, 4] = stock.top[5, 5] = -1.0  # two posts meeting only diagonally
    triangles = read_stl_of(tmp_path, stock)
    check_closed(triangles)
    assert mesh_volume(triangles) > 0


def test_a_stock_read_back_has_its_openings(tmp_path: Path) -> None:
    result = cut(tmp_path, EDGE_THROUGH, Tool(0, "flat", 6.0), box=BOX, resolution=0.5)
    read_stl_of(tmp_path, result.stock)
    again = stock_from_stl(tmp_path / "cut.stl", 0.5)
    assert again.shape == result.stock.shape
    opened = result.stock.top - result.stock.bottom <= 1e-3
    assert opened.any() and np.allclose(again.top[opened], again.bottom)
    assert np.allclose(again.top[~opened], result.stock.top[~opened], atol=1e-4)
