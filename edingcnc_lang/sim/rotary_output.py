"""The part a bar on a rotary axis became (``ecnc sim --stock cylinder:``): a closed STL mesh of
its radii field, a shaded 3D view of it (the second panel of ``-o``), and its deviation from the
intended part (``--compare-stl``).

Both read the surface at the grid's vertices (slice edges along the axis, angle-cell edges around
it): a vertex's radius is the root of the mean square of the radii of the cells that meet there,
so the mesh keeps the cut's volume to within the discretisation.  Coordinates are the job's work
coordinates with the bar at A0 (B0): along X, Y the radius's cosine, Z its sine (the bar along Y
for B: X is minus the cosine).
"""
from __future__ import annotations

import math
from collections.abc import Iterator
from pathlib import Path
from typing import Any

import numpy as np

from edingcnc_lang.errors import Location
from edingcnc_lang.sim.compare import Deviation
from edingcnc_lang.sim.round_stock import RoundStock
from edingcnc_lang.sim.stl import StlError, raster_top, read_stl
from edingcnc_lang.sim.stock import Stock

VIEW_CELLS = 180  # vertices along each side of the shaded view at most (mplot3d draws each facet)


def vertex_radii(field: np.ndarray) -> np.ndarray:
    """(slices + 1, angles) radii at the grid's vertices, angle vertex k between cells k - 1 and k
    (the angle wraps round), from the (slices, angles) cell radii."""
    square = field.astype(np.float64) ** 2
    around = (square + np.roll(square, 1, axis=1)) / 2.0  # at each angle edge, per slice
    padded = np.vstack((around[:1], around, around[-1:]))
    return np.sqrt((padded[:-1] + padded[1:]) / 2.0)


def _points(stock: RoundStock, radii: np.ndarray, axis: str, rows: np.ndarray | None = None,
            columns: np.ndarray | None = None) -> np.ndarray:
    """(rows, angles, 3) work coordinates of vertex radii at slice edges ``rows`` and angle edges
    ``columns`` (default: all of them, in order)."""
    rows = np.arange(radii.shape[0]) if rows is None else rows
    columns = np.arange(radii.shape[1]) if columns is None else columns
    edges = stock.start + rows * stock.resolution
    theta = np.radians(columns * stock.angle_step())
    along = np.broadcast_to(edges[:, None], radii.shape)
    p, q = radii * np.cos(theta), radii * np.sin(theta)
    return np.stack((-p, along, q) if axis == "B" else (along, p, q), axis=-1)


def rotary_mesh(stock: RoundStock, axis: str = "A") -> Iterator[np.ndarray]:
    """The part as (N, 3, 3) float32 triangles, outward normals, closed: the outer surface, the bore
    (when the inner radii are not all 0) and the two end faces."""
    outer = _points(stock, vertex_radii(stock.outer), axis)
    bored = bool(stock.inner.any())
    for row in range(outer.shape[0] - 1):  # a band at a time: memory stays small
        yield _band(outer[row], outer[row + 1], outward=True)
    ends = []
    if bored:
        inner = _points(stock, vertex_radii(stock.inner), axis)
        for row in range(inner.shape[0] - 1):
            yield _band(inner[row], inner[row + 1], outward=False)
        ends = [_ring(outer[0], inner[0], first=True), _ring(outer[-1], inner[-1], first=False)]
    else:
        centres = _points(stock, np.zeros((len(outer), 1)), axis)[[0, -1], 0]
        ends = [_fan(outer[0], centres[0], first=True), _fan(outer[-1], centres[1], first=False)]
    for end in ends:
        yield end


def _band(a: np.ndarray, b: np.ndarray, outward: bool) -> np.ndarray:
    """Quads between vertex rows ``a`` and ``b`` (one slice apart), round the axis."""
    a1, b1 = np.roll(a, -1, axis=0), np.roll(b, -1, axis=0)
    first, second = (np.stack((a, b1, b), axis=1), np.stack((a, a1, b1), axis=1)) if outward else \
        (np.stack((a, b, b1), axis=1), np.stack((a, b1, a1), axis=1))
    return _kept(np.concatenate((first, second)))


def _fan(row: np.ndarray, centre: np.ndarray, first: bool) -> np.ndarray:
    """An end face of a solid bar: triangles from its centre, facing away from the part."""
    nxt = np.roll(row, -1, axis=0)
    c = np.broadcast_to(centre, row.shape)
    return _kept(np.stack((c, nxt, row) if first else (c, row, nxt), axis=1))


def _ring(outer: np.ndarray, inner: np.ndarray, first: bool) -> np.ndarray:
    """An end face of a bored bar, between the bore and the outside."""
    o1, i1 = np.roll(outer, -1, axis=0), np.roll(inner, -1, axis=0)
    one, two = (np.stack((inner, o1, outer), axis=1), np.stack((inner, i1, o1), axis=1)) if first else \
        (np.stack((inner, outer, o1), axis=1), np.stack((inner, o1, i1), axis=1))
    return _kept(np.concatenate((one, two)))


def _kept(triangles: np.ndarray) -> np.ndarray:
    area = np.linalg.norm(np.cross(triangles[:, 1] - triangles[:, 0], triangles[:, 2] - triangles[:, 0]), axis=1)
    return triangles[area > 1e-12].astype(np.float32)


