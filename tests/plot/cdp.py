"""A tiny Chrome DevTools Protocol client over ``--remote-debugging-pipe`` (no websocket library):
enough to open a page from a file, evaluate JavaScript in it, send real mouse and key events and
collect what the page logged.  The browser tests use it to drive the viewer the way a person does.

The pipe is the browser's fd 3 (commands in) and fd 4 (replies and events out), each message a JSON
object ended by a NUL byte.
"""
from __future__ import annotations

import fcntl
import json
import os
import select
import subprocess
from pathlib import Path
from typing import Any


WAIT = 60.0  # seconds; bounds how long a broken browser can hang the suite (no timing is asserted)


class Browser:
    """Headless Chromium with one page open on ``url``; a context manager that closes it."""

    def __init__(self, executable: str, url: str, profile: Path, size: tuple[int, int] = (1280, 800)) -> None:
        to_browser_r, self._to_browser = os.pipe()
        self._from_browser, from_browser_w = os.pipe()
        command = [executable, "--headless", "--no-sandbox", "--disable-gpu", "--remote-debugging-pipe",
                   "--disable-background-networking", "--disable-component-update", "--no-first-run",
                   f"--user-data-dir={profile}", f"--window-size={size[0]},{size[1]}", "about:blank"]

        def child_fds() -> None:  # the browser reads commands on fd 3 and writes on fd 4 (kept: pass_fds)
            high = [fcntl.fcntl(fd, fcntl.F_DUPFD, 10) for fd in (to_browser_r, from_browser_w)]
            os.dup2(high[0], 3)
            os.dup2(high[1], 4)

        self._process = subprocess.Popen(command, stdin=subprocess.DEVNULL, stdout=subprocess.DEVNULL,
                                         stderr=subprocess.DEVNULL, pass_fds=(3, 4, to_browser_r, from_browser_w),
                                         preexec_fn=child_fds)
        os.close(to_browser_r)
        os.close(from_browser_w)
        self._buffer = b""
        self._next_id = 0
        self.events: list[dict[str, Any]] = []
        try:
            target = self.call("Target.createTarget", url="about:blank")["targetId"]
            self._session = self.call("Target.attachToTarget", targetId=target, flatten=True)["sessionId"]
            self.send("Runtime.enable")
            self.send("Page.enable")
            self.send("Page.navigate", url=url)
            self.wait_for("Page.loadEventFired")
        except BaseException:
            self.close()  # no browser left running behind a failed start
            raise

    def __enter__(self) -> Browser:
        return self

    def __exit__(self, *exc: object) -> None:
        self.close()

    def close(self) -> None:
        if self._process.poll() is None:
            try:
                self.call("Browser.close")
            except (OSError, RuntimeError):
                pass
        for fd in (self._to_browser, self._from_browser):
            try:
                os.close(fd)
            except OSError:
                pass
        try:
            self._process.wait(timeout=30)
        except subprocess.TimeoutExpired:
            self._process.kill()
            self._process.wait()

    def _read(self) -> dict[str, Any]:
        while b"\0" not in self._buffer:
            if not select.select([self._from_browser], [], [], WAIT)[0]:
                raise RuntimeError(f"the browser said nothing for {WAIT:.0f} s")
            chunk = os.read(self._from_browser, 65536)
            if not chunk:
                raise RuntimeError("the browser closed its pipe")
            self._buffer += chunk
        message, self._buffer = self._buffer.split(b"\0", 1)
        return json.loads(message)

    def call(self, method: str, session: bool = False, **params: Any) -> dict[str, Any]:
        """Send a command (to the page when ``session``) and return its result; events seen meanwhile
        are kept in ``events``."""
        self._next_id += 1
        message: dict[str, Any] = {"id": self._next_id, "method": method, "params": params}
        if session:
            message["sessionId"] = self._session
        os.write(self._to_browser, json.dumps(message).encode() + b"\0")
        while True:
            reply = self._read()
            if reply.get("id") == self._next_id:
                if "error" in reply:
                    raise RuntimeError(f"{method}: {reply['error']}")
                return reply.get("result", {})
            self.events.append(reply)

    def send(self, method: str, **params: Any) -> dict[str, Any]:
        """A command to the page."""
        return self.call(method, session=True, **params)

    def wait_for(self, method: str) -> dict[str, Any]:
        for event in self.events:
            if event.get("method") == method:
                return event
        while True:
            event = self._read()
            self.events.append(event)
            if event.get("method") == method:
                return event

    def evaluate(self, expression: str) -> Any:
        """The value of a JavaScript expression in the page (promises awaited)."""
        result = self.send("Runtime.evaluate", expression=expression, returnByValue=True, awaitPromise=True)
        if "exceptionDetails" in result:
            raise RuntimeError(f"{expression}: {result['exceptionDetails']}")
        return result["result"].get("value")

    def logged(self) -> list[str]:
        """What the page logged on its console and the exceptions it threw, so far."""
        self.evaluate("0")  # flush the events that arrived before now
        lines = []
        for event in self.events:
            if event.get("method") == "Runtime.consoleAPICalled":
                params = event["params"]
                lines.append(params["type"] + ": " + " ".join(str(a.get("value", a.get("description")))
                                                              for a in params["args"]))
            elif event.get("method") == "Runtime.exceptionThrown":
                details = event["params"]["exceptionDetails"]
                lines.append("exception: " + details.get("exception", {}).get("description", details["text"]))
        return lines

    def mouse(self, kind: str, x: float, y: float, **extra: Any) -> None:
        """A real mouse event: ``mousePressed``, ``mouseMoved``, ``mouseReleased`` or ``mouseWheel``."""
        self.send("Input.dispatchMouseEvent", type=kind, x=x, y=y, **extra)

    def key(self, key: str, code: str, key_code: int) -> None:
        for kind in ("keyDown", "keyUp"):
            self.send("Input.dispatchKeyEvent", type=kind, key=key, code=code, windowsVirtualKeyCode=key_code)
