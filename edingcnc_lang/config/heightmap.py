"""Height maps: a rectilinear grid of Z heights, bilinear between its nodes.

Two features stand on this model: Z height compensation (ZHC: the table the
``zhcmgrid`` macro probes, saved by ``ZHCS`` and read back by ``ZHCL``) and
``ecnc run --probe-surface`` (a CSV surface that makes G38.2 trip where the
probe meets it).  Outside the grid the nearest border value holds, so a move
that leaves the probed area keeps the last known height instead of a guess.
"""
from __future__ import annotations

import csv
import math
import os
from bisect import bisect_right
from collections.abc import Sequence
from dataclasses import dataclass

from edingcnc_lang.canon import Pose
from edingcnc_lang.errors import EcncError, Location, shortened
from edingcnc_lang.syntax.input_limits import MAX_HEIGHT_MAP_VALUE, MAX_ZHC_POINTS
from edingcnc_lang.syntax.source import plain_float
from edingcnc_lang.records import record
from edingcnc_lang.outputs import write_text

TABLE_HEADER = "; ecnc ZHC height table"
_TABLE_KEYS = ("nx", "ny", "x0", "y0", "dx", "dy")


class HeightMapError(EcncError):
    """A height map file that cannot be read (names the file and line)."""


@record(frozen=True)
class HeightMap:
    """Heights ``z[j][i]`` at the nodes (xs[i], ys[j]); xs and ys strictly increase."""

    xs: tuple[float, ...]
    ys: tuple[float, ...]
    z: tuple[tuple[float, ...], ...]

    def height(self, x: float, y: float) -> float:
        """The bilinear height at (x, y), clamped to the border outside the grid."""
        i, u = _cell(self.xs, x)
        j, v = _cell(self.ys, y)
        z = self.z
        i1, j1 = min(i + 1, len(self.xs) - 1), min(j + 1, len(self.ys) - 1)
        low = z[j][i] * (1 - u) + z[j][i1] * u
        high = z[j1][i] * (1 - u) + z[j1][i1] * u
        return low * (1 - v) + high * v

    def crossings(self, a: Sequence[float], b: Sequence[float]) -> list[float]:
        """Fractions t in (0, 1) where the XY line from a to b crosses a grid line, in order.

        Between two crossings the bilinear surface along the line is smooth, so splitting a
        move there makes the compensated path follow the surface.
        """
        found: set[float] = set()
        for axis, lines in ((0, self.xs), (1, self.ys)):
            start, delta = a[axis], b[axis] - a[axis]
            if abs(delta) < 1e-12:
                continue
            for value in lines:
                t = (value - start) / delta
                if 1e-9 < t < 1 - 1e-9:
                    found.add(t)
        return sorted(found)


def _cell(nodes: Sequence[float], value: float) -> tuple[int, float]:
    """The cell index left of ``value`` and the fraction across it (clamped at both ends)."""
    if len(nodes) == 1 or value <= nodes[0]:
        return 0, 0.0
    if value >= nodes[-1]:
        return len(nodes) - 1, 0.0
    i = bisect_right(nodes, value) - 1
    return i, (value - nodes[i]) / (nodes[i + 1] - nodes[i])


# --------------------------------------------------------------------------- the ZHC table

