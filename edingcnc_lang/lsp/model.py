"""The language model every editor feature reads: parsed files, their macro files, subs and calls.

Files open in the editor are read from their unsaved text, the others from disk; each is
parsed once per version.  Calls are resolved by the linter's own ``Project``, so the
editor jumps exactly where ``ecnc lint`` looks (the file, then ``macro.cnc`` and
``user_macro.cnc`` beside it; M codes to ``Sub mNNN``; M6 to ``change_tool``).
"""
from __future__ import annotations

import errno
import os
import stat
from collections.abc import Iterator
from dataclasses import dataclass
from pathlib import Path

from edingcnc_lang.syntax import nodes as n
from edingcnc_lang.gcpause import whole_trees
from edingcnc_lang.diagnostics import Diagnostic
from edingcnc_lang.errors import EcncError, Location
from edingcnc_lang.lint.driver import SOURCE_SUFFIXES, LintOptions, is_macro_name, lint_paths, macros_beside
from edingcnc_lang.lint.model import SourceFile, UnreadableFile, load_source
from edingcnc_lang.machine.tables import m_code_sub
from edingcnc_lang.lint.project import Project, SubKey
from edingcnc_lang.lsp.lexer import SUB_NAME

# Files of a folder bigger than this are left out of references and workspace symbols: they are CAM
# output (long runs of moves), not macro code, and reading them on every request would be slow.
MAX_INDEXED_BYTES = 512 * 1024
MAX_WORKSPACE_FILES = 500


@dataclass(frozen=True)
class Place:
    """A range in a file: 0-based line, start and end columns (end exclusive)."""

    path: str
    line: int
    start: int
    end: int


