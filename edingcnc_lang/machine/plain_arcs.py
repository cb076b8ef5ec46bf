"""Runs of plain arc lines turned into arcs: ``plain_arcs``, the Python form of the compiled
``_speedups.plain_arcs`` (``csrc/speedups_arcs.c``), which the bulk path (``bulk.py``) calls for the arc
lines of a run.  Both read a line as the general path does (``BulkPath._arc_of_words``: its ``_target``
and ``arc_plan`` over geometry.py's ``center_from_radius``, ``check_radius`` and ``sweep``) and give the same
records to the bit (tests/arc_lines.py holds both to it); this one is that reading written as one loop over a
run's lines, the steps of those functions inlined and a run of lines of one shape read as columns, so that a
run of arcs costs the Python core a few microseconds a line instead of a dozen.
"""
from __future__ import annotations

import math
from collections.abc import Callable, Iterator, Sequence
from typing import Any

from edingcnc_lang.machine.plain_runs import (LETTERS_OF, NO_MOTION, POSSESSIVE, SHAPE_LEAST, line_target,
                                               motion_texts, read_motion, shape_values, usual_order, words_row)
from edingcnc_lang.machine.state import G_2, G_3

_LETTERS = "GXYZABCIJKRF"  # the words an arc line may hold besides N, in the order CAM output writes them
ARC_ORDER = usual_order("[0-9.]+" + POSSESSIVE, POSSESSIVE, _LETTERS)
# The slots of a row's centre words by plane (0 XY, 1 XZ, 2 YZ, as _speedups.c numbers them): the first and
# second in-plane centre words (I J, K I, J K), the other plane's word a line of this plane may not hold, and
# the in-plane and normal axes of a pose.
_I, _J, _K = 7, 8, 9
_PLANE_WORDS = ((_I, _J, _K), (_K, _I, _J), (_J, _K, _I))
_PLANE_AXES = ((0, 1, 2), (2, 0, 1), (1, 2, 0))
_HALF_PI = math.pi / 2
_TURN = 2 * math.pi
_MOTIONS = {2.0: G_2, 3.0: G_3}
_MOTION_OF = motion_texts(_MOTIONS)  # "02" is G2, any other text is read as a number (read_motion)

Pose = tuple[float, ...]
# What plain_arcs returns (the compiled one's tuple): the index of the first line it left, whether it read
# that line (always: the compiled scan leaves some lines to the Python reading), the motion and feed in force
# after the run, and its arcs as columns: line numbers, ends, feeds, arcs (canon.Arc) and lengths.
ArcScan = tuple[int, bool, int, float, list[int], list[Pose], list[float], list[Any], list[float]]


