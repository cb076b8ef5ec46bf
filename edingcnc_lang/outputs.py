"""Every file a command writes: never over one of its inputs, and always whole or untouched.

Two promises, shared by every command that writes (``run``, ``test``, ``sim``, ``plot``, ``view``,
``diff``, ``kins``, ``lint``, the ini's ``--save-vars``):

* ``check_outputs`` refuses, before any work, an output that is an input of the same invocation
  (the job, a macro, the ini, a tools, test or STL file) or another of its outputs.  Files are
  compared by device and inode, so another spelling of the path, a symbolic link or a hard link is
  the same file; exit 2 with a message naming both.
* ``replacing`` (and ``write_text``, ``write_bytes``, ``save_figure`` on top of it) writes a
  temporary file in the target's folder and renames it over the target only once it is complete
  and flushed to disk: Ctrl-C, a crash or a full disk mid-write leaves the previous file as it was.
  A write error names the file, never "standard output".

To ``check_outputs``, ``-`` is standard output (``run --trace -``) and is never checked; the
writers here always write a file.  A target that exists but is not a
regular file (``/dev/null``, a FIFO) is written in place: renaming over it would remove it.
"""
from __future__ import annotations

import contextlib
import errno
import io
import os
import stat
from collections.abc import Iterable, Iterator, Mapping
from pathlib import Path
from typing import IO, Any

from edingcnc_lang.errors import EcncError, UsageFailure

STDOUT = "-"  # as an output path: standard output

PathLike = str | os.PathLike[str]


def identity(path: PathLike) -> tuple[int, int] | None:
    """The file ``path`` names as (device, inode): a hard link or another spelling is the same file;
    None when it does not exist (or cannot be looked at)."""
    try:
        info = os.stat(path)
    except (OSError, ValueError):
        return None
    return (info.st_dev, info.st_ino)


def check_outputs(outputs: Mapping[str, PathLike | None], inputs: Iterable[PathLike | None]) -> None:
    """Refuse, before anything is written, an output that is one of the inputs (writing would destroy
    it before or while it is read) or another output (one would overwrite the other).

    ``outputs`` maps what the user calls each (``--trace``, ``--junit``) to its path; ``-`` and None
    are left out.  Raises UsageFailure (exit 2) naming both files.
    """
    read = {ident: os.fspath(path) for path in inputs
            if path is not None and os.fspath(path) != STDOUT and (ident := identity(path)) is not None}
    written: dict[tuple[int, int], str] = {}
    for name, path in outputs.items():
        if path is None or os.fspath(path) == STDOUT:
            continue
        ident = identity(path)
        if ident is None:  # a new file: it can only clash with another new output of the same name
            ident = (-1, hash(os.path.abspath(path)))
        if ident in read:
            raise UsageFailure(f"{name} {os.fspath(path)}: that file is also an input of this run ({read[ident]}); "
                               "writing it would destroy it, so name another file")
        if ident in written:
            raise UsageFailure(f"{written[ident]} and {name} name the same file {os.fspath(path)}: "
                               "it cannot be written twice")
        written[ident] = name


def output_identities(paths: Iterable[PathLike | None]) -> frozenset[tuple[int, int]]:
    """The files of ``paths`` that exist, as (device, inode): what a job's own files may never be."""
    return frozenset(ident for path in paths if path is not None and os.fspath(path) != STDOUT
                     and (ident := identity(path)) is not None)


def write_error(path: PathLike, err: OSError) -> EcncError:
    """``cannot write FILE: No space left on device``: the file named, whatever wrote it."""
    return EcncError(f"cannot write {os.fspath(path)}: {err.strerror or err}")


def owned_by_us(info: os.stat_result) -> bool:
    """Whether a file we write anew gets the owner and group of the file ``info`` describes (always
    without owners, as on Windows)."""
    return (info.st_uid, info.st_gid) == (os.getuid(), os.getgid()) if hasattr(os, "getuid") else True


