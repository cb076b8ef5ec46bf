"""The comparison as text for people: per operation (a tool's share of NEW, in order), what changed
and where, with the OLD and NEW source lines; then the tools, events, offsets, time and rapids."""
from __future__ import annotations

import math
from collections.abc import Iterable

import numpy as np

from edingcnc_lang.errors import EcncError, printable
from edingcnc_lang.motion.planner.estimate import format_duration
from edingcnc_lang.syntax.source import iter_file_lines
from edingcnc_lang.diff.compare import LISTS, Change, Comparison, operation_tools, tool_share
from edingcnc_lang.diff.record import Recording

SHOWN_TEXT = 60  # characters of a source line shown


def source_text(path: str, numbers: Iterable[int]) -> dict[int, str]:
    """The text of lines ``numbers`` of ``path``, read once in a stream (none for a file gone)."""
    wanted = set(numbers)
    found: dict[int, str] = {}
    if not wanted:
        return found
    try:
        for number, text in enumerate(iter_file_lines(path), start=1):
            if number in wanted:
                found[number] = printable(text.strip())[:SHOWN_TEXT]
                if len(found) == len(wanted):
                    break
    except (OSError, EcncError):  # a file gone since the run: no text, the report still stands
        pass
    return found


def headline(change: Change, tolerance: float) -> str:
    where = []
    if change.old_lines:
        where.append(f"OLD {_span(change.old_lines)}")
    if change.new_lines:
        where.append(f"NEW {_span(change.new_lines)}")
    moves = f", {change.moves} moves" if change.moves > 1 else ""
    at = ", ".join(where)
    what = change.what
    if what in ("moved", "added", "removed", "replaced"):
        text = {"moved": "path moved by up to", "added": "path only in NEW, up to",
                "removed": "path only in OLD, up to", "replaced": "path replaced, up to"}[what]
        if change.distance is None or not math.isfinite(change.distance):
            return f"{text.rsplit(',', 1)[0]} (the other job makes no moves){moves}: {at}"
        return f"{text} {change.distance:.4g} mm from the other{moves}: {at}"
    if what == "feed":
        return f"feed {change.old:g} -> {change.new:g} mm/min{moves}: {at}"
    if what == "spindle":
        return f"spindle {change.old:g} -> {change.new:g} rpm{moves}: {at}"
    if what == "tool":
        return f"tool T{change.old} -> T{change.new} in the spindle{moves}: {at}"
    if what == "rapid":
        return f"rapid down to Z{change.new:g} (machine), lower than OLD's rapids there (Z{change.old:g}){moves}: {at}"
    if what == "rapid_into_stock":
        return f"rapid into the stock, {change.distance:.4g} mm deep: {at}"
    if what == "shifted" and change.by is not None:
        return f"moved by ({', '.join(f'{v:g}' for v in change.by)}) mm{moves}: {at}"
    if what == "depth":
        return f"depth Z{change.old:g} -> Z{change.new:g} (machine){moves}: {at}"
    if what == "reversed":
        return f"the same path driven the other way (climb and conventional milling swap){moves}: {at}"
    if what == "reordered":
        return f"the same moves at another place in the order{moves}: {at}"
    if what == "offset":
        return f"work zero at the end: OLD {change.old}, NEW {change.new}"
    return f"{_event_name(change)}: {at}"


def _event_name(change: Change) -> str:
    """An event's change in words: "spindle M3 -> M4", "coolant M8 added", "dwell 3 s removed"."""
    name = {"direction": "spindle", "coolant": "coolant", "dwell": "dwell"}.get(change.what, change.what)
    unit = " s" if change.what == "dwell" else ""

    def words(value: object) -> str:
        values = value if isinstance(value, list) else [value]
        return " ".join(f"{v}{unit}" for v in values)

    if change.old is None:
        return f"{name} {words(change.new)} added"
    if change.new is None:
        return f"{name} {words(change.old)} removed"
    return f"{name} {words(change.old)} -> {words(change.new)}"


def _span(lines: tuple[int, int]) -> str:
    return f"line {lines[0]}" if lines[0] == lines[1] else f"lines {lines[0]}-{lines[1]}"


def _operations(rec: Recording, other: Recording) -> list[tuple[int, int, int]]:
    """(first move, last move, tool) of each run of NEW moves with one tool in the spindle (the tool
    change that puts in a tool OLD never uses counted with that tool)."""
    if not len(rec):
        return []
    tools = operation_tools(rec, other)
    cut = np.flatnonzero(np.diff(tools)) + 1
    firsts = np.concatenate(([0], cut))
    lasts = np.append(cut, len(rec)) - 1
    return [(int(f), int(l), int(tools[f])) for f, l in zip(firsts, lasts)]


