"""Sweeping straight tool moves through the height field, a batch of segments at a time.

For every segment the cells under its swept footprint are listed at once (numpy, no loop per
cell or per move), and for each (segment, cell) pair the lowest height the tool reaches over that
cell along the segment is solved in closed form: the tip's Z is linear along the segment and the
tool's profile is a convex function of the distance, so the lowest point is where the derivative
vanishes, clamped to the part of the segment that passes over the cell (a flat, ball and vee
tool each have their formula; a bull nose is found by a golden-section search, which convexity
makes exact).  The field takes the minimum; what each move removed, and from what height, is
worked out exactly in program order only for the pairs that may be a finding.

A chunk where no pair can be a finding (every segment cuts with the spindle on, and no shank or
holder reaches material) only lowers the field: the compiled core (``_sweep.carve``) does that
segment after segment, skipping the cells its predecessors already cut lower, to the same heights
(the field is the minimum over all pairs, whatever their order).
"""
from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass

import numpy as np

from edingcnc_lang import speedups
from edingcnc_lang.sim.envelope import Geometry, lowest
from edingcnc_lang.sim.stock import Stock
from edingcnc_lang.sim.tools import Tool

EPS = 1e-3            # mm: less than this into the material is no finding (float32 heights)
MAX_PAIRS = 50_000  # (segment, cell) pairs per chunk: its scratch arrays stay in the CPU's cache

# CutFinding codes of a pair: what the part of the tool that made it was doing.
NONE, RAPID, SPINDLE_OFF, PLUNGE, SHANK, HOLDER = range(6)
CARVE = None if speedups.SWEEP is None else speedups.SWEEP.carve  # the compiled field-only sweep, or None
CARVED = ("flat", "ball", "vee", "bull")  # the cutter shapes it knows
CODE_KINDS = {RAPID: "rapid_into_stock", SPINDLE_OFF: "spindle_off", PLUNGE: "plunge",
              SHANK: "shank", HOLDER: "holder"}


@dataclass
class Segments:
    """Straight pieces of tool-tip path (stock frame) with the move each belongs to and its code."""

    a: np.ndarray       # (N, 3) start XYZ of the tip
    b: np.ndarray       # (N, 3) end XYZ
    move: np.ndarray    # (N,) int64 index of the move in the run
    code: np.ndarray    # (N,) int8 what removing material with the cutter means (NONE, RAPID, ...)

    def __len__(self) -> int:
        return len(self.move)

    def take(self, chosen: np.ndarray) -> Segments:
        return Segments(self.a[chosen], self.b[chosen], self.move[chosen], self.code[chosen])


@dataclass
class Hits:
    """Moves that removed material they should not have: move, code, depth, and where the tool tip
    was (x, y, z) when it went deepest."""

    move: np.ndarray
    code: np.ndarray
    depth: np.ndarray
    where: np.ndarray  # (N, 3)

    @classmethod
    def empty(cls) -> Hits:
        return cls(np.zeros(0, np.int64), np.zeros(0, np.int8), np.zeros(0), np.zeros((0, 3)))