def plain_arcs(lines: Sequence[tuple[int, str]], first: int, start: Sequence[float], offset: Sequence[float],
               scale: float, incremental: bool, motion: int, feed: float, room: int, plane: int, reverse: bool,
               tolerance: float, epsilon: float, tiny: float, arc_class: Any, plane_name: str) -> ArcScan:
    """The arcs of lines[first:] while each is a simple arc line, at most ``room`` of them.

    A line may hold G2/G3 (or have either in force), axis words, the plane's centre words or R, F and N,
    each once; F >= 0 and a feed.  Targets are found as plain_moves finds them; the centre, the radius
    check (manual p. 20: ``tolerance`` whatever the radius), the sweep (a full circle when it sweeps less
    than ``epsilon`` and its ends meet) and the length (the helix GetJobDistance counts) as the general
    path finds them.  It stops at the first other line, or one whose arc the general path refuses (the
    general path then reads it again and reports it).
    """
    hypot, atan2, cos, sin, asin = math.hypot, math.atan2, math.cos, math.sin, math.asin
    numbers: list[int] = []
    ends: list[Pose] = []
    feeds: list[float] = []
    arcs: list[Any] = []
    lengths: list[float] = []
    match, motion_of = ARC_ORDER.match, _MOTION_OF.get
    new_arc, set_center, set_plane, set_turn, set_full = _arc_maker(arc_class)
    first_word, second_word, other_word = _PLANE_WORDS[plane]
    u, v, normal = _PLANE_AXES[plane]
    position = tuple(start)
    stop = min(len(lines), first + max(room, 0))
    index = first
    look = True  # whether to look for a run of lines of the shape of the next one read the usual way
    ahead: Iterator[Sequence[str]] = iter(())  # the rows of such a run, read at once
    ahead_stop = index  # the line after it
    while index < stop:
        lineno, text = lines[index]
        row: Sequence[str | None] | None
        if index < ahead_stop:
            row = next(ahead)
        else:
            usual = match(text)
            row = usual.groups() if usual is not None else words_row(text, _LETTERS)
            if row is None:
                break
            if look and usual is not None and stop - index > SHAPE_LEAST and ";" not in text:
                look, count, ahead = _rows_ahead(lines, index + 1, stop, text.translate(LETTERS_OF))
                ahead_stop = index + 1 + count
        g, x, y, z, a, b, c, i, j, k, r, f = row  # number texts; empty or None where the line has no such word
        line_motion = motion
        if g:
            line_motion = motion_of(g, NO_MOTION)
            if line_motion == NO_MOTION:  # a text not in the table: read as a number
                line_motion = read_motion(g, _MOTIONS)
        d1, d2 = row[first_word], row[second_word]  # the centre words' texts
        if (line_motion != G_2 and line_motion != G_3) or row[other_word] or not (x or y or z or a or b or c) \
                or (r and (d1 or d2)) or not (r or d1 or d2):
            break
        line_feed = feed
        if f:
            value = float(f)
            if value < 0:
                break
            line_feed = value * scale
        if line_feed <= 0:
            break
        end = line_target(position, offset, scale, incremental, x, y, z, a, b, c)
        s1, s2, e1, e2 = position[u], position[v], end[u], end[v]
        clockwise = (line_motion == G_2) != reverse
        if r:  # geometry.center_from_radius
            radius = float(r) * scale
            if hypot(e1 - s1, e2 - s2) < tiny:
                break
            abs_r = abs(radius)
            mid1, mid2 = (s1 + e1) / 2.0, (s2 + e2) / 2.0
            half = hypot(mid1 - e1, mid2 - e2)
            if half - abs_r > tolerance or abs_r == 0.0:
                break
            if half / abs_r > 1.0 - tiny:
                half = abs_r
            theta = atan2(e2 - s2, e1 - s1) + (-_HALF_PI if clockwise == (radius > 0) else _HALF_PI)
            shift = abs_r * cos(asin(half / abs_r))
            c1, c2 = mid1 + shift * cos(theta), mid2 + shift * sin(theta)
            r1 = hypot(s1 - c1, s2 - c2)
        else:  # geometry.check_radius
            c1 = s1 + (float(d1) * scale if d1 else 0.0)
            c2 = s2 + (float(d2) * scale if d2 else 0.0)
            r1 = hypot(s1 - c1, s2 - c2)
            if r1 < tiny or abs(r1 - hypot(e1 - c1, e2 - c2)) > tolerance:
                break
        a0, a1 = atan2(s2 - c2, s1 - c1), atan2(e2 - c2, e1 - c1)  # geometry.sweep
        delta = ((a0 - a1) if clockwise else (a1 - a0)) % _TURN
        full = delta == 0.0 or (not r and delta < epsilon and hypot(s1 - e1, s2 - e2) <= tolerance)
        # state.path_length: the helix GetJobDistance counts, a full circle one more turn
        lengths.append(hypot(r1 * (delta + _TURN * full), end[normal] - position[normal]))
        arc = new_arc(arc_class)  # a canon.Arc, made as its __init__ makes it (in half the time)
        set_center(arc, (c2, c1) if plane == 1 else (c1, c2))
        set_plane(arc, plane_name)
        set_turn(arc, -1 if clockwise else 1)
        set_full(arc, int(full))
        arcs.append(arc)
        numbers.append(lineno)
        ends.append(end)
        feeds.append(line_feed)
        position, motion, feed = end, line_motion, line_feed
        index += 1
    return index, True, motion, feed, numbers, ends, feeds, arcs, lengths


def _rows_ahead(lines: Sequence[tuple[int, str]], first: int, stop: int,
                shape: str) -> tuple[bool, int, Iterator[tuple[str, ...]]]:
    """The rows (``ARC_ORDER``'s groups, '' for None) of the lines from ``first`` whose letters are ``shape``
    (a line's words in ARC_ORDER's order, no comment), read as columns with string methods instead of a match
    a line (plain_runs.shape_values): whether to look again after them (not after a look that found none: a
    CAM pass's arcs change shape every few lines), how many and the rows."""
    if lines[min(first + SHAPE_LEAST - 1, stop - 1)][1].translate(LETTERS_OF) != shape:
        return False, 0, iter(())
    count, values = shape_values(lines, first, stop, shape)
    width = len(shape)
    missing = [""] * count
    return count > 0, count, zip(*[values[shape.index(letter)::width] if letter in shape else missing
                                   for letter in _LETTERS])


def _arc_maker(arc_class: Any) -> tuple[Callable[..., Any], ...]:
    """``arc_class.__new__`` and the setters of its four fields past a frozen __setattr__: a slot's descriptor
    (what records.py's __init__ sets it with), else object.__setattr__ (as the compiled one does)."""
    def setter(name: str) -> Callable[[Any, Any], None]:
        descriptor = getattr(arc_class, name, None)
        if hasattr(descriptor, "__set__"):
            return descriptor.__set__  # type: ignore[union-attr]
        return lambda made, value: object.__setattr__(made, name, value)
    return (arc_class.__new__, *(setter(name) for name in ("center", "plane", "turn", "full_turns")))
