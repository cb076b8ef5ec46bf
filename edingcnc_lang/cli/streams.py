"""Standard streams a command can always write to, and failures on them reported, not raised.

A program started with stdout or stderr closed (``ecnc run --json >&-``, ``2>&-``) finds
``sys.stdout``/``sys.stderr`` set to None, where ``print`` would send text meant for stderr to
stdout.  A closed stdout becomes a stream whose writes fail like a closed descriptor, so the
command reports ``cannot write standard output``; a closed stderr becomes the null device (there
is no one left to tell).
"""
from __future__ import annotations

import contextlib
import errno
import io
import os
import stat
import sys
from collections.abc import Iterator
from pathlib import Path
from typing import BinaryIO, TextIO


STDIN = "-"  # as a job or lint path: read standard input
STDIN_NAME = "<stdin>"  # how messages name a file read from standard input


class ClosedStream(io.TextIOBase):
    """Stands for a closed standard stream: every write fails with EBADF."""

    def writable(self) -> bool:
        return True

    def write(self, text: str) -> int:
        raise OSError(errno.EBADF, os.strerror(errno.EBADF))

    def fileno(self) -> int:  # what the language server asks for first
        raise OSError(errno.EBADF, os.strerror(errno.EBADF))


class QuietStream(io.TextIOBase):
    """Stands for stderr: once a write fails (``2> /dev/full``) the rest goes to the null device.

    There is no one left to tell, so the command carries on and keeps its exit code, as with a
    closed stderr, instead of failing on its first message.
    """

    def __init__(self, stream: TextIO) -> None:
        self._stream = stream

    @property
    def encoding(self) -> str:  # type: ignore[override]
        return self._stream.encoding

    def writable(self) -> bool:
        return True

    def isatty(self) -> bool:
        return self._stream.isatty()

    def fileno(self) -> int:
        return self._stream.fileno()

    def write(self, text: str) -> int:
        try:
            return self._stream.write(text)
        except (OSError, ValueError):
            self._give_up()
            return len(text)

    def flush(self) -> None:
        try:
            self._stream.flush()
        except (OSError, ValueError):
            self._give_up()

    def _give_up(self) -> None:
        self._stream = open(os.devnull, "w")  # noqa: SIM115 - lives as long as the process


def make_streams_usable() -> None:
    """Replace a closed stdin, stdout or stderr (see the module's docstring); let text stdout can't encode be escaped.

    A closed stdin reads as empty (``ecnc mdi <&-`` ends at once, ``ecnc run - <&-`` runs nothing).
    """
    if sys.stdin is None:
        sys.stdin = open(os.devnull)  # noqa: SIM115 - lives as long as the process
    if sys.stderr is None:
        sys.stderr = open(os.devnull, "w")  # noqa: SIM115 - lives as long as the process
    elif sys.stderr is sys.__stderr__:  # not an embedding program's or a test's own stream
        sys.stderr = QuietStream(sys.stderr)  # type: ignore[arg-type]  # a text stream, not None here
    if sys.stdout is None:
        sys.stdout = ClosedStream()
    reconfigure = getattr(sys.stdout, "reconfigure", None)
    if reconfigure is not None:  # a source line with 'é' on an ASCII console: \xe9, not a traceback
        reconfigure(errors="backslashreplace")


@contextlib.contextmanager
def stdin_as_file() -> Iterator[Path]:
    """Standard input copied, byte for byte, to a file in a private temporary folder removed afterwards.

    The commands then read it as they read a file: decoded the same way (UTF-8, else Latin-1, UTF-16
    after its BOM) and streamed, so memory stays flat however long the input is (the whole text in
    memory took 2 GB for a million-line job).  No macro.cnc or cnc.ini lies beside it.
    """
    buffer = getattr(sys.stdin, "buffer", None)
    if buffer is None:  # already text (an embedding program's StringIO)
        buffer = io.BytesIO(sys.stdin.read().encode("utf-8"))
    with _copied(buffer) as path:
        yield path


@contextlib.contextmanager
def job_to_read_twice(job: str) -> Iterator[tuple[Path, str | None]]:
    """A job (``-`` for stdin) as a regular file that ``run`` and ``parse --json`` may read twice
    (checked whole, then streamed again), and what messages call it (None: its path).

    Standard input and a FIFO (``ecnc run <(generate-job)``) can be read only once: they are copied
    to a temporary file first (a FIFO read twice ran nothing, silently).
    """
    if job == STDIN:
        with stdin_as_file() as path:
            yield path, STDIN_NAME
        return
    if stat.S_ISREG(os.stat(job).st_mode):
        yield Path(job), None
        return
    with open(job, "rb") as source, _copied(source) as path:
        yield path, str(Path(job))


@contextlib.contextmanager
def _copied(source: BinaryIO) -> Iterator[Path]:
    """``source`` copied in blocks to a file in a private temporary folder, removed afterwards."""
    import shutil
    import tempfile

    with tempfile.TemporaryDirectory(prefix="ecnc-stdin-") as folder:
        path = Path(folder) / "stdin.nc"
        try:
            with open(path, "wb") as spool:
                shutil.copyfileobj(source, spool, 1 << 20)
        except OSError as exc:  # a full temporary folder: name the copy, not standard output
            raise OSError(exc.errno, exc.strerror, str(path)) from exc
        yield path


def flush_quietly() -> None:
    """Flush stdout and stderr at the very end, when a failure can no longer be reported."""
    for stream in (sys.stdout, sys.stderr):
        try:
            stream.flush()
        except (OSError, ValueError, AttributeError):  # a reader that went away, a full disk
            pass


def quiet_stdout() -> None:
    """After a closed pipe: point stdout at the null device so nothing left in its buffer fails again."""
    try:
        os.dup2(os.open(os.devnull, os.O_WRONLY), sys.stdout.fileno())
    except (OSError, ValueError, io.UnsupportedOperation):  # no descriptor (a test's StringIO)
        pass