def split_long(a: np.ndarray, b: np.ndarray, limit: float | np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Cut segments longer than ``limit`` (one, or one per segment) in XY into equal pieces, so that no
    footprint's bounding box grows with the square of a long diagonal move; returns starts, ends and
    the segment each came from."""
    length = np.hypot(b[:, 0] - a[:, 0], b[:, 1] - a[:, 1])
    pieces = np.maximum(np.ceil(length / limit), 1).astype(np.int64)
    owner = np.repeat(np.arange(len(a)), pieces)
    if len(owner) == len(a):
        return a, b, owner
    first = np.cumsum(pieces) - pieces
    k = (np.arange(len(owner)) - first[owner]).astype(float)[:, None]
    n = pieces[owner].astype(float)[:, None]
    step = b[owner] - a[owner]
    return a[owner] + step * (k / n), a[owner] + step * ((k + 1) / n), owner


def _spans(stock: Stock, a: np.ndarray, b: np.ndarray, radius: float) -> list[tuple[np.ndarray, np.ndarray]]:
    """Per segment and axis (X, Y): the first cell index whose centre is in the bounding box widened
    by ``radius``, and how many cells it spans (0: off the grid)."""
    r = stock.resolution
    ny, nx = stock.shape
    spans = []
    for axis, origin, count in ((0, stock.x0, nx), (1, stock.y0, ny)):
        low, high = np.minimum(a[:, axis], b[:, axis]), np.maximum(a[:, axis], b[:, axis])
        first = np.maximum(np.ceil((low - radius - origin) / r - 0.5), 0).astype(np.int64)
        last = np.minimum(np.floor((high + radius - origin) / r - 0.5), count - 1).astype(np.int64)
        spans.append((first, np.maximum(last - first + 1, 0)))
    return spans


def footprint(stock: Stock, a: np.ndarray, b: np.ndarray, radius: float
              ) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
    """The cells a segment's tool of ``radius`` may reach, segment by segment: on each row of its
    bounding box, the columns within ``radius`` of the segment's X range, ``radius`` shrunk by the
    row's distance from its Y range (a rounded box: a short move's disc, not its square).  Returns
    how many cells per segment, each segment's first column and row, and the column and row of each
    cell from those (small numbers, built row by row with ``np.repeat``: no division per cell)."""
    (i0, wide), (j0, tall) = _spans(stock, a, b, radius)
    rows = np.where(wide > 0, tall, 0)
    row_seg = np.repeat(np.arange(len(a)), rows)
    row_j = np.arange(len(row_seg)) - np.repeat(np.cumsum(rows) - rows, rows)
    r = stock.resolution
    y = stock.y0 + (j0[row_seg] + row_j + 0.5) * r
    low_y, high_y = np.minimum(a[row_seg, 1], b[row_seg, 1]), np.maximum(a[row_seg, 1], b[row_seg, 1])
    off = np.maximum(np.maximum(low_y - y, y - high_y), 0.0)
    reach = np.sqrt(np.maximum(radius * radius - off * off, 0.0))
    low_x, high_x = np.minimum(a[row_seg, 0], b[row_seg, 0]), np.maximum(a[row_seg, 0], b[row_seg, 0])
    first = np.maximum(np.ceil((low_x - reach - stock.x0) / r - 0.5), i0[row_seg]).astype(np.int64)
    last = np.minimum(np.floor((high_x + reach - stock.x0) / r - 0.5), i0[row_seg] + wide[row_seg] - 1)
    row_w = np.where(off <= radius, np.maximum(last.astype(np.int64) - first + 1, 0), 0)
    i = np.repeat(first - i0[row_seg] - (np.cumsum(row_w) - row_w), row_w) + np.arange(int(row_w.sum()))
    counts = np.bincount(row_seg, weights=row_w, minlength=len(a)).astype(np.int64)
    return counts, i0, j0, i.astype(np.int32), np.repeat(row_j, row_w).astype(np.int32)


def footprint_cells(stock: Stock, a: np.ndarray, b: np.ndarray, radius: float) -> tuple[np.ndarray, np.ndarray]:
    """``footprint`` as (segment, flat cell index) pairs."""
    counts, i0, j0, i, j = footprint(stock, a, b, radius)
    return np.repeat(np.arange(len(a)), counts), np.repeat(j0 * stock.shape[1] + i0, counts) + j * stock.shape[1] + i


def pair_counts(stock: Stock, a: np.ndarray, b: np.ndarray, radius: float) -> np.ndarray:
    """How many pairs ``footprint_cells`` makes per segment (to cut a batch into chunks)."""
    (_i0, wide), (_j0, tall) = _spans(stock, a, b, radius)
    return wide * tall


@dataclass(frozen=True)
class Part:
    """A part of the tool that sweeps the stock: the cutter, or the shank or holder above it."""

    radius: float
    offset: float      # its lowest face above the tip
    code: int          # NONE for the cutter (each segment has its own code), else SHANK or HOLDER
    flat: bool

    def floor(self, tool: Tool) -> Callable[[np.ndarray], np.ndarray]:
        """Height of this part's lowest surface above the tip at a distance from the axis."""
        if self.code == NONE:
            return tool.profile
        above = np.float32(self.offset)

        def flat(d: np.ndarray) -> np.ndarray:
            return np.full_like(d, above)
        return flat


