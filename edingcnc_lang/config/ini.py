"""The ``cnc.ini`` file format: a lenient reader that keeps each value's line, and a rewrite of
``[VARIABLES]`` lines that leaves every other byte of the file as it was.

Users bring the ``cnc.ini`` of their real controller: thousands of lines written by a Windows
program, full of keys this project never uses.  The reader is therefore lenient about the file
as a whole (unknown sections, keys and odd lines are ignored) and strict only about the values
asked for, which are reported at their ini line when they do not parse.  What the keys mean is
``machine_config.py``'s business.
"""
from __future__ import annotations

import codecs
import contextlib
import errno
import glob
import math
import os
import re
import stat
from collections.abc import Callable, Iterator, Mapping
from dataclasses import dataclass
from pathlib import Path
from types import MappingProxyType
from typing import IO

from edingcnc_lang.errors import ConfigError, Location
from edingcnc_lang.outputs import owned_by_us
from edingcnc_lang.syntax.input_limits import MAX_INI_BYTES

_BOM = b"\xef\xbb\xbf"
_NUMBER = re.compile(r"[+-]?(?:[0-9]+\.?[0-9]*|\.[0-9]+)(?:[eE][+-]?[0-9]+)?")  # ASCII digits: not '１'
_INTEGER = re.compile(r"[+-]?[0-9]+")
_SECTION = re.compile(r"\[([^\]]*)\]")
VARIABLE_KEY = re.compile(r"#([0-9]+)")  # a [VARIABLES] key: the parameter number


@dataclass(frozen=True)
class IniValue:
    """A value as written in the ini (quotes and trailing comment removed) and its 1-based line."""

    text: str
    line: int


@dataclass(frozen=True)
class _Entry:
    """A ``key = value`` line; ``start:end`` is where the raw value (quotes included) sits."""

    key: str
    value: str
    start: int
    end: int


def _split_lines(text: str) -> list[tuple[str, str]]:
    """Split into (body, line ending) pairs whose concatenation is exactly ``text``."""
    pieces = text.split("\n")
    lines = [(p[:-1], "\r\n") if p.endswith("\r") else (p, "\n") for p in pieces[:-1]]
    if pieces[-1]:
        lines.append((pieces[-1], ""))
    return lines


def _parse_entry(body: str) -> _Entry | None:
    """Parse ``key = value ;comment``; a ``;`` inside a double-quoted value is text."""
    if body.lstrip().startswith(";") or "=" not in body:
        return None
    eq = body.index("=")
    key = body[:eq].strip()
    if not key:
        return None
    start = eq + 1
    while start < len(body) and body[start] in " \t":
        start += 1
    if body.startswith('"', start):
        close = body.find('"', start + 1)
        end = close + 1 if close >= 0 else len(body.rstrip())
        return _Entry(key, body[start + 1:close if close >= 0 else end], start, end)
    comment = body.find(";", start)
    end = max(start, len(body[:comment if comment >= 0 else len(body)].rstrip()))
    return _Entry(key, body[start:end], start, end)


def _classify(lines: list[tuple[str, str]]) -> list[tuple[str | None, _Entry | None]]:
    """For every line: the lower-cased section it belongs to and its entry, if any."""
    section: str | None = None
    result: list[tuple[str | None, _Entry | None]] = []
    for body, _ in lines:
        stripped = body.strip()
        header = _SECTION.match(stripped) if stripped.startswith("[") else None
        if header:
            section = header.group(1).strip().lower()
            result.append((section, None))
        else:
            result.append((section, _parse_entry(body)))
    return result


def _read_bytes(path: Path) -> bytes:
    """The whole file, up to MAX_INI_BYTES; a larger one is an error, not gigabytes of memory."""
    try:
        with open(path, "rb") as handle:
            raw = handle.read(MAX_INI_BYTES + 1)
    except OSError as exc:
        raise ConfigError(f"cannot read machine configuration: {exc.strerror or exc}",
                          Location(str(path))) from exc
    if len(raw) > MAX_INI_BYTES:
        raise ConfigError(f"machine configuration larger than {MAX_INI_BYTES // (1024 * 1024)} MB (the limit; a "
                          "cnc.ini holds some 50 KB): is this the right file?", Location(str(path)))
    return raw