def render(comparison: Comparison) -> str:
    """The whole report."""
    old, new = comparison.old, comparison.new
    out = [f"OLD {old.name}: {len(old):,} moves, {format_duration(comparison.time[0])} planned",
           f"NEW {new.name}: {len(new):,} moves, {format_duration(comparison.time[1])} planned"]
    if comparison.same:
        out.append(f"same: nothing the machine does differs beyond {comparison.tolerance:g} mm")
        return "\n".join(out + _part(comparison)) + "\n"
    biggest = "no path to compare with" if comparison.max_deviation is None else f"{comparison.max_deviation:.4g} mm"
    out.append(f"differs: largest path deviation {biggest} (tolerance {comparison.tolerance:g} mm)")
    changes = [c for name in LISTS for c in comparison.changes[name] if c.what != "rapid_into_stock"]
    old_text = source_text(old.name, (n for c in changes if c.old_lines for n in {c.old_lines[0], c.old_lines[1]}))
    new_text = source_text(new.name, (n for c in changes if c.new_lines for n in {c.new_lines[0], c.new_lines[1]}))
    placed: set[int] = set()
    for first, last, tool in _operations(new, old):
        mine = [c for c in changes if c.new_moves and first <= c.new_moves[0] <= last]
        if not mine:
            continue
        lines = [n for n in new.lines[first:last + 1].tolist() if n > 0]
        span = f"NEW lines {min(lines)}-{max(lines)}" if lines else "NEW"
        out.append(f"\nT{tool} ({span}):")
        placed.update(id(change) for change in mine)
        out += _told(sorted(mine, key=lambda c: c.new_moves[0] if c.new_moves else 0), comparison.tolerance,
                     old_text, new_text)
    rest = [c for c in changes if id(c) not in placed]
    if rest:
        out.append("\nelsewhere:")
        out += _told(rest, comparison.tolerance, old_text, new_text)
    if comparison.tools_differ:
        out.append(f"\ntools: OLD {' '.join(f'T{t}' for t in old.tool_order()) or 'none'}, "
                   f"NEW {' '.join(f'T{t}' for t in new.tool_order()) or 'none'}")
    for side, ours, theirs in (("added", new, old), ("removed", old, new)):
        for share in tool_share(ours, theirs):
            where = f"{'NEW' if side == 'added' else 'OLD'} lines {share['lines'][0]}-{share['lines'][1]}, " \
                if share["lines"] else ""
            after = f"after T{share['after']}" if share["after"] is not None else "first"
            out.append(f"T{share['tool']} {side}: {share['moves']} moves, {where}"
                       f"{format_duration(share['seconds'])}, {after}")
    if comparison.time_differs:
        delta = comparison.time[1] - comparison.time[0]
        out.append(f"time: OLD {format_duration(comparison.time[0])}, NEW {format_duration(comparison.time[1])} "
                   f"({'+' if delta >= 0 else '-'}{format_duration(abs(delta))})")
    for name, count in comparison.left_out.items():
        if count:
            out.append(f"({count} more {name} changes left out)")
    return "\n".join(out + _part(comparison)) + "\n"


def _part(comparison: Comparison) -> list[str]:
    """The parts as cut (``--stock``): same or where they differ, and NEW's rapids into the stock."""
    part = comparison.part
    if part is None:
        return []
    if part.same:
        out = [f"part: the same part (no cell of {part.old.resolution:g} mm differs by more than "
               f"{part.tolerance:g} mm)"]
    else:
        out = [f"part: differs by up to {part.max_deviation:.4g} mm (mean {part.mean_deviation:.4g} mm) "
               f"in {len(part.regions)} region{'s' if len(part.regions) != 1 else ''}:"]
        for region in part.regions:
            x0, y0, x1, y1 = region.bounds
            who = {"new": "NEW cuts deeper", "old": "OLD cuts deeper", "both": "each deeper in places"}[region.deeper]
            lines = ", ".join(f"{side} {_span(span)}" for side, span in (("OLD", region.old_lines),
                                                                          ("NEW", region.new_lines)) if span)
            out.append(f"  X{x0:g}..{x1:g} Y{y0:g}..{y1:g}: up to {region.max_deviation:.4g} mm, {who}"
                       f"{': ' + lines if lines else ''}")
    for rapid in comparison.changes["rapids"]:
        if rapid.what == "rapid_into_stock" and rapid.new_lines:
            out.append(f"  {headline(rapid, comparison.tolerance)}")
    return out


def _told(changes: list[Change], tolerance: float, old_text: dict[int, str], new_text: dict[int, str]) -> list[str]:
    """The changes in order; the same change again at once (the passes of a loop) is told once, with a count."""
    out: list[str] = []
    told, times, at = "", 0, 0
    for change in [*changes, None]:
        title = headline(change, tolerance) if change is not None else ""
        if title == told:
            times += 1
            continue
        if times > 1:
            out[at] += f" ({times} times)"
        if change is not None:
            at = len(out)
            out += _described(change, title, old_text, new_text)
        told, times = title, 1
    return out


def _described(change: Change, headline: str, old_text: dict[int, str], new_text: dict[int, str]) -> list[str]:
    lines = [f"  {headline}"]
    for side, span, texts in (("OLD", change.old_lines, old_text), ("NEW", change.new_lines, new_text)):
        if span and span[0] in texts:
            lines.append(f"    {side} {span[0]:>6}: {texts[span[0]]}")
    return lines
