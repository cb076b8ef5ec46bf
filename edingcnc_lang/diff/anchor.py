"""Which moves of NEW are OLD's own: anchors on identical moves, as a patience/histogram diff does on lines.

Each move gets a key of what the machine does: rapid or cut, where it starts and ends and the circle of
an arc, rounded to the tolerance (the tool, the feed and the speed are not in it: they are compared on
the pairs, so another tool on the same path is "T2 -> T5", not a new path).  Keys that occur equally often in both jobs, and rarely (at most ``RARE`` times), pair their
occurrences in order; the longest chain of pairs in order in both jobs is kept (``_chain``), each anchor
grows over the equal keys beside it, and the stretches left between anchors are anchored again by the
keys rare there.  What is left are the gaps: the moves a local edit touched, compared by geometry in
``align``.  Work and memory grow with the moves (``n log n``), never with their square.
"""
from __future__ import annotations

from bisect import bisect_left

import numpy as np

from edingcnc_lang.diff.record import RAPID_KINDS, Recording

RARE = 8           # a key occurring more often than this in a stretch anchors nothing there
MIN_GAP = 2        # a stretch this short on both sides is not searched for anchors again
BUDGET = 40        # the anchoring's work, in moves looked at, stops at this many times the moves
ROWS = 4096       # moves hashed at once


def keys(old: Recording, new: Recording, tolerance: float, dims: int = 6) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """One integer per move naming what it does, the same in both jobs for the same move: the rounded
    columns hashed to 64 bits (splitmix64 over the columns; two different moves share a key with a
    chance of about n^2 / 2^64), then numbered.  The third array is NEW's moves driven backwards: the
    key each would have from its end to its start (an arc the other way round).  ``dims``: the axes
    that count (3: XYZ, when neither job turns a rotary axis)."""
    step = max(tolerance, 1e-9)

    def hashed(rec: Recording, backwards: bool = False) -> np.ndarray:
        key = np.empty(len(rec), dtype=np.uint64)
        for low in range(0, len(rec), ROWS):  # a piece at a time: its arrays stay small enough to reuse memory
            rows = slice(low, low + ROWS)
            kinds = rec.kinds[rows]
            kind = np.where(np.isin(kinds, RAPID_KINDS), -1, kinds.astype(np.int64))
            arc = rec.frames[rows][:, [0, 2, 3, 5 if backwards else 4, 7]]
            arc[:, 1:4] /= step
            arc[:, 4] *= -1e6 if backwards else 1e6  # the sweep (radians): its direction and size
            start, end = (rec.starts[rows, :dims], rec.ends[rows, :dims])[::-1 if backwards else 1]
            part = np.full(len(kind), 0x9E3779B97F4A7C15, dtype=np.uint64)
            for column in (kind.astype(np.float64)[:, None], start / step, end / step, arc):
                whole = np.clip(np.round(column), -2.0 ** 62, 2.0 ** 62).astype(np.int64)
                for values in whole.T:
                    part = _mix(part ^ values.view(np.uint64))
            key[rows] = part
        return key

    every = np.concatenate((hashed(old), hashed(new), hashed(new, backwards=True)))
    _unique, inverse = np.unique(every, return_inverse=True)
    inverse = inverse.astype(np.int64)
    return inverse[:len(old)], inverse[len(old):len(old) + len(new)], inverse[len(old) + len(new):]


def _mix(x: np.ndarray) -> np.ndarray:
    """splitmix64's finaliser: every bit of the input moves about half the bits of the output (in place:
    ``x`` is a temporary of the caller's, and fewer new arrays are fewer new pages)."""
    with np.errstate(over="ignore"):
        x += np.uint64(0x9E3779B97F4A7C15)
        x ^= x >> np.uint64(30)
        x *= np.uint64(0xBF58476D1CE4E5B9)
        x ^= x >> np.uint64(27)
        x *= np.uint64(0x94D049BB133111EB)
        x ^= x >> np.uint64(31)
        return x


