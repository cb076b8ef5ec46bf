"""Messages, dialogs and the log file (msg, warnmsg, errmsg, dlgmsg, logmsg, logfile)."""
from __future__ import annotations

import math
from datetime import datetime
from pathlib import Path
from typing import TextIO

from edingcnc_lang.syntax import nodes as n
from edingcnc_lang.machine import tables as t
from edingcnc_lang.events import DialogEvent, ErrorEvent, LogEvent, MessageEvent, MsgEvent, WarnEvent
from edingcnc_lang.errors import JobAborted, Location
from edingcnc_lang.machine.evaluator import param_index
from edingcnc_lang.syntax.input_limits import MAX_LOG_BYTES
from edingcnc_lang.host import DialogAnswer, DialogField, checked_answer
from edingcnc_lang.syntax.dialogs import dialog_fields
from edingcnc_lang.machine.state import MachineState, MessageKind, format_value, StatementTable

STAMP_FORMAT = "%Y-%m-%d %H:%M:%S"


class Messages(MachineState):
    """What the job tells the operator or asks of them; each message is also an event on the canon."""

    def _text(self, items: tuple[n.MessageItem, ...]) -> str:
        return "".join(item if isinstance(item, str) else self._stamp() if isinstance(item, n.Stamp)
                       else format_value(self.evaluator.value(item)) for item in items)

    def _stamp(self) -> str:
        """``%d``: the date and time now, as ``YYYY-MM-DD HH:MM:SS`` (sortable, the same everywhere)."""
        return (self.host.clock or datetime.now)().strftime(STAMP_FORMAT)

    def message(self, kind: MessageKind, text: str) -> None:
        """A ``msg``, ``warn`` or ``error`` message (``MESSAGES``) at the current line."""
        self.tell(MESSAGES[kind](self.path, self.line, text))

    def tell(self, event: MessageEvent) -> None:
        """Every message goes here: to the run's messages, the canon and the host."""
        self.messages.events.append(event)
        self.canon.event(event)
        if self.host.message:
            self.host.message(event.kind, event.text, self.path, self.line)

    def _exec_message(self, stmt: n.Message) -> None:
        text = self._text(stmt.items)
        if stmt.kind == "logmsg":
            self._log(text, stmt.span)
        elif stmt.kind == "errmsg":
            self.message("error", text)
            raise JobAborted(text, Location(self.path, self.line))
        else:
            self.message("warn" if stmt.kind == "warnmsg" else "msg", text)

    def _exec_dialog(self, stmt: n.Dialog) -> None:
        items = stmt.items
        shape, problems = dialog_fields(stmt)
        if problems:  # the first one, as the controller stops at it
            problem = problems[0]
            item = problem.item
            raise self.fail(problem.message, stmt.span if item is None or isinstance(item, str) else item.span)
        title = items[0]
        assert isinstance(title, str)  # dialog_fields reported a dialog without its title string (D402)
        indices = [param_index(f.index.value, f.index.span) for f in shape]
        fields = [DialogField(f.label, index, self.params.read(index)) for f, index in zip(shape, indices)]
        try:
            answer = checked_answer(self.host.dialog(title, fields) if self.host.dialog else None) or DialogAnswer()
        except ValueError as err:
            raise self.fail(str(err), stmt.span) from None
        unknown = set(answer.values) - {f.index for f in fields}
        if unknown:
            raise self.fail(f"the answer sets #{min(unknown)}, which is not a field of this dialog", stmt.span)
        endless = sorted(i for i, v in answer.values.items() if not math.isfinite(v))
        if endless:  # a host's answer; the CLI refuses these already
            raise self.fail(f"the answer sets #{endless[0]} to {answer.values[endless[0]]}, not a finite number",
                            stmt.span)
        if answer.ok:
            for index, value in answer.values.items():
                self.params.write(index, value, self.where(stmt.span))
        self.params.set(t.DIALOG_RESULT, 1.0 if answer.ok else -1.0)
        self.tell(DialogEvent(self.path, self.line, title, answer.ok,
                              {f.label: self.params.read(f.index) for f in fields}))

    def _exec_logfile(self, stmt: n.LogFile) -> None:
        mode = self.evaluator.value(stmt.mode) if stmt.mode is not None else 1.0
        try:  # never outside the log folder, whatever the path says
            self.messages.log_file = self.files.named(stmt.name, self.path)
        except ValueError as exc:
            raise self.fail(f"logfile {exc}", stmt.span) from None
        if mode == 0:
            self._open_log(stmt.span, truncate=True).close()

    def _log(self, text: str, span: n.Span) -> None:
        if self.messages.log_file is None:
            self._exec_logfile(n.LogFile("log.txt", None, span))
        assert self.messages.log_file is not None
        line = text + "\n"
        self.messages.logged += len(line.encode("utf-8", errors="replace"))
        if self.messages.logged > MAX_LOG_BYTES:
            raise self.fail(f"logmsg: this run has written {MAX_LOG_BYTES // 2**20} MB to its log files, the most "
                            "a run may write (a logmsg in a loop that does not end?)", span)
        with self._open_log(span) as handle:
            handle.write(line)
        self.tell(LogEvent(self.path, self.line, text, str(self.messages.log_file)))

    def move_files(self, scratch: Path, folder: Path) -> None:
        """The run's files go to ``folder`` from here on; a log file opened under ``scratch`` moves with them."""
        self.files.log_dir = folder
        self.messages.move_files(scratch, folder)

    def _open_log(self, span: n.Span, truncate: bool = False) -> TextIO:
        """The log file, opened to append; an error at the job's line if it cannot be, or is not a file of its own."""
        assert self.messages.log_file is not None
        try:
            return self.files.open(self.messages.log_file, "write" if truncate else "append")
        except OSError as exc:
            raise self.fail(f"cannot write the log file {self.messages.log_file}: {exc.strerror or exc}", span) from None


# The messages ``message`` makes, by kind
MESSAGES: dict[MessageKind, type[MessageEvent]] = {"msg": MsgEvent, "warn": WarnEvent, "error": ErrorEvent}

# The statements this part executes, by method name (interpreter.py builds the dispatch table).
STATEMENTS: StatementTable = {n.Message: Messages._exec_message, n.Dialog: Messages._exec_dialog,
                              n.LogFile: Messages._exec_logfile}
