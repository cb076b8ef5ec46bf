"""What the machine does differently: two recordings aligned, then compared move by move.

Geometry is compared both ways (NEW points against OLD's path and OLD points against NEW's), so a
move added in NEW and a move missing from it both show.  Feeds, spindle speeds and the tool in the
spindle are compared between each NEW move and the OLD move its end lies on; dwells, coolant and the
spindle's direction as sequences of events; then the tool order, the work offset, the planner's
time estimate and the lowest rapid.  Runs of neighbouring moves that differ alike become one change.
"""
from __future__ import annotations

import difflib
import math
from collections.abc import Iterator
from dataclasses import dataclass, field
from typing import Any

import numpy as np

from edingcnc_lang.diff.align import CAPTURE, Alignment, align, matched_moves
from edingcnc_lang.diff.record import RAPID_KINDS, Recording, PathSamples, sample

TOLERANCE = 0.001       # mm, the default of --tolerance
LIMIT = 50              # changes kept per list (the rest are counted)
TIME_SECONDS = 0.05     # the time estimate differs when it moves by more than this and ...
TIME_SHARE = 0.001      # ... by more than this share of OLD's
LISTS = ("deviations", "feeds", "spindle", "tool_moves", "dwell", "coolant", "rapids", "offsets")


@dataclass
class Change:
    """One change: a run of neighbouring moves (or one event) that differs alike."""

    # moved, added, removed, replaced, feed, spindle, direction, tool, dwell, coolant, rapid, offset
    what: str
    old_lines: tuple[int, int] | None      # job lines, first and last
    new_lines: tuple[int, int] | None
    old: Any = None
    new: Any = None
    distance: float | None = None
    tool: int | None = None
    moves: int = 1
    new_moves: tuple[int, int] | None = None  # move indices (first, last) in NEW, for pictures and operations
    old_moves: tuple[int, int] | None = None

    def to_json(self) -> dict[str, Any]:
        doc: dict[str, Any] = {"what": self.what}
        for side, lines in (("old", self.old_lines), ("new", self.new_lines)):
            doc[f"{side}_line"] = lines[0] if lines else None
            if lines and lines[1] != lines[0]:
                doc[f"{side}_lines"] = list(lines)
        if self.distance is not None:  # null: the other job makes no moves at all
            doc["distance"] = round(self.distance, 6) if math.isfinite(self.distance) else None
        if self.old is not None or self.new is not None:
            doc["old"], doc["new"] = self.old, self.new
        if self.tool is not None:
            doc["tool"] = self.tool
        if self.moves != 1:
            doc["moves"] = self.moves
        return doc


@dataclass
class Comparison:
    """Everything ``ecnc diff`` reports; ``changes[name]`` are the bounded lists, ``left_out`` counts the rest."""

    old: Recording
    new: Recording
    tolerance: float
    max_deviation: float | None    # None: one job moves and the other does not
    changes: dict[str, list[Change]]
    left_out: dict[str, int]
    time: tuple[float, float]
    time_differs: bool
    # per move, how far it is from the other path (for pictures)
    new_distance: np.ndarray = field(default_factory=lambda: np.zeros(0))
    old_distance: np.ndarray = field(default_factory=lambda: np.zeros(0))

    @property
    def tools_differ(self) -> bool:
        return self.old.tool_order() != self.new.tool_order()

    @property
    def same(self) -> bool:
        return not (any(self.changes.values()) or self.time_differs or self.tools_differ)

    def to_json(self) -> dict[str, Any]:
        lists = {name: [c.to_json() for c in self.changes[name]] for name in LISTS}
        return {
            "same": self.same, "tolerance": self.tolerance, "max_deviation": None if self.max_deviation is None else round(self.max_deviation, 6),
            "deviations": lists["deviations"], "feeds": lists["feeds"], "spindle": lists["spindle"],
            "tools": {"old": self.old.tool_order(), "new": self.new.tool_order(), "moves": lists["tool_moves"]},
            "time": {"old": round(self.time[0], 3), "new": round(self.time[1], 3)},
            "rapids": lists["rapids"], "dwell": lists["dwell"], "coolant": lists["coolant"],
            "offsets": lists["offsets"],
            "moves": {"old": len(self.old), "new": len(self.new)},
            "left_out": {name: count for name, count in self.left_out.items() if count},
        }