def _utf16(raw: bytes) -> tuple[str, bytes] | None:
    """The codec and BOM of a UTF-16 file (with its BOM, or without one: ASCII text with every
    other byte NUL, as Windows editors save "Unicode"), or None for an 8-bit file."""
    if raw.startswith(codecs.BOM_UTF16_LE):
        return "utf-16-le", codecs.BOM_UTF16_LE
    if raw.startswith(codecs.BOM_UTF16_BE):
        return "utf-16-be", codecs.BOM_UTF16_BE
    if len(raw) >= 2 and (raw[0] == 0) != (raw[1] == 0):
        return ("utf-16-be" if raw[0] == 0 else "utf-16-le"), b""
    return None


def _decode_utf16(raw: bytes, codec: str, bom: bytes, path: Path) -> str:
    try:
        return raw[len(bom):].decode(codec)
    except UnicodeDecodeError as exc:
        raise ConfigError(f"machine configuration is not valid UTF-16 (byte {exc.start + len(bom)}): save it as "
                          "UTF-8 or ANSI", Location(str(path))) from None


def _decode(raw: bytes, path: Path) -> str:
    """UTF-16 when the file is (the controller's editor can save it so), else UTF-8 (BOM stripped),
    else Latin-1, which decodes any byte string."""
    wide = _utf16(raw)
    if wide is not None:
        return _decode_utf16(raw, *wide, path)
    raw = raw.removeprefix(_BOM)
    try:
        return raw.decode("utf-8")
    except UnicodeDecodeError:
        return raw.decode("latin-1")


def display_section(section: str) -> str:
    return f"[{section.upper()}]"


@dataclass(frozen=True)
class IniFile:
    """A parsed ini: section and key names lower-cased; the last of duplicate keys wins."""

    path: str
    sections: Mapping[str, Mapping[str, IniValue]]

    def get(self, section: str, key: str) -> IniValue | None:
        return self.sections.get(section.lower(), {}).get(key.lower())

    def get_str(self, section: str, key: str, default: str) -> str:
        value = self.get(section, key)
        return default if value is None else value.text

    def get_float(self, section: str, key: str, default: float) -> float:
        """An empty value counts as absent; anything but a plain decimal number is an error."""
        value = self._present(section, key)
        if value is None:
            return default
        if not _NUMBER.fullmatch(value.text):
            raise self._bad(section, key, value, "a number")
        if not math.isfinite(float(value.text)):  # 1e999 overflows to infinity
            raise self._bad(section, key, value, "a number within the range of a double")
        return float(value.text)

    def get_int(self, section: str, key: str, default: int) -> int:
        """Whole numbers; ``2.000000`` is accepted as 2 since Eding writes some counts that way."""
        value = self._present(section, key)
        if value is None:
            return default
        if _INTEGER.fullmatch(value.text):
            return int(value.text)
        if _NUMBER.fullmatch(value.text) and float(value.text).is_integer():
            return int(float(value.text))
        raise self._bad(section, key, value, "a whole number")

    def get_bool(self, section: str, key: str, default: bool) -> bool:
        """Flags are written as 0/1; any non-zero whole number is true."""
        return self.get_int(section, key, int(default)) != 0

    def section(self, name: str) -> Mapping[str, str]:
        """The raw texts of one section by lower-cased key (empty if the section is absent)."""
        values = self.sections.get(name.lower(), {})
        return MappingProxyType({key: value.text for key, value in values.items()})

    def location(self, section: str, key: str) -> Location:
        """Where a key is written (the file alone if it is not)."""
        value = self.get(section, key)
        return Location(self.path, value.line if value else 0)

    def _present(self, section: str, key: str) -> IniValue | None:
        value = self.get(section, key)
        return value if value is not None and value.text.strip() else None

    def _bad(self, section: str, key: str, value: IniValue, expected: str) -> ConfigError:
        return ConfigError(f"{key} in {display_section(section)}: expected {expected}, got {value.text!r}",
                           Location(self.path, value.line))


def read_ini(path: str | os.PathLike[str]) -> IniFile:
    """Read an ini file; a missing or unreadable file is a ConfigError."""
    text = _decode(_read_bytes(Path(path)), Path(path))
    lines = _split_lines(text)
    sections: dict[str, dict[str, IniValue]] = {}
    for number, (section, entry) in enumerate(_classify(lines), start=1):
        if section is None:
            continue  # keys before the first section header belong to nothing
        values = sections.setdefault(section, {})
        if entry is not None:
            values[entry.key.lower()] = IniValue(entry.value, number)
    frozen = {name: MappingProxyType(values) for name, values in sections.items()}
    return IniFile(os.fspath(path), MappingProxyType(frozen))


