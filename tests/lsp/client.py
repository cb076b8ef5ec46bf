"""A small LSP client speaking JSON-RPC over the server's stdin/stdout, as an editor does.

Requests wait for their answer; notifications the server sends (diagnostics) are kept in
order and can be waited for.  No timing assertions: waits only bound how long a broken
server can hang the suite.
"""
from __future__ import annotations

import json
import queue
import subprocess
import sys
import threading
from pathlib import Path
from typing import Any

WAIT = 30.0  # seconds; a healthy server answers in milliseconds


class LspClient:
    def __init__(self, command: list[str] | None = None) -> None:
        self.proc = subprocess.Popen(command or [sys.executable, "-m", "edingcnc_lang.lsp"],
                                     stdin=subprocess.PIPE, stdout=subprocess.PIPE, stderr=subprocess.PIPE)
        self._next = 0
        self._inbox: queue.Queue[dict[str, Any]] = queue.Queue()
        self.notifications: list[dict[str, Any]] = []
        threading.Thread(target=self._read, daemon=True).start()

    # ----------------------------------------------------------------- framing
    def _send(self, message: dict[str, Any]) -> None:
        body = json.dumps({"jsonrpc": "2.0", **message}).encode("utf-8")
        assert self.proc.stdin is not None
        self.proc.stdin.write(b"Content-Length: %d\r\n\r\n" % len(body) + body)
        self.proc.stdin.flush()

    def _read(self) -> None:
        stream = self.proc.stdout
        assert stream is not None
        while True:
            length = None
            while True:
                header = stream.readline()
                if not header:
                    return
                if header in (b"\r\n", b"\n"):
                    break
                name, _, value = header.decode("ascii").partition(":")
                if name.lower() == "content-length":
                    length = int(value)
            assert length is not None
            self._inbox.put(json.loads(stream.read(length)))

    def _take(self) -> dict[str, Any]:
        return self._inbox.get(timeout=WAIT)

    # ----------------------------------------------------------------- messages
    def request(self, method: str, params: Any = None) -> Any:
        message = self._reply(method, params)
        assert "error" not in message, message["error"]
        return message.get("result")

    def request_error(self, method: str, params: Any = None) -> dict[str, Any]:
        """A request the server must refuse: its error (code and message)."""
        message = self._reply(method, params)
        assert "error" in message, message
        return message["error"]

    def _reply(self, method: str, params: Any) -> dict[str, Any]:
        """Send a request and wait for its response, keeping what else arrives meanwhile."""
        self._next += 1
        ident = self._next
        self._send({"id": ident, "method": method, "params": params})
        while True:
            message = self._take()
            if message.get("id") == ident and "method" not in message:
                return message
            self._keep(message)

    def notify(self, method: str, params: Any = None) -> None:
        self._send({"method": method, "params": params})

    def _keep(self, message: dict[str, Any]) -> None:
        if "method" in message and "id" in message:  # a request from the server: answer it
            self._send({"id": message["id"], "result": None})
        else:
            self.notifications.append(message)

    def diagnostics(self, uri: str) -> list[dict[str, Any]]:
        """Wait for the next diagnostics the server publishes for ``uri``."""
        while True:
            for i, message in enumerate(self.notifications):
                if message.get("method") == "textDocument/publishDiagnostics" and message["params"]["uri"] == uri:
                    del self.notifications[i]
                    return message["params"]["diagnostics"]
            self._keep(self._take())

    # ----------------------------------------------------------------- session
    def initialize(self, root: Path, options: dict[str, Any] | None = None) -> dict[str, Any]:
        result = self.request("initialize", {"processId": None, "rootUri": root.as_uri(), "capabilities": {},
                                             "workspaceFolders": [{"uri": root.as_uri(), "name": root.name}],
                                             "initializationOptions": options})
        self.notify("initialized", {})
        return result

    def open(self, path: Path, text: str | None = None) -> str:
        uri = path.as_uri()
        content = path.read_text(encoding="utf-8") if text is None else text
        self.notify("textDocument/didOpen", {"textDocument": {
            "uri": uri, "languageId": "edingcnc", "version": 1, "text": content}})
        return uri

    def change(self, uri: str, text: str, version: int) -> None:
        self.notify("textDocument/didChange", {"textDocument": {"uri": uri, "version": version},
                                               "contentChanges": [{"text": text}]})

    def close(self) -> int:
        self.request("shutdown")
        self.notify("exit")
        try:
            return self.proc.wait(timeout=WAIT)
        finally:
            for stream in (self.proc.stdin, self.proc.stdout, self.proc.stderr):
                if stream:
                    stream.close()


def at(uri: str, line: int, character: int) -> dict[str, Any]:
    return {"textDocument": {"uri": uri}, "position": {"line": line, "character": character}}
