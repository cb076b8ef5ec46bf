"""Running the linter: find the files, their macro files, run the rules, filter, sort.

Lint never executes anything.  Each job's GoSub targets resolve against the
macro files given on the command line, else ``macro.cnc``/``user_macro.cnc``
beside it.  Macro files found that way are read for context (their subs and
variables) but only the paths asked for are reported.
"""
from __future__ import annotations

import os
import re
from collections.abc import Callable, Iterable, Sequence
from dataclasses import replace
from pathlib import Path
from typing import TYPE_CHECKING

from edingcnc_lang.codes import CODES, RETIRED
from edingcnc_lang.diagnostics import Diagnostic
from edingcnc_lang.errors import EcncError
from edingcnc_lang.syntax.source import iter_file_lines
from edingcnc_lang.records import record
from edingcnc_lang.lint import rules_comp, rules_dialog, rules_files, rules_gm, rules_structure, rules_vars  # noqa: F401  (register)
from edingcnc_lang.lint import rules_lathe  # noqa: F401  (register)
from edingcnc_lang.lint import rules_names  # noqa: F401  (register)
from edingcnc_lang.lint.model import SourceFile, stream_source
from edingcnc_lang.lint.project import Project
from edingcnc_lang.lint.registry import RULES
from edingcnc_lang.lint.targets import applies, resolve

if TYPE_CHECKING:  # the machine model loads only when an ini is checked (start-up time)
    from edingcnc_lang.config.machine_config import MachineConfig

SOURCE_SUFFIXES = frozenset({".cnc", ".nc", ".ngc", ".tap", ".txt"})
CONFIG_SUFFIX = ".ini"
MACRO_NAMES = ("macro.cnc", "user_macro.cnc")
Reader = Callable[[Path, bool], SourceFile]  # (path, is a macro file) -> the parsed file
NOQA = re.compile(r";\s*noqa\b(?:\s*:\s*([A-Za-z0-9_]+(?:\s*,\s*[A-Za-z0-9_]+)*))?\s*$", re.IGNORECASE)


class UnknownCode(ValueError):
    """A code or prefix in --select/--ignore/noqa that matches no registered code."""


@record(frozen=True)
class LintOptions:
    """What ``ecnc lint`` was asked for besides the paths: macro files, ini, selected codes."""

    macro: str | None = None
    user_macro: str | None = None
    ini: str | None = None
    select: tuple[str, ...] = ()  # codes or prefixes; empty selects everything
    ignore: tuple[str, ...] = ()
    target: str | None = None  # controller version ("4.03", "5"); None: see lint.targets.resolve


def parse_codes(text: str | None) -> tuple[str, ...]:
    """``"E1,G503"`` -> ``("E1", "G503")``; raises UnknownCode for a prefix of no code (a retired
    code is accepted and matches nothing)."""
    codes = tuple(c.strip().upper() for c in (text or "").split(",") if c.strip())
    for code in codes:
        if not any(known.startswith(code) for known in (*CODES, *RETIRED)):
            raise UnknownCode(code)
    return codes


def _matches(code: str, patterns: Iterable[str]) -> bool:
    return any(code.startswith(p) for p in patterns)


def wanted(code: str, options: LintOptions) -> bool:
    return (not options.select or _matches(code, options.select)) and not _matches(code, options.ignore)


def expand(paths: Iterable[str | os.PathLike[str]]) -> list[Path]:
    """Files as given, and source files found (recursively, sorted) in folders."""
    found: list[Path] = []
    for path in map(Path, paths):
        if path.is_dir():
            found.extend(sorted(p for p in path.rglob("*")
                                if p.is_file() and p.suffix.lower() in SOURCE_SUFFIXES))
        else:
            found.append(path)
    return found


def is_macro_name(path: Path) -> bool:
    """Macro libraries: the controller's two file names, and any ``.cnc`` file."""
    return path.name.lower() in MACRO_NAMES or path.suffix.lower() == ".cnc"


def macros_beside(folder: Path) -> tuple[Path, ...]:
    """macro.cnc and user_macro.cnc in ``folder``, names matched case-insensitively like Windows."""
    try:
        entries = {p.name.lower(): p for p in folder.iterdir() if p.is_file()}
    except OSError:
        return ()
    return tuple(entries[name] for name in MACRO_NAMES if name in entries)


class _Loader:
    """Parses each file once, whether it is linted, a macro file, or both."""

    def __init__(self, given_macros: Sequence[Path], reader: Reader) -> None:
        self.given = tuple(given_macros)
        self.reader = reader
        self.files: dict[Path, SourceFile] = {}
        self._folders: dict[Path, tuple[Path, ...]] = {}

    def load(self, path: Path, is_macro: bool) -> SourceFile:
        key = path.resolve()
        if key not in self.files:
            self.files[key] = self.reader(path, is_macro)
        return self.files[key]

    def macros_for(self, path: Path) -> list[SourceFile]:
        folder = path.resolve().parent
        if folder not in self._folders:
            self._folders[folder] = macros_beside(folder)
        paths = self.given or self._folders[folder]
        return [self.load(p, True) for p in paths if p.resolve() != path.resolve()]


