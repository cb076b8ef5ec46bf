"""V rules: parameter indices, read-only and never-written variables, M-code arguments, brackets.

A missing pair of brackets around an If/While condition (EdingCNC G1171) is a
syntax error the parser reports as E106.
"""
from __future__ import annotations

from collections.abc import Iterable, Iterator, Sequence

from edingcnc_lang.syntax import nodes as n
from edingcnc_lang.diagnostics import Diagnostic
from edingcnc_lang.machine.tables import (
    ARG_PARAMS,
    FIRST_PARAM,
    LAST_PARAM,
    LETTER_ARGS,
    READ_ONLY_PARAMS,
    VOLATILE_PARAMS,
    is_read_only,
)
from edingcnc_lang.lint.evaluate import constant_index
from edingcnc_lang.lint.model import SourceFile
from edingcnc_lang.lint.names import m_sub_number
from edingcnc_lang.lint.facts import Use
from edingcnc_lang.lint.project import Project
from edingcnc_lang.lint.registry import at, rule
from edingcnc_lang.lint.walk import Scope, assigned, dialog_fields, literal_index


def _indexed(file: SourceFile, project: Project) -> Iterator[tuple[float, n.Span]]:
    """Every parameter index the file names literally, with where it is written."""
    facts = project.facts(file)
    literals = facts.read_indices | facts.target_indices
    if any(literal is None or not FIRST_PARAM <= literal <= LAST_PARAM for literal in literals):  # (few files)
        yield from _computed_or_outside(facts.reads + facts.targets)
    for dialog, _scope in facts.dialogs:
        for item in dialog.items[1:]:
            if isinstance(item, n.Number):
                yield item.value, item.span


def _computed_or_outside(uses: Iterable[Use]) -> Iterator[tuple[float, n.Span]]:
    """The constant indices of the parameters whose index is computed or outside the range."""
    for param, literal, _scope in uses:
        if literal is None or not FIRST_PARAM <= literal <= LAST_PARAM:
            index = constant_index(param)  # computed, not a whole number, or out of range
            if index is not None:
                yield index, param.span


@rule("V300")
def index_range(file: SourceFile, project: Project) -> Iterator[Diagnostic]:
    for index, span in _indexed(file, project):
        if not index.is_integer() or not FIRST_PARAM <= index <= LAST_PARAM:
            shown = int(index) if index.is_integer() else index
            yield at("V300", f"#{shown} does not exist: parameters are numbered "
                     f"{FIRST_PARAM}..{LAST_PARAM}", span)


_FIRST_READ_ONLY = min(r.start for r in READ_ONLY_PARAMS)  # below it no parameter is read-only


@rule("V301")
def read_only_write(file: SourceFile, project: Project) -> Iterator[Diagnostic]:
    facts = project.facts(file)
    fields = [(index, node.span) for dialog, _scope in facts.dialogs for index, node in dialog_fields(dialog)]
    indices = facts.target_indices | {index for index, _span in fields}
    read_only = {index for index in indices if index is not None and index >= _FIRST_READ_ONLY and is_read_only(index)}
    if not read_only:  # most files
        return
    targets = [(index, param.span) for param, index, _scope in facts.targets]
    for index, span in targets + fields:
        if index in read_only:
            yield at("V301", f"#{index} is read-only: the controller sets it, a macro cannot "
                     "(use a variable of your own, e.g. one of #27..#3999)", span)


@rule("V302")
def never_written(file: SourceFile, project: Project) -> Iterator[Diagnostic]:
    """First read in each file of a volatile variable nothing assigns (a typo or a missing setup)."""
    facts = project.facts(file)
    written = project.written
    if not any(index is not None and index in VOLATILE_PARAMS and index not in written
               for index in facts.read_indices):  # most files
        return
    reads = facts.reads
    seen: set[int] = set()
    for param, index, _scope in reads:
        if index is not None and index in VOLATILE_PARAMS and index not in written and index not in seen:
            seen.add(index)
            yield at("V302", f"#{index} is read but never assigned in this file or its macro files, "
                     "so it is 0 or left over from an earlier job: assign it first", param.span)


# ----------------------------------------------------------------------- M-code arguments

Clobbered = dict[int, int]  # argument index -> line of the call that may have overwritten it


class _ArgumentFlow:
    """Follows which of #1..#26 a call may have overwritten, through If and While, in one M-code sub."""

    def __init__(self, file: SourceFile, project: Project, sub: n.Sub) -> None:
        self.file, self.project, self.scope = file, project, Scope(sub)
        self.found: list[Diagnostic] = []

    def run(self, body: Sequence[n.Stmt], state: Clobbered) -> Clobbered:
        for stmt in body:
            state = self.step(stmt, state)
        return state

    def step(self, stmt: n.Stmt, state: Clobbered) -> Clobbered:
        self.check_reads(stmt, state)
        if isinstance(stmt, n.If):
            then, orelse = self.run(stmt.then, dict(state)), self.run(stmt.orelse, dict(state))
            return {**then, **orelse}
        if isinstance(stmt, n.While):
            return {**state, **self.run(stmt.body, dict(state))}
        state = {i: line for i, line in state.items()
                 if i not in {literal_index(t) for t in assigned(stmt)}}
        if self.project.clobbers_arguments(self.file, stmt, self.scope):
            state = {i: stmt.span.line for i in ARG_PARAMS}
        return state

    def check_reads(self, stmt: n.Stmt, state: Clobbered) -> None:
        for param, index in self.project.reads(self.file, stmt):
            if index in state:
                letter = LETTER_ARGS[index - 1]
                self.found.append(at(
                    "V303", f"#{index} (argument {letter}) is read after the call on line {state[index]}, "
                    f"which may have overwritten it: copy #{index} to a variable of your own before "
                    "the call", param.span))


@rule("V303")
def arguments_after_call(file: SourceFile, project: Project) -> Iterator[Diagnostic]:
    for sub in file.subs.values():
        if m_sub_number(sub.name) is not None:
            flow = _ArgumentFlow(file, project, sub)
            flow.run(sub.body, {})
            yield from flow.found


@rule("V304")
def extra_bracket(file: SourceFile, project: Project) -> Iterator[Diagnostic]:
    for stmt in project.facts(file).heads:
        if stmt.extra_brackets:
            keyword = "If" if isinstance(stmt, n.If) else "While"
            yield at("V304", f"{stmt.extra_brackets} extra ']' after the {keyword} condition: the "
                     "controller ignores it, but remove it so the brackets match", stmt.span)
