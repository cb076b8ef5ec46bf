"""Running a job end to end: configuration, macro files, check, execute, report.

This is the embedding API's engine.  A run reads the job twice: first to check
the whole file (syntax and block structure; nothing runs if it is wrong) and to
collect its subs, then to execute it statement by statement as it streams in.
"""
from __future__ import annotations

import os
import queue
import threading
from itertools import islice
from collections.abc import Callable, Iterable, Iterator, Sequence
from dataclasses import replace
from functools import cache
from pathlib import Path

from edingcnc_lang.syntax import nodes as n
from edingcnc_lang.machine import tables as t
from edingcnc_lang.canon import Batch, Move, Pose
from edingcnc_lang.config.machine_config import MachineConfig, load_config, save_variables
from edingcnc_lang.errors import Cancelled, EcncError, Interrupted, Location, MachineError
from edingcnc_lang.host import DialogAnswer, DialogCallback, DialogField, guarded
# the records of a run, re-exported: ``from edingcnc_lang.runner import RunOptions`` keeps working
from edingcnc_lang.run_records import Assumption, CheckedJob, RunOptions, RunResult, result_of
from edingcnc_lang.motion.callback_tap import CallbackTap
from edingcnc_lang.machine.interpreter import Interpreter
from edingcnc_lang.machine.named_commands import tools_used
from edingcnc_lang.machine.observe import MachineView
from edingcnc_lang.kinematics.base import Kinematics
from edingcnc_lang.kinematics.builtin import TrivialKinematics
from edingcnc_lang.kinematics.loader import load_kinematics
from edingcnc_lang.motion.stage import MotionStage, PlannerStage
from edingcnc_lang.motion.sinks import (
    CallbackSink,
    EventsWriter,
    SamplesWriter,
    TraceWriter,
)
from edingcnc_lang.outputs import check_outputs, ensure_parent, output_identities
from edingcnc_lang.diagnostics import Diagnostic
from edingcnc_lang.syntax.parser import StatementReader, check_file, parse_file, parse_text, read_statements
from edingcnc_lang.motion.planner.overrides import Overrides
from edingcnc_lang.motion.planner.stage import Planner, TimedSink
from edingcnc_lang.motion.planner.untimed import Untimed
from edingcnc_lang.syntax.source import iter_file_lines, iter_text_lines
from edingcnc_lang.pipeline import STAGES, Pipeline
from edingcnc_lang.pipeline.height_comp import HeightCompensation

__all__ = ["Assumption", "MoveStream", "Run", "RunOptions", "RunResult", "input_files", "packaged_macro", "result_of",
           "run_file", "run_string"]

PLAIN_MOTION = {t.code_key(c) for c in (0, 1, 2, 3, 33, 33.1, 38.2, 76)}


def _macro_files(opts: RunOptions, cfg: MachineConfig) -> list[Path]:
    main = opts.macro or cfg.macro_file or packaged_macro()
    user = opts.user_macro or cfg.user_macro_file
    return [p for p in (user, main) if p is not None]


def input_files(options: RunOptions) -> list[Path]:
    """The files a run with ``options`` reads besides its job (the ini and the macro files, the ini's
    own included): what a command that writes checks its outputs against (``outputs.check_outputs``)."""
    config = load_config(options.ini) if options.ini else MachineConfig.default()
    return [path for path in (options.ini, *_macro_files(options, config)) if path is not None]


def packaged_macro() -> Path:
    """The default macro file shipped inside the package."""
    return Path(__file__).resolve().parent / "stdlib" / "macro.cnc"


