"""Run control: the job runs in a worker thread and the observer blocks it while the user looks.

The adapter thread only sets what the user asked (``resume``, ``pause``, breakpoints) and reads
the stopped machine; everything that changes the run happens in the worker.  With no breakpoint
in a chunk of plain lines and no step or pause pending, the chunk keeps the bulk path, so a long
job runs at nearly ``ecnc run`` speed until something is there to stop at.
"""
from __future__ import annotations

import shutil
import sys
import tempfile
import threading
from pathlib import Path
from typing import Any

from edingcnc_lang.syntax import nodes as n
from edingcnc_lang.canon import Pose
from edingcnc_lang.errors import EXIT_OK, EcncError
from edingcnc_lang.host import DialogAnswer, Host, ProbeCallback
from edingcnc_lang.machine.observe import MachineView, Observer
from edingcnc_lang.machine.parts import CallFrame
from edingcnc_lang.runner import Run, RunOptions
from edingcnc_lang.debug.breakpoints import Breakpoints, JobCheck, reached
from edingcnc_lang.debug.data_breakpoints import DataBreakpoints, launch_names
from edingcnc_lang.debug.expressions import evaluate
from edingcnc_lang.debug.history import History, Input, Replay, Rewind
from edingcnc_lang.debug.launch import Launch
from edingcnc_lang.debug.protocol import Channel
from edingcnc_lang.debug.variables import Frame, frames_of

LIVE, SEARCH, REPLAY = "live", "search", "replay"
BACK_COMMANDS = ("stepBack", "reverseContinue")
SET_BY_USER = "the debugger"  # the writer of a parameter set with setVariable or in the console


class Terminate(BaseException):
    """Raised in the worker to end the run at once (disconnect, terminate)."""


class _SearchDone(BaseException):
    """A search pass reached the statement it was stepping back from."""


