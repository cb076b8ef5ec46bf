"""What a run is told and what it reports: ``RunOptions``, ``RunResult`` and the ``Assumption``s a run makes.

Records only, so the command line, the debugger, the tests and an embedding program can build and read
them without the engine (``runner.Run``), which re-exports them.
"""
from __future__ import annotations

import os
from collections.abc import Callable, Mapping, Sequence
from dataclasses import dataclass, field
from pathlib import Path
from typing import TYPE_CHECKING, Any, overload

from edingcnc_lang.canon import AXES, Batch, Event, Move, Pose
from edingcnc_lang.diagnostics import Diagnostic
from edingcnc_lang.errors import EcncError, Location
from edingcnc_lang.events import MessageEvent
from edingcnc_lang.records import record
from edingcnc_lang.host import Host
from edingcnc_lang.machine.observe import Observer
from edingcnc_lang.motion.planner.estimate import Estimate
from edingcnc_lang.motion.sinks import Timing
from edingcnc_lang.syntax.input_limits import DEFAULT_MAX_STEPS

if TYPE_CHECKING:
    from edingcnc_lang.motion.planner.stage import TimedSink
    from edingcnc_lang.syntax.parser import CheckedFile


@dataclass(frozen=True)
class Assumption:
    """Something a run assumed because nobody said otherwise: ``what`` names it (``machine``, ``macro``,
    ``probe``), ``text`` says it to a person; ``location`` is where it first mattered (None: the whole run)."""

    what: str
    text: str
    location: Location | None = None

    def to_json(self) -> dict[str, Any]:
        where = self.location
        return {"what": self.what, "text": self.text, "file": where.path if where else None,
                "line": where.line if where else None}


@dataclass
class RunResult:
    """The machine after a run: what ``ecnc run --json`` prints."""

    position: Pose
    machine: Pose
    joints: Pose
    variables: dict[int, float]
    messages: list[MessageEvent]
    kinematics: dict[str, Any]
    tool: int
    moves: int
    modal: list[str]
    ended_by: str = "end of file"   # "M2", "M30" or "end of file"
    error: str | None = None  # the formatted message of the error that stopped the run
    error_record: dict[str, Any] | None = None  # the same error as the --json ``error`` object
    warnings: list[Diagnostic] = field(default_factory=list)  # macro lines that do not parse (tolerant load)
    spindle: dict[str, Any] = field(default_factory=dict)  # direction, G96/G97, S, rpm, max_rpm
    # how long the run took, as planned, and the limits report (docs/planner.md); None when not planned
    estimate: Estimate | None = field(default_factory=Estimate)
    limits: dict[str, Any] | None = field(default_factory=dict)
    # where the work zero is in machine coordinates: G5x + G92 + tool offsets, not turned by G68 or G51
    work_zero: Pose = (0.0,) * 6
    # every parameter #1..#5999 as the run left it, written or not (``variables`` holds only the
    # written ones): a read-only mapping, ``result.parameters[4050]``
    parameters: Mapping[int, float] = field(default_factory=dict)
    # what the run assumed because nobody said (no ini, the packaged macro, a simulated probe)
    assumptions: list[Assumption] = field(default_factory=list)

    def to_json(self) -> dict[str, Any]:
        axes = [a.lower() for a in AXES]
        return {
            "position": dict(zip(axes, self.position)),
            "machine": dict(zip(axes, self.machine)),
            "joints": dict(zip(axes, self.joints)),
            "variables": {str(k): v for k, v in self.variables.items()},
            "messages": [{"kind": e.kind, "text": e.text, "file": e.path, "line": e.line}
                         for e in self.messages],
            "kinematics": self.kinematics,
            "tool": self.tool,
            "moves": self.moves,
            "modal": self.modal,
            "ended_by": self.ended_by,
            "spindle": self.spindle,
            "estimate": self.estimate.to_json() if self.estimate is not None else None,
            "limits": self.limits,
            **({"error": self.error_record or {"text": self.error}} if self.error else {}),
            **({"warnings": [d.format(with_source=False) for d in self.warnings]} if self.warnings else {}),
            "assumptions": [a.to_json() for a in self.assumptions],
        }


