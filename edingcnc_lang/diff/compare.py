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
from typing import TYPE_CHECKING, Any

import numpy as np

from edingcnc_lang.diff.match import CAPTURE, Matching, Shift, match as match_moves
from edingcnc_lang.diff.record import RAPID_KINDS, Recording, slots

if TYPE_CHECKING:
    from edingcnc_lang.diff.part import PartComparison

TOLERANCE = 0.001       # mm, the default of --tolerance
LIMIT = 50              # changes kept per list (the rest are counted)
TIME_SECONDS = 0.05     # the time estimate differs when it moves by more than this and ...
TIME_SHARE = 0.001      # ... by more than this share of OLD's
PLACE = 2.5             # mm in XY: "at that place" for a rapid compared with OLD's rapids
LISTS = ("deviations", "feeds", "spindle", "tool_moves", "dwell", "coolant", "rapids", "offsets")


@dataclass
class Change:
    """One change: a run of neighbouring moves (or one event) that differs alike."""

    # moved, added, removed, replaced, shifted, depth, reordered, reversed, feed, spindle, direction, tool, dwell,
    # coolant, rapid, offset
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
    by: tuple[float, float, float] | None = None  # shifted, depth: NEW is OLD moved by this

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
        if self.by is not None:
            doc["by"] = [round(v, 6) + 0.0 for v in self.by]
            doc["old_lines"], doc["new_lines"] = list(self.old_lines or (0, 0)), list(self.new_lines or (0, 0))
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
    limit: int
    # per move, how far it is from the other path (for pictures)
    new_distance: np.ndarray = field(default_factory=lambda: np.zeros(0))
    old_distance: np.ndarray = field(default_factory=lambda: np.zeros(0))
    part: PartComparison | None = None  # with a stock: both parts as cut (``add_part``)

    @property
    def tools_differ(self) -> bool:
        return self.old.tool_order() != self.new.tool_order()

    @property
    def same(self) -> bool:
        # a rapid into the stock is a finding on NEW, not a difference: the same job twice is the same
        differs = any(c.what != "rapid_into_stock" for changes in self.changes.values() for c in changes)
        return not (differs or self.time_differs or self.tools_differ)

    def to_json(self) -> dict[str, Any]:
        """The comparison as JSON values; a number that is not finite is null (never a bare Infinity/NaN)."""
        lists = {name: [c.to_json() for c in self.changes[name]] for name in LISTS}
        return _finite({
            "same": self.same, "tolerance": self.tolerance, "max_deviation": None if self.max_deviation is None else round(self.max_deviation, 6),
            "deviations": lists["deviations"], "feeds": lists["feeds"], "spindle": lists["spindle"],
            "tools": {"old": self.old.tool_order(), "new": self.new.tool_order(), "moves": lists["tool_moves"],
                      "added": tool_share(self.new, self.old), "removed": tool_share(self.old, self.new)},
            "time": {"old": round(self.time[0], 3), "new": round(self.time[1], 3)},
            "rapids": lists["rapids"], "dwell": lists["dwell"], "coolant": lists["coolant"],
            "offsets": lists["offsets"],
            "moves": {"old": len(self.old), "new": len(self.new)},
            "left_out": {name: count for name, count in self.left_out.items() if count},
            "part": self.part.to_json() if self.part is not None else None,
        })

    def add_part(self, part: PartComparison) -> None:
        """The parts as cut, and NEW's rapids into the stock with the other rapids found."""
        self.part = part
        rapids = self.changes["rapids"] + part.rapids
        self.changes["rapids"] = rapids[:self.limit]
        self.left_out["rapids"] = self.left_out.get("rapids", 0) + max(0, len(rapids) - self.limit)