def draw_shaded(ax: Any, stock: RoundStock, axis: str) -> None:
    """The part in 3D on ``ax`` (a 3D axes), lit from the upper left and coloured by the depth below
    the bar's surface, at most ``VIEW_CELLS`` vertices a side."""
    from matplotlib import colormaps
    from matplotlib.colors import LightSource, Normalize

    radii = vertex_radii(stock.outer)
    step = max(1, math.ceil(max(radii.shape) / VIEW_CELLS))
    rows = np.unique(np.r_[np.arange(0, radii.shape[0], step), radii.shape[0] - 1])
    columns = np.r_[np.arange(0, radii.shape[1], step), radii.shape[1]]  # the last is the first, 360° on
    radii = radii[rows][:, columns % radii.shape[1]]
    points = _points(stock, radii, axis, rows, columns)
    depth = stock.radius - radii[:-1, :-1]
    colours = colormaps["magma_r"](Normalize(0.0, max(float(depth.max()), 1e-6))(depth))
    ax.plot_surface(points[..., 0], points[..., 1], points[..., 2], facecolors=colours, shade=True,
                    lightsource=LightSource(azdeg=315, altdeg=35), linewidth=0, antialiased=False,
                    rcount=points.shape[0], ccount=points.shape[1])
    span = max(stock.length, 2 * stock.radius) / 2.0
    middle = stock.start + stock.length / 2.0
    centre = (0.0, middle, 0.0) if axis == "B" else (middle, 0.0, 0.0)
    for setter, c in zip((ax.set_xlim, ax.set_ylim, ax.set_zlim), centre):
        setter(c - span, c + span)
    ax.set_box_aspect((1, 1, 1), zoom=1.25)
    ax.set_xlabel("X mm")
    ax.set_ylabel("Y mm")
    ax.set_zlabel("Z mm")
    ax.view_init(elev=25, azim=-60)


def compare_rotary(stock: RoundStock, part: str | Path, axis: str = "A") -> Deviation:
    """The cut bar against the intended part (an STL in work coordinates at A0/B0, as ``--stl``
    writes it; ``axis`` "Z": a lathe's bar, the part about the Z axis, its one angle cell the whole
    turn, so the part's outermost radius over each slice is its profile): the part unrolled to (axial position, the bar's angle, radius) and its outermost
    radius over each cell found as ``compare`` finds a part's top (``stl.raster_top``); the
    deviation is the bar's outer radius less the part's, over the cells the part covers."""
    triangles = _unrolled(_fine(read_stl(part).astype(np.float64), stock.angle_step(), axis), axis)
    scale = stock.resolution / stock.angle_step()  # an angle cell as tall as a slice is long
    triangles[:, :, 1] *= scale
    grid = Stock(stock.start, 0.0, stock.resolution, 0.0, stock.radius,
                 np.zeros((stock.shape[1], stock.shape[0]), np.float32))
    top, covered = raster_top(grid, triangles)
    if not covered.any():
        raise StlError("the part does not lie along the bar (no cell of the bar is under it)", Location(str(part)))
    deviation = np.where(covered.T, stock.outer.astype(np.float64) - top.T, np.nan)
    values = deviation[covered.T]
    return Deviation(str(part), deviation, max(0.0, -float(values.min())), max(0.0, float(values.max())),
                     float(np.abs(values).mean()), int(covered.sum()))


def _polar(triangles: np.ndarray, axis: str) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Axial position, the bar's own angle (degrees, 0..360) and radius of each vertex."""
    x, y, z = triangles[..., 0], triangles[..., 1], triangles[..., 2]
    along, p, q = (z, x, y) if axis == "Z" else (y, -x, z) if axis == "B" else (x, y, z)
    return along, np.degrees(np.arctan2(q, p)) % 360.0, np.hypot(p, q)


def _fine(triangles: np.ndarray, step: float, axis: str, rounds: int = 10) -> np.ndarray:
    """Triangles split in four (at their edges' midpoints, in space) until none spans more than an
    angle cell around the axis: between its corners a facet's radius is then near linear in the angle."""
    for _ in range(rounds):
        _, angle, radius = _polar(triangles, axis)
        spread = np.ptp(angle, axis=1)
        spread = np.minimum(spread, 360.0 - spread)  # across the seam at 0 degrees
        wide = (spread > step) & (radius.min(axis=1) > 1e-9)  # a fan's centre on the axis has no angle
        if not wide.any():
            break
        a, b, c = (triangles[wide, k] for k in range(3))
        ab, bc, ca = (a + b) / 2, (b + c) / 2, (c + a) / 2
        split = np.concatenate([np.stack(t, axis=1) for t in ((a, ab, ca), (ab, b, bc), (ca, bc, c), (ab, bc, ca))])
        triangles = np.concatenate((triangles[~wide], split))
    return triangles


def _unrolled(triangles: np.ndarray, axis: str) -> np.ndarray:
    """(axial, angle, radius) triangles; one across the seam at 0 degrees is put on both sides of it
    (its low corners 360 up, and a copy 360 down), so each side's cells see it."""
    along, angle, radius = _polar(triangles, axis)
    seam = np.ptp(angle, axis=1) > 180.0
    angle = np.where(seam[:, None] & (angle < 180.0), angle + 360.0, angle)
    flat = np.stack((along, angle, radius), axis=-1)
    below = flat[seam].copy()
    below[:, :, 1] -= 360.0
    return np.concatenate((flat, below))
