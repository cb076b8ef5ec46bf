"""S rules: subs and calls, and code that can never run.

Unmatched If/While/Sub ends, Else outside If and nested subs are found by the
parser (S200..S206) and reported through the syntax rule.
"""
from __future__ import annotations

from collections.abc import Iterator
from pathlib import Path

from edingcnc_lang.syntax import nodes as n
from edingcnc_lang.diagnostics import Diagnostic
from edingcnc_lang.lint.model import SourceFile
from edingcnc_lang.lint.names import is_entry_point
from edingcnc_lang.lint.project import Project, sub_key
from edingcnc_lang.lint.registry import at, rule
from edingcnc_lang.lint.walk import END_OF_PROGRAM, block_codes


@rule("S207")
def duplicate_sub(file: SourceFile, project: Project) -> Iterator[Diagnostic]:
    for stmt in file.body:
        if isinstance(stmt, n.Sub):
            first = file.subs[stmt.name.lower()]
            if first is not stmt:
                yield at("S207", f"Sub {stmt.name} is already defined on line {first.span.line} "
                         "(sub names ignore case); rename or remove one of them", stmt.span)


@rule("S208")
def unknown_gosub(file: SourceFile, project: Project) -> Iterator[Diagnostic]:
    for stmt, _ in project.facts(file).callers:
        if isinstance(stmt, n.GoSub) and project.resolve(file, stmt.name) is None:
            others = [Path(other.path).name for other in project.searched(file)[1:]]
            if others:
                where = "this file or " + " or ".join(others)
            elif file.is_macro:
                where = "this file"
            else:
                where = "this file or its macro files (--macro/--user-macro, or macro.cnc beside it)"
            yield at("S208", f"GoSub {stmt.name}: no Sub {stmt.name} in {where}", stmt.span)


def _ending(stmt: n.Stmt) -> str:
    if isinstance(stmt, n.Message):
        return "errmsg"
    assert isinstance(stmt, n.Block)
    key = next(k for k, _word in block_codes(stmt)[1] if k in END_OF_PROGRAM)
    return f"M{key // 10}"


@rule("S209")
def unreachable(file: SourceFile, project: Project) -> Iterator[Diagnostic]:
    """Statements after an unconditional end in the same list never run (Sub definitions excepted)."""
    for end, dead in project.facts(file).unreachable:  # found in the one walk
        yield at("S209", f"this never runs: the {_ending(end)} on line {end.span.line} ends the "
                 "program first; move it before that line or remove it", dead.span)


@rule("S210")
def unused_sub(file: SourceFile, project: Project) -> Iterator[Diagnostic]:
    """Only job files: a macro file's subs are a library for jobs that are not being linted."""
    if file.is_macro:
        return
    for sub in file.subs.values():
        if not is_entry_point(sub.name) and sub_key(file, sub) not in project.called:
            yield at("S210", f"Sub {sub.name} is never called: add a GoSub {sub.name} or remove it",
                     sub.span)