def compare(old: Recording, new: Recording, tolerance: float = TOLERANCE, limit: int = LIMIT) -> Comparison:
    """Compare two recorded runs; ``limit`` bounds each list of changes."""
    dims = 6 if _turns_rotary(old) or _turns_rotary(new) else 3
    old_samples, new_samples = sample(old, dims), sample(new, dims)
    # NEW points on OLD's path, then OLD points on NEW's; each kept per move only
    new_distance, new_match = _per_move(align(new_samples, old_samples, tolerance), new_samples, old_samples, len(new))
    old_distance, old_match = _per_move(align(old_samples, new_samples, tolerance), old_samples, new_samples, len(old))
    del old_samples, new_samples
    found: dict[str, list[Change]] = {name: [] for name in LISTS}
    found["deviations"] = _deviations(old, new, tolerance, new_distance, new_match, old_distance, old_match)
    # a move that goes nowhere has no place on the path, so no counterpart to compare its feed with
    near = (new_distance <= CAPTURE) & (new_match >= 0) & _goes_somewhere(new)
    match = np.maximum(new_match, 0)
    for name, what, new_values, old_values in (("feeds", "feed", new.feeds, old.feeds),
                                                ("spindle", "spindle", new.spindles, old.spindles),
                                                ("tool_moves", "tool", new.tools, old.tools)):
        theirs = old_values[match] if len(old) else np.zeros(len(new))  # no OLD move: nothing is near
        found[name] = list(_value_changes(what, old, new, near, match, new_values, theirs))
    for kind, name in (("dwell", "dwell"), ("coolant", "coolant"), ("spindle", "spindle")):
        found[name] += _event_changes(kind, old, new)
    found["rapids"] = _lower_rapids(old, new, tolerance, match)
    found["offsets"] = _offsets(old, new, tolerance)
    kept = {name: changes[:limit] for name, changes in found.items()}
    left_out = {name: max(0, len(changes) - limit) for name, changes in found.items()}
    # a path against none (one job makes no moves) has no finite distance: None in the JSON
    biggest: float | None = max((float(d.max()) for d in (new_distance, old_distance) if d.size), default=0.0)
    if biggest is not None and not np.isfinite(biggest):
        biggest = None
    time = (old.seconds, new.seconds)
    time_differs = abs(time[1] - time[0]) > max(TIME_SECONDS, TIME_SHARE * time[0])
    return Comparison(old, new, tolerance, biggest, kept, left_out, time, time_differs, new_distance, old_distance)


def _goes_somewhere(rec: Recording) -> np.ndarray:
    moving = np.abs(rec.ends - rec.starts).max(axis=1, initial=0.0) > 1e-12
    moving[rec.arc_moves()] = True
    return moving


def _turns_rotary(rec: Recording) -> bool:
    return bool(len(rec)) and bool(np.ptp(np.vstack((rec.starts[:, 3:], rec.ends[:, 3:])), axis=0).max() > 1e-9)


def _per_move(alignment: Alignment, mine: PathSamples, other: PathSamples, count: int) -> tuple[np.ndarray, np.ndarray]:
    """Per move: the largest distance of its points from the other path, and the other's move its end lies on."""
    if not count:
        return np.zeros(0), np.zeros(0, dtype=np.int64)
    firsts = np.searchsorted(mine.owner, np.arange(count))
    distance = np.maximum.reduceat(alignment.distance, firsts).astype(float)
    lasts = np.append(firsts[1:], len(mine.owner)) - 1
    return distance, matched_moves(alignment, other)[lasts]


