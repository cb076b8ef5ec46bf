"""A progress line on stderr for long runs and lints: only on a terminal, only after a second.

A background thread looks at the work every fifth of a second (the run itself is not slowed by
callbacks) and rewrites one line: how far through the job, moves so far, elapsed and remaining
time.  It is cleared when the work ends, so nothing of it stays in the terminal's scrollback.
"""
from __future__ import annotations

import sys
import threading
import time
from collections.abc import Callable
from types import TracebackType

from edingcnc_lang.cli.style import wants_colour

DELAY = 1.0     # seconds of work before the line appears
INTERVAL = 0.2  # seconds between updates
WIDTH = 24      # characters of the bar

# (done, total, detail): done/total give the bar and the time left (total 0: no bar), detail the rest.
Probe = Callable[[], tuple[int, int, str]]


def wanted(quiet: bool) -> bool:
    """Progress is shown on a terminal's stderr only, and not with --quiet or --json (clean output)."""
    isatty = getattr(sys.stderr, "isatty", None)
    return not quiet and bool(isatty and isatty())


def _clock(seconds: float) -> str:
    minutes, secs = divmod(int(seconds), 60)
    hours, minutes = divmod(minutes, 60)
    return f"{hours}:{minutes:02d}:{secs:02d}" if hours else f"{minutes}:{secs:02d}"


def render(done: int, total: int, detail: str, elapsed: float) -> str:
    """One progress line: ``[=====>    ]  45%  line 4,500/10,000  moves 4,410  0:05 elapsed  0:06 left``."""
    parts = []
    if total > 0:
        fraction = min(done / total, 1.0)
        filled = int(fraction * WIDTH)
        bar = "=" * filled + (">" if filled < WIDTH else "") + " " * (WIDTH - filled - 1)
        parts.append(f"[{bar[:WIDTH]}] {fraction * 100:3.0f}%")
    parts.append(detail)
    parts.append(f"{_clock(elapsed)} elapsed")
    if total > 0 and done > 0:
        parts.append(f"{_clock(elapsed * (total - done) / done)} left")
    return "  ".join(parts)


class Progress:
    """``with Progress(probe, enabled):`` shows the line while the block runs (if enabled)."""

    def __init__(self, probe: Probe, enabled: bool) -> None:
        self._probe = probe
        self._enabled = enabled
        self._stop = threading.Event()
        self._thread: threading.Thread | None = None
        self._shown = False
        self._start = 0.0

    def __enter__(self) -> Progress:
        if self._enabled:
            self._start = time.monotonic()
            self._thread = threading.Thread(target=self._loop, name="ecnc-progress", daemon=True)
            self._thread.start()
        return self

    def __exit__(self, kind: type[BaseException] | None, error: BaseException | None,
                 trace: TracebackType | None) -> None:
        if self._thread is not None:
            self._stop.set()
            self._thread.join()
            if self._shown:
                self._write("\r\x1b[K")

    def _loop(self) -> None:
        if self._stop.wait(DELAY):
            return
        while not self._stop.is_set():
            try:
                done, total, detail = self._probe()
            except Exception:  # noqa: BLE001 - a probe racing the work must never break it
                done, total, detail = 0, 0, ""
            line = render(done, total, detail, time.monotonic() - self._start)
            colour = wants_colour(sys.stderr)
            self._write("\r\x1b[K" + (f"\x1b[2m{line}\x1b[0m" if colour else line))
            self._shown = True
            self._stop.wait(INTERVAL)

    @staticmethod
    def _write(text: str) -> None:
        try:
            sys.stderr.write(text)
            sys.stderr.flush()
        except (OSError, ValueError):
            pass
