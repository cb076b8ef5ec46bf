"""The bulk path: runs of plain G0/G1/G2/G3 lines executed without building nodes, as one ``Batch``.

CAM output is mostly lines such as ``G1 X.. Y.. Z..`` and ``G2 X.. Y.. I.. J..``.  While the
machine is in a state where such a line can only be a straight move or an arc (``batchable``, the
one place that decides it), a run of them is turned into targets by ``plain_moves`` (straight
lines, ``plain_runs.py``) and ``plain_arcs`` (arc lines, ``plain_arcs.py``) and handed to the canon as one
``Batch``: the array form of the ``Move`` records the general path would have made, with the same spindle
and caller.  The step budget and GetJobDistance are counted by the general path's own helpers
(``MachineState.travelled``); any other line, and every error, goes to the general path, so messages stay
exactly the same.

``plain_runs.plain_moves`` and ``plain_arcs.plain_arcs`` are the Python references; ``_speedups.plain_moves``
and ``_speedups.plain_arcs`` are the same compiled (``edingcnc_lang/_speedups.c``), used when it is built
and ``ECNC_PURE_PYTHON`` is not set.  ``arc_run`` over ``_arc_of_words`` reads arc lines with the general
path's own ``_target`` and ``arc_plan``: it takes the runs ``plain_arcs`` does not (absolute centres, diameter
programs), and the equivalence tests hold both ``plain_arcs`` to it and whole moves to the general path's.
"""
from __future__ import annotations

import re
from collections.abc import Callable, Iterator, Mapping
from contextlib import contextmanager
from functools import partial
from typing import Any

from edingcnc_lang.syntax import nodes as n
from edingcnc_lang import speedups
from edingcnc_lang.canon import Arc, Batch, Pose
from edingcnc_lang.errors import EcncError
from edingcnc_lang.syntax.plain_words import plain_block, plain_words
from edingcnc_lang.machine.parts import PendingMoves
from edingcnc_lang.machine.geometry import TINY, ArcError, radius_tolerance
from edingcnc_lang.machine.plain_arcs import plain_arcs
from edingcnc_lang.machine.plain_runs import NO_MOTION, plain_moves
from edingcnc_lang.machine.state import (
    AXIS_SET,
    CENTER_WORDS,
    G_0,
    G_1,
    G_2,
    G_3,
    G_91,
    G_94,
    PLANE_OF,
    MachineState,
    path_length,
    StatementTable,
)

# The words a plain arc line may hold besides G and N, by plane: the axes, F, R and the plane's centre words.
_ARC_LETTERS = {plane: frozenset("XYZABCFR" + "".join(centre)) for plane, centre in CENTER_WORDS.items()}
_ARC_WORD = re.compile("[IJKRijkr]")  # a letter an arc line needs one of (R or a centre word)
_PLANE_INDEX = {"XY": 0, "XZ": 1, "YZ": 2}  # as _speedups.c's plain_arcs numbers them
_PLAIN_ARCS: Callable[..., Any] = speedups.compiled("plain_arcs") or plain_arcs  # the arcs of a run of arc lines
_PLAIN_MOVES: Callable[..., Any] = speedups.compiled("plain_moves") or plain_moves  # the targets of a run of plain lines
# What an arc line gives the bulk path: the motion and feed in force after it, its end, its arc and its
# length (``path_length``, what GetJobDistance counts).
ArcLine = tuple[int, float, Pose, Arc, float]
Lines = tuple[tuple[int, str], ...]
# What a run of arc lines gives: the index of the first line not taken, the motion and feed in force after the
# run, and its arcs as columns (line numbers, ends, feeds, arcs, lengths).
ArcColumns = tuple[int, int, float, list[int], list[Pose], list[float], list[Arc], list[float]]
ArcRun = Callable[[Lines, int, Pose, int, float, int], ArcColumns]


