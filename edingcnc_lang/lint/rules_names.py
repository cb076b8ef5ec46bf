"""V rules about what numbers mean: one number named for two things, writes that never run,
numbers the manual reserves, malformed ``;@var`` annotations.

The names come from ``varmap`` (annotations, sidecars, dlgmsg labels, comments), who writes and
reads each number from ``variable_uses``; a write to a read-only number is V301 (``rules_vars``).
"""
from __future__ import annotations

import re
from collections.abc import Iterator, Sequence
from weakref import WeakKeyDictionary

from edingcnc_lang.diagnostics import Diagnostic
from edingcnc_lang.machine.tables import VOLATILE_PARAMS
from edingcnc_lang.lint.model import SourceFile
from edingcnc_lang.lint.names import is_entry_point
from edingcnc_lang.lint.project import Project, SubKey, command_writes, sub_key
from edingcnc_lang.lint.registry import at_line, rule
from edingcnc_lang.lint.variable_uses import VariableUses, key_of
from edingcnc_lang.lint.walk import Scope, assigned, dialog_fields, literal_index
from edingcnc_lang.syntax import nodes as n
from edingcnc_lang.varmap.convention import sidecar_of
from edingcnc_lang.varmap.kinds import RESERVED, SCRATCH, USER, kind_of
from edingcnc_lang.varmap.names import ANNOTATION, COMMENT, DLGMSG, Candidate

SHARED_KINDS = frozenset({USER, SCRATCH})  # the numbers subs use as their own working values
_UNITS = re.compile(r"\[[^\]]*\]|\([^)]*\)")


_USES: WeakKeyDictionary[Project, VariableUses] = WeakKeyDictionary()


def uses_of(project: Project) -> VariableUses:
    """The writers and readers of the project's numbers, worked out once per project."""
    found = _USES.get(project)
    if found is None:
        found = _USES[project] = VariableUses(project)
    return found


def words(name: str) -> frozenset[str]:
    """The words of a name without its units: ``"Vc [m/min]"`` -> ``{"vc"}``."""
    return frozenset(re.findall(r"[^\W_]+", _UNITS.sub(" ", name.lower())))


def _per_sub(found: list[Candidate], source: str) -> dict[SubKey, Candidate]:
    """The first name of one source in each sub."""
    per: dict[SubKey, Candidate] = {}
    for candidate in found:
        if candidate.source == source:
            per.setdefault((candidate.path, (candidate.sub or "").lower()), candidate)
    return per


@rule("V305")
def two_meanings(file: SourceFile, project: Project) -> Iterator[Diagnostic]:
    """One number that unrelated subs of one program name for different things: a dlgmsg label
    against a dlgmsg label, an assignment comment against an assignment comment, no word in common.
    Persistent numbers are left out: two setup dialogs often label one setting in their own words."""
    names = project.names
    uses: VariableUses | None = None
    together = {f.path for f in project.searched(file)}  # the file and its macro files: one program
    for number, found in names.candidates.items():
        if len(found) < 2 or kind_of(number) not in SHARED_KINDS or found[0].source == ANNOTATION:
            continue  # one name, a number of the controller's, or named on purpose (annotations sort first)
        if not any(c.path == file.path for c in found):
            continue
        for source in (DLGMSG, COMMENT):
            per = _per_sub([c for c in found if c.path in together], source)
            if len(per) < 2:
                continue
            uses = uses or uses_of(project)
            clash = _clash(per, file.path, uses)
            if clash is not None:
                here, there = clash
                yield at_line("V305", f"#{number} is {here.name!r} here but {there.name!r} in "
                              f"{there.sub or 'the top level'} ({_short(there.path)}:{there.line}), and neither "
                              "sub runs the other: give one of them a number of its own, or name it with "
                              f";@var #{number} NAME if both mean the same", file, here.line, here.col)
                break


def _clash(per: dict[SubKey, Candidate], path: str, uses: VariableUses) -> tuple[Candidate, Candidate] | None:
    """A name in ``path`` and an earlier one elsewhere with no word in common, in unrelated subs."""
    ordered = sorted(per.items(), key=lambda item: (item[1].path, item[1].line))
    for i, (key, here) in enumerate(ordered):
        if here.path != path:
            continue
        for other_key, there in ordered[:i]:
            if not words(here.name) & words(there.name) and not uses.related(key, other_key):
                return here, there
    return None


def _short(path: str) -> str:
    return path.replace("\\", "/").rsplit("/", 1)[-1]


@rule("V306")
def writes_never_run(file: SourceFile, project: Project) -> Iterator[Diagnostic]:
    """A volatile variable read where no write can have run: every write is in a job's sub that
    nothing calls, or (a job's own numbers) every write comes after the read on every path."""
    facts = project.facts(file)
    candidates = {i for i in facts.read_indices if i is not None and i in VOLATILE_PARAMS}
    if not candidates:
        return
    yield from _dead_writes(file, project, candidates)
    if not file.is_macro and any(i in facts.target_indices for i in candidates):  # read and written in a job
        yield from _JobFlow(file, project, candidates).run()