def _told_as_rapid(found: dict[str, list[Change]]) -> None:
    """A lowered rapid is one change, the safety finding: the path change of the same NEW moves (and a cut
    that became that rapid, feed -> 0) is told by it; the OLD lines it replaced join the finding."""
    def within(change: Change) -> Change | None:
        span = change.new_moves
        return next((r for r in found["rapids"] if span and r.new_moves
                     and r.new_moves[0] <= span[0] and span[1] <= r.new_moves[1]), None)

    for name, kinds in (("deviations", ("moved", "added", "replaced")), ("feeds", ("feed",))):
        kept = []
        for change in found[name]:
            rapid = within(change) if change.what in kinds and (name == "deviations" or change.new == 0) else None
            if rapid is None:
                kept.append(change)
            elif change.old_lines and name == "deviations":
                lines = [n for span in (rapid.old_lines, change.old_lines) if span for n in span]
                rapid.old_lines = (min(lines), max(lines))
        found[name] = kept


def _finite(value: Any) -> Any:
    if isinstance(value, float) and not math.isfinite(value):
        return None
    if isinstance(value, dict):
        return {key: _finite(item) for key, item in value.items()}
    if isinstance(value, (list, tuple)):
        return [_finite(item) for item in value]
    return value


def tool_share(mine: Recording, other: Recording) -> list[dict[str, Any]]:
    """The tools ``mine`` puts in the spindle and ``other`` never does: each with its moves, lines, planned
    time and place in the order (the tool before it, None: first)."""
    order, theirs = mine.tool_order(), set(other.tool_order())
    shares = []
    for place, tool in enumerate(order):
        if tool in theirs or tool in order[:place]:
            continue
        moves = np.flatnonzero(operation_tools(mine, other) == tool)
        lines = _lines(mine, int(moves[0]), int(moves[-1])) if len(moves) else None
        seconds = float(np.sum(mine.times[moves, 1] - mine.times[moves, 0])) if len(moves) else 0.0
        shares.append({"tool": tool, "moves": len(moves), "lines": list(lines) if lines else None,
                       "seconds": round(seconds, 3), "after": order[place - 1] if place else None})
    return shares


def compare(old: Recording, new: Recording, tolerance: float = TOLERANCE, limit: int = LIMIT) -> Comparison:
    """Compare two recorded runs; ``limit`` bounds each list of changes."""
    dims = 6 if _turns_rotary(old) or _turns_rotary(new) else 3
    matching = match_moves(old, new, tolerance, dims)
    new_distance, new_match = matching.new_distance, matching.new_match
    found: dict[str, list[Change]] = {name: [] for name in LISTS}
    found["deviations"] = _deviations(old, new, tolerance, matching)
    # a move that goes nowhere has no place on the path, so no counterpart to compare its feed with
    near = (matching.new_paired | (new_distance <= CAPTURE)) & (new_match >= 0) & _goes_somewhere(new)
    match = np.maximum(new_match, 0)
    for name, what, new_values, old_values in (("feeds", "feed", new.feeds, old.feeds),
                                                ("spindle", "spindle", new.spindles, old.spindles),
                                                ("tool_moves", "tool", new.tools, old.tools)):
        theirs = old_values[match] if len(old) else np.zeros(len(new))  # no OLD move: nothing is near
        compared = near
        if what == "feed":  # a rapid on a rapid has no feed: the passes on either side of it are one run
            compared = near & ~(np.isin(new.kinds, RAPID_KINDS) & (new_values == theirs))
        found[name] = list(_value_changes(what, old, new, compared, match, new_values, theirs))
    for kind, name in (("dwell", "dwell"), ("coolant", "coolant"), ("spindle", "spindle")):
        found[name] += _event_changes(kind, old, new)
    found["rapids"] = lower_rapids(old, new, tolerance, matching)
    _told_as_rapid(found)
    found["offsets"] = _offsets(old, new, tolerance)
    kept = {name: changes[:limit] for name, changes in found.items()}
    left_out = {name: max(0, len(changes) - limit) for name, changes in found.items()}
    # a path against none (one job makes no moves) has no finite distance: None in the JSON
    distances = (matching.new_distance, matching.old_distance)
    biggest: float | None = max((float(d.max()) for d in distances if d.size), default=0.0)
    if biggest is not None and not np.isfinite(biggest):
        biggest = None
    time = (old.seconds, new.seconds)
    time_differs = abs(time[1] - time[0]) > max(TIME_SECONDS, TIME_SHARE * time[0])
    return Comparison(old, new, tolerance, biggest, kept, left_out, time, time_differs, limit, *distances)