def _runs(mask: np.ndarray, *keys: np.ndarray) -> Iterator[tuple[int, int]]:
    """(first, last) of each run of True in ``mask`` over which every key stays the same."""
    if not mask.any():
        return
    cut = np.zeros(len(mask), dtype=bool)
    cut[0] = True
    cut[1:] = mask[1:] != mask[:-1]
    for key in keys:
        cut[1:] |= key[1:] != key[:-1]
    starts = np.flatnonzero(cut)
    stops = np.append(starts[1:], len(mask)) - 1
    for first, last in zip(starts.tolist(), stops.tolist()):
        if mask[first]:
            yield first, last


def _lines(rec: Recording, first: int, last: int) -> tuple[int, int]:
    chosen = rec.lines[first:last + 1]
    chosen = chosen[chosen > 0]
    return (int(chosen.min()), int(chosen.max())) if chosen.size else (0, 0)


Span = tuple[int, int]


def _matched(rec: Recording, match: np.ndarray, first: int, last: int) -> tuple[Span | None, Span | None]:
    """The lines and the moves of ``rec`` that moves ``first``..``last`` of the other job lie on."""
    moves = match[first:last + 1]
    moves = moves[moves >= 0]
    if not moves.size:
        return None, None
    low, high = int(moves.min()), int(moves.max())
    return _lines(rec, low, high), (low, high)


def _deviations(old: Recording, new: Recording, tolerance: float, new_distance: np.ndarray, new_match: np.ndarray,
                old_distance: np.ndarray, old_match: np.ndarray) -> list[Change]:
    """Runs of NEW moves off OLD's path (moved, or added when far); runs of OLD moves off NEW's path join the
    NEW run beside them (both sides of one edit), else stand alone (removed when far)."""
    changes: list[Change] = []
    far = new_distance > CAPTURE
    for first, last in _runs(new_distance > tolerance, far, new.tools):
        old_lines, old_moves = _matched(old, new_match, first, last)
        changes.append(Change("added" if far[first] else "moved", old_lines, _lines(new, first, last),
                              distance=float(new_distance[first:last + 1].max()), tool=int(new.tools[first]),
                              moves=last - first + 1, new_moves=(first, last), old_moves=old_moves))
    alone: list[Change] = []
    for first, last in _runs(old_distance > tolerance, old_distance > CAPTURE, old.tools):
        new_lines, new_moves = _matched(new, old_match, first, last)
        distance = float(old_distance[first:last + 1].max())
        beside = next((c for c in changes
                       if _touch(c.new_moves, new_moves) or _touch(c.old_moves, (first, last))), None)
        if beside is not None:
            low, high = (first, last) if beside.old_moves is None else (min(first, beside.old_moves[0]),
                                                                        max(last, beside.old_moves[1]))
            beside.old_moves, beside.old_lines = (low, high), _lines(old, low, high)
            beside.distance = max(beside.distance or 0.0, distance)
            if beside.what == "added" and distance > CAPTURE:  # OLD went elsewhere there: one path for another
                beside.what = "replaced"
            continue
        alone.append(Change("removed" if old_distance[first] > CAPTURE else "moved", _lines(old, first, last),
                            new_lines, distance=distance, tool=int(old.tools[first]), moves=last - first + 1,
                            new_moves=new_moves, old_moves=(first, last)))
    return sorted(changes + alone, key=lambda c: c.new_moves[0] if c.new_moves else 0)


def _touch(one: tuple[int, int] | None, other: tuple[int, int] | None) -> bool:
    """Do two runs of moves overlap or meet?"""
    return one is not None and other is not None and one[0] <= other[1] + 1 and other[0] <= one[1] + 1


