"""Running one test: its job on a fresh virtual machine, through the embedding API.

The test's answers feed ``Host.dialog`` (``scripted_dialogs``), its probe list answers
``Host.probe``, its ``vars`` are ``RunOptions.variables``; ``on_move``/``on_event`` watch the
moves for the ``forbid`` rules while the run goes on, and an optional ``Observer`` records
coverage.  What the run left behind is kept as an ``Outcome`` (plain data, so a worker process can
send it back); ``checks.failures`` compares it with the test's expectations.
"""
from __future__ import annotations

import tempfile
import time
from collections.abc import Sequence
from dataclasses import dataclass, field
from pathlib import Path

from edingcnc_lang.machine import tables as t
from edingcnc_lang.canon import AXES, Event, Move, Pose, format_pose
from edingcnc_lang.events import SpindleEvent, SpindleSpeedEvent
from edingcnc_lang.errors import EcncError, Interrupted, Location
from edingcnc_lang.host import DialogAnswer, DialogCallback, DialogField, Host, scripted_dialogs
from edingcnc_lang.machine.interpreter import Interpreter
from edingcnc_lang.syntax.input_limits import DEFAULT_MAX_STEPS
from edingcnc_lang.runner import Run, RunOptions
from edingcnc_lang.testing.coverage import CoverageData, CoverageObserver, display_path
from edingcnc_lang.testing.spec import AXES as AXIS_KEYS
from edingcnc_lang.testing.spec import Forbid, TestCase

JOB_NAME = "<job>"  # what messages call a job given as text
MESSAGE_KINDS = ("msg", "warn", "log")  # what expect.messages searches: msg, warnmsg and logmsg texts


class ProbeScriptError(EcncError):
    """The test's probe list asks for a contact the move could not make (a mistake in the test)."""


@dataclass
class Outcome:
    """What one test's run left behind."""

    case: TestCase
    error: str | None = None          # the error that stopped the run, as printed (FILE:LINE:COL: error: ...)
    error_message: str | None = None  # its message alone
    test_problem: str | None = None   # the test itself could not be followed (its probe list)
    params: tuple[float, ...] = ()    # #0..#5999 at the end (index = parameter number)
    position: dict[str, float] = field(default_factory=dict)  # work position at the end (x..c)
    machine: dict[str, float] = field(default_factory=dict)
    messages: list[tuple[str, str]] = field(default_factory=list)  # (kind, text) of msg/warnmsg/logmsg/...
    moves: list[Move] = field(default_factory=list)  # only with keep_moves
    violations: list[str] = field(default_factory=list)  # forbid rules broken, one text per rule
    dialogs: int = 0
    probes: int = 0
    seconds: float = 0.0
    ended_by: str = ""
    files: tuple[str, ...] = ()  # the job file and the macro files the run read (names for messages)

    def var(self, index: int) -> float:
        """The value of parameter ``index`` at the end of the run."""
        return self.params[index]


def run_case(case: TestCase, coverage: CoverageData | None = None, keep_moves: bool = False) -> Outcome:
    """Run one test on a fresh machine; every error of the run is kept in the outcome, never raised
    (but Ctrl-C).

    With ``coverage``, what the run reaches in its macro files is added to it; ``keep_moves`` keeps
    every move in ``Outcome.moves`` (for Python tests; the forbid rules need no list).
    """
    started = time.perf_counter()
    outcome = Outcome(case)
    watch = _Watch(case.forbid, keep_moves)
    holder: list[Run] = []
    observer = CoverageObserver(coverage) if coverage is not None else None
    with tempfile.TemporaryDirectory(prefix="ecnc-test-") as logs:  # logmsg/logfile write here, not beside the test
        options = RunOptions(
            ini=_shown(case.ini), macro=_shown(case.macro), user_macro=_shown(case.user_macro),
            host=Host(dialog=_counted(scripted_dialogs(case.answers), outcome), probe=_Probe(case, holder, outcome)),
            max_steps=case.max_steps or DEFAULT_MAX_STEPS, log_dir=Path(logs), simulation=case.simulation,
            on_move=watch.move, on_event=watch.event, plan=False, variables=case.vars, observer=observer)
        try:
            run = Run(options)
            holder.append(run)
            if observer is not None:
                observer.watch(run.macro_files())
            watch.interpreter = run.interpreter
            outcome.files = tuple(str(p) for p in ([case.job_file] if case.job_file else []) + run.macro_files())
            if case.job_file is not None:
                run.execute_file(case.job_file, display_path(str(case.job_file)))
            else:
                run.execute_text(case.job or "", JOB_NAME)
        except Interrupted:  # Ctrl-C ends every test, not this one
            raise
        except ProbeScriptError as err:
            outcome.test_problem = err.message
        except EcncError as err:
            outcome.error, outcome.error_message = err.format(), err.message
    if holder:
        _final_state(outcome, holder[0])
    outcome.moves = watch.moves
    outcome.violations = watch.violations()
    outcome.seconds = time.perf_counter() - started
    return outcome


def _shown(path: Path | None) -> Path | None:
    """A file as the run's messages should name it: relative to the current folder when below it."""
    return Path(display_path(str(path))) if path is not None else None


