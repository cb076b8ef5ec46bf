"""STL out and in: the cut stock as a closed mesh of the right volume; a mesh as stock; the deviation."""
from __future__ import annotations

from collections import Counter

import numpy as np
import pytest

from edingcnc_lang.sim import Stock, Tool
from edingcnc_lang.sim.compare import compare
from edingcnc_lang.sim.stl import StlError, read_stl, stock_from_stl, stock_mesh, write_stl

from .jobs import cut


def mesh_volume(triangles: np.ndarray) -> float:
    """Divergence theorem: the signed volume of a closed, outward-facing mesh."""
    return float(np.einsum("ij,ij->i", triangles[:, 0], np.cross(triangles[:, 1], triangles[:, 2])).sum() / 6.0)


def pocket() -> Stock:
    stock = Stock.box((0, 0, -5), (10, 8, 0), 0.5)
    stock.top[3:6, 4:10] = -2.0
    return stock


@pytest.mark.parametrize("band", [256, 3])  # written whole, or a few rows at a time
def test_the_mesh_is_closed_faces_out_and_holds_the_stock(tmp_path, band):
    stock = pocket()
    write_stl(tmp_path / "part.stl", stock_mesh(stock, band))
    triangles = read_stl(tmp_path / "part.stl")
    edges: Counter[tuple[tuple[float, ...], tuple[float, ...]]] = Counter()
    for tri in triangles.round(6):
        for k in range(3):
            edges[(tuple(tri[k]), tuple(tri[(k + 1) % 3]))] += 1
    assert all(edges[(b, a)] == count for (a, b), count in edges.items())  # every edge met once each way
    # the cells' columns are the volume; the mesh through the cell centres differs by the slopes between
    assert mesh_volume(triangles) == pytest.approx(stock.remaining_volume, rel=0.02)
    assert (tmp_path / "part.stl").stat().st_size == 84 + 50 * len(triangles)


def test_a_mesh_read_back_as_stock_gives_the_same_heights(tmp_path):
    write_stl(tmp_path / "part.stl", stock_mesh(pocket()))
    again = stock_from_stl(tmp_path / "part.stl", 0.5)
    assert again.shape == pocket().shape
    assert np.allclose(again.top, pocket().top, atol=1e-5)


def test_ascii_stl_and_bad_files(tmp_path):
    ascii_stl = tmp_path / "tri.stl"
    ascii_stl.write_text("solid t\n facet normal 0 0 1\n  outer loop\n   vertex 0 0 1\n   vertex 4 0 1\n"
                         "   vertex 0 4 1\n  endloop\n endfacet\nendsolid t\n")
    stock = Stock.box((0, 0, 0), (4, 4, 2), 0.5)
    assert read_stl(ascii_stl).shape == (1, 3, 3)
    result = compare(stock, ascii_stl)
    assert result.cells == 36  # centres (i + 0.5, j + 0.5) / 2 with x + y <= 4: i + j <= 7, 8 + 7 + ... + 1
    assert result.max_undercut == pytest.approx(1.0)
    (tmp_path / "bad.stl").write_bytes(b"not a mesh at all")
    with pytest.raises(StlError, match="not an STL file"):
        read_stl(tmp_path / "bad.stl")


def test_compare_finds_the_gouge_and_the_material_left(tmp_path):
    intended = Stock.box((0, 0, -10), (40, 30, 0), 0.25)
    # the part: a 2 mm deep slot 6 wide from X10 to X30 (with round ends); we cut 2.5 deep
    result = cut(tmp_path, "G0 X10 Y15\nG1 Z-2.5 F300\nG1 X30\nG0 Z5", Tool(0, "flat", 6.0), resolution=0.25)
    part = cut(tmp_path, "G0 X10 Y15\nG1 Z-2 F300\nG1 X30\nG0 Z5", Tool(0, "flat", 6.0), resolution=0.25)
    write_stl(tmp_path / "part.stl", stock_mesh(part.stock))
    deviation = compare(result.stock, tmp_path / "part.stl")
    assert deviation.max_overcut == pytest.approx(0.5, abs=1e-4)
    assert deviation.max_undercut < 2.1  # the mesh's slope across one cell at the slot's wall
    assert deviation.cells == intended.shape[0] * intended.shape[1]
