"""The files a job itself names (``logfile``, ``ZHCS``, ``ZHCL``): only in the log folder, opened safely.

A job archive may ship a symbolic link, a hard link or a FIFO under an innocent name; one opener
refuses them all for every command, reading or writing, so the rules of docs/security.md hold
everywhere a job touches a file.
"""
from __future__ import annotations

import io
import os
import stat
from pathlib import Path, PureWindowsPath
from collections.abc import Collection
from typing import Literal, TextIO

from edingcnc_lang.errors import printable

OpenMode = Literal["append", "write", "read"]

_COMMON = getattr(os, "O_NOFOLLOW", 0) | getattr(os, "O_NONBLOCK", 0) | getattr(os, "O_CLOEXEC", 0)
# Flags by mode: never through a symbolic link, never blocking on a FIFO.
_FLAGS: dict[str, int] = {"append": os.O_WRONLY | os.O_CREAT | os.O_APPEND | _COMMON,
                          "write": os.O_WRONLY | os.O_CREAT | _COMMON,
                          "read": os.O_RDONLY | _COMMON}
_ELSEWHERE = "a job reads and writes only files in its log folder"


def job_file(folder: Path, raw: str) -> Path:
    """The file ``raw`` names inside ``folder``: a path keeps only its last part (``..\\x.txt`` is
    ``x.txt``).  Raises ValueError for a name that names no file or holds control characters."""
    name = PureWindowsPath(raw).name
    if name in ("", ".", ".."):
        raise ValueError(f"{raw!r} names no file")
    if printable(name) != name:  # NUL, escapes, and the bidi overrides that show "txt.exe" as "exe.txt"
        raise ValueError(f"{raw!r}: a file name cannot hold control characters or direction overrides")
    return folder / name


class KeptFile(io.StringIO):
    """A job file written by a run that only looks (``ecnc plot``, ``view``, ``sim``, ``diff``): kept in
    memory under its name when closed, so the job reads back what it wrote and no file changes."""

    def __init__(self, kept: dict[Path, str], path: Path, text: str) -> None:
        super().__init__(text)
        self.seek(0, io.SEEK_END)
        self._kept, self._path = kept, path

    def close(self) -> None:
        if not self.closed:
            self._kept[self._path] = self.getvalue()
        super().close()


def open_job_file(path: Path, mode: OpenMode, own: Collection[tuple[int, int]] = (),
                  kept: dict[Path, str] | None = None) -> TextIO:
    """Open ``path`` (``write`` truncates), refusing what would reach another file: a symbolic link,
    a hard link, a device or a FIFO, and for writing one of ``own``, the files the run itself reads
    or writes (job, macro files, ini, outputs) as (device, inode).  Raises OSError with a reason
    fit for the user.  ``kept``: the run only looks; what it writes goes there, not to disk, and a
    file it wrote is read back from there."""
    if kept is not None:
        if mode == "read":
            return io.StringIO(kept[path]) if path in kept else open_job_file(path, mode, own)
        if mode == "write":
            return KeptFile(kept, path, "")
        if path not in kept and path.exists():
            with open_job_file(path, "read", own) as existing:
                return KeptFile(kept, path, existing.read())
        return KeptFile(kept, path, kept.get(path, ""))
    if not hasattr(os, "O_NOFOLLOW") and path.is_symlink():  # Windows: no O_NOFOLLOW
        raise OSError(0, f"it is a symbolic link; {_ELSEWHERE}")
    try:
        fd = os.open(path, _FLAGS[mode], 0o666)
    except OSError as exc:
        if path.is_symlink():
            raise OSError(exc.errno, f"it is a symbolic link; {_ELSEWHERE}") from None
        raise
    info = os.fstat(fd)
    if not stat.S_ISREG(info.st_mode) or info.st_nlink > 1:
        os.close(fd)
        raise OSError(0, f"it is not a plain file of its own (a hard link, a device or a pipe); {_ELSEWHERE}")
    if mode != "read" and (info.st_dev, info.st_ino) in own:
        os.close(fd)
        raise OSError(0, "it is a file this run reads or writes (the job, a macro file, the ini or an output); "
                      "a job may not overwrite it")
    if mode == "write":
        os.ftruncate(fd, 0)
    if mode == "read":
        return os.fdopen(fd, "r", encoding="utf-8", errors="replace")
    return os.fdopen(fd, "a" if mode == "append" else "w", encoding="utf-8", newline="\n" if mode == "write" else None)
