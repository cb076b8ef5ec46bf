"""Control flow and subs: statements in order, If/While, GoSub and the call stack."""
from __future__ import annotations

from collections.abc import Iterable

from edingcnc_lang.syntax import nodes as n
from edingcnc_lang.diagnostics import Diagnostic, SyntaxErrors
from edingcnc_lang.errors import EcncError, Frame
from edingcnc_lang.machine.parts import CallFrame
from edingcnc_lang.machine.state import MAX_CALL_DEPTH, MachineState, ProgramEnd, StatementTable


class ControlFlow(MachineState):
    """Runs statements; every other part of the interpreter is reached from ``execute``."""

    def define_subs(self, subs: Iterable[n.Sub]) -> None:
        """Register subs (the first definition of a name wins, like a lookup in file order)."""
        for sub in subs:
            self.flow.subs.setdefault(sub.name.lower(), sub)

    def run(self, statements: Iterable[n.Stmt]) -> bool:
        """Execute top-level statements; Sub definitions are skipped. False if M2/M30 ended the run."""
        try:
            for stmt in statements:
                kind = type(stmt)
                if kind is n.PlainRun:  # a chunk of lines, each counted as a statement
                    if self.observer is not None and self.observer.line_by_line(self.view, stmt):  # type: ignore[arg-type]
                        self._exec_plain_lines(stmt)  # type: ignore[arg-type]
                    else:
                        self._exec_plain_run(stmt)  # type: ignore[arg-type]
                elif kind is not n.Sub:
                    self.execute(stmt)
        except ProgramEnd:
            return False
        return True

    def call_sub(self, name: str, span: n.Span | None = None) -> None:
        """GoSub: run a sub by (case-insensitive) name."""
        sub = self.flow.subs.get(name.lower())
        if sub is None:
            raise self.fail(f"GoSub {name}: no Sub {name} is defined in the job or the macro files", span)
        if len(self.flow.stack) >= MAX_CALL_DEPTH:
            raise self.fail(f"GoSub {name}: calls nested deeper than {MAX_CALL_DEPTH} (endless recursion?)", span)
        frame = CallFrame(sub.name.lower(), self.path, self.line)
        self.flow.stack.append(frame)
        observer = self.observer
        try:
            if observer is not None:
                observer.call(self.view, frame, sub)
            self.execute_body(sub.body)
        except EcncError as err:
            err.notes = (*err.notes, f"in Sub {sub.name}, called from {frame.path}:{frame.line}")
            err.frames = (*err.frames, Frame(sub.name, frame.path, frame.line))
            raise
        finally:
            if observer is not None:
                observer.ret(self.view, frame)
            self.flow.stack.pop()

    def execute_body(self, body: tuple[n.Stmt, ...]) -> None:
        for stmt in body:
            self.execute(stmt)

    def execute(self, stmt: n.Stmt) -> None:
        span = stmt.span
        self.path, self.line = span.path, span.line
        budget = self.budget
        budget.steps += 1
        if budget.limit is not None and budget.steps > budget.limit:
            self.spend(0, span)  # reports the exhausted budget
        if self.observer is not None:
            self.observer.statement(self.view, stmt)
        self._EXECUTE[type(stmt)](self, stmt)

    def _condition(self, stmt: n.If | n.While) -> bool:
        taken = self.evaluator.value(stmt.cond) != 0.0
        if self.observer is not None:
            self.observer.branch(self.view, stmt, taken)
        return taken

    def _exec_if(self, stmt: n.If) -> None:
        self.execute_body(stmt.then if self._condition(stmt) else stmt.orelse)

    def _exec_while(self, stmt: n.While) -> None:
        while self._condition(stmt):
            self.execute_body(stmt.body)
            self.path, self.line = stmt.span.path, stmt.span.line
            self.spend(1, stmt.span)

    def _exec_gosub(self, stmt: n.GoSub) -> None:
        self.call_sub(stmt.name, stmt.span)

    def _exec_bad_line(self, stmt: n.BadLine) -> None:
        """A macro-file line that does not parse, reached: the syntax error it was warned about (exit 65)."""
        span = stmt.span
        raise SyntaxErrors([Diagnostic.make(stmt.code, stmt.message, span.path, span.line, stmt.col, stmt.source)])

    def _exec_sub(self, stmt: n.Sub) -> None:
        raise self.fail(f"Sub {stmt.name} is defined inside a block; subs must be at the top level", stmt.span)


# The statements this part executes (interpreter.py builds the dispatch table from every part's).
STATEMENTS: StatementTable = {n.If: ControlFlow._exec_if, n.While: ControlFlow._exec_while,
                              n.GoSub: ControlFlow._exec_gosub, n.Sub: ControlFlow._exec_sub,
                              n.BadLine: ControlFlow._exec_bad_line}
