"""Runs of plain G0/G1 lines turned into targets: ``plain_moves``, the Python reference of the compiled
``_speedups.plain_moves`` (``csrc/speedups_plain.c``), which the bulk path (``bulk.py``) calls for the
straight lines of a run.  Both give the same columns for the same lines, to the bit (tests/speedups/test_speedups.py).
"""
from __future__ import annotations

import re
import string
import sys
from collections.abc import Iterable, Mapping, Sequence
from itertools import accumulate, islice, repeat, takewhile
from operator import add, mul

from edingcnc_lang.syntax.plain_words import plain_words
from edingcnc_lang.machine.state import G_0, G_1

NO_MOTION = -1  # the motion in force is neither G0 nor G1: a line must name one itself
# The usual order of a CAM line's words, [N] [G] [X] [Y] [Z] [A] [B] [C] [F], so it reads a line as
# plain_words would, only faster.  A number is any run of digits and points: the lines are plain
# (FAST_LINE), whose every number is a whole FAST_NUMBER (no digit or point follows one), so this reads
# the same words as FAST_NUMBER would (tests/interpreter/test_plain_runs.py holds it to
# ``usual_order(FAST_NUMBER, "")``).  For the same reason no word, blank or number ever has to give
# back what it took: from Python 3.11 on they are possessive, so that a line of other words (an arc's)
# fails at once instead of trying every shorter number; before, each optional word is "(?:...|)", which
# Python's engine runs faster than "(?:...)?".
POSSESSIVE = "+" if sys.version_info >= (3, 11) else ""


def usual_order(number: str, possessive: str, letters: str = "GXYZABCF") -> re.Pattern[str]:
    """The usual order's pattern, its numbers read by ``number``; ``possessive``: "+" or ""; ``letters``: the
    words after N, in their order (plain_arcs.py reads arc lines with the same pattern of its own letters)."""
    blank = r"[ \t]*" + possessive
    word = "(?:{}" + (")?+" if possessive else "|)")
    return re.compile(blank + word.format(f"[Nn]{blank}[+-]?{number}{blank}")
                      + "".join(word.format(f"[{a}{a.lower()}]{blank}([+-]?{number}){blank}") for a in letters)
                      + word.format(";.*") + "$")


USUAL_ORDER = usual_order("[0-9.]+" + POSSESSIVE, POSSESSIVE)


def motion_texts(motions: Mapping[float, int]) -> dict[str, int]:
    """The motion of each G text CAM output writes for the codes ``motions`` (number: motion), looked up
    instead of read as a number: "1", "01", "1.", "1.0", "+1" (and "-0"); a text is its number's motion."""
    texts = {}
    for number, motion in motions.items():
        code = f"{number:g}"
        for text in (code, "0" + code, code + ".", code + ".0", "+" + code, *(("-0",) if number == 0 else ())):
            texts[text] = motion
    return texts


def read_motion(g: str, motions: Mapping[float, int]) -> int:
    """The motion of a G text that is not in ``motion_texts``' table, read as a number; NO_MOTION for another code."""
    return motions.get(float(g), NO_MOTION)


_MOTIONS = {0.0: G_0, 1.0: G_1}
_MOTION_OF = motion_texts(_MOTIONS)
# A run of lines of one shape (the same letters in the same order, the same G text, no comment), as
# CAM output and surfacing jobs write them, is read as columns with string methods instead of a match
# and a loop step per line: the lines are plain (the check pass's FAST_LINE), so deleting the numbers
# and blanks leaves a line's letters, and blanking the letters leaves its number texts.
LETTERS_OF = str.maketrans({**dict.fromkeys("0123456789.+- \t"), **{c: c.upper() for c in string.ascii_lowercase}})
SHAPE_LEAST = 16  # lines of one shape that make a run worth reading in bulk
SHAPE_BLOCK = 32  # lines read for the first block of a run of one shape; each further block is four times larger
MAX_SKIP = 63  # chances let pass at most after looks for a run of one shape that found none

class _Looks:
    """How often ``plain_moves`` looks for a run of one shape ahead: a guess for speed alone (the
    moves are the same either way).  After looks that found none it lets more and more chances pass
    (1, 3, 7, ... at most MAX_SKIP), so CAM output, whose shape changes every few lines, costs few
    looks; a look that finds a run looks at every chance again."""

    skip = 0  # chances still to let pass
    misses = 0  # how many to let pass after the next look that finds none

    def found(self, found: bool) -> None:
        self.misses = 0 if found else min(2 * self.misses + 1, MAX_SKIP)
        self.skip = self.misses


_looks = _Looks()

# What plain_moves returns: the index of the first line it left, the steps it took (lines it
# consumed), the motion and feed in force after them, and the moves as columns: kinds, line
# numbers, end points, feeds (0 for rapids) and the feed in force at each move.
Columns = tuple[list[str], list[int], list[tuple[float, ...]], list[float], list[float]]
Scanned = tuple[int, int, int, float, list[str], list[int], list[tuple[float, ...]], list[float], list[float]]


