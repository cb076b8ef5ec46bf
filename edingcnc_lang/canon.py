"""The canon seam: what the interpreter tells the machine, as plain records (moves here, events in ``events.py``).

The interpreter emits these to a ``Canon`` and knows nothing of what happens
next; the motion stage (kinematics, joints, limits), the trace writer and the
API's event stream all sit behind this interface.  Positions are machine
coordinates in mm and degrees.
"""
from __future__ import annotations

import math

from collections.abc import Callable, Iterator
from dataclasses import replace
from typing import Mapping, Protocol, Sequence

from edingcnc_lang.errors import EcncError
from edingcnc_lang.events import Event
from edingcnc_lang.records import record


Pose = tuple[float, ...]  # six values: x y z a b c (or the joints jx .. jc)
AXES = "XYZABC"


def format_pose(values: Sequence[float] | None, names: Sequence[str] = AXES, spec: str = ".6g") -> str:
    """``X10 Y-2.5 Z0 A0 B0 C0``: one word per value, for every message and report that shows a pose.

    ``None`` is ``-`` (no pose); NaN stays visible.  ``names`` may be joint names instead of axes.
    """
    if values is None:
        return "-"
    return " ".join(f"{name}{float(v):{spec}}" for name, v in zip(names, values))

# Arc planes: the two in-plane axis indices and the normal axis index.
PLANES: Mapping[str, tuple[int, int, int]] = {"XY": (0, 1, 2), "XZ": (2, 0, 1), "YZ": (1, 2, 0)}


@record(frozen=True, slots=True)
class Arc:
    """Circle data of an arc move: centre (machine, in-plane pair), plane, direction and turns.

    ``full_turns`` says whether the arc closes on itself.  0: the arc goes from its start to its end
    point the short way round in its direction (less than one turn).  N >= 1: start and end are the
    same point of the plane (a full circle, or a helix that comes back above its start) and the arc
    makes N whole turns: add no partial angle to them.  ``kinematics.trajectory.move_length(move)``
    gives the length as the planner counts it, ``move_points(move)`` points along the path.
    """

    center: tuple[float, float]  # in-plane coordinates in the plane's name order (XZ -> x, z)
    plane: str                   # "XY" | "XZ" | "YZ"
    turn: int                    # +1 counter-clockwise seen from the normal's positive end, -1 clockwise
    full_turns: int = 0          # 0: less than a turn, start to end; N >= 1: N whole turns (start = end)


@record(frozen=True, slots=True)
class Css:
    """Constant surface speed in force (a lathe's G96): the spindle turns so the edge cuts at ``surface`` mm/min.

    ``axis_x`` is the machine X of the turning centre (work X0), so the cutting radius of a
    machine position x is ``|x - axis_x|``.  ``max_rpm``/``min_rpm`` of 0 mean no limit.
    """

    surface: float
    max_rpm: float
    min_rpm: float
    axis_x: float

    def rpm(self, x: float) -> float:
        """Spindle speed with the tool at machine X ``x`` (inf at the centre with no maximum)."""
        radius = abs(x - self.axis_x)
        rpm = self.surface / (2.0 * math.pi * radius) if radius > 0.0 else math.inf
        if self.max_rpm > 0.0:
            rpm = min(rpm, self.max_rpm)
        return max(rpm, self.min_rpm)

    def minutes_per_rev(self, x: float) -> float:
        """1/rpm in minutes, finite even at the centre when a maximum applies."""
        rpm = self.rpm(x)
        return 0.0 if math.isinf(rpm) else 1.0 / rpm


@record(frozen=True, slots=True)
class Move:
    """One executed move; ``feed`` in mm/min (0 for rapids and homing).

    The spindle along the move: ``spindle`` is its speed in rpm at the end of the move (0 when
    stopped); under constant surface speed (G96) ``css`` gives the speed at any X
    (``css.rpm(x)``), and ``spindle`` is ``css.rpm(end[0])``.  ``sync`` is the path length per
    spindle revolution (mm) of a spindle-synchronised move (G33, G33.1, the cuts of G76), 0 for
    any other move; such a move's ``feed`` is its mean speed at the programmed spindle speed.
    Under feed per revolution (G95) ``feed`` is likewise the mean speed over the move.
    """

    kind: str  # "rapid" | "linear" | "arc" | "probe" | "home"
    path: str
    line: int
    start: Pose
    end: Pose
    feed: float = 0.0
    arc: Arc | None = None
    spindle: float = 0.0
    css: Css | None = None
    sync: float = 0.0
    caller: int = 0  # a move made inside a sub: the line of the outermost call (GoSub, M code, T M6)


