"""The Debug Adapter Protocol side: requests in, responses and events out, over a byte stream.

Each request is answered on the reading thread from the session's state; the run itself only
ever changes in the worker thread (session.py).  One thread is shown to the client: the machine.
"""
from __future__ import annotations

import re

import os
from collections.abc import Callable
from typing import Any, BinaryIO

from edingcnc_lang.errors import EcncError
from edingcnc_lang.host import DialogAnswer
from edingcnc_lang.debug.breakpoints import JobCheck, job_facts, sub_of
from edingcnc_lang.debug.expressions import (
    ExpressionError,
    dialog_answer,
    evaluate,
    parse_assignment,
    parse_expression,
    parse_parameter,
    probe_answer,
)
from edingcnc_lang.debug.arguments import arguments_problem
from edingcnc_lang.debug.protocol import Channel, Message, ProtocolError, Reader
from edingcnc_lang.debug.launch import Launch, LaunchError, launch_of
from edingcnc_lang.debug.session import Session
from edingcnc_lang.debug.variables import PERSISTENT, SYSTEM, USER, parameter, scopes, variables

CAPABILITIES = {
    "supportsConfigurationDoneRequest": True,
    "supportsConditionalBreakpoints": True,
    "supportsHitConditionalBreakpoints": True,
    "supportsLogPoints": True,
    "supportsFunctionBreakpoints": True,
    "supportsStepBack": True,
    "supportsEvaluateForHovers": True,
    "supportsSetVariable": True,
    "supportsExceptionInfoRequest": True,
    "supportsTerminateRequest": True,
    "supportsDataBreakpoints": True,
    "exceptionBreakpointFilters": [{"filter": "runError", "label": "Run errors", "default": True,
                                    "description": "Stop where the run fails (the error's text), before it ends"}],
}
RESUMES = {"continue": "continue", "next": "next", "stepIn": "stepIn", "stepOut": "stepOut",
           "stepBack": "stepBack", "reverseContinue": "reverseContinue"}

# a parameter as the variables view names it: its number, then the name the variable map gives it
_SHOWN_NAME = re.compile(r"\s*(#\d+)\s+[^\s\[\]+\-*/=<>].*")


class RequestError(Exception):
    """A request that cannot be done; its text is the failed response's message."""


