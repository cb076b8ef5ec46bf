"""The Debug Adapter Protocol side: requests in, responses and events out, over a byte stream.

Each request is answered on the reading thread from the session's state; the run itself only
ever changes in the worker thread (session.py).  One thread is shown to the client: the machine.
"""
from __future__ import annotations

import os
from collections.abc import Callable
from typing import Any, BinaryIO

from edingcnc_lang.errors import EcncError
from edingcnc_lang.host import DialogAnswer
from edingcnc_lang.debug.breakpoints import sub_of
from edingcnc_lang.debug.expressions import (
    ExpressionError,
    dialog_answer,
    evaluate,
    parse_assignment,
    parse_expression,
    probe_answer,
)
from edingcnc_lang.debug.protocol import Channel, Message, ProtocolError, read_message
from edingcnc_lang.debug.launch import Launch, LaunchError, launch_of
from edingcnc_lang.debug.session import Session
from edingcnc_lang.debug.data_breakpoints import launch_names
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


class RequestError(Exception):
    """A request that cannot be done; its text is the failed response's message."""


class Adapter:
    """Answers one client's requests for one debugged run."""

    def __init__(self, channel: Channel) -> None:
        self.channel = channel
        self.session: Session | None = None
        self.subs: dict[str, str] = {}  # sub name -> file, for function breakpoints
        self.done = False

    def handle(self, request: Message) -> None:
        command = request.get("command", "")
        handler: Callable[[dict[str, Any]], dict[str, Any] | None] | None = getattr(self, f"on_{command}", None)
        if command in RESUMES:
            handler = self._resume_request(RESUMES[command])
        if handler is None:
            self.channel.fail(request, f"{command} is not supported by ecnc debug")
            return
        try:
            body = handler(request.get("arguments") or {})
        except RequestError as err:
            self.channel.fail(request, str(err))
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
        try:
            launch = launch_of(args)
        except LaunchError as err:
            raise RequestError(str(err)) from None
        self.subs = known_subs(launch)
        if launch.probe_surface is not None:
            from edingcnc_lang.config.heightmap import read_surface

            try:
                read_surface(launch.probe_surface)
            except EcncError as err:
                raise RequestError(err.format()) from None
        self.session = Session(self.channel, launch)
        self.session.names = launch_names(launch)

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
        placed = self._session().breakpoints.set_functions(args.get("breakpoints", []), self.subs)
        return {"breakpoints": [bp.to_json(self.subs.get(sub_of(str(spec.get("name", ""))))) for bp, spec
                                in zip(placed, args.get("breakpoints", []))]}

    def on_dataBreakpointInfo(self, args: dict[str, Any]) -> dict[str, Any]:
        session = self._session()
        return session.data.info(str(args.get("name", "")), session.names)

    def on_setDataBreakpoints(self, args: dict[str, Any]) -> dict[str, Any]:
        return {"breakpoints": self._session().data.set(list(args.get("breakpoints", [])))}

    def on_setExceptionBreakpoints(self, args: dict[str, Any]) -> dict[str, Any]:
        self._session().stop_on_errors = "runError" in args.get("filters", [])
        return {"breakpoints": [{"verified": True} for _f in args.get("filters", [])]}

    def on_configurationDone(self, _args: dict[str, Any]) -> None:
        self._session().start()

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
        return {"variables": variables(session.run, int(args.get("variablesReference", 0)), session.writers,
                                       session.names)}

    def on_setVariable(self, args: dict[str, Any]) -> dict[str, Any]:
        session = self._stopped()
        if int(args.get("variablesReference", 0)) not in (USER, PERSISTENT, SYSTEM):
            raise RequestError("only parameters (#n) can be set")
        name = str(args.get("name", ""))
        try:
            index = int(name.lstrip("#").split()[0])  # "#1552 thread_major_diameter": the number
        except (ValueError, IndexError):
            raise RequestError(f"{name!r} is not a parameter") from None
        return self._assign(session, index, str(args.get("value", "")))

    def _assign(self, session: Session, index: int, text: str) -> dict[str, Any]:
        assert session.run is not None
        try:
            value = evaluate(session.run.interpreter.evaluator, parse_expression(text))
            session.edit(index, value)
        except (ExpressionError, EcncError) as err:
            raise RequestError(getattr(err, "message", None) or str(err)) from None
        shown = parameter(session.run, index, session.writers, session.names)
        return {"value": shown["value"], "type": shown["type"], "variablesReference": 0}

    def on_evaluate(self, args: dict[str, Any]) -> dict[str, Any]:
        session = self._session()
        text = str(args.get("expression", "")).strip()
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
                trip = probe_answer(text, tuple(session.run.interpreter.pos))  # type: ignore[arg-type]
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
            self._session().resume(command)
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


def known_subs(launch: Launch) -> dict[str, str]:
    """Every sub the run can call, by lower-case name, with its file; a job or macro file that
    does not load is the launch's error."""
    from edingcnc_lang.runner import Run, RunOptions
    from edingcnc_lang.debug.breakpoints import facts

    try:
        run = Run(RunOptions(ini=launch.ini, macro=launch.macro, user_macro=launch.user_macro, plan=False))
        found: dict[str, str] = {}
        for path, program in run.load_macros():
            for name in program.subs:
                found.setdefault(name.lower(), str(path))
        job = facts(str(launch.program))
        if job.error is not None:
            raise job.error
        for name in job.subs:
            found[name] = str(launch.program)
        return found
    except EcncError as err:
        raise RequestError(err.format()) from None


def serve(stdin: BinaryIO, stdout: BinaryIO) -> int:
    """Speak DAP on these streams until the client disconnects or closes them."""
    channel = Channel(stdout)
    adapter = Adapter(channel)
    try:
        while not adapter.done:
            message = read_message(stdin)
            if message is None:
                break
            if message.get("type") == "request":
                adapter.handle(message)
    except ProtocolError as err:
        channel.output(f"ecnc debug: {err}", "stderr")
    session = adapter.session
    if session is not None:
        session.terminate()
        if session.thread.is_alive():
            session.thread.join(timeout=5)
    return 0
