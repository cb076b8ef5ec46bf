"""The variable map: one row per number a set of files uses, with its name, kind, writers and readers."""
from __future__ import annotations

from collections.abc import Iterable, Sequence

from edingcnc_lang.records import record
from edingcnc_lang.diagnostics import Diagnostic
from edingcnc_lang.varmap.convention import Problem
from edingcnc_lang.varmap.kinds import kind_of
from edingcnc_lang.varmap.names import Candidate, Names


@record(frozen=True)
class Use:
    """A write or a read of a variable: where, and in which sub (None: the file's top level)."""

    path: str
    line: int
    col: int
    sub: str | None


@record(frozen=True)
class Variable:
    """One row of the map."""

    number: int
    name: str | None
    source: str | None  # names.SOURCES, or None when nothing names it
    kind: str  # kinds.KINDS
    writers: tuple[Use, ...]
    readers: tuple[Use, ...]
    named_at: Candidate | None = None  # where the shown name is written (None: the manual, or no name)
    description: str = ""

    def touched_by(self, sub: str) -> bool:
        """True if ``sub`` (any case) writes or reads it."""
        key = sub.lower()
        return any(use.sub is not None and use.sub.lower() == key for use in (*self.writers, *self.readers))


@record(frozen=True)
class VarMap:
    """Every variable the files use, in number order, with the findings about them."""

    variables: tuple[Variable, ...]
    findings: tuple[Diagnostic, ...] = ()
    problems: tuple[Problem, ...] = ()  # malformed annotations and sidecars

    def unnamed(self) -> VarMap:
        return VarMap(tuple(v for v in self.variables if v.name is None), self.findings, self.problems)

    def of_sub(self, sub: str) -> VarMap:
        return VarMap(tuple(v for v in self.variables if v.touched_by(sub)), self.findings, self.problems)


def assemble(names: Names, writers: dict[int, list[Use]], readers: dict[int, list[Use]],
             findings: Iterable[Diagnostic] = ()) -> VarMap:
    """The map of every number written, read or named explicitly."""
    numbers = sorted(set(writers) | set(readers) | {n for n, found in names.candidates.items()
                                                       if any(c.source == "annotation" for c in found)})
    rows = []
    for number in numbers:
        best = names.best(number)
        rows.append(Variable(number, best.name if best else None, best.source if best else None, kind_of(number),
                             _sorted(writers.get(number, ())), _sorted(readers.get(number, ())),
                             best if best is not None and best.path else None, best.description if best else ""))
    return VarMap(tuple(rows), tuple(findings), tuple(names.problems))


def _sorted(uses: Sequence[Use] | Iterable[Use]) -> tuple[Use, ...]:
    return tuple(sorted(set(uses), key=lambda u: (u.path, u.line, u.col)))
