"""A small DAP client for the tests: starts ``python -m edingcnc_lang debug`` and speaks
Content-Length framed JSON with it over its standard input and output."""
from __future__ import annotations

import json
import queue
import subprocess
import sys
import threading
from typing import Any

TIMEOUT = 60  # seconds a response or event may take before the test fails (a hang, not a timing test)


class DapClient:
    def __init__(self, *command: str) -> None:
        argv = list(command) or [sys.executable, "-m", "edingcnc_lang", "debug"]
        self.proc = subprocess.Popen(argv, stdin=subprocess.PIPE, stdout=subprocess.PIPE, stderr=subprocess.PIPE)
        self.seq = 0
        self.responses: dict[int, dict[str, Any]] = {}
        self.events: queue.Queue[dict[str, Any]] = queue.Queue()
        self.seen: list[dict[str, Any]] = []  # every event, in order
        self.cv = threading.Condition()
        threading.Thread(target=self._read, daemon=True).start()

    def _read(self) -> None:
        out = self.proc.stdout
        assert out is not None
        while True:
            length = None
            while True:
                try:
                    line = out.readline()
                except (ValueError, OSError):  # the test closed the pipe: the session is over
                    line = b""
                if not line:
                    self.events.put({"event": "<eof>"})
                    return
                if not line.strip():
                    break
                name, _, value = line.decode().partition(":")
                if name.lower() == "content-length":
                    length = int(value)
            assert length is not None
            message = json.loads(out.read(length))
            if message["type"] == "response":
                with self.cv:
                    self.responses[message["request_seq"]] = message
                    self.cv.notify_all()
            else:
                self.seen.append(message)
                self.events.put(message)

    def send(self, command: str, **arguments: Any) -> int:
        self.seq += 1
        body = json.dumps({"seq": self.seq, "type": "request", "command": command, "arguments": arguments}).encode()
        assert self.proc.stdin is not None
        self.proc.stdin.write(b"Content-Length: %d\r\n\r\n" % len(body) + body)
        self.proc.stdin.flush()
        return self.seq

    def request(self, command: str, **arguments: Any) -> dict[str, Any]:
        """Send a request and wait for its response (asserting it succeeded); the response's body."""
        response = self.raw(command, **arguments)
        assert response["success"], response.get("message")
        return response.get("body") or {}

    def raw(self, command: str, **arguments: Any) -> dict[str, Any]:
        seq = self.send(command, **arguments)
        with self.cv:
            assert self.cv.wait_for(lambda: seq in self.responses, TIMEOUT), f"no response to {command}"
            return self.responses.pop(seq)

    def wait(self, name: str) -> dict[str, Any]:
        """The next event called ``name`` (other events are skipped)."""
        while True:
            event = self.events.get(timeout=TIMEOUT)
            if event["event"] == name:
                return event.get("body") or {}
            assert event["event"] != "<eof>", f"the adapter ended before {name}"

    def outputs(self) -> str:
        return "".join(e["body"]["output"] for e in self.seen if e.get("event") == "output")

    # conveniences
    def start(self, breakpoints: dict[str, list[dict[str, Any]]] | None = None,
              functions: list[str] | None = None, **launch: Any) -> dict[str, Any]:
        """initialize, launch, breakpoints, configurationDone; the capabilities."""
        caps = self.request("initialize", adapterID="ecnc", linesStartAt1=True, columnsStartAt1=True)
        self.request("launch", **launch)
        self.wait("initialized")
        placed = {}
        for path, specs in (breakpoints or {}).items():
            placed[path] = self.request("setBreakpoints", source={"path": path}, breakpoints=specs)["breakpoints"]
        self.placed = placed
        if functions is not None:
            self.functions = self.request("setFunctionBreakpoints",
                                          breakpoints=[{"name": f} for f in functions])["breakpoints"]
        self.request("setExceptionBreakpoints", filters=["runError"])
        self.request("configurationDone")
        return caps

    def top(self) -> dict[str, Any]:
        return self.request("stackTrace", threadId=1)["stackFrames"][0]

    def stack(self) -> list[tuple[str, int]]:
        return [(f["name"], f["line"]) for f in self.request("stackTrace", threadId=1)["stackFrames"]]

    def value(self, expression: str) -> str:
        return self.request("evaluate", expression=expression, context="watch", frameId=1)["result"]

    def scope(self, name: str) -> dict[str, dict[str, Any]]:
        scopes = self.request("scopes", frameId=1)["scopes"]
        ref = next(s["variablesReference"] for s in scopes if s["name"].startswith(name))
        # keyed by the expression (#4006), which stays when the view shows a name (#4006 change_y)
        return {v.get("evaluateName") or v["name"]: v for v in self.request("variables", variablesReference=ref)["variables"]}

    def step(self, command: str) -> dict[str, Any]:
        self.request(command, threadId=1)
        return self.wait("stopped")

    def close(self) -> int:
        try:
            if self.proc.poll() is None:
                self.raw("disconnect", terminateDebuggee=True)
        finally:
            assert self.proc.stdin is not None
            self.proc.stdin.close()
            code = self.proc.wait(timeout=TIMEOUT)
            for stream in (self.proc.stdout, self.proc.stderr):
                if stream is not None:
                    stream.close()
        return code