class PathOption:
    """A file name of ``RunOptions``: set as a ``str`` or any path-like, read as a ``Path`` (or None).

    (A descriptor, so ``RunOptions(ini="cnc.ini")`` type-checks and every reader still gets a ``Path``.)
    """

    def __set_name__(self, owner: type, name: str) -> None:
        self._name = "_" + name

    @overload
    def __get__(self, obj: None, objtype: Any = None) -> None: ...

    @overload
    def __get__(self, obj: object, objtype: Any = None) -> Path | None: ...

    def __get__(self, obj: object | None, objtype: Any = None) -> Path | None:
        if obj is None:  # the dataclass asks the class for the default
            return None
        value: Path | None = getattr(obj, self._name)
        return value

    def __set__(self, obj: object, value: str | os.PathLike[str] | None) -> None:
        setattr(obj, self._name, None if value is None else Path(value))


@dataclass
class RunOptions:
    """Everything a run can be told; the CLI and the API both fill one of these."""

    # file names may be given as ``str`` or any path-like; read back, they are ``Path`` (or None)
    ini: PathOption = PathOption()
    macro: PathOption = PathOption()
    user_macro: PathOption = PathOption()
    host: Host = field(default_factory=Host)
    max_steps: int | None = DEFAULT_MAX_STEPS  # None: no budget at all
    trace: PathOption = PathOption()
    samples: PathOption = PathOption()
    events: PathOption = PathOption()
    log_dir: PathOption = PathOption()
    allow_exec: bool = False
    simulation: bool = True
    block_delete: bool = False
    save_vars: bool = False
    # False: the run only looks (ecnc plot, view, sim, diff): the files the job writes (logfile, logmsg,
    # ZHCS) are kept in memory (the job reads back what it wrote), nothing on disk changes
    write_job_files: bool = True
    # told of each thing the run assumes because nobody said (the CLI prints them on stderr)
    on_assumption: Callable[[Assumption], None] | None = None
    # told, once at the start, what the run uses that was given: the ini, the macro files (``-v``)
    on_setup: Callable[[str], None] | None = None
    on_move: Callable[[Move, Pose], None] | None = None
    on_event: Callable[[Event], None] | None = None
    strict: bool = False  # macro lines that do not parse are errors at load, not warnings
    on_warning: Callable[[Diagnostic], None] | None = None  # each load warning, once, as it is found
    on_timed_move: Callable[[Move, Pose, Timing], None] | None = None  # every move with its planned Timing
    # the moves the machine makes in bulk, a ``Batch`` at once (the array form of the records ``on_move`` would
    # hear: ``batch.moves()``); ``on_move`` then hears only the moves made one at a time.  Not with
    # ``on_timed_move``, whose moves come one at a time with their timing
    on_batch: Callable[[Batch], None] | None = None
    # more outputs in this process (``ecnc diff``'s recorder): each hears every planned move, every batch of
    # straight moves at once (``write_batch``: the columns, no Move per move) and every event, in program order
    sinks: Sequence[TimedSink] = ()
    feed_override: float = 100.0   # percent
    rapid_override: float = 100.0  # percent, at most 100
    # False: time the moves only if an output reads time (trace, samples, events, on_timed_move);
    # otherwise the run skips the planner (no numpy) and its estimate and limits are None
    plan: bool = True
    # watches every statement, branch and sub call (the debugger, macro coverage): machine/observe.py
    observer: Observer | None = None
    # parameters set before the job's first line (after the macro files' top-level lines and the
    # ini's initialString, before the start sub), as if the machine had them: a test's starting state
    variables: Mapping[int, float] = field(default_factory=dict)


@record(frozen=True)
class CheckedJob:
    """A job's check pass (``Run.check_job``): its structure and the T words it names (GetToolInfo).
    A run of the unchanged file may take it instead of reading the file through again: the debugger's
    launch checks the job for its breakpoint lines, and the run it starts uses that check."""

    file: CheckedFile
    tools: frozenset[int]


def result_of(error: EcncError) -> RunResult | None:
    """The machine as the error left it, typed: a run sets ``error.result`` on the error that stopped it."""
    result = error.result
    return result if isinstance(result, RunResult) else None