class Run:
    """One job run on one virtual machine; build it, then call ``execute``."""

    def __init__(self, options: RunOptions) -> None:
        self.options = options
        self._files: dict[str, Path] = {}  # a job run under another name (a pipe's copy): name -> file
        self._texts: dict[str, str] = {}  # jobs run from a string, to find an error's column in
        self._reader: StatementReader | None = None  # the run pass over a job file: an error's line text
        self.job_lines = 0  # lines of the job file, counted by the check pass (for a progress line)
        self.warnings: list[Diagnostic] = []
        self.assumptions: list[Assumption] = []
        self.config = load_config(options.ini) if options.ini else MachineConfig.default()
        for warning in self.config.warnings:
            self._warn(warning)
        self.kinematics = self._load_kinematics()
        overrides = Overrides(options.feed_override, options.rapid_override)
        self._jobs: list[Path] = []  # the job files this run reads, which no output may be
        self._writers: list[TraceWriter | SamplesWriter | EventsWriter] = []
        if options.trace:
            self._writers.append(TraceWriter(ensure_parent(options.trace)))
        if options.samples:
            self._writers.append(SamplesWriter(ensure_parent(options.samples)))
        if options.events:
            self._writers.append(EventsWriter(ensure_parent(options.events)))
        sinks: list[TimedSink] = [*self._writers, *options.sinks]
        timed = options.on_timed_move is not None
        if timed:  # all the callbacks in program order, as the planner hands each window on
            sinks.append(CallbackSink(options.on_move, options.on_event, options.on_timed_move))
        self.planner: Planner | None = None
        stage: PlannerStage
        if options.plan or _reads_time(options):
            stage = self.planner = Planner(self.config, sinks, overrides, want_samples=options.samples is not None)
        else:
            stage = Untimed(overrides)
        # without on_timed_move, on_move and on_event hear each move and event as the machine makes it;
        # with it, the tap only stops the run at once when it is cancelled (motion/callback_tap.py)
        self._tap: CallbackTap | None = None
        if timed and options.on_batch is not None:
            raise EcncError("on_batch hears the moves as the machine makes them, on_timed_move one at a "
                             "time with their timing: give one of them")
        if options.on_move or options.on_event or options.on_batch or timed:
            stage = self._tap = CallbackTap(stage, None if timed else options.on_move,
                                            None if timed else options.on_event, options.on_batch)
        self.motion = MotionStage(self.config, self.kinematics, stage, self._write_param,
                                  sample_always=options.samples is not None)
        if self.planner is not None:
            self.planner.joints_of = self.motion.joints_at
        self.pipeline = Pipeline(STAGES, self.motion, self.config)
        host = options.host
        if host.probe is None:  # the simulated probe: trips at its target, and the run says so once
            host = replace(host, probe=self._simulated_probe)
        host = replace(host, dialog=self._answered(host.dialog))
        self.interpreter = Interpreter(self.pipeline.head, self.config, guarded(host, self._where),
                                       max_steps=options.max_steps,
                                       log_dir=options.log_dir, allow_exec=options.allow_exec,
                                       simulation=options.simulation, block_delete=options.block_delete,
                                       observer=options.observer)
        self.interpreter.on_warning = self._warn
        if not options.write_job_files:
            self.interpreter.files.kept = {}
        # the configured kinematics' type is there from the start; it is not something the job wrote
        self.interpreter.params.load({t.KIN_TYPE: float(self.kinematics.kin_type())})
        if self.planner is not None:
            self.planner.tool = int(self.interpreter.params.read(t.TOOL_CURRENT))

    @property
    def view(self) -> MachineView:
        """The machine as it is now, read-only (where the run is, the call stack, the position, every
        parameter with ``variable(n)``, expressions' values): for a callback during the run."""
        return self.interpreter.view

    def cancel(self) -> None:
        """Stop the run at its next move, statement, loop turn or hole, or before its next callback
        or dialog; safe to call from another thread or from a callback.  The run then ends with
        ``Cancelled`` (exit 130 on the command line), whose ``result`` is the state so far."""
        self.interpreter.cancel()
        if self._tap is not None:
            self._tap.cancelled = True

    def moves(self, job: str | os.PathLike[str], *, buffer: int = 1024) -> MoveStream:
        """Run ``job`` in a thread of its own and hand its moves over as they are made:
        ``for move in run.moves("job.nc")``.  At most ``buffer`` moves wait in memory; leaving the loop
        early (``break``, or ``close()``) cancels the run.  ``stream.result`` is the result afterwards;
        an error that stopped the run is raised from the loop after the moves made before it, except
        ``Cancelled`` (``Run.cancel()``, a stop button): the loop just ends and ``stream.error`` holds it."""
        return MoveStream(self, Path(job), buffer)

    def _assume(self, what: str, text: str, location: Location | None = None, tell: bool = True) -> None:
        assumption = Assumption(what, text, location)
        self.assumptions.append(assumption)
        if tell and self.options.on_assumption is not None:
            self.options.on_assumption(assumption)

    def _answered(self, ask: DialogCallback | None) -> DialogCallback:
        """The dialog callback, noting each dialog nobody answered (OK with its values unchanged) as an
        assumption at its line; not told again: the command line shows every dialog as it is asked."""
        def answer(title: str, fields: Sequence[DialogField]) -> DialogAnswer | None:
            given = ask(title, fields) if ask is not None else None
            if given is None:
                self._assume("dialog", f"the dialog {title!r} was answered OK with its values unchanged "
                             "(no answer given: --answer)", self._where(), tell=False)
            return given
        return answer

    def _simulated_probe(self, start: Pose, target: Pose) -> Pose:
        if not any(a.what == "probe" for a in self.assumptions):
            self._assume("probe", "the probe is simulated: G38.2 trips at its target, so a measured length "
                         "is the target's (give --probe-at Z or --probe-surface FILE)", self._where())
        return target

    def _assume_setup(self) -> None:
        """Say what the machine is when the user did not: no ini, no macro file of theirs (and, to
        ``on_setup``, what was given)."""
        if self.options.on_setup is not None:
            for line in self._setup_lines():
                self.options.on_setup(line)
        if self.config.path is None:
            self._assume("machine", "no cnc.ini given: a built-in 6-axis mill (EdingCNC 4.03), machine zero = work "
                         "zero, travel +-1,000,000 mm at 1000 mm/s, an empty tool table (give --ini FILE)")
        if not (self.options.macro or self.config.macro_file):
            self._assume("macro", f"no macro file given or named by the ini: the packaged {packaged_macro().name} "
                         "(M6's change_tool, homing, tool measurement) (give --macro FILE)")

    def _setup_lines(self) -> list[str]:
        """The machine and macro files this run uses, one line each, for ``-v``."""
        config, lines = self.config, []
        if config.path is not None:
            kind = ("lathe, X as a diameter" if config.diameter_programming else "lathe") if config.lathe else "mill"
            travel = ", ".join(f"{j.name} {j.negative_limit:g}..{j.positive_limit:g}" for j in config.joints if j.visible)
            lines.append(f"{config.path}: a {kind}, travel {travel}, {len(config.tools)} tools in the table, "
                         f"kinematics {self.kinematics.name}")
        lines.append("macro files, in lookup order: " + ", ".join(map(str, self.macro_files())))
        return lines

    def _where(self) -> Location:
        return Location(self.interpreter.path, self.interpreter.line)

    def _write_param(self, index: int, value: float) -> None:
        self.interpreter.params.set(index, value)

    def _load_kinematics(self) -> Kinematics:
        """The ini's plug-in; without an ini the built-in trivial kinematics (no plug-in lookup)."""
        if not self.config.path:
            return TrivialKinematics(self.config.kinematics_settings)
        try:
            return load_kinematics(self.config.kinematics_name or "trivial", self.config.kinematics_settings,
                                   [folder for folder in (self.config.folder,) if folder is not None])
        except EcncError as err:
            if err.location is None:  # point at the ini that names the plug-in
                err.location = Location(self.config.path)
            raise

    def macro_files(self) -> list[Path]:
        """Macro files in lookup order: user macro first (its subs win), then the main macro file."""
        return _macro_files(self.options, self.config)

    def load_macro(self, path: Path) -> n.Program:
        """A macro file as the controller loads it: lines that do not parse wait (as BadLine) until
        a run reaches them, each reported once as a warning; ``strict`` makes them errors here."""
        if self.options.strict:
            return parse_file(path, check_dialogs=True)
        reader = read_statements(path, tolerant=True)
        body = tuple(reader)
        reader.raise_errors()  # block structure (Sub/EndSub, If/EndIf) must still be right
        for warning in reader.warnings:
            self._warn(warning)
        return n.Program(reader.path, body, reader.unit)

    def _warn(self, warning: Diagnostic) -> None:
        self.warnings.append(warning)
        if self.options.on_warning:
            self.options.on_warning(warning)

    def load_macros(self) -> list[tuple[Path, n.Program]]:
        """The macro files, loaded, in lookup order."""
        return [(path, self.load_macro(path)) for path in self.macro_files()]

    def open_outputs(self) -> None:
        """Open the trace, samples and events files, after refusing one that is an input of the run
        (the job, the ini, a macro file) or another output; the job may then write none of them."""
        opts = self.options
        inputs = [*self._jobs, opts.ini, *self.macro_files()]
        check_outputs({"--trace": opts.trace, "--samples": opts.samples, "--events": opts.events}, inputs)
        for writer in self._writers:
            writer.open()
        self.interpreter.files.own = output_identities([*inputs, *self._outputs])

    def start(self, macros: Sequence[tuple[Path, n.Program]]) -> None:
        """What happens before a job's first line (and before an MDI session's): the outputs are
        opened, the macro files' subs are defined and their top-level lines run, then the ini's
        initialString; then ``RunOptions.variables`` are set."""
        self._assume_setup()
        self.open_outputs()
        interp = self.interpreter
        for _path, program in macros:
            interp.define_subs(program.subs.values())
        for _path, program in reversed(macros):  # top-level statements of macro files run once at load
            # (prose between subs is never executed: the controller only runs a macro file's subs)
            interp.run(stmt for stmt in program.body if not isinstance(stmt, n.BadLine))
        if self.config.initial_string:
            interp.run(parse_text(self.config.initial_string, f"{self.config.path}:initialString").body)
        self._set_variables()

    def check_job(self, job: Path, name: str | None = None,
                  on_statement: Callable[[n.Stmt], None] | None = None) -> CheckedJob:
        """The job read through before its first line runs: its syntax errors raised, its subs, which
        lines are plain and its T words (GetToolInfo) noted; ``on_statement`` as ``check_file``'s."""
        tools: set[int] = set()  # the T words, found by the check pass: the job is read twice, not more

        def find_tools(chunk: list[str]) -> None:
            joined = "\n".join(chunk)
            if "T" in joined or "t" in joined:
                tools.update(tools_used((joined,)))

        try:
            checked = check_file(job, name, on_chunk=find_tools, on_statement=on_statement)
        except KeyboardInterrupt:  # Ctrl-C while the job is read through before its first move
            raise Interrupted("interrupted (Ctrl-C) while checking the job, before its first move",
                              Location(name or os.fspath(job))) from None
        return CheckedJob(checked, frozenset(tools))

    def execute_file(self, job: Path, name: str | None = None, checked: CheckedJob | None = None) -> RunResult:
        """Check the job (unless ``checked``, its check of the file as it is now, is given), then run it as
        it streams in; ``name`` is what messages call it (default its path)."""
        self._jobs.append(job)
        if checked is None:
            checked = self.check_job(job, name)
        if name is not None:
            self._files[name] = job
        self.job_lines = checked.file.lines
        tools = tuple(sorted(checked.tools))
        self.interpreter.job_tools = lambda: tools
        macros = self.load_macros()

        def statements() -> Iterable[n.Stmt]:
            self._reader = read_statements(job, mode="run", non_plain=checked.file.non_plain, name=name)
            return self._reader
        return self._execute(statements, checked.file.subs, macros)

    def execute_text(self, text: str, path: str = "<string>") -> RunResult:
        self._texts[path] = text
        reader = StatementReader(iter_text_lines(text), path, check_dialogs=True)
        program = n.Program(path, tuple(reader), reader.unit)
        reader.raise_errors()
        self.interpreter.job_tools = cache(lambda: tools_used(iter_text_lines(text)))
        macros = self.load_macros()
        return self._execute(lambda: program.body, program.subs, macros)

    def _execute(self, statements: Callable[[], Iterable[n.Stmt]], job_subs: dict[str, n.Sub],
                 macros: Sequence[tuple[Path, n.Program]]) -> RunResult:
        interp = self.interpreter
        interp.define_subs(job_subs.values())
        error: EcncError | None = None
        try:
            self.start(macros)
            if "start" in interp.flow.subs:
                interp.call_sub("start")
            interp.run(statements())
        except EcncError as err:
            error = err
        except RecursionError:  # If/While/GoSub nested beyond what the interpreter's stack holds
            error = MachineError("blocks and sub calls are nested too deeply to run",
                                 Location(interp.path, interp.line))
        except OSError as err:  # a trace, samples or log file that cannot be written (disk full, ...)
            error = _write_error(err, self._outputs)
        except KeyboardInterrupt:  # Ctrl-C: say where the job was, report the state so far (exit 130)
            error = Interrupted("interrupted (Ctrl-C)", Location(interp.path, interp.line))
        finally:
            error = self._flush(error)
            try:
                self.motion.close()
            except OSError as err:
                error = error or _write_error(err, self._outputs)
        if error is not None:
            _add_column(error, self._texts, self._files, self._reader)
        result = self.result(error)
        if error is not None:
            error.result = result
            raise error
        if self.options.save_vars and self.config.path:
            save_variables(self.config.path, interp.params.snapshot_changed())
        return result

    def _set_variables(self) -> None:
        """``RunOptions.variables``: loaded like the ini's persisted values (they count as the start,
        not as written by the run); a read-only system variable or a number out of range is refused."""
        values = self.options.variables
        for index in values:
            if not t.FIRST_PARAM <= index <= t.LAST_PARAM:
                raise EcncError(f"variables: #{index} is not a parameter (#{t.FIRST_PARAM}..#{t.LAST_PARAM})")
            if t.is_read_only(index):
                raise EcncError(f"variables: #{index} is a read-only system variable (the machine sets it)")
        if values:
            self.interpreter.params.load({i: float(v) for i, v in values.items()})

    @property
    def _outputs(self) -> tuple[Path | None, ...]:
        """The files the run writes, to name in an error when a buffered write fails without a name."""
        return (self.options.trace, self.options.samples, self.options.events)

    def _flush(self, error: EcncError | None) -> EcncError | None:
        """Emit the moves the pipeline still holds; on a failed run the first error is the one reported."""
        try:
            self.pipeline.flush()
        except EcncError as err:
            return error or err
        except OSError as err:
            return error or _write_error(err, self._outputs)
        return error

    def machine_position(self) -> tuple[float, ...]:
        """Where the machine is: the programmed pose through G68 and G51, plus the Z that height
        compensation added at the end of the last move (ZHC follows the surface in machine Z)."""
        machine = list(self.interpreter.machine_frame(self.interpreter.pos))
        machine[2] += sum(stage.applied for stage in self.pipeline.stages if isinstance(stage, HeightCompensation))
        return tuple(machine)

    def result(self, error: EcncError | None = None) -> RunResult:
        interp = self.interpreter
        motion = interp.modal["motion"]
        modal_codes = [code for group, code in interp.modal.items() if group not in ("motion", "rotation")]
        modal_codes.append(motion if motion in PLAIN_MOTION else t.code_key(0))
        modal_codes.append(motion if motion in t.CANNED_CYCLES else t.code_key(80))
        kin = self.kinematics
        return RunResult(
            position=tuple(interp.reported_position()),
            machine=self.machine_position(),
            joints=tuple(self.motion.joints),
            variables=interp.params.snapshot_written(),
            messages=list(interp.messages.events),
            kinematics={"name": kin.name, "type": kin.kin_type(), "active": interp.guards.kinematics_active},
            tool=int(interp.params.read(t.TOOL_CURRENT)),
            moves=self.motion.moves,
            modal=[t.code_name("G", c) for c in sorted(set(modal_codes))],
            ended_by=interp.flow.ended_by,
            error=error.format() if error else None,
            error_record=error.to_json() if error else None,
            warnings=list(self.warnings),
            spindle=interp.spindle_state(),
            estimate=self.planner.estimate if self.planner else None,
            limits=self.planner.limits.to_json() if self.planner else None,
            work_zero=tuple(interp.offset()),
            parameters=interp.params.frozen(),
            assumptions=list(self.assumptions),
        )