@dataclass
class ZhcTable:
    """The grid ``ZHCINIT``/``ZHCINITEX`` define: nx by ny nodes from (x0, y0), dx and dy apart.

    Heights arrive one probe at a time (``ZHCADDPOINT``) and are stored at the node nearest
    to the probed XY, so raster and serpentine probing orders both fill the right nodes.
    """

    nx: int
    ny: int
    x0: float
    y0: float
    dx: float
    dy: float
    heights: list[list[float | None]]

    @staticmethod
    def grid_problem(dx: float, dy: float, nx: float, ny: float) -> str | None:
        """What is wrong with a grid's spacing and size, if anything (checked before it is allocated)."""
        sizes_ok = all(math.isfinite(v) for v in (dx, dy, nx, ny)) and dx > 0 and dy > 0
        if sizes_ok and nx >= 1 and ny >= 1 and nx == int(nx) and ny == int(ny) and nx * ny <= MAX_ZHC_POINTS:
            return None
        return (f"grid sizes must be above 0 and nX, nY whole numbers from 1 (at most {MAX_ZHC_POINTS:,} points); "
                f"got {dx:g} x {dy:g} mm, {nx:g} x {ny:g} points")

    @classmethod
    def empty(cls, nx: int, ny: int, x0: float, y0: float, dx: float, dy: float) -> "ZhcTable":
        return cls(nx, ny, x0, y0, dx, dy, [[None] * nx for _ in range(ny)])

    def node_of(self, x: float, y: float) -> tuple[int, int] | None:
        """The node within half a cell of (x, y), or None."""
        i, j = round((x - self.x0) / self.dx), round((y - self.y0) / self.dy)
        if not (0 <= i < self.nx and 0 <= j < self.ny):
            return None
        if abs(self.x0 + i * self.dx - x) > self.dx / 2 + 1e-9 or abs(self.y0 + j * self.dy - y) > self.dy / 2 + 1e-9:
            return None
        return i, j

    def add(self, x: float, y: float, z: float) -> tuple[int, int] | None:
        node = self.node_of(x, y)
        if node is not None:
            self.heights[node[1]][node[0]] = z
        return node

    def measured(self) -> list[float]:
        return [z for row in self.heights for z in row if z is not None]

    def complete(self) -> bool:
        return len(self.measured()) == self.nx * self.ny

    def height_map(self) -> HeightMap:
        """The table as a height map; only a complete table has one."""
        xs = tuple(self.x0 + i * self.dx for i in range(self.nx))
        ys = tuple(self.y0 + j * self.dy for j in range(self.ny))
        return HeightMap(xs, ys, tuple(tuple(float(z) for z in row) for row in self.heights))  # type: ignore[arg-type]

    def statistics(self) -> str:
        """What ``ZHCcheck`` reports: how much of the grid is measured and the spread of heights."""
        values = self.measured()
        head = f"ZHC table {self.nx} x {self.ny} points, {self.dx:g} x {self.dy:g} mm: {len(values)} measured"
        if not values:
            return head
        mean = sum(values) / len(values)
        return (f"{head}, min {min(values):.4f}, max {max(values):.4f}, range {max(values) - min(values):.4f}, "
                f"mean {mean:.4f}")

    def to_text(self) -> str:
        """The documented text format: a header line, ``key value`` lines, then one row of heights per Y."""
        lines = [TABLE_HEADER, *(f"{key} {getattr(self, key):.6g}" for key in _TABLE_KEYS)]
        lines += [" ".join("nan" if z is None else f"{z:.6f}" for z in row) for row in self.heights]
        return "\n".join(lines) + "\n"

    def save(self, path: str | os.PathLike[str]) -> None:
        write_text(path, self.to_text(), newline="\n")

    @classmethod
    def load(cls, path: str | os.PathLike[str]) -> "ZhcTable":
        try:
            with open(path, encoding="utf-8", errors="replace") as handle:
                return cls.from_text(handle.read(), os.fspath(path))
        except OSError as err:
            raise HeightMapError(f"cannot read the height table: {err.strerror}", Location(os.fspath(path))) from None

    @classmethod
    def from_text(cls, content: str, shown: str) -> "ZhcTable":
        """A table from the text ``to_text`` writes; errors name ``shown`` and the line."""
        text = content.splitlines()
        rows = [(number, line.split()) for number, line in enumerate(text, 1)
                if line.strip() and not line.lstrip().startswith(";")]
        header: dict[str, float] = {}
        for number, parts in rows[:len(_TABLE_KEYS)]:
            if len(parts) != 2 or parts[0] not in _TABLE_KEYS:
                raise HeightMapError(f"expected one of {', '.join(_TABLE_KEYS)} and a value", Location(shown, number))
            header[parts[0]] = _number(parts[1], shown, number, count=parts[0] in ("nx", "ny"))
        missing = [key for key in _TABLE_KEYS if key not in header]
        if missing:
            raise HeightMapError(f"the table header lacks {', '.join(missing)}", Location(shown))
        problem = cls.grid_problem(header["dx"], header["dy"], header["nx"], header["ny"])
        if problem or not math.isfinite(header["x0"] + header["y0"]):
            raise HeightMapError(problem or "x0 and y0 must be numbers", Location(shown))
        table = cls.empty(int(header["nx"]), int(header["ny"]), header["x0"], header["y0"], header["dx"], header["dy"])
        data = rows[len(_TABLE_KEYS):]
        if len(data) != table.ny:
            raise HeightMapError(f"the table has {len(data)} rows of heights; ny says {table.ny}", Location(shown))
        for j, (number, parts) in enumerate(data):
            if len(parts) != table.nx:
                raise HeightMapError(f"{len(parts)} heights on this row; nx says {table.nx}", Location(shown, number))
            values = [_number(p, shown, number) for p in parts]
            table.heights[j] = [None if math.isnan(z) else z for z in values]
        return table


