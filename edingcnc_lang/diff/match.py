"""Every move of each job with its counterpart in the other and how far it is from the other's path.

Identical moves are paired by ``anchor.anchors``; between two anchors lies a gap (the moves a local
edit touched).  A gap whose moves are OLD's moved by one vector (a feature shifted rigidly, a cut made
deeper) pairs them move by move (``Shift``); moves identical to moves elsewhere in the other job are
paired too (``Shift`` with no vector: done at another place in the order); the rest are measured by
geometry against the other job's moves in the same gap and the anchors either side (``align.nearest``),
so a change is found at its own lines and nowhere else, wherever it sits in the file.
"""
from __future__ import annotations

from collections import Counter
from dataclasses import dataclass, field

import numpy as np

from edingcnc_lang.diff.align import Stretch, matched_moves, nearest
from edingcnc_lang.diff.anchor import anchors, between, keys
from edingcnc_lang.diff.record import RAPID_KINDS, Recording, PathSamples, sample

CAPTURE = 1.0        # mm: a point this close to the other path is on it, moved; farther, it is elsewhere
MIN_SHIFTED = 2      # moves moved whole (both ends) that make a shifted feature


@dataclass
class Shift:
    """A run of pairs of moves: NEW's are OLD's moved by ``by`` (None: the same moves at another place
    in the order, or with ``backwards`` the same path driven the other way)."""

    old: tuple[int, int]
    new: tuple[int, int]
    by: tuple[float, float, float] | None
    backwards: bool = False   # NEW drives OLD's moves the other way, last first


@dataclass
class Matching:
    """Per move of each job: its largest distance from the other path and the other's move it lies on
    (-1: none); ``paired`` marks moves with a counterpart by identity or shift (their values are compared)."""

    new_distance: np.ndarray
    new_match: np.ndarray
    old_distance: np.ndarray
    old_match: np.ndarray
    new_paired: np.ndarray
    shifts: list[Shift] = field(default_factory=list)


def match(old: Recording, new: Recording, tolerance: float, dims: int) -> Matching:
    """Pair and measure the moves of ``old`` and ``new``."""
    old_keys, new_keys, backwards = keys(old, new, tolerance, dims)
    pairs = anchors(old_keys, new_keys)
    result = Matching(np.zeros(len(new)), np.full(len(new), -1, dtype=np.int64), np.zeros(len(old)),
                      np.full(len(old), -1, dtype=np.int64), np.zeros(len(new), dtype=bool))
    _pair(result, pairs[:, 0], pairs[:, 1], 0.0)
    gaps = [(a, b, c, d) for a, b, c, d in between(pairs, len(old), len(new)).tolist()]
    for o0, o1, n0, n1 in gaps:
        for shift in _shifted(old, new, o0, o1, n0, n1, tolerance):
            result.shifts.append(shift)
            (a, b), (c, d) = shift.old, shift.new
            _pair(result, np.arange(a, b + 1), np.arange(c, d + 1), float(np.linalg.norm(shift.by or 0.0)))
    _reversed(result, old_keys, backwards)
    _reordered(result, old_keys, new_keys, gaps)
    for o0, o1, n0, n1 in gaps:
        _reordered_gap(result, old, new, o0, o1, n0, n1)
    if not ((result.new_match == -1).any() or (result.old_match == -1).any()):
        return result  # every move has its counterpart: no path to measure
    # the path of the moves of the gaps and the anchors beside them, sampled where it is measured
    old_paths = _Paths(old, [(o0 - 1, o1 + 1) for o0, o1, _n0, _n1 in gaps], dims)
    new_paths = _Paths(new, [(n0 - 1, n1 + 1) for _o0, _o1, n0, n1 in gaps], dims)
    old_samples, new_samples = _needed(result, old_paths, new_paths, gaps)
    for o0, o1, n0, n1 in gaps:
        _measure(result.new_distance, result.new_match, new_samples, n0, n1, old_samples, old_paths, o0, o1)
        _measure(result.old_distance, result.old_match, old_samples, o0, o1, new_samples, new_paths, n0, n1)
    return result