def _in_place(target: str) -> bool:
    """Whether ``target`` is written in place, never replaced: it exists and is not a regular file (a
    device, a FIFO: renaming over it would remove it), or a new file would lose its other hard links
    or its owner (as the ini's write-back and the ``.npz`` samples file keep them)."""
    try:
        info = os.stat(target)
    except OSError:
        return False
    return not stat.S_ISREG(info.st_mode) or info.st_nlink > 1 or not owned_by_us(info)


def _temporary_beside(folder: str, name: str) -> tuple[int, str]:
    """A new file ``.NAME.RANDOM.tmp`` in ``folder``, open for writing, only the owner may read it (as
    ``tempfile.mkstemp`` makes one: ``tempfile`` and the ``shutil`` and ``random`` it imports cost a run's
    start-up 5 ms)."""
    flags = os.O_RDWR | os.O_CREAT | os.O_EXCL | getattr(os, "O_NOFOLLOW", 0) | getattr(os, "O_BINARY", 0)
    for _ in range(100):
        path = os.path.join(folder, f".{name}.{os.urandom(6).hex()}.tmp")
        try:
            return os.open(path, flags, 0o600), path
        except FileExistsError:
            continue
    raise FileExistsError(errno.EEXIST, "no unused temporary name", os.path.join(folder, f".{name}.*.tmp"))


@contextlib.contextmanager
def replacing(path: PathLike, binary: bool = False, newline: str | None = None) -> Iterator[IO[Any]]:
    """A stream whose text becomes ``path`` only when the block ends without an exception.

    The temporary file sits beside the target (the same file system, so the rename is atomic) and
    takes the old file's permissions; a symbolic link keeps pointing where it did (its target is
    replaced).  Any exception, Ctrl-C included, removes the temporary file and leaves ``path`` as
    it was; an OSError becomes an EcncError naming ``path``.
    """
    shown = os.fspath(path)
    target = os.path.realpath(shown)
    temporary = None
    if not _in_place(target):
        folder, name = os.path.split(target)
        try:
            fd, temporary = _temporary_beside(folder or ".", name)
        except OSError as err:  # a folder that takes no new file: an existing target is written in place
            if not os.path.exists(target):
                raise write_error(shown, err) from None
    if temporary is None:
        try:
            with _stream(target, binary, newline) as handle:
                yield handle
        except OSError as err:
            raise write_error(shown, err) from None
        return
    try:
        try:
            handle = _stream(fd, binary, newline)
        except BaseException:
            os.close(fd)
            raise
        with handle:
            yield handle
            handle.flush()
            _sync(handle.fileno())
        os.chmod(temporary, _mode_for(target))
        os.replace(temporary, target)
    except OSError as err:
        _remove(temporary)
        raise write_error(shown, err) from None
    except BaseException:
        _remove(temporary)
        raise


class ReplacingText(io.TextIOWrapper):
    """A text stream written into a temporary file beside ``target`` that replaces it when the stream
    is closed (``run``'s trace, events and CSV samples, written as the run goes): Ctrl-C or a job
    error still swaps in the rows so far, whole; a failed write (a full disk) or ``discard()``
    leaves the target as it was.  ``holder`` is a descriptor of the target (the lock of its run),
    closed last."""

    def __init__(self, target: str, temporary: str, fd: int, holder: int | None = None) -> None:
        super().__init__(io.BufferedWriter(io.FileIO(fd, "w"), 1 << 16), encoding="utf-8", newline="")
        self._target, self._temporary, self._holder = target, temporary, holder
        self._failed = False

    def write(self, text: str) -> int:
        try:
            return super().write(text)
        except BaseException:
            self._failed = True  # part of it may be in the buffer: the file is not whole
            raise

    def discard(self) -> None:
        """Close without replacing the target."""
        self._failed = True
        self.close()

    def close(self) -> None:
        if self.closed:
            return
        try:
            if not self._failed:
                try:
                    self.flush()
                    _sync(self.fileno())
                except BaseException:
                    self._failed = True
                    raise
        finally:
            with contextlib.suppress(OSError):
                super().close()
            self._finish()

    def _finish(self) -> None:
        try:
            if self._failed:
                _remove(self._temporary)
                return
            try:
                os.chmod(self._temporary, _mode_for(self._target))
                os.replace(self._temporary, self._target)
            except OSError as err:
                _remove(self._temporary)
                raise write_error(self._target, err) from None
        finally:
            if self._holder is not None:
                os.close(self._holder)


