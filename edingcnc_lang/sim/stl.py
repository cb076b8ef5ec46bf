"""STL in and out: the cut stock as a closed mesh, and a mesh's top surface as a height field.

Written as binary STL with numpy (two triangles per cell on the top, the four walls and a fanned
bottom, so the mesh is closed), a band of rows at a time; 50 bytes a triangle, so about 100 bytes
per cell on disk (1.6 GB for a 1 m x 1 m table at 0.25 mm: mesh a coarser --resolution).  Read: binary or
ASCII; only the surface seen from above is kept (a height field holds no undercuts).
"""
from __future__ import annotations

import re
from collections.abc import Iterable, Iterator
from pathlib import Path

import numpy as np

from edingcnc_lang.errors import EXIT_USAGE, EcncError, Location
from edingcnc_lang.sim.stock import Stock, grid_size
from edingcnc_lang.sim.sweep import MAX_PAIRS, footprint_cells, pair_counts
from edingcnc_lang.outputs import replacing
from edingcnc_lang.syntax.input_limits import MAX_SIM_LENGTH

TRIANGLE = np.dtype([("normal", "<f4", (3,)), ("vertices", "<f4", (3, 3)), ("attribute", "<u2")])
_VERTEX = re.compile(rb"vertex\s+(\S+)\s+(\S+)\s+(\S+)")


class StlError(EcncError):
    """An STL file that cannot be read as a mesh: the user's input (exit 2)."""

    exit_code = EXIT_USAGE
    kind = "usage"


def read_stl(path: str | Path) -> np.ndarray:
    """The triangles of an STL file, (N, 3, 3) float64; binary and ASCII alike.  A mesh without
    triangles, or with a coordinate that is not a number or lies beyond MAX_SIM_LENGTH, is refused
    (the stock and the part alike: a NaN triangle was dropped from the part without a word)."""
    triangles = _triangles(path)
    if not len(triangles) or not (np.abs(triangles) <= MAX_SIM_LENGTH).all():
        raise StlError(f"the mesh has no triangles, or a coordinate that is not a number or lies beyond "
                       f"{MAX_SIM_LENGTH:g} mm", Location(str(path)))
    return triangles


def _triangles(path: str | Path) -> np.ndarray:
    where = Location(str(path))
    try:
        data = Path(path).read_bytes()
    except OSError as err:
        raise StlError(f"cannot read: {err.strerror or err}", where) from None
    if len(data) >= 84:
        count = int(np.frombuffer(data, "<u4", 1, 80)[0])
        if len(data) == 84 + 50 * count:
            return np.frombuffer(data, TRIANGLE, count, 84)["vertices"].astype(np.float64)
    if data.lstrip()[:5].lower() == b"solid":
        try:
            points = np.array(_VERTEX.findall(data), dtype=np.float64)
        except ValueError:
            raise StlError("an ASCII STL vertex is not three numbers", where) from None
        if len(points) and len(points) % 3 == 0:
            return points.reshape(-1, 3, 3)
    raise StlError("not an STL file (neither binary with a matching triangle count, nor ASCII with facets)", where)


def stock_from_stl(path: str | Path, resolution: float) -> Stock:
    """A stock shaped like the mesh seen from above: its top surface over its bounding box; cells
    the mesh does not cover hold no material."""
    triangles = read_stl(path)
    lower, upper = triangles.reshape(-1, 3).min(axis=0), triangles.reshape(-1, 3).max(axis=0)
    nx, ny = grid_size(tuple(lower), tuple(upper), resolution)  # type: ignore[arg-type]
    empty = np.full((ny, nx), lower[2], dtype=np.float32)
    stock = Stock(float(lower[0]), float(lower[1]), resolution, float(lower[2]), float(upper[2]), empty)
    top, covered = raster_top(stock, triangles)
    stock.top = np.where(covered, np.maximum(top, stock.bottom), stock.bottom).astype(np.float32)
    stock.initial = stock.top.copy()
    return stock


