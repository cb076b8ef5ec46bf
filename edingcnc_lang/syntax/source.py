"""Reading source files: decoding and line splitting, lazily.

Real macro files come as ASCII, UTF-8 (with or without BOM) and Latin-1 with
CRLF or LF line ends.  Each line is decoded on its own (UTF-8 first, Latin-1 as
fallback) so a stray byte never breaks a file and nothing is held in memory
beyond the current line.  A file that starts with a UTF-16 BOM (what Windows
Notepad saves as "Unicode") is decoded as UTF-16.
"""
from __future__ import annotations

import codecs
import os
import re
import stat
from collections.abc import Iterator
from itertools import chain
from typing import BinaryIO

from edingcnc_lang.errors import Location, UnreadableFile
from edingcnc_lang.syntax.input_limits import MAX_LINE_LENGTH

BOM = b"\xef\xbb\xbf"
UTF16_BOMS = (codecs.BOM_UTF16_LE, codecs.BOM_UTF16_BE)
# Bytes kept of a line longer than the limit: enough for MAX_LINE_LENGTH + 1 characters in any
# encoding, so the parser still sees it is too long; the rest is skipped, not held in memory.
LONG_LINE_BYTES = 4 * (MAX_LINE_LENGTH + 1)


# A number as the docs allow it everywhere (job words, cnc.ini, --answer, height files, command
# arguments): ASCII digits, one point, an exponent.  Python's float() and int() also take '١٠',
# '１', '𝟏' and '1_0', which no controller reads as numbers.
_PLAIN_FLOAT = re.compile(r"[+-]?(?:[0-9]+\.?[0-9]*|\.[0-9]+)(?:[eE][+-]?[0-9]+)?")
_PLAIN_INT = re.compile(r"[+-]?[0-9]+")
_SPECIAL = ("inf", "+inf", "-inf", "infinity", "+infinity", "-infinity", "nan", "+nan", "-nan")


def plain_float(text: str, special: bool = False) -> float:
    """``text`` (blanks around it allowed) as a float if it is a plain decimal number; ``special``
    also lets ``inf`` and ``nan`` through.  Raises ValueError otherwise."""
    word = text.strip()
    if _PLAIN_FLOAT.fullmatch(word) or (special and word.lower() in _SPECIAL):
        return float(word)
    raise ValueError(f"{text!r} is not a plain decimal number")


def plain_int(text: str) -> int:
    """``text`` (blanks around it allowed) as an int if it is ASCII digits with an optional sign."""
    word = text.strip()
    if _PLAIN_INT.fullmatch(word):
        return int(word)
    raise ValueError(f"{text!r} is not a whole number")


def decode_line(raw: bytes) -> str:
    """Decode one line; Latin-1 accepts every byte, so this never fails."""
    try:
        return raw.decode("utf-8")
    except UnicodeDecodeError:
        return raw.decode("latin-1")


CHUNK = 1 << 20  # bytes read at a time


def is_device(mode: int) -> bool:
    """Whether a file of this ``st_mode`` is a device (``/dev/zero``): input that never ends, so never read."""
    return stat.S_ISCHR(mode) or stat.S_ISBLK(mode)


def iter_file_lines(path: str | os.PathLike[str]) -> Iterator[str]:
    """Yield the lines of a file without their line ends (LF, with any CRs before it); see iter_file_blocks."""
    for block in iter_file_blocks(path):
        yield from block


def iter_file_blocks(path: str | os.PathLike[str]) -> Iterator[list[str]]:
    """Yield the lines of a file, without their line ends, in lists: the lines of each block read.

    A file that cannot be opened raises UnreadableFile (an EcncError naming it), when the first
    block is asked for.

    The file is read in blocks of about a megabyte and each block is decoded and split at once
    (a reader that goes through the lines in lists pays nothing per line here); only a block that
    is not valid UTF-8 is decoded line by line.  A line longer than LONG_LINE_BYTES is cut there
    (the parser refuses it), so memory stays bounded.
    """
    try:
        handle = open(path, "rb")
    except OSError as exc:
        raise UnreadableFile.of(os.fspath(path), exc) from None
    with handle:
        if is_device(os.fstat(handle.fileno()).st_mode):
            raise UnreadableFile("cannot read: a device, not a file", Location(os.fspath(path)))
        head = handle.read(len(BOM))
        if head.startswith(UTF16_BOMS):
            yield from _utf16_blocks(handle, head)
            return
        pending = b"" if head == BOM else head
        skipping = False  # inside the rest of an over-long line
        while True:
            block = handle.read(CHUNK)
            if skipping and block:
                end = block.find(b"\n")
                if end < 0:
                    continue
                skipping, block = False, block[end:]
            data = pending + block
            if block:
                cut = data.rfind(b"\n")
                if cut < 0:
                    skipping = len(data) > LONG_LINE_BYTES
                    pending = data[:LONG_LINE_BYTES]
                    continue
                pending, body = data[cut + 1:], data[:cut]
            elif not data:
                return
            else:  # the end of the file: what is left is the last line(s)
                pending, body = b"", data[:-1] if data.endswith(b"\n") else data
            try:
                text = body.decode("utf-8")
            except UnicodeDecodeError:
                lines = [decode_line(raw) for raw in body.split(b"\n")]
                yield _without_crs(lines) if b"\r" in body else lines
            else:
                yield _split_crlf(text) if "\r" in text else text.split("\n")


def _without_crs(lines: list[str]) -> list[str]:
    return [line.rstrip("\r") for line in lines]


def _split_crlf(text: str) -> list[str]:
    """``text`` split at LF, the CRs before each LF dropped (CRLF files): the same as ``_without_crs``
    but without a call per line, unless a line ends in more than one CR."""
    if "\r\r" in text:
        return _without_crs(text.split("\n"))
    lines = text.replace("\r\n", "\n").split("\n")
    lines[-1] = lines[-1].rstrip("\r")  # the block's last line: its LF was cut off
    return lines


def _utf16_blocks(handle: BinaryIO, head: bytes) -> Iterator[list[str]]:
    """The lines of a UTF-16 file (``head``: its first bytes, BOM included), decoded as a stream and
    cut after MAX_LINE_LENGTH + 1 characters like any other file's; a broken pair shows as U+FFFD."""
    decoder = codecs.getincrementaldecoder("utf-16")(errors="replace")
    limit = MAX_LINE_LENGTH + 1
    pending, skipping = "", False
    for block in chain([head], iter(lambda: handle.read(CHUNK), b"")):
        text = decoder.decode(block)
        if skipping:
            end = text.find("\n")
            if end < 0:
                continue
            skipping, text = False, text[end:]
        lines = (pending + text).split("\n")
        pending = lines.pop()
        if len(pending) > limit:
            pending, skipping = pending[:limit], True
        if lines:
            yield _without_crs(lines)
    if not skipping:
        pending += decoder.decode(b"", final=True)
    if pending:
        yield [pending.rstrip("\r")]


def iter_text_lines(text: str) -> Iterator[str]:
    """Yield the lines of an in-memory string (BOM stripped)."""
    if text.startswith("\ufeff"):
        text = text[1:]
    lines = text.split("\n")
    if lines and lines[-1] == "":
        lines.pop()
    for line in lines:  # only LF/CRLF end a line, as in files (str.splitlines would split on \f)
        yield line.rstrip("\r")


def read_text(path: str | os.PathLike[str]) -> str:
    """The whole file decoded line by line, joined with LF."""
    return "\n".join(iter_file_lines(path))
