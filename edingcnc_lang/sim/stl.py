"""STL in and out: the cut stock as a closed mesh, and a mesh's top surface as a height field.

Written as binary STL with numpy (two triangles per cell on the top, two under it on the bottom, and
walls on the box's edge and around every opening, so the mesh is closed and manifold), a band of rows
at a time; 50 bytes a triangle, so about 200 bytes per cell on disk (3.2 GB for a 1 m x 1 m table at
0.25 mm: mesh a coarser --resolution).  Read: binary or
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
    nx, ny = grid_size(tuple(lower), tuple(upper), resolution)
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


OPENING = 1e-3  # mm: a cell centre with less material than this over the bottom is an opening


def stock_mesh(stock: Stock, band: int = 256) -> Iterator[np.ndarray]:
    """The cut stock as a closed, manifold solid: (N, 3, 3) float32 triangle arrays, a band of rows
    at a time (so a large field is never a mesh in memory at once).

    The top runs through the cell centres (the outer row moved out to the box's edge), two triangles
    a cell; the material is where a centre has more than ``OPENING`` over the bottom.  A triangle
    with a centre of no material is cut at its edges' midpoints (marching triangles: one way to cut
    each, so no ambiguous case), and a wall stands on every cut and on the box's edge down to a
    bottom that mirrors the top: a cut through the stock's edge or a through-hole is a real opening,
    every edge belongs to two triangles, and no face has zero thickness behind it.
    """
    ny, nx = stock.shape
    if nx < 2 or ny < 2:
        raise EcncError("the stock needs at least 2 x 2 cells for a mesh: use a finer --resolution")
    x0, y0, _z0, x1, y1, _z1 = stock.box_bounds
    xs, ys = stock.xs(), stock.ys()
    xs[0], xs[-1], ys[0], ys[-1] = x0, x1, y0, y1
    bottom = float(stock.bottom)

    def rows(first: int, last: int) -> tuple[np.ndarray, np.ndarray]:
        """The top's points of rows first..last-1, (rows, nx, 3) float32 as written, and which hold material."""
        gx, gy = np.meshgrid(xs, ys[first:last])
        heights = stock.top[first:last]
        return (np.stack((gx, gy, heights), axis=-1).astype(np.float32),
                heights.astype(np.float64) - bottom > OPENING)

    for first in range(0, ny - 1, band):
        last = min(first + band + 1, ny)
        points, solid = rows(first, last)
        a, b, c, d = (points[:-1, :-1], points[:-1, 1:], points[1:, 1:], points[1:, :-1])
        fa, fb, fc, fd = (solid[:-1, :-1], solid[:-1, 1:], solid[1:, 1:], solid[1:, :-1])
        triangles = np.concatenate((np.stack((a, b, c), axis=-2).reshape(-1, 3, 3),
                                    np.stack((a, c, d), axis=-2).reshape(-1, 3, 3)))
        inside = np.concatenate((np.stack((fa, fb, fc), axis=-1).reshape(-1, 3),
                                 np.stack((fa, fc, fd), axis=-1).reshape(-1, 3)))
        top, cuts = _clip(triangles, inside)
        edges = [cuts, *(_rim(points[:, k], solid[:, k], forward) for k, forward in ((-1, True), (0, False)))]
        if first == 0:
            edges.append(_rim(points[0], solid[0], True))
        if last == ny:
            edges.append(_rim(points[-1], solid[-1], False))
        yield _solid(top, np.concatenate(edges), bottom)


def _mid(p: np.ndarray, q: np.ndarray) -> np.ndarray:
    """Where a cut crosses the edge p-q: its midpoint (the same bits from either triangle of the edge:
    float32 addition is commutative, and halving exact)."""
    return (p + q) * np.float32(0.5)


def _clip(triangles: np.ndarray, inside: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """The parts of counter-clockwise triangles over material, and the cuts as edges (N, 2, 3)
    directed with the material on their left."""
    count = inside.sum(axis=1)
    kept = [triangles[count == 3]]
    cuts = []
    for alone, pick in ((1, np.argmax), (2, np.argmin)):  # the one vertex inside / the one outside
        chosen = count == alone
        turn = (pick(inside[chosen], axis=1)[:, None] + np.arange(3)) % 3
        p0, p1, p2 = np.moveaxis(np.take_along_axis(triangles[chosen], turn[:, :, None], axis=1), 1, 0)
        m01, m20 = _mid(p0, p1), _mid(p2, p0)
        if alone == 1:
            kept.append(np.stack((p0, m01, m20), axis=1))
            cuts.append(np.stack((m01, m20), axis=1))
        else:
            kept += [np.stack((m01, p1, p2), axis=1), np.stack((m01, p2, m20), axis=1)]
            cuts.append(np.stack((m20, m01), axis=1))
    return np.concatenate(kept), np.concatenate(cuts)


def _rim(line: np.ndarray, solid: np.ndarray, forward: bool) -> np.ndarray:
    """The parts over material of a run of points on the box's edge, as edges (N, 2, 3) directed
    counter-clockwise around the box (``forward``: in the run's order)."""
    if not forward:
        line, solid = line[::-1], solid[::-1]
    p, q, fp, fq = line[:-1], line[1:], solid[:-1], solid[1:]
    half = _mid(p, q)
    return np.concatenate((np.stack((p, q), axis=1)[fp & fq], np.stack((p, half), axis=1)[fp & ~fq],
                           np.stack((half, q), axis=1)[~fp & fq]))


def _solid(top: np.ndarray, edges: np.ndarray, bottom: float) -> np.ndarray:
    """The top triangles, the bottom under them facing down, and a wall down from each edge."""
    floor = top[:, ::-1].copy()
    floor[..., 2] = bottom
    p, q = edges[:, 0], edges[:, 1]
    pb, qb = p.copy(), q.copy()
    pb[:, 2] = qb[:, 2] = bottom
    walls = np.concatenate((np.stack((pb, qb, q), axis=1), np.stack((pb, q, p), axis=1)))
    return np.concatenate((top, floor, walls))


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
