"""V rules about what numbers mean: one number named for two things, writes that never run,
numbers the manual reserves, malformed ``;@var`` annotations.

The names come from ``varmap`` (annotations, sidecars, dlgmsg labels, comments), who writes and
reads each number from ``variable_uses``; a write to a read-only number is V301 (``rules_vars``).
"""
from __future__ import annotations

import re
from collections.abc import Iterator
from weakref import WeakKeyDictionary

from edingcnc_lang.diagnostics import Diagnostic
from edingcnc_lang.machine.tables import VOLATILE_PARAMS
from edingcnc_lang.lint.model import SourceFile
from edingcnc_lang.lint.names import is_entry_point
from edingcnc_lang.lint.project import Project, SubKey
from edingcnc_lang.lint.registry import at_line, rule
from edingcnc_lang.lint.variable_uses import VariableUses, key_of
from edingcnc_lang.lint.walk import dialog_fields
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
    """A volatile variable read here whose every write is in a job's sub that nothing calls."""
    facts = project.facts(file)
    candidates = {i for i in facts.read_indices if i is not None and i in VOLATILE_PARAMS}
    dead = _dead_subs(project) if candidates else frozenset()
    if not dead:  # most files: every sub may run
        return
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
