"""Who writes and who reads each numbered variable, from the facts the linter already gathered.

The variable map (``ecnc vars``), its lint rules and the editor read the same lists: every
assignment by number, every dlgmsg field and every command that stores a result count as
writes; every parameter read with a literal index counts as a read.  Computed indices
(``#[#1 + 40]``) are decided when the job runs and are left out.
"""
from __future__ import annotations

from collections.abc import Iterable
from functools import cached_property

from edingcnc_lang.syntax import nodes as n
from edingcnc_lang.lint.model import SourceFile
from edingcnc_lang.lint.project import Project, SubKey, command_writes, sub_key
from edingcnc_lang.lint.walk import Scope, dialog_fields
from edingcnc_lang.varmap.model import Use

Uses = dict[int, list[Use]]


def _use(span: n.Span, scope: Scope) -> Use:
    return Use(span.path, span.line, span.col, scope.sub.name if scope.sub is not None else None)


class VariableUses:
    """The writers and readers of every number in a project's files, and which subs reach which."""

    def __init__(self, project: Project, files: Iterable[SourceFile] | None = None) -> None:
        self.project = project
        self.files = tuple(project.files if files is None else files)

    @cached_property
    def writers(self) -> Uses:
        """Every write by number: assignments, dlgmsg fields, commands that store a result."""
        found: Uses = {}
        for file in self.files:
            facts = self.project.facts(file)
            for param, index, scope in facts.targets:
                if index is not None:
                    found.setdefault(index, []).append(_use(param.span, scope))
            for dialog, scope in facts.dialogs:
                for index, node in dialog_fields(dialog):
                    found.setdefault(index, []).append(_use(node.span, scope))
            commands = {id(c) for c in facts.commands}
            for stmt, scope in facts.walked if commands else ():
                if id(stmt) in commands:
                    assert isinstance(stmt, n.Command)
                    for index in command_writes(stmt):
                        found.setdefault(index, []).append(_use(stmt.span, scope))
        return found

    @cached_property
    def readers(self) -> Uses:
        """Every read of a number known without running."""
        found: Uses = {}
        for file in self.files:
            for param, index, scope in self.project.facts(file).reads:
                if index is not None:
                    found.setdefault(index, []).append(_use(param.span, scope))
        return found

    @cached_property
    def reach(self) -> dict[SubKey, frozenset[SubKey]]:
        """Every sub (and each file's top level, as ``(path, "")``) with the subs it may run, directly or not."""
        direct: dict[SubKey, set[SubKey]] = {}
        for call in self.project.calls:
            caller = sub_key(call.caller, call.scope.sub) if call.scope.sub is not None else (call.caller.path, "")
            direct.setdefault(caller, set()).add(call.key)
        found: dict[SubKey, frozenset[SubKey]] = {}
        for start in direct:
            seen: set[SubKey] = set()
            stack = list(direct[start])
            while stack:
                key = stack.pop()
                if key not in seen:
                    seen.add(key)
                    stack.extend(direct.get(key, ()))
            found[start] = frozenset(seen)
        return found

    def related(self, a: SubKey, b: SubKey) -> bool:
        """True if one of the two may run the other (or they are the same)."""
        return a == b or b in self.reach.get(a, ()) or a in self.reach.get(b, ())


def key_of(use: Use) -> SubKey:
    """The sub a use is in, as the project keys subs (top level: ``(path, "")``)."""
    return use.path, (use.sub or "").lower()