class Adapter:
    """Answers one client's requests for one debugged run."""

    def __init__(self, channel: Channel) -> None:
        self.channel = channel
        self.session: Session | None = None
        self.subs: dict[str, tuple[str, int]] = {}  # sub name -> its file and line, for function breakpoints
        self.done = False

    def handle(self, request: Message) -> None:
        """Answer one request: a malformed one, or one whose arguments fail their check
        (arguments.py), gets ``success: false`` before any handler sees it."""
        command, seq = request.get("command"), request.get("seq")
        if not isinstance(command, str) or not command:
            self.channel.fail(request, "a request needs a command (a string)")
            return
        if type(seq) is not int or seq < 0:
            self.channel.fail(request, f"{command[:100]}: a request needs a seq (a whole number)")
            return
        handler: Callable[[dict[str, Any]], dict[str, Any] | None] | None = (
            self._resume_request(RESUMES[command]) if command in RESUMES
            else getattr(self, f"on_{command}", None) if command.isidentifier() else None)
        if handler is None:
            self.channel.fail(request, f"{command[:100]} is not supported by ecnc debug")
            return
        arguments = request.get("arguments")
        problem = arguments_problem(command, {} if arguments is None else arguments)
        if problem is not None:
            self.channel.fail(request, problem)
            return
        try:
            body = handler(arguments or {})
        except RequestError as err:
            self.channel.fail(request, str(err))
            return
        except Exception as err:  # a bug of ours (a RecursionError too): this request fails, the session goes on
            self.channel.fail(request, f"internal error of the debugger: {type(err).__name__}: {err}")
            return
        self.channel.respond(request, body)
        if command == "launch":
            self.channel.event("initialized")

    def _session(self) -> Session:
        if self.session is None:
            raise RequestError("launch first")
        return self.session

    def _stopped(self) -> Session:
        session = self._session()
        if not session.stopped or session.run is None:
            raise RequestError("the machine is running: pause it first")
        return session

    # ------------------------------------------------------------------ set-up

    def on_initialize(self, _args: dict[str, Any]) -> dict[str, Any]:
        return CAPABILITIES

    def on_launch(self, args: dict[str, Any]) -> None:
        if self.session is not None and self.session.started and not self.session.ended:
            raise RequestError("launch: a run is going on in this session (terminate it first)")
        try:
            launch = launch_of(args)
        except LaunchError as err:
            raise RequestError(str(err)) from None
        self.subs, check = known_subs(launch)
        if launch.probe_surface is not None:
            from edingcnc_lang.config.heightmap import read_surface

            try:
                read_surface(launch.probe_surface)
            except EcncError as err:
                raise RequestError(err.format()) from None
        self.session = Session(self.channel, launch, check)

    def on_setBreakpoints(self, args: dict[str, Any]) -> dict[str, Any]:
        path = (args.get("source") or {}).get("path")
        if not path:
            raise RequestError("setBreakpoints needs a source with a path")
        specs = args.get("breakpoints")
        if specs is None:
            specs = [{"line": line} for line in args.get("lines", [])]
        placed = self._session().breakpoints.set_source(path, specs)
        return {"breakpoints": [bp.to_json(path) for bp in placed]}

    def on_setFunctionBreakpoints(self, args: dict[str, Any]) -> dict[str, Any]:
        specs = args["breakpoints"]
        placed = self._session().breakpoints.set_functions(specs, self.subs)
        return {"breakpoints": [bp.to_json(self.subs.get(sub_of(spec["name"]), ("", 0))[0])
                                for bp, spec in zip(placed, specs)]}

    def on_dataBreakpointInfo(self, args: dict[str, Any]) -> dict[str, Any]:
        session = self._session()
        return session.data.info(str(args.get("name", "")), session.names)

    def on_setDataBreakpoints(self, args: dict[str, Any]) -> dict[str, Any]:
        return {"breakpoints": self._session().data.set(list(args.get("breakpoints", [])))}

    def on_setExceptionBreakpoints(self, args: dict[str, Any]) -> dict[str, Any]:
        self._session().stop_on_errors = "runError" in args.get("filters", [])
        return {"breakpoints": [{"verified": True} for _f in args.get("filters", [])]}

    def on_configurationDone(self, _args: dict[str, Any]) -> None:
        session = self._session()
        if session.started:
            raise RequestError("configurationDone was sent already: the run has started")
        session.start()

    def on_threads(self, _args: dict[str, Any]) -> dict[str, Any]:
        return {"threads": [{"id": 1, "name": "machine"}]}

    # ------------------------------------------------------------------ a stopped machine

    def on_stackTrace(self, _args: dict[str, Any]) -> dict[str, Any]:
        session = self._session()
        frames = session.frames if session.stopped else []
        return {"stackFrames": [{"id": i + 1, "name": f.name, "line": f.line, "column": 1,
                                 **({"source": {"name": os.path.basename(f.path), "path": f.path}}
                                    if f.path and not f.path.startswith("<") else {})}
                                for i, f in enumerate(frames)], "totalFrames": len(frames)}

    def on_scopes(self, _args: dict[str, Any]) -> dict[str, Any]:
        session = self._stopped()
        assert session.run is not None
        return {"scopes": scopes(session.run)}

    def on_variables(self, args: dict[str, Any]) -> dict[str, Any]:
        session = self._stopped()
        assert session.run is not None
        return {"variables": variables(session.run, args["variablesReference"], session.writers, session.names)}

    def on_setVariable(self, args: dict[str, Any]) -> dict[str, Any]:
        """The name is read as the dialect reads ``NAME = 0`` (``#4005``, ``#[4000 + 5]``): a number
        outside #1..#5999 or a read-only system variable is refused as a job's assignment is."""
        session = self._stopped()
        assert session.run is not None
        if args["variablesReference"] not in (USER, PERSISTENT, SYSTEM):
            raise RequestError("only parameters (#n) can be set")
        evaluator = session.run.interpreter.evaluator
        named = _SHOWN_NAME.fullmatch(args["name"])  # the view shows "#1552 thread_major_diameter"
        try:
            index = evaluator.index(parse_parameter(named[1] if named else args["name"]))
            value = evaluate(evaluator, parse_expression(args["value"]))
            session.edit(index, value)
        except (ExpressionError, EcncError) as err:
            raise RequestError(getattr(err, "message", None) or str(err)) from None
        shown = parameter(session.run, index, session.writers, session.names)
        return {"value": shown["value"], "type": shown["type"], "variablesReference": 0}

    def on_evaluate(self, args: dict[str, Any]) -> dict[str, Any]:
        session = self._session()
        text = args["expression"].strip()
        if args.get("context") == "repl":
            answered = self._console_answer(session, text)
            if answered is not None:
                return {"result": answered, "variablesReference": 0}
        session = self._stopped()
        assert session.run is not None
        try:
            if args.get("context") == "repl":
                assignment = parse_assignment(text)
                if assignment is not None:
                    target, expr = assignment
                    index = session.run.interpreter.evaluator.index(target)
                    from edingcnc_lang.machine.state import format_value

                    value = evaluate(session.run.interpreter.evaluator, expr)
                    session.edit(index, value)
                    return {"result": f"#{index} = {format_value(value)}", "variablesReference": 0}
            expr = parse_expression(text)
            value = evaluate(session.run.interpreter.evaluator, expr)
        except (ExpressionError, EcncError) as err:
            raise RequestError(getattr(err, "message", None) or str(err)) from None
        from edingcnc_lang.machine.state import format_value

        return {"result": format_value(value), "variablesReference": 0}

    def _console_answer(self, session: Session, text: str) -> str | None:
        """The operator answering the dialog or probe the machine waits at; None if the text is no answer."""
        try:
            if session.waiting == "dialog":
                answer = dialog_answer(text)
                if answer is not None:
                    unknown = sorted(set(answer.values) - set(session.fields))
                    if unknown:
                        fields = ", ".join(f"#{i}" for i in session.fields) or "none"
                        raise RequestError(f"#{unknown[0]} is not a field of this dialog (its fields: {fields})")
                    session.answer(answer)
                    return "answered: " + _shown(answer)
            elif session.waiting == "probe":
                assert session.run is not None
                trip = probe_answer(text, tuple(session.run.interpreter.pos))
                if trip is not None:
                    session.answer(trip)
                    return "answered: " + text
            elif dialog_answer(text) is not None or text.lower() in ("miss",):
                raise RequestError("nothing waits for an answer: the machine asks with a dlgmsg or G38.2")
        except ExpressionError as err:
            raise RequestError(str(err)) from None
        return None

    def on_exceptionInfo(self, _args: dict[str, Any]) -> dict[str, Any]:
        err = self._session().error
        if err is None:
            raise RequestError("the machine did not stop at an error")
        return {"exceptionId": err.code, "description": err.message, "breakMode": "always",
                "details": {"message": err.format(), "typeName": type(err).__name__, "code": err.code}}

    # ------------------------------------------------------------------ running

    def _resume_request(self, command: str) -> Callable[[dict[str, Any]], dict[str, Any]]:
        def resume(_args: dict[str, Any]) -> dict[str, Any]:
            if not self._session().resume(command):
                raise RequestError(f"{command}: the machine is not stopped (it is running or has ended)")
            return {"allThreadsContinued": True}
        return resume

    def on_pause(self, _args: dict[str, Any]) -> None:
        self._session().pause()

    def on_terminate(self, _args: dict[str, Any]) -> None:
        self._session().terminate()

    def on_disconnect(self, _args: dict[str, Any]) -> None:
        if self.session is not None:
            self.session.terminate()
        self.done = True