# --------------------------------------------------------------------------- write-back

def _line_ending(lines: list[tuple[str, str]]) -> str:
    """The file's own line ending; CRLF (what EdingCNC writes) if it has none yet."""
    return next((end for _, end in lines if end), "\r\n")


def _format(value: float) -> str:
    if not math.isfinite(value):
        raise ValueError(f"cannot persist a non-finite value: {value}")
    return f"{value:.6f}"


def _update_variables(text: str, values: Mapping[int, float]) -> str:
    """Rewrite the value text of known ``#n`` lines; append the others to ``[VARIABLES]``."""
    lines = _split_lines(text)
    classes = _classify(lines)
    written: set[int] = set()
    for i, (section, entry) in enumerate(classes):
        match = VARIABLE_KEY.fullmatch(entry.key) if entry and section == "variables" else None
        if entry and match and int(match.group(1)) in values:
            number = int(match.group(1))
            body, end = lines[i]
            lines[i] = (body[:entry.start] + _format(values[number]) + body[entry.end:], end)
            written.add(number)
    missing = [f"#{n} = {_format(values[n])}" for n in sorted(set(values) - written)]
    if not missing:
        return "".join(body + end for body, end in lines)
    eol = _line_ending(lines)
    in_section = [i for i, (section, _) in enumerate(classes) if section == "variables"]
    if in_section:
        at = max(i for i in in_section if lines[i][0].strip()) + 1
        added = []
    else:
        at = len(lines)
        added = ([("", eol)] if lines and lines[-1][0].strip() else []) + [("[VARIABLES]", eol)]
    if at > 0 and not lines[at - 1][1]:
        lines[at - 1] = (lines[at - 1][0], eol)  # the last line had no ending
    lines[at:at] = added + [(line, eol) for line in missing]
    return "".join(body + end for body, end in lines)


def write_atomic(path: Path, write: Callable[[IO[bytes]], object], info: os.stat_result) -> bool:
    """Write (``write`` fills the file) beside the target and rename over it, with the mode and owner
    of ``info`` (the old file's), so a kill leaves the old file or the new one.  Also used for the
    ``.npz`` samples file, which is assembled at the end of a run.

    Returns False, having changed nothing, when the new file could not keep the old one's owner.
    """
    import tempfile  # only when writing back (start-up time)

    tmp: str | None = None
    try:
        fd, tmp = tempfile.mkstemp(prefix=f".{path.name}.", suffix=".tmp", dir=path.parent)
        with os.fdopen(fd, "wb") as handle:
            write(handle)
            handle.flush()
            os.fsync(handle.fileno())
        os.chmod(tmp, stat.S_IMODE(info.st_mode))
        if not owned_by_us(info):
            try:
                os.chown(tmp, info.st_uid, info.st_gid)
            except OSError:  # someone else's file we may write: keep it theirs by writing in place
                os.unlink(tmp)
                return False
        os.replace(tmp, path)
        return True
    except BaseException:
        if tmp is not None:
            with contextlib.suppress(OSError):
                os.unlink(tmp)
        raise


def _reserve(fd: int, offset: int, length: int) -> None:
    """Give the file ``length`` more bytes of disk from ``offset`` (its end), or raise OSError (ENOSPC)."""
    try:
        os.posix_fallocate(fd, offset, length)
        return
    except (AttributeError, OSError) as exc:  # no posix_fallocate (macOS, Windows), or not on this file system
        if isinstance(exc, OSError) and exc.errno not in (errno.EOPNOTSUPP, errno.EINVAL, errno.ENOSYS):
            raise
    os.lseek(fd, offset, os.SEEK_SET)
    os.write(fd, b"\0" * length)  # at most MAX_INI_BYTES
    os.fsync(fd)
    os.lseek(fd, 0, os.SEEK_SET)