def raster_top(stock: Stock, triangles: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """The highest point of the mesh over each cell centre of the stock's grid, and which cells the
    mesh covers at all; walls (triangles seen edge-on from above) add nothing."""
    ny, nx = stock.shape
    top = np.full(ny * nx, -np.inf)
    xy = triangles[:, :, :2]
    area = ((xy[:, 1, 0] - xy[:, 0, 0]) * (xy[:, 2, 1] - xy[:, 0, 1])
            - (xy[:, 2, 0] - xy[:, 0, 0]) * (xy[:, 1, 1] - xy[:, 0, 1]))
    tris = triangles[np.abs(area) > 1e-12]
    low, high = tris.min(axis=1), tris.max(axis=1)
    counts = pair_counts(stock, low, high, 0.0)
    bounds = np.searchsorted(np.cumsum(counts), np.arange(MAX_PAIRS, int(counts.sum()), MAX_PAIRS))
    for chosen in np.split(np.arange(len(tris)), np.unique(np.maximum(bounds, 1))):
        tri, cell = footprint_cells(stock, low[chosen], high[chosen], 0.0)
        v = tris[chosen][tri]
        px = stock.x0 + (cell % nx + 0.5) * stock.resolution
        py = stock.y0 + (cell // nx + 0.5) * stock.resolution
        (x0, y0, z0), (x1, y1, z1), (x2, y2, z2) = (v[:, k].T for k in range(3))
        d = (y1 - y2) * (x0 - x2) + (x2 - x1) * (y0 - y2)
        l0 = ((y1 - y2) * (px - x2) + (x2 - x1) * (py - y2)) / d
        l1 = ((y2 - y0) * (px - x2) + (x0 - x2) * (py - y2)) / d
        l2 = 1.0 - l0 - l1
        inside = (l0 >= -1e-9) & (l1 >= -1e-9) & (l2 >= -1e-9)
        np.maximum.at(top, cell[inside], (l0 * z0 + l1 * z1 + l2 * z2)[inside])
    covered = np.isfinite(top)
    return top.reshape(ny, nx), covered.reshape(ny, nx)


def stock_mesh(stock: Stock, band: int = 256) -> Iterator[np.ndarray]:
    """The cut stock as closed triangles, (N, 3, 3) float32 arrays a band of rows at a time (so a
    large field is never a mesh in memory at once): the top through the cell centres (the outer
    row moved out to the box's edge), four walls down to the bottom, a bottom fanned from its centre."""
    ny, nx = stock.shape
    if nx < 2 or ny < 2:
        raise EcncError("the stock needs at least 2 x 2 cells for a mesh: use a finer --resolution")
    x0, y0, _z0, x1, y1, _z1 = stock.box_bounds
    xs, ys = stock.xs(), stock.ys()
    xs[0], xs[-1], ys[0], ys[-1] = x0, x1, y0, y1

    def rows(first: int, last: int) -> np.ndarray:
        gx, gy = np.meshgrid(xs, ys[first:last])
        return np.stack((gx, gy, stock.top[first:last]), axis=-1).astype(np.float32)  # (rows, nx, 3)

    for first in range(0, ny - 1, band):
        top = rows(first, min(first + band + 1, ny))
        a, b, c, d = top[:-1, :-1], top[:-1, 1:], top[1:, 1:], top[1:, :-1]
        yield np.concatenate((np.stack((a, b, c), axis=-2).reshape(-1, 3, 3),
                              np.stack((a, c, d), axis=-2).reshape(-1, 3, 3)))
    front, back = rows(0, 1)[0], rows(ny - 1, ny)[0]
    left = np.stack((np.full(ny, x0), ys, stock.top[:, 0]), axis=-1).astype(np.float32)
    right = np.stack((np.full(ny, x1), ys, stock.top[:, -1]), axis=-1).astype(np.float32)
    ring = np.concatenate((front, right[1:], back[-2::-1], left[-2:0:-1]))  # counter-clockwise from above
    ring = np.vstack((ring, ring[:1]))
    floor = ring.copy()
    floor[:, 2] = stock.bottom
    upper, lower = ring[:-1], ring[1:]
    centre = np.array([(x0 + x1) / 2.0, (y0 + y1) / 2.0, stock.bottom], dtype=np.float32)
    yield np.concatenate((np.stack((upper, floor[:-1], floor[1:]), axis=1),
                          np.stack((upper, floor[1:], lower), axis=1),
                          np.stack((np.broadcast_to(centre, floor[:-1].shape), floor[1:], floor[:-1]), axis=1)))


def write_stl(path: str | Path, chunks: Iterable[np.ndarray], name: str = "ecnc sim") -> None:
    """Binary STL of (N, 3, 3) triangle arrays, written as they come; normals from the vertex
    order (counter-clockwise seen from outside)."""
    count = 0
    with replacing(path, binary=True) as handle:
        handle.write(name.encode("ascii", "replace")[:80].ljust(80, b" "))
        handle.write(b"\0\0\0\0")  # the count, once known
        for triangles in chunks:
            normal = np.cross(triangles[:, 1] - triangles[:, 0], triangles[:, 2] - triangles[:, 0])
            length = np.linalg.norm(normal, axis=1, keepdims=True)
            records = np.zeros(len(triangles), dtype=TRIANGLE)
            records["normal"] = np.divide(normal, length, out=np.zeros_like(normal), where=length > 0)
            records["vertices"] = triangles
            handle.write(records.tobytes())
            count += len(records)
        handle.seek(80)
        handle.write(np.uint32(count).tobytes())