def _number(text: str, path: str, line: int, nan: bool = True, count: bool = False) -> float:
    """A value of a height file; ``nan`` (a ZHC node not probed) only where ``nan`` allows it; a
    ``count`` (nx, ny) is left to the grid's own check."""
    try:
        value = plain_float(text, special=True)
    except ValueError:
        raise HeightMapError(f"{shortened(repr(text))} is not a number", Location(path, line)) from None
    if math.isinf(value) or (math.isnan(value) and not nan):
        raise HeightMapError(f"{text!r} is not a finite number", Location(path, line))
    if abs(value) > MAX_HEIGHT_MAP_VALUE and not count:
        raise HeightMapError(f"{shortened(text)} is beyond {MAX_HEIGHT_MAP_VALUE:g} mm (the limit of a height file)",
                             Location(path, line))
    return value


# --------------------------------------------------------------------------- probe surfaces

def read_surface(path: str | os.PathLike[str]) -> HeightMap:
    """A CSV of ``x,y,z`` rows (a header row and ``#`` comments allowed) covering a full grid."""
    shown = os.fspath(path)
    points: dict[tuple[float, float], float] = {}
    try:
        with open(path, encoding="utf-8-sig", errors="replace", newline="") as handle:
            for number, row in enumerate(csv.reader(handle), 1):
                cells = [c.strip() for c in row]
                if not cells or not cells[0] or cells[0].startswith("#"):
                    continue
                if len(cells) != 3:
                    raise HeightMapError(f"expected x,y,z, got {len(cells)} values", Location(shown, number))
                if number == 1 and not _is_number(cells[0]):
                    continue  # a header row such as x,y,z
                x, y, z = (_number(c, shown, number, nan=False) for c in cells)
                points[(x, y)] = z
    except OSError as err:
        raise HeightMapError(f"cannot read the probe surface: {err.strerror}", Location(shown)) from None
    xs, ys = sorted({p[0] for p in points}), sorted({p[1] for p in points})
    if not points:
        raise HeightMapError("the probe surface has no points", Location(shown))
    gaps = [(x, y) for y in ys for x in xs if (x, y) not in points]
    if gaps:
        raise HeightMapError(f"the points do not form a full grid: no height at x={gaps[0][0]:g} y={gaps[0][1]:g} "
                             f"({len(gaps)} missing of {len(xs) * len(ys)})", Location(shown))
    return HeightMap(tuple(xs), tuple(ys), tuple(tuple(points[(x, y)] for x in xs) for y in ys))


def _is_number(text: str) -> bool:
    try:
        plain_float(text, special=True)
    except ValueError:
        return False
    return True


@record(frozen=True)
class ProbeAt:
    """Trips a G38.2 move (machine coordinates) where Z first drops to the surface below it."""

    surface: HeightMap

    def __call__(self, start: Pose, target: Pose) -> Pose | None:
        def gap(t: float) -> float:
            x, y, z = _lerp(start, target, t)[:3]
            return z - self.surface.height(x, y)

        if gap(0.0) <= 0.0:
            return start  # already touching
        previous = 0.0
        for t in (*self.surface.crossings(start, target), 1.0):
            if gap(t) <= 0.0:
                low, high = previous, t
                for _ in range(60):  # bisection: the surface is smooth between crossings
                    middle = (low + high) / 2
                    low, high = (low, middle) if gap(middle) <= 0.0 else (middle, high)
                return _lerp(start, target, high)
            previous = t
        return None  # the move ends above the surface: no contact


@dataclass(frozen=True)
class ProbePlane:
    """Trips a G38.2 move (machine coordinates) where its Z first reaches ``z``: a tool setter's
    height, a surface known to be flat (``--probe-at Z``).  A move that stays above it makes no contact."""

    z: float

    def __call__(self, start: Pose, target: Pose) -> Pose | None:
        if start[2] <= self.z:
            return start  # already touching
        if target[2] > self.z:
            return None
        return _lerp(start, target, (start[2] - self.z) / (start[2] - target[2]))


def _lerp(a: Pose, b: Pose, t: float) -> Pose:
    return tuple(p + (q - p) * t for p, q in zip(a, b))