class LanguageModel:
    """Open documents plus the files on disk around them, parsed on demand and cached.

    Rename and references read the model in a worker thread while the server's thread opens and
    changes documents: the open documents are iterated over a snapshot (``list(self.texts)``), and
    a parsed file is replaced in the cache, never changed.
    """

    def __init__(self) -> None:
        self.texts: dict[str, str] = {}  # unsaved editor contents by absolute path
        self.roots: list[str] = []  # workspace folders, for workspace symbols
        self.options = LintOptions()  # the codes the editor asked for (select, ignore)
        self._real: dict[str, str] = {}  # open documents by their real path (symbolic links resolved)
        self._parsed: dict[tuple[str, bool], tuple[object, SourceFile]] = {}

    # ----------------------------------------------------------------- files
    def set_text(self, path: str, text: str | None) -> None:
        """The editor opened or changed ``path`` (text), or closed it (None: read the disk again)."""
        if text is None:
            self.texts.pop(path, None)
            self._real.pop(os.path.realpath(path), None)
            for macro in (False, True):  # the editor's version is gone: read the disk next time
                self._parsed.pop((path, macro), None)
        else:
            self.texts[path] = text
            self._real[os.path.realpath(path)] = path

    def source(self, path: str, is_macro: bool | None = None) -> SourceFile | None:
        """The parsed file (None when it cannot be read); macro or job by its name unless told."""
        macro = is_macro_name(Path(path)) if is_macro is None else is_macro
        text = self.texts.get(path)
        if text is None and path not in self.texts and self._real:  # the same file by another name
            text = self.texts.get(self._real.get(os.path.realpath(path), ""))
        try:
            stamp: object = text if text is not None else _stamp(path)
        except OSError:
            return None
        cached = self._parsed.get((path, macro))
        if cached is not None and cached[0] == stamp:
            return cached[1]
        try:
            with whole_trees():
                parsed = load_source(path, macro, text)
        except (UnreadableFile, RecursionError):
            return None
        self._parsed[path, macro] = (stamp, parsed)
        return parsed

    def macros(self, path: str) -> list[SourceFile]:
        """macro.cnc and user_macro.cnc beside ``path`` (not the file itself)."""
        found = (self.source(os.fspath(p)) for p in macros_beside(Path(path).parent) if os.fspath(p) != path)
        return [f for f in found if f is not None]

    def folder(self, path: str) -> list[SourceFile]:
        """Every source file of the folder of ``path`` (small enough to be macro code) and ``path`` itself."""
        folder = Path(path).parent
        paths = {path} | {p for p in list(self.texts) if Path(p).parent == folder}
        try:
            paths |= {os.fspath(p) for p in folder.iterdir() if _indexable(p)}
        except OSError:
            pass
        return [f for f in (self.source(p) for p in sorted(paths)) if f is not None]

    def workspace(self) -> list[SourceFile]:
        """Macro files (``*.cnc``) under the workspace folders, and every open document.  An editor
        that opened single files, with no workspace folder, gets the macro files beside them."""
        paths = dict.fromkeys(list(self.texts))
        beside = {Path(p).parent: "*.[cC][nN][cC]" for p in paths if os.path.isabs(p)}
        folders = {Path(root): "**/*.[cC][nN][cC]" for root in self.roots} or beside
        for folder, pattern in folders.items():
            for found in folder.glob(pattern):
                if len(paths) >= MAX_WORKSPACE_FILES:
                    break
                if _indexable(found):
                    paths.setdefault(os.fspath(found))
        return [f for f in (self.source(p) for p in paths) if f is not None]

    # ----------------------------------------------------------------- checks
    def lint(self, path: str) -> list[Diagnostic]:
        """What ``ecnc lint PATH`` reports, for the editor's text of every open file."""
        try:
            with whole_trees():
                found = lint_paths([path], self.options, reader=self._read)
        except EcncError:  # a macro file beside it vanished while being read: lint again on the next change
            return []
        return [d for d in found if d.path == path]

    def _read(self, path: Path, is_macro: bool) -> SourceFile:
        found = self.source(os.fspath(path), is_macro)
        if found is None:
            raise UnreadableFile("cannot read", Location(os.fspath(path)))
        return found

    # ----------------------------------------------------------------- subs and calls
    def project(self, path: str) -> tuple[SourceFile, Project] | None:
        """The file with its macro files, as one lint project."""
        file = self.source(path)
        if file is None:
            return None
        macros = self.macros(path)
        return file, Project([file, *macros], {file.path: macros})

    def resolve(self, path: str, name: str) -> tuple[SourceFile, n.Sub] | None:
        """The sub ``name`` as a call in ``path`` reaches it."""
        found = self.project(path)
        return found[1].resolve(found[0], name) if found else None

    def calls_to(self, target: SubKey, path: str) -> Iterator[Place]:
        """Where the files of the folder of ``path`` call the sub ``target``."""
        files = self.folder(path)
        project = Project(files, {f.path: self.macros(f.path) for f in files})
        for call in project.calls:
            if call.key != target:
                continue
            if isinstance(call.stmt, n.GoSub):
                yield sub_name_place(call.caller, call.stmt.span.line)
            else:
                for key, word in project.codes(call.caller, call.stmt, "M"):
                    if m_code_sub(key) == call.sub.name.lower():
                        span = word.span
                        yield Place(call.caller.path, span.line - 1, span.col - 1, span.end_col - 1)


def file_name(path: str) -> str:
    """The last part of a path, also of a Windows one or an ``untitled:`` name, for labels."""
    return path.replace("\\", "/").rsplit("/", 1)[-1]


def definition_place(file: SourceFile, sub: n.Sub) -> Place:
    return sub_name_place(file, sub.span.line)


def sub_name_place(file: SourceFile, line: int) -> Place:
    """Where the name is on a ``Sub name`` or ``GoSub name`` line (1-based ``line``)."""
    text = file.line(line)
    match = SUB_NAME.match(text)
    if match:
        return Place(file.path, line - 1, match.start(1), match.end(1))
    return Place(file.path, line - 1, 0, len(text))


def _stamp(path: str) -> tuple[int, int]:
    """The version of a file on disk; OSError for anything but a regular file: opening a FIFO
    would block the whole server until something writes to it, a device never ends."""
    info = os.stat(path)
    if not stat.S_ISREG(info.st_mode):
        raise OSError(errno.EINVAL, "not a regular file", path)
    return info.st_mtime_ns, info.st_size


def _indexable(path: Path) -> bool:
    try:
        return (path.suffix.lower() in SOURCE_SUFFIXES and path.is_file()
                and path.stat().st_size <= MAX_INDEXED_BYTES)
    except OSError:
        return False