def _value_changes(what: str, old: Recording, new: Recording, near: np.ndarray, match: np.ndarray,
                   new_values: np.ndarray, old_values: np.ndarray) -> Iterator[Change]:
    """Runs of NEW moves whose value (feed, rpm, tool) is not that of the OLD move they lie on; moves
    that are not compared (going nowhere, or far from OLD) neither break a run nor count in it."""
    compared = np.flatnonzero(near)
    mine, theirs = new_values[compared], old_values[compared]
    differs = ~np.isclose(mine, theirs, rtol=1e-9, atol=1e-9)
    for first, last in _runs(differs, mine, theirs):
        low, high = int(compared[first]), int(compared[last])
        old_lines, old_moves = _matched(old, np.where(near, match, -1), low, high)
        yield Change(what, old_lines, _lines(new, low, high), old=_number(theirs[first]), new=_number(mine[first]),
                     tool=int(new.tools[low]), moves=last - first + 1, new_moves=(low, high), old_moves=old_moves)


def _number(value: Any) -> float | int:
    number = float(value)
    return int(number) if number.is_integer() else round(number, 6)


SPINDLE_WORDS = {3.0: "M3", 4.0: "M4", 5.0: "M5"}
COOLANT_WORDS = {7.0: "M7", 8.0: "M8", 9.0: "M9"}


def _event_changes(kind: str, old: Recording, new: Recording) -> list[Change]:
    """Events of one kind compared as sequences: what was replaced, added or left out, at its lines."""
    words = {"spindle": SPINDLE_WORDS, "coolant": COOLANT_WORDS}.get(kind, {})
    mine = [(line, value) for k, line, value, _at in old.events if k == kind]
    theirs = [(line, value) for k, line, value, _at in new.events if k == kind]
    what = "direction" if kind == "spindle" else kind
    changes: list[Change] = []
    matcher = difflib.SequenceMatcher(None, [v for _l, v in mine], [v for _l, v in theirs], autojunk=False)
    for tag, i1, i2, j1, j2 in matcher.get_opcodes():
        if tag == "equal":
            continue
        for k in range(max(i2 - i1, j2 - j1)):
            before = mine[i1 + k] if i1 + k < i2 else None
            after = theirs[j1 + k] if j1 + k < j2 else None
            show = (lambda v: words.get(v, _number(v)))
            changes.append(Change(what, (before[0], before[0]) if before else None,
                                  (after[0], after[0]) if after else None,
                                  old=show(before[1]) if before else None, new=show(after[1]) if after else None))
    return changes


def _lower_rapids(old: Recording, new: Recording, tolerance: float, match: np.ndarray) -> list[Change]:
    """NEW rapids that pass lower than every rapid of OLD (a new way the tool can hit the part or the vise)."""
    def rapid(rec: Recording) -> np.ndarray:
        return np.isin(rec.kinds, RAPID_KINDS[:1])

    lows = np.minimum(new.starts[:, 2], new.ends[:, 2])
    if not rapid(old).any():
        return []
    floor = float(np.minimum(old.starts[rapid(old), 2], old.ends[rapid(old), 2]).min())
    below = rapid(new) & (lows < floor - tolerance)
    changes = []
    for first, last in _runs(below):
        old_lines, old_moves = _matched(old, match, first, last)
        changes.append(Change("rapid", old_lines, _lines(new, first, last), old=round(floor, 6),
                              new=round(float(lows[first:last + 1].min()), 6), tool=int(new.tools[first]),
                              moves=last - first + 1, new_moves=(first, last), old_moves=old_moves))
    return changes


def _offsets(old: Recording, new: Recording, tolerance: float) -> list[Change]:
    """The work zero at the end (G5x + G92 + tool length): the moves show the offsets' effect, this names the cause."""
    if old.result is None or new.result is None:
        return []
    before, after = old.result.work_zero, new.result.work_zero
    if max(abs(a - b) for a, b in zip(before, after)) <= tolerance:
        return []
    return [Change("offset", None, None, old=[round(v, 6) for v in before[:3]], new=[round(v, 6) for v in after[:3]])]