def _goes_somewhere(rec: Recording) -> np.ndarray:
    moving = np.zeros(len(rec), dtype=bool)
    for axis in range(rec.ends.shape[1]):  # column by column: numpy is slow across a row of six
        moving |= np.abs(rec.ends[:, axis] - rec.starts[:, axis]) > 1e-12
    moving[rec.arc_moves()] = True
    return moving


def _turns_rotary(rec: Recording) -> bool:
    if not len(rec):
        return False
    columns = [(rec.starts[:, axis], rec.ends[:, axis]) for axis in range(3, rec.starts.shape[1])]
    return any(bool(np.maximum(a.max(), b.max()) - np.minimum(a.min(), b.min()) > 1e-9) for a, b in columns)


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


def _deviations(old: Recording, new: Recording, tolerance: float, matching: Matching) -> list[Change]:
    """Shifted features and moves done elsewhere in the order, one change each; then runs of NEW moves off
    OLD's path (moved, or added when far) and runs of OLD moves off NEW's path, which join the NEW run
    beside them with the same tool (both sides of one edit), else stand alone (removed when far)."""
    changes = [_shift_change(old, new, shift) for shift in matching.shifts]
    new_distance, old_distance = matching.new_distance.copy(), matching.old_distance.copy()
    for shift in matching.shifts:  # told once, as a whole
        new_distance[shift.new[0]:shift.new[1] + 1] = 0.0
        old_distance[shift.old[0]:shift.old[1] + 1] = 0.0
    new_match, old_match = matching.new_match, matching.old_match
    far = new_distance > CAPTURE
    tools = operation_tools(new, old)
    runs: list[Change] = []
    for first, last in _runs(new_distance > tolerance, far, tools):
        old_lines, old_moves = _matched(old, new_match, first, last)
        runs.append(Change("added" if far[first] else "moved", old_lines, _lines(new, first, last),
                           distance=float(new_distance[first:last + 1].max()), tool=int(tools[first]),
                           moves=last - first + 1, new_moves=(first, last), old_moves=old_moves))
    # which NEW run each NEW move is in, and which NEW run each OLD move lies beside: a join is a lookup
    run_of_new = np.full(len(new) + 2, -1, dtype=np.int64)
    run_of_old = np.full(len(old) + 2, -1, dtype=np.int64)
    for number, change in reversed(list(enumerate(runs))):
        for table, span in ((run_of_new, change.new_moves), (run_of_old, change.old_moves)):
            if span is not None:
                table[span[0] + 1:span[1] + 2] = number  # shifted by one: a run touches the moves beside it
    alone: list[Change] = []
    for first, last in _runs(old_distance > tolerance, old_distance > CAPTURE, old.tools):
        new_lines, new_moves = _matched(new, old_match, first, last)
        distance = float(old_distance[first:last + 1].max())
        tool = int(old.tools[first])
        near = run_of_old[first:last + 3]
        if new_moves is not None:
            near = np.concatenate((run_of_new[new_moves[0]:new_moves[1] + 3], near))
        beside = next((runs[n] for n in np.unique(near[near >= 0]).tolist() if runs[n].tool == tool), None)
        if beside is not None:
            low, high = (first, last) if beside.old_moves is None else (min(first, beside.old_moves[0]),
                                                                        max(last, beside.old_moves[1]))
            beside.old_moves, beside.old_lines = (low, high), _lines(old, low, high)
            beside.distance = max(beside.distance or 0.0, distance)
            if beside.what in ("added", "moved") and distance > CAPTURE:  # OLD went elsewhere: one path for another
                beside.what = "replaced"
            continue
        alone.append(Change("removed" if old_distance[first] > CAPTURE else "moved", _lines(old, first, last),
                            new_lines, distance=distance, tool=tool, moves=last - first + 1,
                            new_moves=new_moves, old_moves=(first, last)))
    return _one_reordering(old, new, matching, sorted(changes + runs + alone, key=lambda c: c.new_moves[0]
                                                      if c.new_moves else (c.old_moves[0] if c.old_moves else 0)))


