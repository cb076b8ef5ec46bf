"""DAP message framing: ``Content-Length: N\r\n\r\n`` then N bytes of UTF-8 JSON, both ways.

A message that cannot be read (a negative, huge or non-numeric length, a body that is not a
JSON object, JSON nested past the parser's depth) is refused with a ``ProtocolError`` and the
stream stays usable: the reader skips to the next ``Content-Length`` header and goes on.
"""
from __future__ import annotations

import json
import re
import threading
from typing import Any, BinaryIO

Message = dict[str, Any]

# Bytes of one message's body: a real request is a few hundred bytes, a launch with a long list
# of answers a few kilobytes.  A larger length is refused before anything is allocated.
MAX_MESSAGE_BYTES = 16 * 1024 * 1024
# Bytes of one header line ("Content-Length: 123" and the optional Content-Type).
MAX_HEADER_BYTES = 1024
_LENGTH_HEADER = re.compile(rb"content-length\s*:", re.IGNORECASE)
_SCAN_BYTES = 64 * 1024  # what the resynchronising reader reads at a time


class ProtocolError(Exception):
    """The peer sent something that is not a DAP message (a bad header, a body that is no JSON object)."""


class Reader:
    """Messages from a byte stream, one at a time; after a framing error it finds the next header."""

    def __init__(self, stream: BinaryIO) -> None:
        self._stream = stream
        self._pending: bytes | None = None  # a header line found while skipping a refused body
        self._skip = False  # the last message was refused before its body: skip that first

    def read(self) -> Message | None:
        """The next message, or None at the end of the stream; raises ProtocolError for one that
        cannot be read (the next call first skips to the next message's header)."""
        if self._skip:
            self._skip = False
            self._resync()
        length, problem = self._headers()
        if length is None and problem is None:
            return None
        if problem is not None:
            self._skip = True
            raise ProtocolError(problem)
        assert length is not None
        body = self._stream.read(length)
        if len(body) < length:
            return None
        return _decoded(body)

    def _line(self) -> bytes:
        if self._pending is not None:
            line, self._pending = self._pending, None
            return line
        return self._stream.readline(MAX_HEADER_BYTES + 1)

    def _headers(self) -> tuple[int | None, str | None]:
        """The Content-Length of the next message, or why there is none usable; (None, None) at the end."""
        length: int | None = None
        problem: str | None = None
        seen = False  # a header line was read (a blank line before any is a stray one)
        while True:
            line = self._line()
            if not line:
                return None, None
            if not line.endswith(b"\n"):
                if len(line) <= MAX_HEADER_BYTES:
                    return None, None  # the stream ended inside a header
                self._skip_line()
                seen, problem = True, problem or f"a header line longer than {MAX_HEADER_BYTES} bytes"
                continue
            text = line.strip()
            if not text:
                if not seen:
                    continue
                if length is None and problem is None:
                    problem = "a message without a Content-Length header"
                return length, problem
            seen = True
            name, _, value = text.partition(b":")
            if name.strip().lower() == b"content-length":
                length, refused = _length(value.strip())
                problem = problem or refused

    def _skip_line(self) -> None:
        while True:
            chunk = self._stream.readline(_SCAN_BYTES)
            if not chunk or chunk.endswith(b"\n"):
                return

    def _resync(self) -> None:
        """Skip a refused message's body (of unknown length): read up to the next Content-Length header."""
        tail = b""
        while True:
            chunk = self._stream.readline(_SCAN_BYTES)
            if not chunk:
                return
            window = tail + chunk
            found = _LENGTH_HEADER.search(window)
            if found is not None and window.endswith(b"\n"):
                self._pending = window[found.start():]
                return
            tail = b"" if window.endswith(b"\n") else window[-64:]


def _length(value: bytes) -> tuple[int | None, str | None]:
    shown = value[:40].decode("ascii", errors="replace")
    if not value.isdigit() or len(value) > 12:  # digits only: no sign, no spaces, no "1e3"
        if value.startswith(b"-") and value[1:].isdigit():
            return None, f"Content-Length {shown} is negative"
        if value.isdigit():
            return None, f"Content-Length {shown}... is more than the {MAX_MESSAGE_BYTES:,} bytes a message may have"
        return None, f"Content-Length {shown!r} is not a number"
    length = int(value)
    if length > MAX_MESSAGE_BYTES:
        return None, f"Content-Length {length:,} is more than the {MAX_MESSAGE_BYTES:,} bytes a message may have"
    return length, None


def _decoded(body: bytes) -> Message:
    try:
        message = json.loads(body.decode("utf-8"))
    except UnicodeDecodeError as err:
        raise ProtocolError(f"message is not UTF-8: {err}") from None
    except RecursionError:
        raise ProtocolError("message is not JSON: nested too deeply") from None
    except ValueError as err:  # JSONDecodeError, and an integer of more than 4,300 digits
        raise ProtocolError(f"message is not JSON: {err}") from None
    if not isinstance(message, dict):
        raise ProtocolError("message is not a JSON object")
    return message


def read_message(stream: BinaryIO) -> Message | None:
    """The next message of ``stream`` (one read, no resynchronisation after it), None at its end."""
    return Reader(stream).read()


class Channel:
    """The adapter's side of the connection: numbered responses and events, one writer at a time
    (the worker thread sends events while the adapter thread answers requests)."""

    def __init__(self, out: BinaryIO) -> None:
        self._out = out
        self._seq = 0
        self._lock = threading.Lock()

    def send(self, message: Message) -> None:
        with self._lock:
            self._seq += 1
            body = json.dumps({"seq": self._seq, **message}).encode("utf-8")
            self._out.write(b"Content-Length: %d\r\n\r\n" % len(body) + body)
            self._out.flush()

    def event(self, name: str, body: Message | None = None) -> None:
        self.send({"type": "event", "event": name, **({"body": body} if body is not None else {})})

    def respond(self, request: Message, body: Message | None = None) -> None:
        self.send({"type": "response", **_answering(request), "success": True,
                   **({"body": body} if body is not None else {})})

    def fail(self, request: Message, message: str) -> None:
        self.send({"type": "response", **_answering(request), "success": False, "message": message,
                   "body": {"error": {"id": 1, "format": message, "showUser": True}}})

    def output(self, text: str, category: str = "console", path: str | None = None, line: int = 0) -> None:
        body: Message = {"category": category, "output": text if text.endswith("\n") else text + "\n"}
        if path:
            body.update(source={"path": path}, line=line)
        self.event("output", body)


def _answering(request: Message) -> Message:
    """The ``request_seq`` and ``command`` of a response: the request's own when they are a number
    and a string, else 0 and "" (a malformed request is never echoed back as it came)."""
    seq, command = request.get("seq"), request.get("command")
    return {"request_seq": seq if type(seq) is int and 0 <= seq < 2**53 else 0,
            "command": command if isinstance(command, str) and len(command) <= 100 else ""}