def lint_paths(paths: Iterable[str | os.PathLike[str]], options: LintOptions = LintOptions(),
               reader: Reader = stream_source, kept: list[object] | None = None) -> list[Diagnostic]:
    """Every finding in the files under ``paths``, filtered by the options, sorted by file and line.

    ``.ini`` files (given as paths or with ``--ini``) are checked as machine configurations; the
    variables their kinematics writes count as written for V302.  ``reader`` parses a file; the
    language server passes one that reads the editor's unsaved text and keeps parsed files.
    ``kept``: a list the parsed files and the facts about them are left in, not freed when this returns
    (the ``ecnc`` program ends the process without freeing them: ~10-20 ms of a big file).
    """
    names = [os.fspath(p) for p in paths]
    inis = [os.fspath(options.ini)] if options.ini else [p for p in names if p.lower().endswith(CONFIG_SUFFIX)]
    target = resolve(options.target, names, inis[0] if inis else None)
    given = [Path(p) for p in (options.macro, options.user_macro) if p]
    given_resolved = {g.resolve() for g in given}
    loader = _Loader(given, reader)
    found: list[Diagnostic] = []
    written: frozenset[int] = frozenset()
    targets: list[SourceFile] = []
    configs = [Path(options.ini)] if options.ini else []
    for path in expand(names):
        if path.suffix.lower() == CONFIG_SUFFIX:
            configs.append(path)
        else:
            targets.append(loader.load(path, is_macro_name(path) or path.resolve() in given_resolved))
    tool_diameters: dict[int, float] = {}
    mill = False
    spindle_range = (0.0, 0.0)
    for config in dict.fromkeys(configs):
        from edingcnc_lang.lint.rules_config import check_config  # the ini reader: only with an ini

        diags, outputs = check_config(config)
        found.extend(diags)
        written |= outputs
        machine = None if diags else _valid_config(config)
        if machine is not None:
            tool_diameters.update({number: tool.diameter for number, tool in machine.tools.items() if tool.diameter})
            mill = mill or not machine.lathe
            spindle_range = (machine.spindle_min_rpm, machine.spindle_max_rpm)
    for file in list(loader.files.values()):  # also loads the macro files of every file
        loader.macros_for(Path(file.path))
    macros = {file.path: loader.macros_for(Path(file.path)) for file in loader.files.values()}
    active = [r for r in RULES if any(wanted(c, options) for c in r.codes)]
    project = Project(list(loader.files.values()), macros, written, tool_diameters, mill, spindle_range)
    if kept is not None:
        kept += [*loader.files.values(), project]
    for file in dict.fromkeys(targets):
        for rule in active:  # the parser's nesting limits keep every walk within the stack
            found.extend(rule.check(file, project))
    return _finish(found, options, target, {f.path: f.lines for f in loader.files.values()})


def _valid_config(path: Path) -> MachineConfig | None:
    """The machine of an ini check_config passed: its tool table (``[TOOL_n] diameter``, mm) for the
    compensation rules, its machine type for the lathe codes."""
    from edingcnc_lang.config.machine_config import load_config

    try:
        return load_config(path)
    except EcncError:  # already reported by check_config
        return None


def _finish(found: list[Diagnostic], options: LintOptions, target: str,
            lines: dict[str, tuple[str, ...]]) -> list[Diagnostic]:
    """Attach source lines, apply the target, --select/--ignore and noqa, sort and drop duplicates."""
    kept: dict[tuple[str, int, int, str, str], Diagnostic] = {}
    for diag in found:
        if not wanted(diag.code, options) or not applies(diag.code, target):
            continue
        if diag.path not in lines:
            lines[diag.path] = _read_lines(diag.path)
        source = _line(lines[diag.path], diag.line)
        if _silenced(diag.code, source):
            continue
        kept.setdefault((diag.path, diag.line, diag.col, diag.code, diag.message), replace(diag, source=source))
    return [kept[k] for k in sorted(kept)]


def _read_lines(path: str) -> tuple[str, ...]:
    try:
        return tuple(iter_file_lines(path))
    except OSError:
        return ()


def _line(lines: tuple[str, ...], number: int) -> str:
    return lines[number - 1] if 0 < number <= len(lines) else ""


def _silenced(code: str, source: str) -> bool:
    """``; noqa`` silences every finding on its line, ``; noqa: G503,V3`` only those codes."""
    match = NOQA.search(source)
    if not match:
        return False
    listed = match.group(1)
    return listed is None or _matches(code, (c.strip().upper() for c in listed.split(",")))