def open_replacing_text(path: PathLike, holder: int | None = None) -> IO[str]:
    """A ``ReplacingText`` for ``path``, or the file itself, cut to nothing, where it must be written
    in place (see ``_in_place``); ``holder`` as for ReplacingText, the stream's own descriptor in place."""
    shown = os.fspath(path)
    target = os.path.realpath(shown)
    if not _in_place(target):
        try:
            fd, temporary = _temporary_beside(os.path.dirname(target), os.path.basename(target))
        except OSError:  # a folder that takes no new file (the output itself may be writable): in place
            pass
        else:
            return ReplacingText(target, temporary, fd, holder)
    try:
        if holder is None:
            return open(target, "w", encoding="utf-8", newline="", buffering=1 << 16)
        if os.fstat(holder).st_size:  # a FIFO or device has none to cut
            os.ftruncate(holder, 0)  # only now: the lock is held
        return open(holder, "w", encoding="utf-8", newline="", buffering=1 << 16)
    except OSError as err:
        if holder is not None:
            os.close(holder)
        raise write_error(shown, err) from None


def _stream(file: int | str, binary: bool, newline: str | None) -> IO[Any]:
    """``file`` (a path or a descriptor) opened for writing: bytes, or UTF-8 text."""
    if binary:
        return open(file, "wb")
    return open(file, "w", encoding="utf-8", newline=newline)


def _sync(fd: int) -> None:
    """Flush the file's blocks to the disk before the rename makes it the target (a power cut
    after the rename must not leave an empty file); a file system that cannot sync is let be."""
    try:
        os.fsync(fd)
    except OSError as err:
        if err.errno not in (getattr(os, "EINVAL", 22), getattr(os, "ENOTSUP", 95)):
            raise


def _mode_for(target: str) -> int:
    """The old file's permissions, or what a new file would get (0666 less the umask)."""
    try:
        return stat.S_IMODE(os.stat(target).st_mode)
    except OSError:
        return 0o666 & ~umask()


def umask() -> int:
    """The process's umask (what a file created now loses of its permissions)."""
    mask = os.umask(0)
    os.umask(mask)
    return mask


def _remove(path: str) -> None:
    with contextlib.suppress(OSError):
        os.unlink(path)


def write_text(path: PathLike, text: str, newline: str | None = None) -> None:
    """``path`` replaced whole by ``text`` (UTF-8), or left as it was."""
    with replacing(path, newline=newline) as handle:
        handle.write(text)


def write_bytes(path: PathLike, data: bytes) -> None:
    """``path`` replaced whole by ``data``, or left as it was."""
    with replacing(path, binary=True) as handle:
        handle.write(data)


def save_figure(figure: Any, path: PathLike, fmt: str, dpi: int) -> None:
    """A matplotlib figure saved to ``path`` (whole or not at all)."""
    with replacing(path, binary=True) as handle:
        figure.savefig(handle, format=fmt, dpi=dpi)


def ensure_parent(path: PathLike) -> Path:
    """``path`` as a Path, once its folder is known to exist (an error naming the file otherwise)."""
    result = Path(path)
    if result.parent and not result.parent.exists():
        raise EcncError(f"cannot write {result}: folder {result.parent} does not exist")
    return result
