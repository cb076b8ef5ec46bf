"""Runs of hole lines read in bulk: ``hole_moves``, the Python reference of the compiled
``_speedups.hole_moves`` (``csrc/speedups_holes.c``), which the canned cycles (``canned.py``) call for
the lines of a run that only name the next hole (``X.. Y..`` under G81).  Both give the same moves for
the same lines, to the bit (tests/interpreter/test_hole_runs.py).
"""
from __future__ import annotations

from collections.abc import Sequence
from functools import cache
from itertools import islice, repeat, takewhile
from operator import add, mul

from edingcnc_lang.canon import AXES
from edingcnc_lang.machine.plain_runs import letters_of_lines, numbers_of_lines

BLOCK = 512  # lines read at a time

# What hole_moves returns: the index of the first line it left, the line number of each move and its end.
Holes = tuple[int, list[int], list[tuple[float, ...]]]


@cache
def _shapes(first: str, second: str) -> dict[str, tuple[int, int, int]]:
    """The letters a hole line may have (an N first, then one or both of the plane's axes, each once), each
    with where the two axes' numbers are among the line's numbers (-1: no such word) and how many it has."""
    shapes = {}
    for n in ("", "N"):
        for axes in (first, second, first + second, second + first):
            letters = n + axes
            shapes[letters] = (letters.find(first), letters.find(second), len(letters))
    return shapes


def hole_moves(lines: Sequence[tuple[int, str]], first: int, stop: int, axes: tuple[int, int, int],
               pos: Sequence[float], offset: Sequence[float], scale: float, incremental: bool,
               levels: Sequence[float]) -> Holes:
    """The moves of the holes that lines[first:stop] name, while each line only names the next hole.

    A line may hold an N word and then the words of the cycle's plane axes ``axes[0]`` and
    ``axes[1]`` (one or both, each once) and nothing else, not even a comment.  Each hole is drilled
    as the general path drills it: its work position is the machine position of the hole before
    (``pos`` for the first) less ``offset``, the line's words put in (times ``scale``, added under
    G91), and its moves end there plus ``offset``, at the machine ``levels`` along ``axes[2]``.
    """
    a1, a2, normal = axes
    shapes = _shapes(AXES[a1], AXES[a2])
    o1, o2 = offset[a1], offset[a2]
    p1, p2 = pos[a1], pos[a2]
    firsts: list[float] = []  # each hole's machine position on the plane's two axes
    seconds: list[float] = []
    numbers: list[int] = []
    index = first
    stop = min(stop, len(lines))
    while index < stop:
        chunk = lines[index:min(index + BLOCK, stop)]
        joined = "\n".join([text for _, text in chunk])
        # each line's letters and the lines' number texts: the lines are plain (the check pass's FAST_LINE), so
        # each letter has exactly one number
        letters = letters_of_lines(joined).decode("ascii").split("\n")
        values = numbers_of_lines(joined)
        at = taken = 0  # the numbers and lines of the chunk taken
        while taken < len(chunk):
            shape = shapes.get(letters[taken])
            if shape is None:
                stop = index + taken
                break
            i1, i2, width = shape
            same = 1
            if i1 >= 0 and i2 >= 0 and not incremental:  # lines of one shape ahead: read as columns
                same = sum(1 for _ in takewhile(letters[taken].__eq__, islice(letters, taken, None)))
            if same > 1:
                words = values[at:at + same * width]
                firsts += map(add, map(mul, map(float, words[i1::width]), repeat(scale)), repeat(o1))
                seconds += map(add, map(mul, map(float, words[i2::width]), repeat(scale)), repeat(o2))
                p1, p2 = firsts[-1], seconds[-1]
            else:
                w1 = p1 - o1 if i1 < 0 or incremental else 0.0
                if i1 >= 0:
                    w1 = w1 + float(values[at + i1]) * scale if incremental else float(values[at + i1]) * scale
                w2 = p2 - o2 if i2 < 0 or incremental else 0.0
                if i2 >= 0:
                    w2 = w2 + float(values[at + i2]) * scale if incremental else float(values[at + i2]) * scale
                p1, p2 = w1 + o1, w2 + o2
                firsts.append(p1)
                seconds.append(p2)
            numbers += [number for number, _text in chunk[taken:taken + same]]
            at += same * width
            taken += same
        index += taken
    # the other axes stay, each at the work position plus the offset, as the general path writes them
    a, b, c = rest = tuple((pos[i] - offset[i]) + offset[i] for i in range(3, 6))
    lines_of = [number for number in numbers for _ in levels]
    if any((r - o) + o != r for r, o in zip(rest, offset[3:])):  # not the same for every hole: hole by hole
        rests = []
        for _ in numbers:
            rests.append(rest)
            rest = tuple((r - o) + o for r, o in zip(rest, offset[3:]))
        holes = zip(firsts, seconds, rests)
        if normal == 2:  # XY: (first, second) = (X, Y)
            return index, lines_of, [(x, y, z, *r) for x, y, r in holes for z in levels]
        if normal == 1:  # XZ: (first, second) = (Z, X)
            return index, lines_of, [(x, y, z, *r) for z, x, r in holes for y in levels]
        return index, lines_of, [(x, y, z, *r) for y, z, r in holes for x in levels]
    if normal == 2:
        return index, lines_of, [(x, y, z, a, b, c) for x, y in zip(firsts, seconds) for z in levels]
    if normal == 1:
        return index, lines_of, [(x, y, z, a, b, c) for z, x in zip(firsts, seconds) for y in levels]
    return index, lines_of, [(x, y, z, a, b, c) for y, z in zip(firsts, seconds) for x in levels]