def _one_reordering(old: Recording, new: Recording, matching: Matching, changes: list[Change]) -> list[Change]:
    """Work done in another order is one change per operation: reorderings of one tool with nothing
    between them but the same moves and rapids become one, and so do the rapids that join them in the
    new order (the way to the next hole, and home from another last one)."""
    def rapids(rec: Recording, span: tuple[int, int] | None, off: np.ndarray) -> bool:
        """Are the moves of ``span`` off the other path all rapids?"""
        if span is None:
            return True
        moves = np.arange(span[0], span[1] + 1)
        return bool(np.isin(rec.kinds[moves[off[moves] > 0.0]], RAPID_KINDS).all())

    def between_is_plain(low: int, high: int) -> bool:  # NEW moves strictly between: identical, or rapids
        inside = np.arange(low + 1, high)
        same = matching.new_paired[inside] & (matching.new_distance[inside] == 0.0)
        return bool((same | np.isin(new.kinds[inside], RAPID_KINDS)).all())

    merged: list[Change] = []
    for change in changes:
        last = merged[-1] if merged else None
        joins = (last is not None and last.new_moves is not None and change.new_moves is not None
                 and last.tool == change.tool and between_is_plain(last.new_moves[1], change.new_moves[0]))
        if joins and last is not None and {last.what, change.what} <= {"reordered", "moved", "added", "replaced"} \
                and "reordered" in (last.what, change.what) \
                and all(c.what == "reordered" or (rapids(new, c.new_moves, matching.new_distance)
                                                  and rapids(old, c.old_moves, matching.old_distance))
                        for c in (last, change)):
            spans = [s for s in (last.old_moves, change.old_moves) if s]
            low, high = last.new_moves[0], change.new_moves[1]  # type: ignore[index]
            olds = (min(a for a, _b in spans), max(b for _a, b in spans)) if spans else None
            merged[-1] = Change("reordered", _lines(old, *olds) if olds else None, _lines(new, low, high),
                                distance=0.0, tool=last.tool, moves=high - low + 1, new_moves=(low, high),
                                old_moves=olds)
            continue
        merged.append(change)
    return merged


def operation_tools(new: Recording, old: Recording) -> np.ndarray:
    """The tool of each NEW move, the moves of a tool change (the macro's, made on its line) counted with
    the tool it puts in when OLD never uses that tool: they are part of the tool added."""
    tools = new.tools.copy()
    added = set(new.tool_order()) - set(old.tool_order())
    for kind, line, value, at in new.events:
        if kind == "tool_change" and int(value) in added:
            move = at - 1
            while move >= 0 and new.lines[move] == line:
                tools[move] = int(value)
                move -= 1
    return tools


def _shift_change(old: Recording, new: Recording, shift: Shift) -> Change:
    """A shifted feature (``depth`` when it moved in Z only), or moves done at another place in the order."""
    (a, b), (c, d) = shift.old, shift.new
    common: dict[str, Any] = {"tool": int(new.tools[c]), "moves": d - c + 1, "new_moves": (c, d), "old_moves": (a, b)}
    if shift.backwards:
        return Change("reversed", _lines(old, a, b), _lines(new, c, d), distance=0.0, **common)
    if shift.by is None:
        return Change("reordered", _lines(old, a, b), _lines(new, c, d), distance=0.0, **common)
    by = shift.by
    size = float(np.linalg.norm(by))
    if abs(by[0]) < 1e-9 and abs(by[1]) < 1e-9:  # deeper or shallower: the lowest Z of the feature, before and after
        low = float(np.minimum(old.starts[a:b + 1, 2], old.ends[a:b + 1, 2]).min())
        return Change("depth", _lines(old, a, b), _lines(new, c, d), old=_number(low), new=_number(low + by[2]),
                      distance=size, by=by, **common)
    return Change("shifted", _lines(old, a, b), _lines(new, c, d), distance=size, by=by, **common)


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
    """Events of one kind compared as sequences: each stretch replaced, added or left out is one change at
    its lines, its values in words (M3/M4/M5, M7/M8/M9; a list when the stretch holds several)."""
    words = {"spindle": SPINDLE_WORDS, "coolant": COOLANT_WORDS}.get(kind, {})
    mine = [(line, value) for k, line, value, _at in old.events if k == kind]
    theirs = [(line, value) for k, line, value, _at in new.events if k == kind]
    what = "direction" if kind == "spindle" else kind

    def told(events: list[tuple[int, float]]) -> tuple[tuple[int, int] | None, Any]:
        if not events:
            return None, None
        lines = [line for line, _v in events]
        values = [words.get(v, _number(v)) for _l, v in events]
        return (min(lines), max(lines)), values[0] if len(values) == 1 else values

    changes: list[Change] = []
    matcher = difflib.SequenceMatcher(None, [v for _l, v in mine], [v for _l, v in theirs], autojunk=False)
    for tag, i1, i2, j1, j2 in matcher.get_opcodes():
        if tag != "equal":
            (old_lines, before), (new_lines, after) = told(mine[i1:i2]), told(theirs[j1:j2])
            changes.append(Change(what, old_lines, new_lines, old=before, new=after, moves=max(i2 - i1, j2 - j1)))
    return changes