def _write_in_place(path: Path, data: bytes) -> None:
    """Rewrite the file itself: keeps its hard links and owner.  The room the new text needs is
    taken first, so a full disk refuses the write with the old file untouched instead of cutting
    it mid-line; only a kill mid-write can cut it short (see _signals_held)."""
    with open(path, "r+b") as handle:
        old = os.fstat(handle.fileno()).st_size
        if len(data) > old:
            try:
                _reserve(handle.fileno(), old, len(data) - old)
            except OSError:
                os.ftruncate(handle.fileno(), old)
                raise
        handle.write(data)
        handle.truncate()
        handle.flush()
        os.fsync(handle.fileno())


@contextlib.contextmanager
def _locked(path: Path) -> Iterator[None]:
    """Hold an exclusive lock on the ini's folder, so concurrent runs write back in turn.

    The folder rather than the file, whose inode the atomic replace swaps, and rather than a lock
    file, which would be left behind; without fcntl (Windows) there is no lock.
    """
    try:
        import fcntl
    except ImportError:
        yield
        return
    fd = os.open(path.parent, os.O_RDONLY | getattr(os, "O_CLOEXEC", 0))
    try:
        fcntl.flock(fd, fcntl.LOCK_EX)
        yield
    finally:
        os.close(fd)


@contextlib.contextmanager
def _signals_held() -> Iterator[None]:
    """Hold Ctrl-C and SIGTERM until the block is done, so a write-back is never cut short.

    Above all the in-place rewrite (hard links, another owner), which a stop between writing and
    truncating would leave half old, half new.  A signal that arrives meanwhile is noted and sent
    again once the old handlers are back (a mask would not do: another thread may take it).
    Only in the main thread, where Python handles signals.
    """
    import signal
    import threading

    if threading.current_thread() is not threading.main_thread():
        yield
        return
    received: list[int] = []
    held = [sig for sig in (signal.SIGINT, getattr(signal, "SIGTERM", None))
            if sig is not None and signal.getsignal(sig) is not None]
    previous = {sig: signal.signal(sig, lambda signum, _frame: received.append(signum)) for sig in held}
    try:
        yield
    finally:
        for sig, handler in previous.items():
            signal.signal(sig, handler)
        for sig in received[:1]:
            signal.raise_signal(sig)


def _remove_stale_temporaries(path: Path) -> None:
    """Temporary files of a write-back that was killed (only called under the lock, so none is live)."""
    for stale in path.parent.glob(f".{glob.escape(path.name)}.*.tmp"):
        with contextlib.suppress(OSError):
            stale.unlink()


def write_variables(path: str | os.PathLike[str], values: Mapping[int, float]) -> None:
    """Store ``values`` as ``#n = value`` lines in ``[VARIABLES]``, changing nothing else in the file.

    Under a lock, the file is read as it is now and only ``values`` change in it, so concurrent
    runs each keep their own changes.  A read-only file is refused; the new file replaces the old
    one atomically unless that would lose a hard link or the owner, then it is rewritten in place.
    An 8-bit file is handled as Latin-1, which maps each byte to one character and back, so text in
    any such encoding survives byte for byte (the ini syntax itself is ASCII); a UTF-16 file is
    written back as UTF-16, with its BOM if it had one.
    """
    if not values:
        return
    target = Path(os.path.realpath(path))
    try:
        with _locked(target), _signals_held():
            info = target.stat()
            if not info.st_mode & (stat.S_IWUSR | stat.S_IWGRP | stat.S_IWOTH) or not os.access(target, os.W_OK):
                raise ConfigError("cannot write variables back: the file is read-only (mode "
                                  f"{stat.S_IMODE(info.st_mode):04o}); make it writable or leave out --save-vars",
                                  Location(str(path)))
            _remove_stale_temporaries(target)
            raw = _read_bytes(target)
            wide = _utf16(raw)
            if wide is not None:  # written back in its own encoding, BOM and all
                data = wide[1] + _update_variables(_decode_utf16(raw, *wide, target), values).encode(wide[0])
            else:
                bom = _BOM if raw.startswith(_BOM) else b""
                data = bom + _update_variables(raw[len(bom):].decode("latin-1"), values).encode("latin-1")
            if info.st_nlink > 1 or not write_atomic(target, lambda handle: handle.write(data), info):
                _write_in_place(target, data)
    except OSError as exc:
        raise ConfigError(f"cannot write variables back: {exc.strerror or exc}", Location(str(path))) from exc