class Session(Observer):
    """One debugged run (and the re-runs that step back in it)."""

    def __init__(self, channel: Channel, launch: Launch, check: JobCheck | None = None) -> None:
        self.channel = channel
        self.launch = launch
        self.check = check  # the launch's check of the job: the run (and each re-run) reads the job once
        self.breakpoints = Breakpoints()
        self.stop_on_errors = True
        self.history = History()
        self.cv = threading.Condition()
        self.run: Run | None = None
        self.stopped = False
        self.frames: list[Frame] = []
        self.writers: dict[int, tuple[str, int]] = {}
        self._names: dict[int, str] | None = None  # read on first use (``names``)
        self._names_lock = threading.Lock()
        self.data = DataBreakpoints()
        self.waiting: str | None = None  # "dialog" | "probe" while the machine asks the operator
        self.fields: list[int] = []  # the parameters the waiting dialog edits
        self.error: EcncError | None = None  # the run error the machine stopped at
        self._resume: str | None = None
        self._early: str | None = None  # a resume sent before the entry stop: it acts there
        self._stops = 0
        self.started = False
        self.ended = False  # the run is over (exited is sent): a new launch may follow
        self._answer: object = None
        self._pause = False
        self._terminate = False
        self._mode: str | None = "in" if launch.stop_on_entry else None  # "in" | "over" | "out"
        self._mode_depth = 0
        self._reason = "entry" if launch.stop_on_entry else "step"
        self._function_stop = False
        self.last_step = 0
        self._phase = LIVE
        self._replay: Replay | None = None
        self._target = 0
        self._target_chunk: tuple[str, int] | None = None
        self._chunk: tuple[str, int] | None = None
        self._search: Rewind | None = None
        self._refine: tuple[str, int] | None = None  # the one chunk a second search runs line by line
        self._open_bulk: tuple[str, int] | None = None  # a chunk the search ran in bulk, not yet left
        self._found: tuple[int, tuple[str, int] | None] | None = None
        self._first: tuple[int, tuple[str, int] | None] | None = None
        self._scripted = 0
        self._error_frames: list[Frame] | None = None
        self._error_at: tuple[str, int] | None = None  # where the run failed, for the search back to it
        self._last_where: tuple[str, int] = ("", 0)
        self._last_chunk: tuple[str, int] | None = None  # the chunk of the last statement seen
        # the last statement seen at each call depth, and the one a step back goes to
        self._trail: list[tuple[int, tuple[str, int] | None] | None] = []
        self._before: tuple[int, tuple[str, int] | None] | None = None
        self._scratch = Path()  # the folder re-runs write their log files to (made when the run starts)
        # the last statement the live run executed: a statement re-run after a step back up to it
        # writes its files (logmsg, logfile, ZHCS) to the scratch folder, as they were written once
        self._done_step = 0
        self._files_scratch = False
        self._probe_surface: ProbeCallback | None = None
        self.thread = threading.Thread(target=self._work, name="machine", daemon=True)

    @property
    def names(self) -> dict[int, str]:
        """The names the job and its macro files give their numbers (``data_breakpoints.launch_names``),
        read when first shown (a variable, a data breakpoint): a run that shows none does not read its
        files a second time for them (a 200,000-line job took 0.2 s more than the run itself)."""
        with self._names_lock:
            if self._names is None:
                self._names = launch_names(self.launch)
            return self._names

    # ------------------------------------------------------------------ the adapter's side

    def start(self) -> None:
        self.started = True
        self.thread.start()

    def resume(self, command: str) -> bool:
        """Continue, step or step back from a stop; False if the machine is not stopped.  Before
        the entry stop of ``stopOnEntry`` the command is kept and acts there (not dropped)."""
        with self.cv:
            if self.stopped:
                self._resume = command
                self.cv.notify_all()
                return True
            if (self.launch.stop_on_entry and self._stops == 0 and self._phase == LIVE
                    and command not in BACK_COMMANDS and not self._terminate):
                self._early = command
                return True
            return False

    def answer(self, value: object) -> None:
        """The operator's answer to the dialog or probe the machine waits at; the run goes on."""
        with self.cv:
            self._answer = value
            self._resume = "answer"
            self.cv.notify_all()

    def pause(self) -> None:
        self._pause = True

    def terminate(self) -> None:
        self._terminate = True
        self.resume("terminate")

    def edit(self, index: int, value: float) -> None:
        """Set a parameter at the stop (setVariable); replayed at this statement after a step back."""
        assert self.run is not None
        interp = self.run.interpreter
        interp.params.write(index, value, interp.where())
        self.writers[index] = (SET_BY_USER, 0)
        self.history.record(Input(self.last_step, "edit", (index, value)))

    # ------------------------------------------------------------------ the worker

    def _work(self) -> None:
        self._scratch = Path(tempfile.mkdtemp(prefix="ecnc-debug-"))
        code = EXIT_OK
        rewind: Rewind | None = None
        while True:
            code = EXIT_OK
            try:
                if rewind is not None:
                    self._prepare(rewind)
                self._execute()
                break
            except Rewind as back:
                rewind = back
            except Terminate:
                break
            except EcncError as err:
                code = err.exit_code
                try:
                    rewind = self._stop_at_error(err)
                except Terminate:
                    break
                if rewind is None:
                    break
            except Exception as err:  # a bug of ours: say so in the console, end the session cleanly
                self.channel.output(f"internal error of the debugger: {type(err).__name__}: {err}", "stderr")
                code = 70
                break
        shutil.rmtree(self._scratch, ignore_errors=True)
        self.ended = True
        self.channel.event("exited", {"exitCode": code})
        self.channel.event("terminated")

    def _execute(self) -> None:
        launch = self.launch
        if launch.probe_surface is not None:
            from edingcnc_lang.config.heightmap import ProbeAt, read_surface

            self._probe_surface = ProbeAt(read_surface(str(launch.probe_surface)))
        elif launch.probe_at is not None:
            from edingcnc_lang.config.heightmap import ProbePlane

            self._probe_surface = ProbePlane(launch.probe_at)
        live = self._phase == LIVE
        options = RunOptions(ini=launch.ini, macro=launch.macro, user_macro=launch.user_macro,
                             host=Host(dialog=self._dialog, probe=self._probe, message=self._message),
                             log_dir=self._log_dir() if live else self._scratch, plan=False,
                             observer=None if launch.no_debug else self, variables=launch.variables)
        if launch.max_steps is not None:
            options.max_steps = launch.max_steps
        run = Run(options)
        self.writers = {}
        interp = run.interpreter
        run.interpreter.params.on_write = lambda index: self._written(index, interp.path, interp.line)
        self.run = run
        self._trail, self._before, self._chunk, self._open_bulk = [], None, None, None
        self.error = None
        self._error_frames = None
        result = run.execute_file(launch.program, checked=self.check.current() if self.check else None)
        if self._phase == LIVE:
            self.channel.output(f"the job ended ({result.ended_by}) after {result.moves:,} moves")

    def _written(self, index: int, path: str, line: int) -> None:
        """A parameter was written: where (the variables view), and a data breakpoint's hit (live runs only)."""
        self.writers[index] = (path, line)
        if self._phase == LIVE:
            self.data.written(index)

    def _log_dir(self) -> Path:
        return self.launch.log_dir or self.launch.program.resolve().parent

    def _prepare(self, rewind: Rewind) -> None:
        """Find where a step back goes (search re-runs), then set up the re-run that stops there."""
        if rewind.exact:
            target, chunk = rewind.step, rewind.chunk
        else:
            self._searching_pass(rewind, None)
            if rewind.kind == "stepBack" and rewind.depth == 0 and self._open_bulk is not None:
                # the statement before may be a plain line the bulk path ran unseen: look again,
                # line by line in that chunk only
                self._searching_pass(rewind, self._open_bulk)
            target, chunk = self._found or self._first or (rewind.step, None)
        self.history.truncate(target)
        self._scripted = self.history.scripted_used()
        self._replay = self.history.until(target)
        self._phase, self._target, self._target_chunk = REPLAY, target, chunk
        self._mode, self._function_stop, self._pause = None, False, False
        self._reason = ("step" if rewind.kind in ("stepBack", "error")
                        else "breakpoint" if self._found else "entry")

    def _searching_pass(self, rewind: Rewind, refine: tuple[str, int] | None) -> None:
        """A re-run up to statement ``rewind.step`` that notes the statement to go back to."""
        self._phase, self._search, self._found, self._first = SEARCH, rewind, None, None
        self._refine, self._open_bulk, self._chunk = refine, None, None
        self._replay = self.history.until(rewind.step)
        try:
            self._execute()
        except _SearchDone:
            pass
        except EcncError:
            pass  # the search ran into the error the user steps back from

    def _stop_at_error(self, err: EcncError) -> Rewind | None:
        """The run failed: stop there when the exception filter is on (the user may step back)."""
        self.channel.output(err.format(), "stderr")
        if self._phase != LIVE:  # a re-run failed where the run did not (our bug): end, do not loop
            self.channel.output("internal error of the debugger: the re-run went another way", "stderr")
            return None
        if not self.stop_on_errors or self.run is None or self.launch.no_debug:
            return None
        self.error = err
        where = err.location
        self.frames = self._error_frames or [Frame("job", where.path if where else "", where.line if where else 0)]
        command = self._wait("exception", {"description": err.message, "text": err.message})
        if command == "stepBack" and where is not None and (where.path, where.line) == self._last_where:
            # the failing statement, before it ran
            return Rewind(command, self.last_step, 0, exact=True, chunk=self._last_chunk)
        if command in BACK_COMMANDS:  # it failed in a plain line the bulk path ran: find that line
            self._error_at = (where.path, where.line) if where is not None else None
            return Rewind("error" if command == "stepBack" else command, self.run.interpreter.budget.steps + 1,
                          len(self.frames) - 1)
        return None

    # ------------------------------------------------------------------ stopping

    def _stop(self, machine: MachineView, reason: str, extra: dict[str, Any] | None = None) -> str:
        """Stop and wait for the user; returns the command that ended the stop (after acting on it)."""
        self.frames = frames_of(machine)
        command = self._wait(reason, extra)
        if command == "answer":
            return command
        if command in BACK_COMMANDS:
            if self.history.full:
                self.channel.output("cannot step back: the session has more than 10,000 inputs to replay",
                                    "stderr")
            elif command == "stepBack" and self._before is not None:  # seen on the way here: no search
                raise Rewind(command, self._before[0], len(machine.stack), exact=True, chunk=self._before[1])
            else:
                raise Rewind(command, self.last_step, len(machine.stack))
        self._mode = {"next": "over", "stepIn": "in", "stepOut": "out"}.get(command)
        self._mode_depth = len(machine.stack)
        self._reason = "step"
        return command

    def _wait(self, reason: str, extra: dict[str, Any] | None = None) -> str:
        with self.cv:
            self.stopped = True
            self._stops += 1
            self._resume, self._early = self._early, None
            self.channel.event("stopped", {"reason": reason, "threadId": 1, "allThreadsStopped": True,
                                           **(extra or {})})
            if self._resume is not None:  # sent before this stop: the client knows it goes on
                self.channel.event("continued", {"threadId": 1, "allThreadsContinued": True})
            while self._resume is None:
                self.cv.wait()
            command = self._resume
            self.stopped = False
        if command == "terminate" or self._terminate:
            raise Terminate()
        return command

    # ------------------------------------------------------------------ the observer seam

    def statement(self, machine: MachineView, stmt: n.Stmt) -> None:
        step = machine.steps
        self.last_step = step
        self._last_where = (machine.path, machine.line)
        depth = len(machine.stack)
        if self._phase == SEARCH:
            back = self._search
            assert back is not None
            if step >= back.step and back.kind != "error":
                raise _SearchDone()  # (the chunk before it is still open: _prepare may look into it)
        if depth == 0 and type(stmt) is not n.PlainBlock:
            # a top-level statement of its own: no chunk of plain lines holds it
            self._chunk = self._open_bulk = None
        self._last_chunk = self._chunk
        if self._phase != LIVE:
            self._rerun_statement(machine, stmt, step)
            return
        if self._files_scratch and step > self._done_step:  # past what the run had done: files again
            self._files_scratch = False
            self._relocate_log(machine)
        self._done_step = max(self._done_step, step - 1)
        self._follow(step, depth)
        if self._terminate:
            raise Terminate()
        if self._pause:
            self._pause = False
            self._stop(machine, "pause")
            return
        mode = self._mode
        if mode is not None:
            depth = len(machine.stack)
            if mode == "in" or (mode == "over" and depth <= self._mode_depth) or depth < self._mode_depth:
                self._stop(machine, self._reason)
                return
        if self._function_stop:
            self._function_stop = False
            self._stop(machine, "function breakpoint")
            return
        written = self.data.take()
        if written is not None:
            self._stop(machine, "data breakpoint", self.data.stopped_at(
                written, machine.variable(written), self.writers.get(written, ("", 0)), self.names))
            return
        lines = self.breakpoints.watched(machine.path)
        if lines:
            bp = lines.get(machine.line)
            if bp is not None:
                decision = reached(bp, machine.evaluator)
                if decision.log is not None:
                    self.channel.output(decision.log, "console", machine.path, machine.line)
                if decision.stop:
                    self._stop(machine, "breakpoint", {"hitBreakpointIds": [bp.id]})

    def line_by_line(self, machine: MachineView, run: n.PlainRun) -> bool:
        self._chunk = key = (run.path, run.lines[0][0])
        first, last = run.lines[0][0], run.lines[-1][0]
        if self._phase == SEARCH:
            back = self._search
            assert back is not None
            if self._refine is not None:
                seen = key == self._refine
            else:
                seen = back.kind == "error" or (back.kind == "reverseContinue"
                                                and self.breakpoints.any_between(run.path, first, last))
        elif self._phase == REPLAY:
            seen = key == self._target_chunk
        else:
            seen = (self._pause or self._terminate or self._mode is not None or self.data.hit is not None
                    or self.breakpoints.any_between(run.path, first, last))
        self._open_bulk = None if seen else key
        if not seen:
            self._trail.clear()  # its lines run unseen: what came before them is no step back
        return seen

    def _follow(self, step: int, depth: int) -> None:
        """Note the statement a step back from this one goes to: the last one seen at this depth or
        an outer one; unknown (None: a search re-run finds it) after lines the bulk path ran unseen."""
        trail = self._trail
        if self._open_bulk is not None:  # seen in a chunk whose other lines run unseen
            self._before = None
            return
        del trail[depth + 1:]
        self._before = max((t for t in trail if t is not None), default=None)
        trail.extend([None] * (depth + 1 - len(trail)))
        trail[depth] = (step, self._chunk)

    def branch(self, machine: MachineView, stmt: n.If | n.While, taken: bool) -> None:
        """A While line is reached again at every turn (its first decision follows its statement):
        seen as a statement, it can be stopped at, stepped to and stepped back to."""
        if type(stmt) is n.While and machine.steps != self.last_step:
            self.statement(machine, stmt)

    def call(self, machine: MachineView, frame: CallFrame, sub: n.Sub) -> None:
        if self._phase == LIVE:
            bp = self.breakpoints.functions.get(frame.name)
            if bp is not None:
                decision = reached(bp, machine.evaluator)
                if decision.log is not None:
                    self.channel.output(decision.log, "console", machine.path, machine.line)
                self._function_stop = self._function_stop or decision.stop

    def ret(self, machine: MachineView, frame: CallFrame) -> None:
        if self._error_frames is None and isinstance(sys.exc_info()[1], EcncError):
            self._error_frames = frames_of(machine)  # the stack as it was where the error happened

    def _rerun_statement(self, machine: MachineView, stmt: n.Stmt, step: int) -> None:
        """A statement of a search or replay re-run: the user's edits, then the way back."""
        assert self._replay is not None
        for index, value in self._replay.edits.get(step, ()):
            machine.set_variable(index, value)
            self.writers[index] = (SET_BY_USER, 0)
        if self._phase == SEARCH:
            self._searching(machine, stmt, step)
            return
        self._follow(step, len(machine.stack))
        if step >= self._target:
            self._phase = LIVE
            self._files_scratch = True
            if step > self._done_step:
                self._files_scratch = False
                self._relocate_log(machine)
            self._stop(machine, self._reason)

    def _searching(self, machine: MachineView, stmt: n.Stmt, step: int) -> None:
        back = self._search
        assert back is not None
        depth = len(machine.stack)
        here = (step, self._chunk)
        if self._first is None:
            self._first = here
        if back.kind == "stepBack":
            if depth <= back.depth:
                self._found = here
        elif back.kind == "error":
            if self._error_at == (machine.path, machine.line):
                self._found = here
        else:
            lines = self.breakpoints.watched(machine.path)
            bp = lines.get(machine.line) if lines else None
            if bp is not None and bp.log is None:
                try:
                    if bp.condition is None or evaluate(machine.evaluator, bp.condition) != 0.0:
                        self._found = here
                except EcncError:
                    self._found = here

    def _relocate_log(self, machine: MachineView) -> None:
        """A re-run's log file went to the scratch folder; from here on the real one is written."""
        machine.move_files(self._scratch, self._log_dir())

    # ------------------------------------------------------------------ the operator's part

    def _message(self, kind: str, text: str, path: str, line: int) -> None:
        if self._phase == LIVE and kind != "dialog":
            label = {"msg": "msg", "warn": "warning", "error": "error", "log": "log"}.get(kind, kind)
            self.channel.output(f"{label}: {text}", "stderr" if kind == "error" else "stdout", path, line)

    def _dialog(self, title: str, fields: Any) -> DialogAnswer | None:
        if self._phase != LIVE:
            assert self._replay is not None
            given = self._replay.next("dialog")
            return given.value if given is not None else None  # type: ignore[return-value]
        if self._scripted < len(self.launch.answers):
            answer = self.launch.answers[self._scripted]
            self._scripted += 1
            self.history.record(Input(self.last_step, "dialog", answer, scripted=True))
            return answer
        if self.launch.no_debug or self.run is None:
            return None
        shown = "; ".join(f"{f.label} #{f.index} = {f.value:g}" for f in fields) if fields else "no fields"
        self.channel.output(f'dlgmsg "{title}": {shown}\nanswer in the debug console: ok #N=V ... or cancel '
                            "(continue answers ok, values unchanged)")
        self.fields = [f.index for f in fields]
        value = self._ask(self.run.interpreter.view, "dialog", f"dlgmsg \"{title}\" waits for an answer")
        answer = value if isinstance(value, DialogAnswer) else DialogAnswer()
        self.history.record(Input(self.last_step, "dialog", answer))
        return answer

    def _probe(self, start: Pose, target: Pose) -> Pose | None:
        if self._phase != LIVE:
            assert self._replay is not None
            given = self._replay.next("probe")
            return given.value if given is not None else target  # type: ignore[return-value]
        if self._probe_surface is not None:
            trip = self._probe_surface(start, target)
        elif self.launch.no_debug or self.run is None:
            trip = target
        else:
            where = " ".join(f"{a}{v:g}" for a, v in zip("XYZABC", target))
            self.channel.output(f"G38.2 towards {where} (machine): answer in the debug console: ok (trips at "
                                "the target), miss (no contact) or trip Z-3.2 (trips there)")
            value = self._ask(self.run.interpreter.view, "probe", "G38.2 waits for the probe")
            trip = value[1] if isinstance(value, tuple) else target
        self.history.record(Input(self.last_step, "probe", trip))
        return trip

    def _ask(self, machine: MachineView, what: str, text: str) -> object:
        """Stop until the console answers (or the user continues: the default answer)."""
        self.waiting, self._answer = what, None
        try:
            mode, depth, reason = self._mode, self._mode_depth, self._reason
            command = self._stop(machine, what, {"description": text, "text": text})
            if command == "answer":  # the run goes on as it was going before it asked
                self._mode, self._mode_depth, self._reason = mode, depth, reason
                self.channel.event("continued", {"threadId": 1, "allThreadsContinued": True})
                return self._answer
            return None
        finally:
            self.waiting = None