def lower_rapids(old: Recording, new: Recording, tolerance: float, matching: Matching) -> list[Change]:
    """NEW rapids that end lower than OLD's rapids went at that place (within ``PLACE`` mm in XY; where OLD
    made no rapid, lower than all of them): a new way into the part or the vise.  A rapid that climbs (a
    retract) is never one: it goes where the tool already was."""
    def descending(rec: Recording) -> np.ndarray:
        return (rec.kinds == RAPID_KINDS[0]) & (rec.ends[:, 2] <= rec.starts[:, 2] + tolerance)

    old_down = np.flatnonzero(descending(old))
    if not len(old_down):
        return []
    floor = float(old.ends[old_down, 2].min())
    same = matching.new_paired & (matching.new_distance == 0.0)  # identical, here or at another place in the order
    suspects = np.flatnonzero(descending(new) & ~same)
    # OLD's descending rapids as points every PLACE / 2 mm, filed by their XY cell with the lowest Z in it
    a, b = old.starts[old_down, :3], old.ends[old_down, :3]
    steps = np.maximum(1, np.ceil(np.linalg.norm(b[:, :2] - a[:, :2], axis=1) / (PLACE / 2))).astype(np.int64)
    which, slot = slots(np.arange(len(a)), steps)
    points = a[which] + ((slot + 1) / steps[which])[:, None] * (b[which] - a[which])
    cells: dict[tuple[int, int], float] = {}
    for (x, y), z in zip(np.floor(points[:, :2] / PLACE).astype(np.int64).tolist(), points[:, 2].tolist()):
        cells[(x, y)] = min(z, cells.get((x, y), math.inf))
    below = np.zeros(len(new), dtype=bool)
    reference = np.full(len(new), floor)
    for move in suspects.tolist():
        x, y = (int(v) for v in np.floor(new.ends[move, :2] / PLACE))
        here = min((cells.get((x + i, y + j), math.inf) for i in (-1, 0, 1) for j in (-1, 0, 1)), default=math.inf)
        reference[move] = here if math.isfinite(here) else floor
        below[move] = new.ends[move, 2] < reference[move] - tolerance
    changes = []
    for first, last in _runs(below):
        old_lines, old_moves = _matched(old, matching.new_match, first, last)
        changes.append(Change("rapid", old_lines, _lines(new, first, last),
                              old=_number(round(float(reference[first:last + 1][below[first:last + 1]].min()), 6)),
                              new=_number(round(float(new.ends[first:last + 1, 2].min()), 6)),
                              tool=int(new.tools[first]), moves=last - first + 1, new_moves=(first, last),
                              old_moves=old_moves))
    return changes


def _offsets(old: Recording, new: Recording, tolerance: float) -> list[Change]:
    """The work zero at the end (G5x + G92 + tool length): the moves show the offsets' effect, this names the cause."""
    if old.result is None or new.result is None:
        return []
    before, after = old.result.work_zero, new.result.work_zero
    if max(abs(a - b) for a, b in zip(before, after)) <= tolerance:
        return []
    return [Change("offset", None, None, old=[round(v, 6) for v in before[:3]], new=[round(v, 6) for v in after[:3]])]
