"""The embedding program's ``on_move``/``on_event``/``on_batch``, called as the machine makes each move.

The tap sits between the motion stage and the planner (or ``Untimed``), so a callback hears a move
when the machine makes it, not a look-ahead window later: when a callback raises, or the program
cancels the run (``Run.cancel``), the run stops at that move and the result counts exactly the moves
whose callback returned.  A move the tap stops is refused as a limit is: the state is the one before
it (``EcncError.done`` says how many moves of a batch were made).  ``on_timed_move`` needs the
planned time, so when it is given all three come from the planner's sinks (``CallbackSink``), a window
later, in program order, and the tap only stops the run at once when it is cancelled.  ``on_batch`` hears
the moves the machine makes in bulk as their ``Batch`` (the array form of the records ``on_move`` would
hear, ``batch.moves()``), once a batch; ``on_move`` then hears only the moves made one at a time.  When it
raises, none of the batch is made.
"""
from __future__ import annotations

import math
from collections.abc import Callable
from typing import TYPE_CHECKING, Any

from edingcnc_lang.canon import Batch, Event, Move, Pose
from edingcnc_lang.errors import CallbackError, Cancelled, EcncError, Location

if TYPE_CHECKING:
    from edingcnc_lang.motion.arc_table import ArcTable
    from edingcnc_lang.motion.stage import AxisLimits, PlainLimits, PlannerStage, Samples


class CallbackTap:
    """A ``PlannerStage`` that calls the callbacks, then hands everything on to ``inner``."""

    def __init__(self, inner: PlannerStage, on_move: Callable[[Move, Pose], None] | None,
                 on_event: Callable[[Event], None] | None, on_batch: Callable[[Batch], None] | None = None) -> None:
        self.inner = inner
        self.needs_limits = inner.needs_limits
        self.on_move = on_move
        self.on_event = on_event
        self.on_batch = on_batch
        self.cancelled = False  # set by Run.cancel (from any thread): the next move or event stops the run
        self.stopped: EcncError | None = None  # once stopped, nothing more reaches the callbacks

    @property
    def overrides(self) -> Any:
        return self.inner.overrides

    def move(self, move: Move, joints: Pose, samples: Samples | None,
             limits: AxisLimits | PlainLimits | None,
             cap: float = math.inf, accel_cap: float = math.inf) -> None:
        self._deliver(move, joints)
        self.inner.move(move, joints, samples, limits, cap, accel_cap)

    def move_batch(self, batch: Batch, limits: dict[str, PlainLimits] | None, arcs: ArcTable | None = None) -> None:
        if self.on_move is None or self.on_batch is not None:  # once per batch: on_batch, or only cancelling
            where = Location(batch.path, batch.lines[0])
            try:
                if self.stopped is not None or self.cancelled:
                    self._check(where)
                if self.on_batch is not None:
                    self._call(self.on_batch, (batch,), "on_batch", where)
            except EcncError as err:
                err.done = 0
                raise
            self.inner.move_batch(batch, limits, arcs)
            return
        count = 0
        try:
            for move in batch.moves():
                self._deliver(move, move.end)
                count += 1
        except EcncError as err:
            if count:  # the moves before it were made: they go on as a batch of their own
                self.inner.move_batch(batch.head(count), limits, None)
            err.done = count
            raise
        self.inner.move_batch(batch, limits, arcs)

    def event(self, event: Event) -> None:
        if self.stopped is not None or self.cancelled:
            self._check(Location(event.path, event.line))
        if self.on_event is not None:
            try:
                self.on_event(event)
            except EcncError as err:  # the embedding program's own error, raised on purpose: as it is
                self.stopped = err
                raise
            except Exception as exc:
                raise self._stop(CallbackError.of(f"on_event (at a {event.kind} event)", exc,
                                                  Location(event.path, event.line)), exc) from exc
        self.inner.event(event)

    def flush(self) -> None:
        self.inner.flush()

    def close(self) -> None:
        self.inner.close()

    def _deliver(self, move: Move, joints: Pose) -> None:
        if self.stopped is not None or self.cancelled:
            self._check(Location(move.path, move.line))
        if self.on_move is not None:
            self._call(self.on_move, (move, joints), "on_move", Location(move.path, move.line))

    def _call(self, callback: Callable[..., None], arguments: tuple[Any, ...], name: str, where: Location) -> None:
        """``callback(*arguments)``: an EcncError it raises stops the run as it is (raised on purpose), any other
        error as a CallbackError naming ``name`` at ``where``."""
        try:
            callback(*arguments)
        except EcncError as err:
            self.stopped = err
            raise
        except Exception as exc:
            raise self._stop(CallbackError.of(name, exc, where), exc) from exc

    def _check(self, where: Location) -> None:
        """Stop here if the run was stopped or cancelled (``where``: the move or event not made)."""
        if self.stopped is not None:
            raise Cancelled("the run was stopped before this move", where)
        if self.cancelled:
            raise self._stop(Cancelled("cancelled by the embedding program", where), None)

    def _stop(self, error: EcncError, cause: BaseException | None) -> EcncError:
        self.stopped = error
        error.__cause__ = cause
        return error