def arc_run(read_arc: Callable[[str, Pose, int, float], ArcLine | None], lines: Lines, index: int, start: Pose,
            motion: int, feed: float, room: int) -> ArcColumns:
    """The arc lines of ``lines[index:]`` one after another, at most ``room`` of them, each as ``read_arc`` reads
    it (``BulkPath._arc_of_words``), as columns.  What ``plain_arcs`` (compiled and Python) is held to."""
    numbers: list[int] = []
    ends: list[Pose] = []
    feeds: list[float] = []
    arcs: list[Arc] = []
    lengths: list[float] = []
    while index < len(lines) and len(numbers) < room:
        taken = read_arc(lines[index][1], start, motion, feed)
        if taken is None:
            break
        motion, feed, start, arc, length = taken
        numbers.append(lines[index][0])
        ends.append(start)
        feeds.append(feed)
        arcs.append(arc)
        lengths.append(length)
        index += 1
    return index, motion, feed, numbers, ends, feeds, arcs, lengths


class BulkPath(MachineState):
    """Runs of plain lines: moves in bulk while they are simple, any other line on its own."""

    def _exec_plain_run(self, run: n.PlainRun) -> None:
        """Plain lines: straight moves and arcs in bulk while they are simple, any other line on its own."""
        lines = run.lines
        done = 0
        while done < len(lines):
            if self.batchable():
                done = self._simple_moves(run.path, lines, done)
            if done < len(lines):
                lineno, text = lines[done]
                block = plain_block(text, run.path, lineno)
                taken = self.hole_run(run.path, lines, done, block)  # (canned.py: lines that only name a hole)
                if taken == done:
                    self.execute(block)
                    taken += 1
                done = taken

    def make_batch(self, batch: Batch, arc_lengths: Mapping[int, float], by_line: bool) -> None:
        """Hand ``batch`` to the canon and count it into GetJobDistance, as ``_move`` does one move (the bulk
        path's runs of lines, a canned cycle's holes).  When a move of it is refused, the position and the
        distance are those after the moves before it, and the error says how many those were (``done``).

        ``by_line``: the refused move is found by its line (a plain line makes one move, and compensation
        may hand on more moves than it was given); else by the count the stages give (a cycle's moves share
        one line; compensation refuses cycles, and stages that split moves count the moves they were given)."""
        try:
            self.canon.move_batch(batch)
        except EcncError as err:
            if by_line or err.done is None:
                err.done = next((k for k, number in enumerate(batch.lines)
                                 if err.location is not None and number == err.location.line), 0)
            failed = err.done
            self.travelled(batch.start, batch.ends[:failed], {k: v for k, v in arc_lengths.items() if k < failed})
            self.pos = list(batch.ends[failed - 1] if failed else batch.start)
            self.line = batch.lines[failed]  # (a run of holes is handed on after the lines that made it)
            raise
        self.travelled(batch.start, batch.ends, arc_lengths)
        self.pos = list(batch.end)

    @contextmanager
    def moves_held(self) -> Iterator[None]:
        """The straight moves made inside go to the canon as one batch (``pending``), handed on before any other
        move or event (``flush_pending``) and at the end, also when an error ends it: the moves before it were
        made (one of them refused is the error reported then)."""
        self.cycle.pending = PendingMoves(tuple(self.pos))
        try:
            yield
            self.flush_pending()
        except BaseException:
            self.flush_pending()
            raise
        finally:
            self.cycle.pending = None

    def flush_pending(self) -> None:
        """Hand on the straight moves a canned cycle has collected so far (before an event, another kind of
        move, or at the end of its line) as one batch; the cycle goes on collecting after them."""
        pending = self.cycle.pending
        if pending is not None and pending.lines:
            self.cycle.pending = PendingMoves(pending.ends[-1])
            rpm, _css = self.spindle_along()  # (not under G96: the cycle collects only when batchable)
            self.make_batch(Batch(self.path, pending.start, pending.kinds, pending.lines, pending.ends, pending.feeds,
                                  rpm, None, 0.0, self.caller()), {}, by_line=False)

    def _exec_plain_lines(self, run: n.PlainRun) -> None:
        """Plain lines one statement at a time, for an observer that watches every line."""
        for lineno, text in run.lines:
            self.execute(plain_block(text, run.path, lineno))

    def batchable(self) -> bool:
        """Whether a plain G0/G1/G2/G3 line can only be a straight move or an arc now, so it may go in a batch.

        Not with a tangential knife (it turns C), clamped rotary axes or TCAGuard (refusals per
        move), not outside G94 (the feed depends on the move), not under G96 (the speed follows
        X), not on a lathe (X words are diameters there).  G68, G51, G41/G42 and ZHC do not stop
        it: they are later pipeline stages, which take batches too.
        """
        guards = self.guards
        return not (guards.tanknife or guards.clamped or guards.tca_guard or self.modal["feed_mode"] != G_94
                    or self.spindle.css is not None or self.config.lathe)

    def _simple_moves(self, path: str, lines: tuple[tuple[int, str], ...], first: int) -> int:
        """Execute lines[first:] as long as each is a plain G0/G1 move or arc; returns the first it left.

        ``plain_moves`` takes the straight lines; a line it stops at may start a run of arcs (``_arc_reader``),
        which joins the same batch, and the straight lines after it are scanned on.
        """
        start = tuple(self.pos)
        left = self.budget.room()
        room = len(lines) if left is None else left  # statements left in the step budget
        offset, scale, incremental = self.offset(), self.scale, self.modal["distance"] == G_91
        motion, feed, pos = self.modal["motion"], self.feed, start
        kinds: list[str] = []
        numbers: list[int] = []
        ends: list[Pose] = []
        feeds: list[float] = []
        in_force: list[float] = []
        arcs: list[Arc | None] | None = None
        lengths: dict[int, float] = {}  # the arcs' lengths, by their index among the moves
        read_arcs: ArcRun | None = None
        index = first
        total = len(lines)
        while index < total and room > 0:  # (a CAM pass comes here every few lines: each step counts)
            index, done, after, feed, run_kinds, run_numbers, run_ends, run_feeds, run_force = _PLAIN_MOVES(
                lines, index, pos, offset, scale, incremental, motion if motion in (G_0, G_1) else NO_MOTION,
                feed, room)
            room -= done
            if after != NO_MOTION:
                motion = after
            if run_numbers:
                kinds += run_kinds
                numbers += run_numbers
                ends += run_ends
                feeds += run_feeds
                in_force += run_force
                if arcs is not None:
                    arcs += [None] * len(run_numbers)
                pos = ends[-1]
            if index >= total or room <= 0:
                break
            text = lines[index][1]
            if motion not in (G_2, G_3) and "G" not in text and "g" not in text:
                break  # no arc in force and no G word: not an arc (a canned cycle's next hole, say)
            if read_arcs is None:
                read_arcs = self._arc_reader()
            index, motion, feed, run_numbers, run_ends, run_feeds, run_arcs, run_lengths = read_arcs(
                lines, index, pos, motion, feed, room)
            if not run_numbers:
                break  # neither a straight line nor an arc
            if arcs is None:
                arcs = [None] * len(numbers)
            lengths.update(zip(range(len(numbers), len(numbers) + len(run_numbers)), run_lengths))
            kinds.extend(["arc"] * len(run_numbers))
            numbers.extend(run_numbers)
            ends.extend(run_ends)
            feeds.extend(run_feeds)
            in_force.extend(run_feeds)
            arcs.extend(run_arcs)
            pos = ends[-1]
            room -= len(run_numbers)
        self.budget.steps += index - first
        if numbers:
            rpm, _css = self.spindle_along()
            self.path, self.line = path, numbers[-1]
            try:
                self.make_batch(Batch(path, start, kinds, numbers, ends, feeds, rpm, None, 0.0, self.caller(), arcs),
                                lengths, by_line=True)
            except EcncError as err:  # a move was refused: the state is that of the move before it
                failed = err.done or 0
                self.feed = in_force[failed]
                self.modal["motion"] = self._motion_of(kinds[failed], None if arcs is None else arcs[failed])
                raise
        self.pos = list(pos)
        self.feed = feed
        if motion != NO_MOTION:
            self.modal["motion"] = motion
        return index

    def _arc_reader(self) -> ArcRun:
        """What reads the arc lines of one run (the state it reads cannot change within a run): ``plain_arcs``
        (compiled or Python) takes arcs with centre words or R, and leaves absolute centres and diameter
        programs to ``arc_run`` over the general path's reading (and a line the compiled one cannot scan)."""
        if self.config.absolute_center_coords or self.diameter_mode:
            return partial(arc_run, self._arc_of_words)
        plane = PLANE_OF[self.modal["plane"]]
        offset, scale, incremental = self.offset(), self.scale, self.modal["distance"] == G_91
        fixed = (_PLANE_INDEX[plane], self.config.reverse_g2g3, radius_tolerance(self.inch),
                 self.config.full_circle_theta_epsilon, TINY, Arc, plane)

        def read(lines: Lines, index: int, start: Pose, motion: int, feed: float, room: int) -> ArcColumns:
            columns: tuple[list[Any], ...] = ([], [], [], [], [])  # line numbers, ends, feeds, arcs, lengths
            while True:
                index, scanned, motion, feed, *run = _PLAIN_ARCS(
                    lines, index, start, offset, scale, incremental, motion, feed, room - len(columns[0]), *fixed)
                for column, values in zip(columns, run):
                    column.extend(values)
                if columns[1]:
                    start = columns[1][-1]
                if scanned or index >= len(lines) or len(columns[0]) >= room:
                    break
                taken = self._arc_of_words(lines[index][1], start, motion, feed)  # a line the scan cannot read
                if taken is None:
                    break
                motion, feed, start, arc, length = taken
                for column, value in zip(columns, (lines[index][0], start, feed, arc, length)):
                    column.append(value)
                index += 1
            return (index, motion, feed, *columns)  # type: ignore[return-value]
        return read

    def _arc_of_words(self, text: str, start: Pose, motion: int, feed: float) -> ArcLine | None:
        """The arc a plain line makes from ``start``, if it is a simple one: G2/G3 (or either in force), axis
        words, the plane's centre words or R, F and N, each once; with it the motion and feed in force
        after it.  None for any other line, and for an arc the general path would refuse (it reports it).
        What ``plain_arcs``' reading of a line is held to: the general path's own target and ``arc_plan``.
        """
        if _ARC_WORD.search(text) is None:  # no R, I, J or K: no arc (arc_plan would refuse it), told at once
            return None  # (a run of arcs ends at such a line: the straight line after it, in a CAM pass)
        pairs = plain_words(text)
        words = {letter.upper(): float(number) for letter, number in pairs}
        if len(words) < len(pairs):  # a letter twice
            return None
        code = words.pop("G", None)
        if code is not None:
            motion = G_2 if code == 2.0 else G_3 if code == 3.0 else NO_MOTION
        words.pop("N", None)
        plane = PLANE_OF[self.modal["plane"]]
        if motion not in (G_2, G_3) or AXIS_SET.isdisjoint(words) or self.config.absolute_center_coords \
                or not words.keys() <= _ARC_LETTERS[plane]:
            return None
        if "F" in words:
            if words["F"] < 0:
                return None
            feed = words["F"] * self.scale
        if feed <= 0 or ("R" in words and not words.keys().isdisjoint(CENTER_WORDS[plane])):
            return None
        end = self._target(words, start=start)
        try:
            plan = self.arc_plan(plane, (motion == G_2) != self.config.reverse_g2g3, start, end, words)
        except ArcError:
            return None
        # path_length of an arc of less than a turn is the plan's own length (the same angle, radius and
        # helix, computed alike); a full circle counts its turn from the angle between its ends
        length = plan.length if not plan.arc.full_turns else path_length(start, end, plan.arc)
        return motion, feed, tuple(end), plan.arc, length

    def _motion_of(self, kind: str, arc: Arc | None) -> int:
        """The motion mode a move of the bulk path was made in."""
        if arc is not None:
            return G_2 if (arc.turn < 0) != self.config.reverse_g2g3 else G_3
        return G_1 if kind == "linear" else G_0


# The statements this part executes (interpreter.py builds the dispatch table from every part's).
STATEMENTS: StatementTable = {n.PlainRun: BulkPath._exec_plain_run}