def anchors(old_keys: np.ndarray, new_keys: np.ndarray) -> np.ndarray:
    """Pairs (OLD move, NEW move) of identical moves, in order in both jobs, as an (A, 2) array."""
    pairs: list[np.ndarray] = []
    budget = BUDGET * (len(old_keys) + len(new_keys)) + 1024
    stretches = [(0, len(old_keys), 0, len(new_keys))]
    while stretches:
        o0, o1, n0, n1 = stretches.pop()
        # equal keys at both ends of the stretch: the anchors beside it grow over them
        head = _common(old_keys[o0:o1], new_keys[n0:n1])
        if head:
            pairs.append(np.column_stack((np.arange(o0, o0 + head), np.arange(n0, n0 + head))))
            o0, n0 = o0 + head, n0 + head
        tail = _common(old_keys[o0:o1][::-1], new_keys[n0:n1][::-1])
        if tail:
            pairs.append(np.column_stack((np.arange(o1 - tail, o1), np.arange(n1 - tail, n1))))
            o1, n1 = o1 - tail, n1 - tail
        if min(o1 - o0, n1 - n0) < 1 or max(o1 - o0, n1 - n0) < MIN_GAP or budget <= 0:
            continue
        budget -= (o1 - o0) + (n1 - n0)
        found = _rare_pairs(old_keys[o0:o1], new_keys[n0:n1])
        if not len(found):
            continue
        found = found + (o0, n0)
        pairs.append(found)
        # the stretches between these anchors, searched again with the keys rare there
        stretches += [(a, b, c, d) for a, b, c, d in between(found - (o0, n0), o1 - o0, n1 - n0) + (o0, o0, n0, n0)]
    if not pairs:
        return np.zeros((0, 2), dtype=np.int64)
    every = np.vstack(pairs)
    return every[np.argsort(every[:, 1], kind="stable")]


def between(pairs: np.ndarray, old_count: int, new_count: int) -> np.ndarray:
    """The stretches between consecutive ``pairs`` (and before the first, after the last) that hold a move
    of either job, as rows (OLD first, OLD stop, NEW first, NEW stop)."""
    bounds = np.vstack(([-1, -1], pairs.reshape(-1, 2), [old_count, new_count]))
    low, high = bounds[:-1] + 1, bounds[1:]
    gap = (high[:, 0] > low[:, 0]) | (high[:, 1] > low[:, 1])
    return np.column_stack((low[gap, 0], high[gap, 0], low[gap, 1], high[gap, 1]))


def _common(one: np.ndarray, other: np.ndarray) -> int:
    """How many keys at the start of both are equal."""
    size = min(len(one), len(other))
    if not size:
        return 0
    differs = np.flatnonzero(one[:size] != other[:size])
    return int(differs[0]) if differs.size else size


def _rare_pairs(old: np.ndarray, new: np.ndarray) -> np.ndarray:
    """Pairs (i, j) of the keys that occur equally and at most ``RARE`` times in both, the k-th occurrence
    with the k-th, then the longest chain of them in order in both (the rarest keys first: unique ones)."""
    values, old_counts = np.unique(old, return_counts=True)
    new_values, new_counts = np.unique(new, return_counts=True)
    shared, in_old, in_new = np.intersect1d(values, new_values, assume_unique=True, return_indices=True)
    equal = old_counts[in_old] == new_counts[in_new]
    if not equal.any():
        return np.zeros((0, 2), dtype=np.int64)
    rarest = int(old_counts[in_old][equal].min())
    if rarest > RARE:
        return np.zeros((0, 2), dtype=np.int64)
    chosen = shared[equal & (old_counts[in_old] == rarest)]
    old_at = np.flatnonzero(np.isin(old, chosen))
    new_at = np.flatnonzero(np.isin(new, chosen))
    # the k-th occurrence of a key in OLD with its k-th in NEW: sort both by (key, position)
    old_at = old_at[np.lexsort((old_at, old[old_at]))]
    new_at = new_at[np.lexsort((new_at, new[new_at]))]
    order = np.argsort(new_at, kind="stable")
    return _chain(old_at[order], new_at[order])


def _chain(old_at: np.ndarray, new_at: np.ndarray) -> np.ndarray:
    """The longest run of pairs (sorted by NEW) whose OLD positions increase too (patience sorting)."""
    tails: list[int] = []      # OLD position ending the best chain of each length
    ends: list[int] = []       # ... and the pair's index
    back = np.full(len(old_at), -1, dtype=np.int64)
    for index, position in enumerate(old_at.tolist()):
        length = bisect_left(tails, position)
        if length == len(tails):
            tails.append(position)
            ends.append(index)
        else:
            tails[length], ends[length] = position, index
        back[index] = ends[length - 1] if length else -1
    chain: list[int] = []
    at = ends[-1] if ends else -1
    while at >= 0:
        chain.append(at)
        at = int(back[at])
    chain.reverse()
    return np.column_stack((old_at[chain], new_at[chain])).astype(np.int64)
