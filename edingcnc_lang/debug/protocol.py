"""DAP message framing: ``Content-Length: N\r\n\r\n`` then N bytes of UTF-8 JSON, both ways."""
from __future__ import annotations

import json
import threading
from typing import Any, BinaryIO

Message = dict[str, Any]


class ProtocolError(Exception):
    """The peer sent something that is not a DAP message (a bad header, broken JSON)."""


def read_message(stream: BinaryIO) -> Message | None:
    """The next message, or None at the end of the stream."""
    length: int | None = None
    while True:
        header = stream.readline()
        if not header:
            return None
        text = header.decode("ascii", errors="replace").strip()
        if not text:
            if length is None:
                continue  # stray blank line between messages
            break
        name, _, value = text.partition(":")
        if name.strip().lower() == "content-length":
            try:
                length = int(value.strip())
            except ValueError:
                raise ProtocolError(f"bad Content-Length header: {text!r}") from None
    body = stream.read(length)
    if len(body) < length:
        return None
    try:
        message = json.loads(body.decode("utf-8"))
    except (UnicodeDecodeError, json.JSONDecodeError) as err:
        raise ProtocolError(f"message is not JSON: {err}") from None
    if not isinstance(message, dict):
        raise ProtocolError("message is not a JSON object")
    return message


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
        self.send({"type": "response", "request_seq": request.get("seq", 0), "success": True,
                   "command": request.get("command", ""), **({"body": body} if body is not None else {})})

    def fail(self, request: Message, message: str) -> None:
        self.send({"type": "response", "request_seq": request.get("seq", 0), "success": False,
                   "command": request.get("command", ""), "message": message,
                   "body": {"error": {"id": 1, "format": message, "showUser": True}}})

    def output(self, text: str, category: str = "console", path: str | None = None, line: int = 0) -> None:
        body: Message = {"category": category, "output": text if text.endswith("\n") else text + "\n"}
        if path:
            body.update(source={"path": path}, line=line)
        self.event("output", body)