def _shown(answer: DialogAnswer) -> str:
    values = ", ".join(f"#{i}={v:g}" for i, v in answer.values.items())
    return ("ok" if answer.ok else "cancel") + (f" {values}" if values else "")


def known_subs(launch: Launch) -> tuple[dict[str, tuple[str, int]], JobCheck | None]:
    """Every sub the run can call, by lower-case name, with its file and the line of its ``Sub``;
    a job or macro file that does not load is the launch's error.  The job is read by the run's own
    check (``job_facts``), which the run then uses: with the check, when it passed."""
    from edingcnc_lang.runner import Run, RunOptions

    try:
        run = Run(RunOptions(ini=launch.ini, macro=launch.macro, user_macro=launch.user_macro, plan=False))
        found: dict[str, tuple[str, int]] = {}
        for path, program in run.load_macros():
            for name, sub in program.subs.items():
                found.setdefault(name.lower(), (str(path), sub.span.line))
        job, check = job_facts(run, launch.program)
        if job.error is not None:
            raise job.error
        for name, line in job.subs:
            found[name] = (str(launch.program), line)
        return found, check
    except EcncError as err:
        raise RequestError(err.format()) from None


def serve(stdin: BinaryIO, stdout: BinaryIO) -> int:
    """Speak DAP on these streams until the client disconnects or closes them.  A message that
    cannot be read is refused with an output event and the next one is read: nothing the client
    sends ends the session but ``disconnect`` or the end of the stream."""
    channel = Channel(stdout)
    adapter = Adapter(channel)
    reader = Reader(stdin)
    while not adapter.done:
        try:
            message = reader.read()
        except ProtocolError as err:
            channel.output(f"ecnc debug: {err} (the message is skipped)", "stderr")
            continue
        if message is None:
            break
        if message.get("type") == "request":
            adapter.handle(message)
        elif message.get("type") not in ("response", "event"):
            channel.fail(message, "a message's type must be \"request\"")
    session = adapter.session
    if session is not None:
        session.terminate()
        if session.thread.is_alive():
            session.thread.join(timeout=5)
    return 0