def parts_of(tool: Tool) -> list[Part]:
    """The cutter, and the shank and holder when their place is known."""
    parts = [Part(tool.radius, 0.0, NONE, tool.shape == "flat")]
    if tool.flute_length is not None:
        parts.append(Part(tool.shank_radius, tool.flute_length, SHANK, True))
    if tool.holder_length is not None and tool.holder_diameter is not None:
        parts.append(Part(tool.holder_diameter / 2.0, tool.holder_length, HOLDER, True))
    return parts


def sweep(stock: Stock, tool: Tool, segs: Segments, plunge_limit: float, ceiling: float) -> Hits:
    """Cut ``segs`` (in program order) into the field and return what each move hit that it should
    not have.  ``ceiling`` is at or above the highest material: pieces whose lowest point of a
    part is above it cannot touch anything and are skipped."""
    if not len(segs):
        return Hits.empty()
    a, b, owner = split_long(segs.a, segs.b, max(2.0 * tool.radius, 32.0 * stock.resolution))
    segs = Segments(a, b, segs.move[owner], segs.code[owner])
    low = np.minimum(a[:, 2], b[:, 2])
    parts = parts_of(tool)
    reach = [low + part.offset < ceiling for part in parts]
    counts = np.sum([np.where(near, pair_counts(stock, a, b, part.radius), 0) for part, near in zip(parts, reach)],
                    axis=0)
    busy = np.flatnonzero(counts)
    if not len(busy):
        return Hits.empty()
    bounds = np.searchsorted(np.cumsum(counts[busy]), np.arange(MAX_PAIRS, int(counts.sum()), MAX_PAIRS))
    found, quiet = [Hits.empty()], []
    top = stock.top
    carving = (CARVE is not None and tool.shape in CARVED and top.dtype == np.float32 and top.flags.c_contiguous
               and top.flags.writeable)
    for chosen in np.split(busy, np.unique(np.maximum(bounds, 1))):
        if carving and _quiet(segs, reach, chosen):
            quiet.append(chosen)  # carved with the next chunk that may find something, or at the end
            continue
        if quiet:
            _carve(stock, tool, segs, reach[0], np.concatenate(quiet))
            quiet = []
        found.append(_chunk(stock, tool, segs, parts, reach, chosen, plunge_limit))
    if quiet:
        _carve(stock, tool, segs, reach[0], np.concatenate(quiet))
    return Hits(*(np.concatenate([getattr(h, name) for h in found])
                  for name in ("move", "code", "depth", "where")))


def _quiet(segs: Segments, reach: list[np.ndarray], chosen: np.ndarray) -> bool:
    """No pair of the chunk can be a finding: every segment's code is NONE and only the cutter reaches material."""
    return not (segs.code[chosen] != NONE).any() and not any(near[chosen].any() for near in reach[1:])


def _carve(stock: Stock, tool: Tool, segs: Segments, near: np.ndarray, chosen: np.ndarray) -> None:
    """``_chunk`` without findings, compiled (``CARVE``): the field lowered by the cutter (``near``:
    the segments where it reaches material), segment by segment."""
    assert CARVE is not None
    picked = chosen[near[chosen]]
    a, b = (np.ascontiguousarray(ends[picked], dtype=float) for ends in (segs.a, segs.b))
    CARVE(stock.top, a, b, float(stock.x0), float(stock.y0), float(stock.resolution), float(stock.bottom), tool.shape, tool.radius,
          tool.corner_radius, tool.cone_slope)


def _chunk(stock: Stock, tool: Tool, segs: Segments, parts: list[Part], reach: list[np.ndarray],
           chosen: np.ndarray, plunge_limit: float) -> Hits:
    """One chunk of segments, all parts of the tool: the hits, then the field lowered."""
    cells, heights, moves, codes, owners = [], [], [], [], []
    for part, near in zip(parts, reach):
        picked = chosen[near[chosen]]
        if not len(picked):  # this part reaches no material here (a shank above the stock): nothing to add
            continue
        a, b = segs.a[picked], segs.b[picked]
        g = Geometry(stock, a, b, footprint(stock, a, b, part.radius), part.radius, part.floor(tool))
        seg, cell = picked[g.seg], g.cell
        h = g.az + g.downhill() * g.dz if part.flat else lowest(tool, g)
        cells.append(cell)
        heights.append(h + part.offset)
        moves.append(segs.move[seg])
        owners.append(seg)
        codes.append(segs.code[seg] if part.code == NONE else np.full(len(seg), part.code, np.int8))
    cell, h = np.concatenate(cells), np.maximum(np.concatenate(heights), stock.bottom)
    move, owner = np.concatenate(moves), np.concatenate(owners)
    pair, depth = _hits(stock, cell, h, move, np.concatenate(codes), owner, plunge_limit)
    hits = Hits(move[pair], np.concatenate(codes)[pair], depth, _tool_at(stock, segs, owner[pair], cell[pair]))
    np.minimum.at(stock.top.reshape(-1), cell, h.astype(np.float32))
    return hits