def plain_moves(lines: Sequence[tuple[int, str]], first: int, pos: Sequence[float], offset: Sequence[float],
                scale: float, incremental: bool, motion: int, feed: float, room: int) -> Scanned:
    """Targets of lines[first:] while each is a plain straight move: the batch form of a line's steps.

    A line may hold G0/G1, X Y Z A B C, F and N words, each once, and nothing else; F >= 0; a G1
    needs a feed.  Axis values are scaled by ``scale`` (inch) on X Y Z; a target is the position
    plus the value under G91, the work offset plus it under G90, as the general path's
    ``_target``.  It stops at the first other line, or after ``room`` lines (the step budget).
    ``lines`` are plain lines (the check pass's ``FAST_LINE``), which a run of one shape relies on.
    """
    kinds: list[str] = []
    numbers: list[int] = []
    ends: list[tuple[float, ...]] = []
    feeds: list[float] = []
    in_force: list[float] = []
    # (bound once: a CAM pass calls this for every few lines, and each line costs a handful of steps)
    match, add_kind, add_number, add_end, add_feed, add_force = (
        USUAL_ORDER.match, kinds.append, numbers.append, ends.append, feeds.append, in_force.append)
    position = tuple(pos)
    stop = min(len(lines), first + max(room, 0))
    bulk = True  # whether to look for a run of lines of the shape of this one (_same_shape)
    index = first
    while index < stop:
        lineno, text = lines[index]
        usual = match(text)
        row = usual.groups() if usual is not None else words_row(text)
        if row is None:
            break
        g, x, y, z, a, b, c, f = row  # the number texts, empty or None where the line has no such word
        line_motion, new_feed = motion, feed
        if g:
            line_motion = _MOTION_OF.get(g, NO_MOTION)
            if line_motion == NO_MOTION:  # a text not in the table: read as a number
                line_motion = read_motion(g, _MOTIONS)
        if f:
            value = float(f)
            if value < 0:
                break
            new_feed = value * scale
        if line_motion == NO_MOTION:
            break
        if x or y or z or a or b or c:
            if line_motion == G_1:
                if new_feed <= 0:
                    break
                add_kind("linear")
                add_feed(new_feed)
            else:
                add_kind("rapid")
                add_feed(0.0)
            position = line_target(position, offset, scale, incremental, x, y, z, a, b, c)
            add_number(lineno)
            add_end(position)
            add_force(new_feed)
            if bulk and usual is not None and stop - index > SHAPE_LEAST and ";" not in text:
                # a run of this line's shape ahead (its SHAPE_LEAST-th line, then all of them, checked)?
                bulk = False  # tried again after a run of one shape, not after a line that starts none
                if _looks.skip:
                    _looks.skip -= 1
                else:
                    shape = text.translate(LETTERS_OF)
                    taken = 0
                    if lines[index + SHAPE_LEAST][1].translate(LETTERS_OF) == shape:
                        taken = _same_shape(lines, index + 1, stop, shape, g, line_motion, new_feed, position,
                                            offset, scale, incremental, (kinds, numbers, ends, feeds, in_force))
                    _looks.found(taken > 0)
                    if taken:
                        bulk = True
                        index += taken
                        position = ends[-1]
                        new_feed = in_force[-1]
        motion, feed = line_motion, new_feed
        index += 1
    return index, index - first, motion, feed, kinds, numbers, ends, feeds, in_force


def line_target(position: Sequence[float], offset: Sequence[float], scale: float, incremental: bool, x: str | None,
                y: str | None, z: str | None, a: str | None, b: str | None, c: str | None) -> tuple[float, ...]:
    """The machine position a line's axis words (number texts, empty or None where it has none) point at
    from ``position``, as the general path's ``_target`` finds it: X Y Z times ``scale`` (inch), added to
    the position under G91, to the work ``offset`` under G90; the bulk path's straight lines and arcs."""
    base = position if incremental else offset
    return (base[0] + float(x) * scale if x else position[0],
            base[1] + float(y) * scale if y else position[1],
            base[2] + float(z) * scale if z else position[2],
            base[3] + float(a) if a else position[3],
            base[4] + float(b) if b else position[4],
            base[5] + float(c) if c else position[5])