def _pair(result: Matching, old_moves: np.ndarray, new_moves: np.ndarray, distance: float) -> None:
    result.new_match[new_moves], result.old_match[old_moves] = old_moves, new_moves
    result.new_distance[new_moves] = result.old_distance[old_moves] = distance
    result.new_paired[new_moves] = True


def _shifted(old: Recording, new: Recording, o0: int, o1: int, n0: int, n1: int, tolerance: float) -> list[Shift]:
    """The runs of a gap where NEW's moves are OLD's moved by one vector, pairing the gap's moves from its
    start (or, when its two sides differ in length, from its end too)."""
    size = min(o1 - o0, n1 - n0)
    if size < MIN_SHIFTED:
        return []
    found = _shift_run(old, new, np.arange(o0, o0 + size), np.arange(n0, n0 + size), tolerance)
    if not found and o1 - o0 != n1 - n0:
        found = _shift_run(old, new, np.arange(o1 - size, o1), np.arange(n1 - size, n1), tolerance)
    return found


def _shift_run(old: Recording, new: Recording, olds: np.ndarray, news: np.ndarray, tolerance: float) -> list[Shift]:
    """The longest run of pairs that fits one vector: moved whole, or (the moves into and out of the
    feature) moved at one end only; the vector is the one most moves are moved by whole.  ``olds`` and
    ``news``: runs of consecutive moves, read as views of the recordings."""
    o, n = slice(int(olds[0]), int(olds[-1]) + 1), slice(int(news[0]), int(news[-1]) + 1)
    ends = new.ends[n, :3] - old.ends[o, :3]
    starts = new.starts[n, :3] - old.starts[o, :3]
    alike = (new.kinds[n] == old.kinds[o]) & (new.tools[n] == old.tools[o])
    alike &= _largest(new.frames[n, 4:8] - old.frames[o, 4:8]) <= tolerance
    still_end, still_start = (_largest(d) <= tolerance for d in (ends, starts))
    whole = alike & ~still_end & (_largest(ends - starts) <= tolerance)
    # a feature cuts: rapids alone moved (the way home from another place) are not one
    if whole.sum() < MIN_SHIFTED or np.isin(new.kinds[n][whole], RAPID_KINDS).all():
        return []
    vote = Counter(map(tuple, np.round(ends[whole] / max(tolerance, 1e-9)).astype(np.int64).tolist()))
    step = np.array(vote.most_common(1)[0][0], dtype=float) * max(tolerance, 1e-9)
    by = ends[whole][np.argmin(np.abs(ends[whole] - step).max(axis=1))]
    on_end, on_start = (_largest(d - by) <= tolerance for d in (ends, starts))
    fits = alike & (on_end | still_end) & (on_start | still_start) & ~(still_end & still_start)
    moved_whole = fits & on_end & on_start
    best: tuple[int, int] | None = None
    for first, last in _true_runs(fits):
        if moved_whole[first:last + 1].sum() >= MIN_SHIFTED and (best is None or last - first > best[1] - best[0]):
            best = (first, last)
    if best is None:
        return []
    first, last = best
    return [Shift((int(olds[first]), int(olds[last])), (int(news[first]), int(news[last])),
                  (float(by[0]), float(by[1]), float(by[2])))]


def _largest(rows: np.ndarray) -> np.ndarray:
    """The largest absolute value in each row (NaN if any is), column by column: numpy is slow across a
    short row."""
    largest = np.abs(rows[:, 0])
    for column in range(1, rows.shape[1]):
        np.maximum(largest, np.abs(rows[:, column]), out=largest)
    return largest


def _true_runs(mask: np.ndarray) -> list[tuple[int, int]]:
    edges = np.flatnonzero(np.diff(np.concatenate(([0], mask.astype(np.int8), [0]))))
    return list(zip(edges[::2].tolist(), (edges[1::2] - 1).tolist()))