def _final_state(outcome: Outcome, run: Run) -> None:
    interp = run.interpreter
    params = interp.params
    outcome.params = (0.0, *(params.read(i) for i in range(t.FIRST_PARAM, t.LAST_PARAM + 1)))
    outcome.position = dict(zip(AXIS_KEYS, interp.reported_position()))
    outcome.machine = dict(zip(AXIS_KEYS, run.machine_position()))
    outcome.messages = [(e.kind, e.text) for e in interp.messages.events]
    outcome.ended_by = interp.flow.ended_by


def _counted(dialog: DialogCallback, outcome: Outcome) -> DialogCallback:
    """The dialog callback, counting the dialogs shown (answers left over fail the test)."""

    def answer(title: str, fields: Sequence[DialogField]) -> DialogAnswer | None:
        outcome.dialogs += 1
        return dialog(title, fields)

    return answer


class _Probe:
    """The test's probe list, one entry per G38.x in turn; past its end the probe trips at the target.

    An entry names where the probe trips in work coordinates; the axes it leaves out are the
    target's.  A named value outside the move (beyond the target, behind the start) is a mistake in
    the test and stops the run as such.
    """

    def __init__(self, case: TestCase, holder: list[Run], outcome: Outcome) -> None:
        self.steps = list(case.probe)
        self.holder = holder
        self.outcome = outcome

    def __call__(self, start: Pose, goal: Pose) -> Pose | None:
        self.outcome.probes += 1
        if not self.steps:
            return goal
        step = self.steps.pop(0)
        if step is None:
            return None
        interp = self.holder[0].interpreter
        work_start = interp.work_position(interp.program_frame(start))
        work_goal = interp.work_position(interp.program_frame(goal))
        trip = list(work_goal)
        for axis, value in step.items():
            i = AXIS_KEYS.index(axis)
            low, high = sorted((work_start[i], work_goal[i]))
            if not low - 1e-9 <= value <= high + 1e-9:
                raise ProbeScriptError(
                    f"probe {self.outcome.probes}: {axis} = {value:g} is not on the move from {axis} = "
                    f"{work_start[i]:g} to {axis} = {work_goal[i]:g}", Location(interp.path, interp.line))
            trip[i] = value
        return interp.machine_frame(interp.to_machine(trip))


class _Watch:
    """The forbid rules, checked on every move as it is made (``on_move``/``on_event``).

    Positions are turned into work coordinates with the machine's offsets at that moment (the run
    is unplanned, so each move arrives while the interpreter is still on its line).
    """

    def __init__(self, forbid: Forbid, keep_moves: bool) -> None:
        self.forbid = forbid
        self.keep_moves = keep_moves
        self.interpreter: Interpreter | None = None
        self.moves: list[Move] = []
        self.turning = False
        self.found: dict[str, list[str]] = {}

    def event(self, event: Event) -> None:
        """A ``spindle`` event carries rpm 0 when it stops; a new S (``spindle_speed``) turns only a running spindle."""
        if isinstance(event, (SpindleEvent, SpindleSpeedEvent)):
            interp = self.interpreter
            running = isinstance(event, SpindleEvent) or (interp is not None and interp.spindle.direction != 5)
            self.turning = running and event.rpm > 0.0

    def move(self, move: Move, _joints: Pose) -> None:
        if self.keep_moves:
            self.moves.append(move)
        forbid, interp = self.forbid, self.interpreter
        if interp is None:
            return
        where = f"{move.path}:{move.line}"
        if forbid.rapid_below_z is not None and move.kind == "rapid":
            z = self._work(move.end)[2]
            if z < forbid.rapid_below_z - 1e-9:
                self._add("rapid_below_z", f"the rapid at {where} ends at work Z{z:g}, below Z{forbid.rapid_below_z:g}")
        if forbid.outside is not None and move.kind != "home":
            box = forbid.outside
            for pose in self._points(move):
                work = self._work(pose)
                if any(not box[i] - 1e-9 <= work[i] <= box[i + 3] + 1e-9 for i in range(3)):
                    self._add("outside", f"the {move.kind} move at {where} reaches work "
                              f"{format_pose(work[:3], AXES[:3], '.6g')}, outside the box")
                    break
        if forbid.feed_with_spindle_off and move.kind in ("linear", "arc") and not self.turning:
            self._add("feed_with_spindle_off", f"the {move.kind} move at {where} feeds with the spindle off")

    def _work(self, machine: Pose) -> list[float]:
        """Work coordinates as the program reads them (#5001..: X a diameter on a diameter lathe)."""
        interp = self.interpreter
        assert interp is not None
        return interp.reported_position(interp.program_frame(machine))

    @staticmethod
    def _points(move: Move) -> list[Pose]:
        """The end of a move, and for an arc also where it bulges furthest along each axis."""
        if move.arc is None:
            return [move.end]
        from edingcnc_lang.kinematics.trajectory import geometry_of
        from edingcnc_lang.motion.reach import arc_extremes_of  # as the limit check and the limits report read it

        return [move.end, *arc_extremes_of(geometry_of(move))]

    def _add(self, rule: str, text: str) -> None:
        self.found.setdefault(rule, []).append(text)

    def violations(self) -> list[str]:
        """One text per broken rule: its first offence, and how many more there were."""
        texts = []
        for rule, found in self.found.items():
            more = f" (and {len(found) - 1} more)" if len(found) > 1 else ""
            texts.append(f"forbid.{rule}: {found[0]}{more}")
        return texts