def _same_shape(lines: Sequence[tuple[int, str]], first: int, stop: int, shape: str, g: str | None, motion: int,
                feed: float, position: tuple[float, ...], offset: Sequence[float], scale: float, incremental: bool,
                columns: Columns) -> int:
    """The lines from ``first`` on whose letters are ``shape`` (a line's words in the usual order, no
    comment) and whose G text is ``g``, taken as the loop of ``plain_moves`` would take them once it has
    read a line of that shape and appended to ``columns``; returns how many (0 for fewer than SHAPE_LEAST)."""
    count, values = shape_values(lines, first, stop, shape)
    if not count:
        return 0
    width = len(shape)
    if g is not None:  # the G word's text, the same on every line
        at = shape.index("G")
        codes = values[at::width]
        if codes.count(g) != count:
            count = sum(1 for _ in takewhile(g.__eq__, codes))
    if "F" in shape:
        given = list(map(float, islice(values, shape.index("F"), width * count, width)))
        in_force = list(map(mul, given, repeat(scale)))
        if count and (min(given) < 0 or (motion == G_1 and min(in_force) <= 0)):
            # stop at the line the loop would stop at (it reports nothing: the general path does)
            count = next(i for i, (v, f) in enumerate(zip(given, in_force)) if v < 0 or (motion == G_1 and f <= 0))
            del in_force[count:]
    elif motion == G_1 and feed <= 0:
        return 0
    else:
        in_force = [feed] * count
    if not count:
        return 0
    axes: list[Iterable[float]] = []
    for axis, letter in enumerate("XYZABC"):
        if letter not in shape:
            axes.append(repeat(position[axis]))
            continue
        column: Iterable[float] = map(float, islice(values, shape.index(letter), width * count, width))
        if axis < 3:
            column = map(mul, column, repeat(scale))
        if incremental:
            axes.append(islice(accumulate(column, add, initial=position[axis]), 1, None))
        else:
            axes.append(map(add, repeat(offset[axis]), column))
    kinds, numbers, ends, feeds, forces = columns
    ends.extend(zip(*axes))
    numbers.extend([number for number, _ in lines[first:first + count]])
    kinds.extend(["linear" if motion == G_1 else "rapid"] * count)
    feeds.extend(in_force if motion == G_1 else [0.0] * count)
    forces.extend(in_force)
    return count


def shape_values(lines: Sequence[tuple[int, str]], first: int, stop: int, shape: str) -> tuple[int, list[str]]:
    """How many of the lines from ``first`` (before ``stop``) have the letters ``shape`` (a line's words in
    the order ARC_ORDER or USUAL_ORDER read, no comment), and their number texts, ``len(shape)`` a line, read
    in blocks of SHAPE_BLOCK lines, each four times larger than the last; (0, []) for fewer than SHAPE_LEAST.

    A block is read as ASCII bytes (any other character a '?', which no shape has), whose translations
    run over a table instead of a dict a character: what LETTERS_OF and a letter's blanking do to a str."""
    letters_of = shape.encode() + b"\n"
    if letters_of_lines("\n".join([line for _, line in lines[first:first + SHAPE_LEAST]])) != letters_of * SHAPE_LEAST:
        return 0, []  # too short a run to be worth it (CAM output changes shape every few lines)
    values: list[str] = []
    block, start = SHAPE_BLOCK, first
    while start < stop:
        texts = [line for _, line in lines[start:min(start + block, stop)]]
        joined = "\n".join(texts)
        letters = letters_of_lines(joined)
        if letters != letters_of * len(texts):
            taken = sum(1 for _ in takewhile(letters_of[:-1].__eq__, letters.split(b"\n")))
            values += numbers_of_lines("\n".join(texts[:taken]))
            start += taken
            break
        values += numbers_of_lines(joined)
        start += len(texts)
        block *= 4
    return start - first, values


_UPPER = bytes.maketrans(string.ascii_lowercase.encode(), string.ascii_uppercase.encode())
_BLANK_LETTERS = bytes.maketrans(string.ascii_letters.encode(), b" " * len(string.ascii_letters))


def letters_of_lines(text: str) -> bytes:
    """The letters of the lines ``text`` (``text.translate(LETTERS_OF)``: upper case, numbers and blanks
    deleted), each line's ended by a newline, as ASCII bytes (another character a '?', which no shape has)."""
    return (text + "\n").encode("ascii", "replace").translate(_UPPER, b"0123456789.+- \t")


def numbers_of_lines(text: str) -> list[str]:
    """The number texts of plain lines: what is left of them with their letters blanked, split."""
    return text.encode("ascii", "replace").translate(_BLANK_LETTERS).decode("ascii").split()


def _otherletters_of_lines(letters: str) -> dict[int, int | None]:
    """A translation that deletes a line's blanks, numbers, N and ``letters`` (either case): what is left
    is the letters of other words."""
    return str.maketrans(dict.fromkeys("0123456789.+- \tN" + letters + ("N" + letters).lower()))


_ROWS: dict[str, tuple[dict[str, int], dict[int, int | None]]] = {}  # by letters: their columns, _other_letters


def words_row(text: str, letters: str = "GXYZABCF") -> list[str] | None:
    """The number texts of the words ``letters`` of a line whose words are in another order than usual_order's
    ('' where it has no such word); None when it has another word (but N) or one twice."""
    if letters not in _ROWS:
        _ROWS[letters] = ({letter: column for column, letter in enumerate(letters)}, _otherletters_of_lines(letters))
    columns, other_letters = _ROWS[letters]
    if "(" not in text and ";" not in text and text.translate(other_letters):
        return None  # a word of another letter (an arc's centre, M, S, T): told without reading the words
    row = [""] * len(letters)
    seen = ""
    for letter, number in plain_words(text):
        letter = letter.upper()
        if letter in seen or (letter not in columns and letter != "N"):
            return None
        seen += letter
        if letter != "N":
            row[columns[letter]] = number
    return row