_END = object()  # MoveStream's queue: the run is over


class MoveStream(Iterator[Move]):
    """The moves of one job as the machine makes them (``Run.moves``), from a worker thread through a
    bounded queue: memory stays at ``buffer`` moves whatever the job's length."""

    def __init__(self, run: Run, job: Path, buffer: int) -> None:
        if run._tap is None:  # a tap of its own: the moves come from it as they are made
            run._tap = CallbackTap(run.motion.planner, None, None)
            run.motion.planner = run._tap
        self._run = run
        self._queue: queue.Queue[object] = queue.Queue(maxsize=max(1, buffer))
        self._closed = False
        self.result: RunResult | None = None
        self.error: EcncError | None = None
        outer, outer_batch = run._tap.on_move, run._tap.on_batch

        def put(move: Move, joints: Pose) -> None:
            if outer is not None:
                outer(move, joints)
            self._queue.put(move)

        def put_batch(batch: Batch) -> None:  # (the moves of a batch one at a time, as without on_batch)
            if outer_batch is not None:
                outer_batch(batch)
            for move in batch.moves():
                self._queue.put(move)
        run._tap.on_move = put
        if outer_batch is not None:
            run._tap.on_batch = put_batch
        self._thread = threading.Thread(target=self._work, args=(job,), name="ecnc-run", daemon=True)
        self._thread.start()

    def _work(self, job: Path) -> None:
        try:
            self.result = self._run.execute_file(job)
        except EcncError as err:
            self.error = err
            self.result = result_of(err)
        except BaseException as err:  # never lost in the thread: raised again from the loop
            self.error = EcncError(f"the run failed: {type(err).__name__}: {err}")
            self.error.__cause__ = err
        finally:
            self._queue.put(_END)

    def __next__(self) -> Move:
        item = self._queue.get()
        if item is _END:
            self._queue.put(_END)  # a second next() ends again
            self._thread.join()
            if self.error is not None and not isinstance(self.error, Cancelled):
                error, self.error = self.error, None
                raise error
            raise StopIteration  # a cancelled run (a stop button) ends the loop quietly: ``error`` says so
        assert isinstance(item, Move)
        return item

    def close(self) -> None:
        """Stop the run (if it is still going) and wait for its thread; ``result`` is the state it reached."""
        if not self._thread.is_alive():
            return
        self._closed = True
        self._run.cancel()
        while self._thread.is_alive():  # empty the queue so the worker is not left waiting to put
            try:
                self._queue.get(timeout=0.05)
            except queue.Empty:
                pass
        self._thread.join()

    def __enter__(self) -> MoveStream:
        return self

    def __exit__(self, *exc: object) -> None:
        self.close()

    def __del__(self) -> None:
        if not self._closed and getattr(self, "_thread", None) is not None and self._thread.is_alive():
            self.close()


