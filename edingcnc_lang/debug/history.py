"""What stepping back needs: the operator's inputs, so that a re-run from the start is the same run.

The interpreter's state lives partly on Python's call stack (a sub in the middle of a While in
the middle of an If), so a copy of the machine cannot be resumed.  A step back therefore re-runs
the job from its start, with every output suppressed, to the statement wanted (the run is
deterministic), and the inputs that made it the run it was are replayed: dialog and probe
answers and the variables the user set, each at the statement (step number) it happened on.
Memory holds these inputs only, at most ``MAX_INPUTS``; a session past that cannot step back.
Statements are numbered by the machine's step counter (``MachineState.budget.steps``), which counts a
plain line the same on the bulk path as line by line.
"""
from __future__ import annotations

from collections import deque
from dataclasses import dataclass, field

from edingcnc_lang.records import record

MAX_INPUTS = 10_000


@record(frozen=True)
class Input:
    """One thing the run was told: a dialog answer, a probe result, or a variable set by the user."""

    step: int
    kind: str  # "dialog" | "probe" | "edit"
    value: object  # DialogAnswer | Pose | None | (index, value)
    scripted: bool = False  # a dialog answer from the launch's ``answers``


class Rewind(BaseException):
    """Raised in the worker to leave the run: go back (``stepBack``/``reverseContinue``) from
    statement ``step`` at call depth ``depth``; ``exact`` goes to ``step`` itself (known already),
    which runs in the plain-line chunk ``chunk`` (its path and first line) if it is a plain line."""

    def __init__(self, kind: str, step: int, depth: int, exact: bool = False,
                 chunk: tuple[str, int] | None = None) -> None:
        super().__init__(kind)
        self.kind, self.step, self.depth, self.exact, self.chunk = kind, step, depth, exact, chunk


@dataclass
class History:
    """The inputs of the run so far, in order."""

    inputs: list[Input] = field(default_factory=list)
    full: bool = False

    def record(self, item: Input) -> None:
        if len(self.inputs) >= MAX_INPUTS:
            self.full = True
        else:
            self.inputs.append(item)

    def until(self, step: int) -> Replay:
        """What a re-run to statement ``step`` is fed: answers given before it, edits made up to it."""
        kept = [i for i in self.inputs if i.step < step or (i.kind == "edit" and i.step == step)]
        return Replay(kept)

    def truncate(self, step: int) -> None:
        """Forget what happened at and after ``step`` (the future is open again), but keep the edits
        made while stopped at ``step`` itself."""
        self.inputs = self.until(step).kept
        self.full = False

    def scripted_used(self) -> int:
        return sum(1 for i in self.inputs if i.scripted)


@dataclass
class Replay:
    """The inputs of a re-run, handed out in order."""

    kept: list[Input]
    answers: deque[Input] = field(init=False)
    edits: dict[int, list[tuple[int, float]]] = field(init=False)

    def __post_init__(self) -> None:
        self.answers = deque(i for i in self.kept if i.kind != "edit")
        self.edits = {}
        for item in self.kept:
            if item.kind == "edit":
                self.edits.setdefault(item.step, []).append(item.value)  # type: ignore[arg-type]

    def next(self, kind: str) -> Input | None:
        """The next recorded answer, if it is of this kind (a run that asks differently gets none)."""
        if self.answers and self.answers[0].kind == kind:
            return self.answers.popleft()
        return None