def _dead_writes(file: SourceFile, project: Project, candidates: set[int]) -> Iterator[Diagnostic]:
    """Reads of numbers whose every write is in a sub that nothing calls."""
    dead = _dead_subs(project)
    if not dead:  # most files: every sub may run
        return
    facts = project.facts(file)
    uses = uses_of(project)
    seen: set[int] = set()
    for param, index, scope in facts.reads:
        if index not in candidates or index in seen:
            continue
        writers = uses.writers.get(index, ())
        if not writers or not all(key_of(w) in dead for w in writers):
            continue
        if scope.sub is not None and (file.path, scope.sub.name.lower()) in dead:
            continue
        seen.add(index)
        subs = sorted({w.sub or "" for w in writers})
        yield at_line("V306", f"#{index} is read here but only written in {', '.join(subs)}, which nothing "
                      "calls: it never holds what those writes store", file, param.span.line, param.span.col)


class _JobFlow:
    """A job's top level in order, with the numbers some path may have written so far: a read of a
    number only the job's top level writes, before any such write, sees 0 or an earlier run's value.

    Conservative: a write on any path counts (an If's branches are joined), a loop's body counts as
    written before it runs (its next round reads them), a call counts every number its sub (and the
    subs it runs) may write.
    """

    def __init__(self, file: SourceFile, project: Project, candidates: set[int]) -> None:
        self.file, self.project = file, project
        uses = uses_of(project)
        top = (file.path, "")
        # the job's own numbers: read here, and written only by this job's top level
        self.watched = {i for i in candidates
                        if uses.writers.get(i) and all(key_of(w) == top for w in uses.writers[i])}
        self.sub_writes: dict[SubKey, set[int]] = {}
        for index, writers in uses.writers.items():
            for writer in writers:
                self.sub_writes.setdefault(key_of(writer), set()).add(index)
        self.reach = uses.reach
        self.found: list[Diagnostic] = []
        self.reported: set[int] = set()

    def run(self) -> list[Diagnostic]:
        if self.watched:
            self.flow(self.file.body, set())
        return self.found

    def flow(self, body: Sequence[n.Stmt], written: set[int]) -> None:
        for stmt in body:
            if isinstance(stmt, n.Sub):
                continue
            if isinstance(stmt, n.While):
                written |= self.writes_in(stmt.body)
            self.check(stmt, written)
            if isinstance(stmt, n.If):
                then, orelse = set(written), set(written)
                self.flow(stmt.then, then)
                self.flow(stmt.orelse, orelse)
                written |= then | orelse
            elif isinstance(stmt, n.While):
                self.flow(stmt.body, written)
            else:
                written |= self.writes(stmt)

    def check(self, stmt: n.Stmt, written: set[int]) -> None:
        for param, index in self.project.reads(self.file, stmt):
            if index in self.watched and index not in written and index not in self.reported:
                self.reported.add(index)
                first = min(w.line for w in uses_of(self.project).writers[index])
                self.found.append(at_line(
                    "V306", f"#{index} is read before this job writes it (first on line {first}): it holds 0 "
                    "or what an earlier run left; assign it first", self.file, param.span.line, param.span.col))

    def writes(self, stmt: n.Stmt) -> set[int]:
        """What one statement (not its nested ones) may write, with the subs it runs."""
        found = {i for i in map(literal_index, assigned(stmt)) if i is not None}
        if isinstance(stmt, n.Dialog):
            found |= {i for i, _node in dialog_fields(stmt)}
        elif isinstance(stmt, n.Command):
            found |= set(command_writes(stmt))
        for callee, sub in self.project.callees(self.file, stmt, Scope()):
            key = sub_key(callee, sub)
            for reached in (key, *self.reach.get(key, ())):
                found |= self.sub_writes.get(reached, set())
        return found

    def writes_in(self, body: Sequence[n.Stmt]) -> set[int]:
        """What a block of statements may write, nested ones included."""
        found: set[int] = set()
        for stmt in body:
            found |= self.writes(stmt)
            if isinstance(stmt, n.If):
                found |= self.writes_in(stmt.then) | self.writes_in(stmt.orelse)
            elif isinstance(stmt, n.While):
                found |= self.writes_in(stmt.body)
        return found


def _dead_subs(project: Project) -> frozenset[SubKey]:
    """The subs of jobs that nothing calls and the controller does not call by name (S210's)."""
    return frozenset((file.path, name) for file in project.files if not file.is_macro
                     for name, sub in file.subs.items()
                     if (file.path, name) not in project.called and not is_entry_point(sub.name))


@rule("V307")
def reserved_number(file: SourceFile, project: Project) -> Iterator[Diagnostic]:
    """A number from #5000 up that the manual reserves or gives no meaning."""
    facts = project.facts(file)
    indices = facts.read_indices | facts.target_indices
    fields = [(index, node.span) for dialog, _scope in facts.dialogs for index, node in dialog_fields(dialog)]
    if not any(i is not None and i >= 5000 and kind_of(i) == RESERVED for i in indices | {i for i, _ in fields}):
        return  # most files
    uses = [(index, param.span) for param, index, _scope in (*facts.reads, *facts.targets) if index is not None]
    for index, span in uses + fields:
        if index >= 5000 and kind_of(index) == RESERVED:
            yield at_line("V307", f"#{index} is reserved: the manual gives it no use a macro may rely on, and "
                          "the controller may change it; use one of #27..#3999 (or #4000..#4999 to keep it)",
                          file, span.line, span.col)


@rule("V308")
def bad_annotation(file: SourceFile, project: Project) -> Iterator[Diagnostic]:
    """A malformed ``;@var`` annotation in this file, or entry of the sidecar beside it."""
    sidecar = sidecar_of(file.path)
    for problem in project.names.problems:
        if problem.path in (file.path, sidecar):
            yield Diagnostic.make("V308", problem.message, problem.path, max(problem.line, 1), max(problem.col, 1))
