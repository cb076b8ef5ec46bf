"""The move pipeline: a chain of small ``Canon`` stages between the interpreter and the motion stage.

The interpreter emits what is programmed; each stage takes the moves and events, changes what it
owns (scaling, rotation, cutter compensation, ...) and hands the result to the next canon.  The
last canon is the motion stage.  A ``Stage`` passes everything through unchanged, so a stage
overrides only what it transforms, and an inactive stage costs one call per bulk batch.

A ``LookaheadStage`` must see the next move before it can emit the current one (a corner needs
both its sides).  It holds one move back; events that arrive meanwhile queue behind it, so the
order downstream is the programmed order.  It flushes (emits what it holds) on a program stop
or end event, before any kinematics call, at the end of the run and when the run fails.
"""
from __future__ import annotations

from collections.abc import Callable, Iterable, Sequence

from edingcnc_lang.canon import Batch, Canon, Event, Move, Pose
from edingcnc_lang.events import EndEvent, PauseEvent
from edingcnc_lang.config.machine_config import MachineConfig


# Events after which the machine must have finished every move programmed before them.
FLUSHING_EVENTS = (EndEvent, PauseEvent)


class Stage:
    """A canon that hands everything to ``next`` unchanged; subclasses override what they change."""

    def __init__(self, next_canon: Canon, config: MachineConfig) -> None:
        self.next = next_canon
        self.config = config

    def move(self, move: Move) -> None:
        self.next.move(move)

    def move_batch(self, batch: Batch) -> None:
        self.next.move_batch(batch)

    def event(self, event: Event) -> None:
        self.next.event(event)

    def kinematics(self, mode: str, args: tuple[float, ...], pos: Pose, path: str, line: int) -> Pose:
        return self.next.kinematics(mode, args, pos, path, line)

    def flush(self) -> None:
        """Emit anything held back; a plain stage holds nothing."""


class LookaheadStage(Stage):
    """A stage with a one-move buffer: ``release`` decides what a held move becomes once its successor is known.

    Subclasses override ``release`` (and ``active``, which says when bulk moves may pass straight
    through).  ``following`` is None when the move is flushed without a successor.
    """

    def __init__(self, next_canon: Canon, config: MachineConfig) -> None:
        super().__init__(next_canon, config)
        self.held: Move | None = None
        self.queued: list[Event] = []  # events programmed after the held move

    @property
    def active(self) -> bool:
        """Whether moves must be buffered now; while not, bulk moves pass straight through."""
        return True

    def release(self, held: Move, following: Move | None) -> Iterable[Move]:
        """The moves ``held`` becomes, given the move after it (None: none follows)."""
        return (held,)

    def move(self, move: Move) -> None:
        held = self.held
        if held is None:
            self.held = move
            return
        self.held = None
        self._emit(self.release(held, move))
        self.held = move

    def move_batch(self, batch: Batch) -> None:
        if not self.active and self.held is None:
            self.next.move_batch(batch)
            return
        batch.each(self.move)

    def event(self, event: Event) -> None:
        if self.held is None:
            self.next.event(event)
            return
        self.queued.append(event)
        if isinstance(event, FLUSHING_EVENTS):
            self.flush()

    def kinematics(self, mode: str, args: tuple[float, ...], pos: Pose, path: str, line: int) -> Pose:
        self.flush()
        return self.next.kinematics(mode, args, pos, path, line)

    def flush(self) -> None:
        held = self.held
        if held is not None:
            self.held = None
            self._emit(self.release(held, None))

    def _emit(self, moves: Iterable[Move]) -> None:
        """Hand released moves on, then the events that were queued behind them."""
        queued, self.queued = self.queued, []
        for move in moves:
            self.next.move(move)
        for event in queued:
            self.next.event(event)


StageFactory = Callable[[Canon, MachineConfig], Stage]


class Pipeline:
    """The chain of stages in front of ``sink``; ``head`` is the canon the interpreter talks to."""

    def __init__(self, factories: Sequence[StageFactory], sink: Canon, config: MachineConfig) -> None:
        head: Canon = sink
        stages: list[Stage] = []
        for factory in reversed(factories):
            stage = factory(head, config)
            stages.insert(0, stage)
            head = stage
        self.head = head
        self.stages = tuple(stages)

    def flush(self) -> None:
        """Emit everything held back, first stage first (so what it releases passes the later ones)."""
        for stage in self.stages:
            stage.flush()