def _reversed(result: Matching, old_keys: np.ndarray, backwards: np.ndarray) -> None:
    """Moves left that are OLD's driven the other way (climb milling become conventional): NEW's leftover
    moves read last first against OLD's; runs of them become ``Shift``s with ``backwards``."""
    old_left = np.flatnonzero(result.old_match < 0)
    new_left = np.flatnonzero(result.new_match < 0)[::-1]
    if not len(old_left) or not len(new_left):
        return
    pairs = anchors(old_keys[old_left], backwards[new_left])
    if not len(pairs):
        return
    olds, news = old_left[pairs[:, 0]], new_left[pairs[:, 1]]
    order = np.argsort(olds)
    olds, news = olds[order], news[order]
    _pair(result, olds, news, 0.0)
    cut = np.r_[True, (np.diff(olds) != 1) | (np.diff(news) != -1)]
    starts = np.flatnonzero(cut)
    for first, last in zip(starts.tolist(), (np.r_[starts[1:], len(olds)] - 1).tolist()):
        result.shifts.append(Shift((int(olds[first]), int(olds[last])), (int(news[last]), int(news[first])),
                                   None, backwards=True))


def _reordered(result: Matching, old_keys: np.ndarray, new_keys: np.ndarray,
               gaps: list[tuple[int, int, int, int]]) -> None:
    """Moves left in the gaps that are identical to moves left in another gap of the other job: the same
    work at another place in the order (runs of them become ``Shift``s with no vector)."""
    old_left = np.flatnonzero(result.old_match < 0)
    new_left = np.flatnonzero(result.new_match < 0)
    if not len(old_left) or not len(new_left):
        return
    pairs = anchors(old_keys[old_left], new_keys[new_left])
    if not len(pairs):
        return
    olds, news = old_left[pairs[:, 0]], new_left[pairs[:, 1]]
    _pair(result, olds, news, 0.0)
    gap_of_old = np.zeros(len(result.old_match), dtype=np.int64)
    gap_of_new = np.zeros(len(result.new_match), dtype=np.int64)
    for number, (o0, o1, n0, n1) in enumerate(gaps, start=1):
        gap_of_old[o0:o1], gap_of_new[n0:n1] = number, number
    elsewhere = gap_of_old[olds] != gap_of_new[news]
    # runs of pairs that follow each other in both jobs, done elsewhere in the order
    cut = np.r_[True, (np.diff(olds) != 1) | (np.diff(news) != 1) | (elsewhere[1:] != elsewhere[:-1])]
    starts = np.flatnonzero(cut)
    for first, last in zip(starts.tolist(), (np.r_[starts[1:], len(olds)] - 1).tolist()):
        if elsewhere[first]:
            result.shifts.append(Shift((int(olds[first]), int(olds[last])), (int(news[first]), int(news[last])), None))


def _reordered_gap(result: Matching, old: Recording, new: Recording, o0: int, o1: int, n0: int, n1: int) -> None:
    """A gap whose moves are all done elsewhere in the order but for the rapids between them (holes drilled
    in another order) is one reordering: the rapids that join the moves in their new order are part of it."""
    inside = [s for s in result.shifts if s.by is None and n0 <= s.new[0] < n1]
    if not inside:
        return
    new_left = np.flatnonzero(result.new_match[n0:n1] < 0) + n0
    old_left = np.flatnonzero(result.old_match[o0:o1] < 0) + o0
    if not (np.isin(new.kinds[new_left], RAPID_KINDS).all() and np.isin(old.kinds[old_left], RAPID_KINDS).all()):
        return
    result.shifts = [s for s in result.shifts if s not in inside]
    olds = [s.old for s in inside]
    first, last = min(a for a, _b in olds), max(b for _a, b in olds)
    if o1 > o0:
        first, last = min(first, o0), max(last, o1 - 1)
    result.shifts.append(Shift((first, last), (n0, n1 - 1), None))
    result.new_distance[new_left] = result.old_distance[old_left] = 0.0
    result.new_match[new_left], result.old_match[old_left] = -2, -2  # told as the reordering, compared with nothing