def _tool_at(stock: Stock, segs: Segments, seg: np.ndarray, cell: np.ndarray) -> np.ndarray:
    """Where the tool tip was when it reached each cell: the point of its segment nearest the cell
    in XY (the lower end of a vertical segment)."""
    nx, r = stock.shape[1], stock.resolution
    a, b = segs.a[seg], segs.b[seg]
    d = b - a
    c = np.column_stack((stock.x0 + (cell % nx + 0.5) * r - a[:, 0], stock.y0 + (cell // nx + 0.5) * r - a[:, 1]))
    l2 = d[:, 0] ** 2 + d[:, 1] ** 2
    along = np.where(l2 > 0, (c[:, 0] * d[:, 0] + c[:, 1] * d[:, 1]) / np.where(l2 > 0, l2, 1.0),
                     (d[:, 2] < 0).astype(float))
    return a + np.clip(along, 0.0, 1.0)[:, None] * d


def _hits(stock: Stock, cell: np.ndarray, h: np.ndarray, move: np.ndarray, code: np.ndarray, seg: np.ndarray,
          plunge_limit: float) -> tuple[np.ndarray, np.ndarray]:
    """The deepest pair per (move, code) among pairs that removed material they should not have,
    each measured from the height the cell had just before that move (not before the chunk), the
    earliest along the move among those as deep (to the µm): the index of each and its depth."""
    top = stock.top.reshape(-1)
    candidate = (code != NONE) & (h < top[cell] - EPS)
    if not candidate.any():
        return np.zeros(0, np.int64), np.zeros(0)
    before = _height_before(top, cell, h, move, candidate)
    depth = before - h[candidate]
    c_move, c_code, c_pair = move[candidate], code[candidate], np.flatnonzero(candidate)
    real = depth > np.where(c_code == PLUNGE, plunge_limit, 0.0) + EPS
    if not real.any():
        return np.zeros(0, np.int64), np.zeros(0)
    c_move, c_code, c_pair, depth = (v[real] for v in (c_move, c_code, c_pair, depth))
    order = np.lexsort((seg[c_pair], -np.round(depth / EPS), c_code, c_move))
    first = order[np.r_[True, (np.diff(c_move[order]) != 0) | (np.diff(c_code[order]) != 0)]]
    return c_pair[first], depth[first]


def _height_before(top: np.ndarray, cell: np.ndarray, h: np.ndarray, move: np.ndarray,
                   candidate: np.ndarray) -> np.ndarray:
    """For the candidate pairs: the cell's height just before their move, i.e. the lower of the
    height before the chunk and the lowest any earlier move of the chunk cut it to."""
    related = np.isin(cell, np.unique(cell[candidate]))
    r_cell, r_move, r_h = cell[related], move[related], h[related].astype(np.float64)  # the shift below needs it
    order = np.lexsort((r_move, r_cell))
    r_cell, r_move, r_h = r_cell[order], r_move[order], r_h[order]
    group = np.flatnonzero(np.r_[True, (np.diff(r_cell) != 0) | (np.diff(r_move) != 0)])
    g_cell, g_move, g_low = r_cell[group], r_move[group], np.minimum.reduceat(r_h, group)
    new_cell = np.r_[True, np.diff(g_cell) != 0]
    index = np.cumsum(new_cell) - 1
    # a running minimum that starts afresh at each cell: later cells are shifted below earlier ones
    shift = 2.0 * float(g_low.max() - g_low.min()) + 1.0
    running = np.minimum.accumulate(g_low - index * shift) + index * shift
    earlier = np.r_[np.inf, running[:-1]]
    earlier[new_cell] = np.inf
    before = np.minimum(top[g_cell].astype(np.float64), earlier)
    stride = int(move.max()) + 1
    keys = g_cell * stride + g_move
    return before[np.searchsorted(keys, cell[candidate] * stride + move[candidate])]