def _write_error(err: OSError, outputs: Sequence[Path | None] = ()) -> EcncError:
    """A failed write, naming the file: the error's own, else the output files the run writes.

    A buffered write that fails (a full disk) carries no file name; it is the trace, samples or events file.
    A closed pipe (``ecnc run --trace - | head``) is no failure of the run: it is raised again, so
    the CLI ends quietly with exit 1 as after any closed pipe.
    """
    if isinstance(err, BrokenPipeError):
        raise err
    names = ["standard output" if str(p) == "-" else str(p) for p in outputs if p is not None]
    return EcncError(f"cannot write {err.filename or ' or '.join(names) or 'an output file'}: {err.strerror}")


def _add_column(error: EcncError, texts: dict[str, str], files: dict[str, Path],
                reader: StatementReader | None = None) -> None:
    """Give a line-only location the column where that line's code starts.

    The stages after the interpreter (cutter compensation, scaling, rotation, height compensation)
    and the motion stage (limits, kinematics) see moves, which carry a line but no column; the
    report still promises ``FILE:LINE:COL``.  The run's reader still holds the lines it read last,
    where such an error nearly always is; only an older line is read from the file again.
    """
    where = error.location
    if where is None or not where.line or where.col:
        return
    line = reader.line_text(where.line) if reader is not None and reader.path == where.path else None
    if line is not None:
        error.location = Location(where.path, where.line, len(line) - len(line.lstrip()) + 1)
        return
    try:
        if where.path in texts:
            lines = iter_text_lines(texts[where.path])
        else:
            path = files.get(where.path, Path(where.path))
            if not path.is_file():  # never open a pipe or a device again just for a column
                return
            lines = iter_file_lines(path)
        line = next(islice(lines, where.line - 1, None), None)
    except (EcncError, OSError, ValueError):  # not a file (an ini's string, a name with NUL): the line alone
        return
    if line is not None:
        error.location = Location(where.path, where.line, len(line) - len(line.lstrip()) + 1)


def _reads_time(options: RunOptions) -> bool:
    """An output that reads each move's planned time: the trace's t column, samples, events, ``on_timed_move``,
    an in-process sink."""
    return bool(options.trace or options.samples or options.events or options.on_timed_move or options.sinks)


def run_file(job: str | os.PathLike[str], options: RunOptions | None = None) -> RunResult:
    """Run a job file; raises EcncError subclasses (with ``.result`` for runtime errors)."""
    return Run(options or RunOptions()).execute_file(Path(job))


def run_string(text: str, options: RunOptions | None = None, path: str = "<string>") -> RunResult:
    """Run G-code given as a string (parsed whole first)."""
    return Run(options or RunOptions()).execute_text(text, path)