class _Paths:
    """One job's path along the moves of ``spans`` (first, stop; clipped to the job): each move's points
    as ``sample`` gives them for all those moves at once (a move that starts where the one before it in
    the spans ends has no point of its own there), so sampling some of them gives the same points."""

    def __init__(self, rec: Recording, spans: list[tuple[int, int]], dims: int) -> None:
        chosen = np.zeros(len(rec), dtype=bool)
        for first, stop in spans:
            chosen[max(first, 0):min(stop, len(rec))] = True
        self.rec, self.dims = rec, dims
        self.moves = np.flatnonzero(chosen)
        starts, ends = rec.starts[self.moves, :dims], rec.ends[self.moves, :dims]
        self.jumps = np.ones(len(self.moves), dtype=bool)
        self.jumps[1:] = np.any(np.abs(starts[1:] - ends[:-1]) > 1e-9, axis=1)
        self._whole: PathSamples | None = None

    def whole(self) -> PathSamples:
        """The path of all the moves of the spans."""
        if self._whole is None:
            self._whole = self._sample(np.arange(len(self.moves)), self.jumps)
        return self._whole

    def part(self, needed: np.ndarray) -> PathSamples:
        """The path of the moves marked in ``needed`` (a mask over the job): a run of them that continues
        the move before it starts from that move's last point (that move with a point of its own at its
        start), so the segments of the run are those of the whole path."""
        want = needed[self.moves]
        lead = np.flatnonzero(want[1:] & ~want[:-1] & ~self.jumps[1:])
        jumps = self.jumps.copy()
        jumps[lead] = True
        want[lead] = True
        chosen = np.flatnonzero(want)
        return self._sample(chosen, jumps[chosen])

    def _sample(self, chosen: np.ndarray, jumps: np.ndarray) -> PathSamples:
        """The path of moves ``chosen`` (positions in the spans' moves), each point owned by its move's
        index in the whole job."""
        rec, moves = self.rec, self.moves[chosen]
        samples = sample(rec, self.dims, moves=moves, jumps=jumps)
        samples.owner = moves[samples.owner].astype(np.int32) if len(moves) else samples.owner
        centers, normals, radii = (np.zeros((len(rec), 3)), np.full(len(rec), -1, dtype=np.int8), np.zeros(len(rec)))
        centers[moves], normals[moves], radii[moves] = samples.centers, samples.normals, samples.radii
        samples.centers, samples.normals, samples.radii = centers, normals, radii
        samples.arc_of = np.where(samples.arc_of >= 0, moves[np.maximum(samples.arc_of, 0)], -1).astype(np.int32) \
            if len(moves) else samples.arc_of
        return samples


def _needed(result: Matching, old: _Paths, new: _Paths,
            gaps: list[tuple[int, int, int, int]]) -> tuple[PathSamples, PathSamples]:
    """Each job's path where ``_measure`` looks: the moves of a gap still without a counterpart, and the
    moves of a gap (with the anchors beside it) the other job's such moves are measured against."""
    old_needed, new_needed = np.zeros(len(old.rec), dtype=bool), np.zeros(len(new.rec), dtype=bool)
    for o0, o1, n0, n1 in gaps:
        old_left, new_left = (result.old_match[o0:o1] == -1), (result.new_match[n0:n1] == -1)
        old_needed[o0:o1] |= old_left
        new_needed[n0:n1] |= new_left
        if new_left.any():
            old_needed[max(o0 - 1, 0):o1 + 1] = True
        if old_left.any():
            new_needed[max(n0 - 1, 0):n1 + 1] = True
    return old.part(old_needed), new.part(new_needed)


def _measure(distance: np.ndarray, match: np.ndarray, mine: PathSamples, m0: int, m1: int, other: PathSamples,
             others: _Paths, o0: int, o1: int) -> None:
    """The moves ``m0``..``m1`` - 1 not paired yet, against the other's moves of the gap and its anchors
    (``other``: the other's path there; ``others``: all of it, for a gap where the other job makes no move)."""
    moves = np.arange(m0, m1)
    moves = moves[match[moves] == -1]
    if not len(moves):
        return
    stretch = Stretch(other, max(o0 - 1, 0), o1 + 1)
    low, high = np.searchsorted(mine.owner, (m0, m1))
    owner = mine.owner[low:high]
    chosen = np.flatnonzero(match[owner] == -1)
    if not len(stretch) and len(others.moves):  # the other job moves, but not here: far from all of it
        other = others.whole()
        stretch = Stretch(other, 0, len(other.owner))
    dist, seg, at = nearest(mine.points[low:high][chosen], stretch, CAPTURE)
    owners = owner[chosen]
    firsts = np.searchsorted(owners, moves)
    distance[moves] = np.maximum.reduceat(dist, firsts)
    lasts = np.r_[firsts[1:], len(owners)] - 1
    match[moves] = matched_moves(seg[lasts], at[lasts], other)