@record(frozen=True, slots=True)
class Batch:
    """Moves in bulk: the array form of ``Move`` (a single move is a batch of one).

    The per-move fields are columns (``kinds``, ``lines``, ``ends``, ``feeds`` and ``arcs``, the
    circle data of the arcs among them; ``arcs`` is None when every move is straight, the common
    case); the fields a run of moves shares are kept once (``path``, and the spindle state:
    ``spindle``, ``css``, ``sync``, ``caller``).  Move ``i`` starts where move ``i - 1`` ended, the
    first at ``start``; its spindle speed is ``css.rpm(end x)`` under constant surface speed, else
    ``spindle``.  ``move(i)`` and ``moves()`` give the very ``Move`` records the general path would
    have made.  A stage changes what it owns with ``dataclasses.replace`` here as it does on a
    ``Move``.
    """

    path: str
    start: Pose
    kinds: Sequence[str]   # "rapid" | "linear" | "arc"
    lines: Sequence[int]
    ends: Sequence[Pose]
    feeds: Sequence[float]
    spindle: float = 0.0
    css: Css | None = None
    sync: float = 0.0
    caller: int = 0
    arcs: Sequence[Arc | None] | None = None  # None: no arcs (every move straight)

    def __len__(self) -> int:
        return len(self.lines)

    @property
    def end(self) -> Pose:
        """Where the last move ends (the start of an empty batch)."""
        return self.ends[-1] if self.lines else self.start

    def move(self, index: int, start: Pose) -> Move:
        """Move ``index`` as a record, starting at ``start`` (where move ``index - 1`` ended)."""
        end = self.ends[index]
        css = self.css
        return Move(self.kinds[index], self.path, self.lines[index], start, end, self.feeds[index],
                    None if self.arcs is None else self.arcs[index],
                    css.rpm(end[0]) if css is not None else self.spindle, css, self.sync, self.caller)

    def each(self, take: Callable[[Move], None]) -> None:
        """Hand the moves to ``take`` one at a time (a stage that has no batch form for what it does); a move
        refused says how many of the batch were made before it (``EcncError.done``)."""
        count = 0
        try:
            for count, move in enumerate(self.moves()):
                take(move)
        except EcncError as err:
            err.done = count
            raise

    def moves(self) -> Iterator[Move]:
        """The batch as single moves, each starting where the one before ended."""
        start = self.start
        for index in range(len(self.lines)):
            move = self.move(index, start)
            yield move
            start = move.end

    def head(self, count: int) -> Batch:
        """The first ``count`` moves."""
        if count >= len(self.lines):
            return self
        return replace(self, kinds=self.kinds[:count], lines=self.lines[:count], ends=self.ends[:count],
                       feeds=self.feeds[:count], arcs=None if self.arcs is None else self.arcs[:count])

    def tail(self, count: int) -> Batch:
        """The moves after the first ``count``, starting where those ended."""
        start = self.ends[count - 1] if count else self.start
        return replace(self, start=start, kinds=self.kinds[count:], lines=self.lines[count:],
                       ends=self.ends[count:], feeds=self.feeds[count:],
                       arcs=None if self.arcs is None else self.arcs[count:])

    @classmethod
    def of(cls, move: Move) -> Batch:
        """A rapid, feed or arc move as a batch of one."""
        if move.kind not in ("rapid", "linear", "arc"):
            raise ValueError(f"a batch holds rapids, feed moves and arcs, not a {move.kind} move")
        spindle = 0.0 if move.css is not None else move.spindle
        return cls(move.path, move.start, (move.kind,), (move.line,), (move.end,), (move.feed,),
                   spindle, move.css, move.sync, move.caller, None if move.arc is None else (move.arc,))


class Canon(Protocol):
    """The interface between the interpreter and everything downstream of it."""

    def move(self, move: Move) -> None:
        """Execute a move (called in program order)."""

    def move_batch(self, batch: Batch) -> None:
        """Moves in bulk: the same as one ``move`` per ``batch.moves()``, so the common case costs less."""

    def event(self, event: Event) -> None:
        """Record a non-motion event."""

    def kinematics(self, mode: str, args: tuple[float, ...], pos: Pose, path: str, line: int) -> Pose:
        """Switch or control the kinematics (``KIN`` / tanknife); returns the Cartesian position after it."""
