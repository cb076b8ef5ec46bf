"""The variable map in the editor: hover, inlay hints, completion by name, workspace symbols, go to
definition and rename of a name, and the quick fix that names a number with an annotation.

Names, kinds and writers come from the same map as ``ecnc vars`` (``varmap``, ``lint.variable_uses``)
over the file and its macro files, so the editor shows what the command prints.  Lines and
columns are 0-based here, as in the other feature modules.
"""
from __future__ import annotations

import re
from collections.abc import Sequence
from dataclasses import dataclass

from edingcnc_lang.knowledge import parameter_number
from edingcnc_lang.lint.project import Project
from edingcnc_lang.lint.variable_uses import VariableUses
from edingcnc_lang.lsp.actions import Fix, ShownDiagnostic, _insert_line
from edingcnc_lang.lsp.completion import Item
from edingcnc_lang.lsp.lexer import token_at, tokens
from edingcnc_lang.lsp.model import LanguageModel, Place, file_name
from edingcnc_lang.varmap.convention import ANNOTATION, MARKER, NAME, annotation_line, identifier, sidecar_of
from edingcnc_lang.varmap.kinds import kind_of
from edingcnc_lang.varmap.names import ANNOTATION as EXPLICIT, MANUAL, Candidate, Names, source_of
from edingcnc_lang.varmap.model import Use

MAX_WRITERS_SHOWN = 8
_TYPED_NAME = re.compile(r"(?<![A-Za-z0-9_#])([A-Za-z_][A-Za-z0-9_]+)$")  # two letters at least
_UNIT = re.compile(r"\s*;?\s*@unit\b", re.IGNORECASE)
_NUMBER_IN_V305 = re.compile(r"^#(\d+) is '(.*?)' here")


@dataclass(frozen=True)
class Hint:
    """A name shown after a ``#n`` (0-based line, the column after the number)."""

    line: int
    col: int
    label: str


class _Map:
    """The names and uses of a file with its macro files."""

    def __init__(self, project: Project) -> None:
        self.project = project
        self.names: Names = project.names
        self._uses: VariableUses | None = None

    @property
    def uses(self) -> VariableUses:
        if self._uses is None:
            self._uses = VariableUses(self.project)
        return self._uses


def _map(model: LanguageModel, path: str) -> _Map | None:
    found = model.project(path)
    return _Map(found[1]) if found else None


def _number_at(model: LanguageModel, path: str, line: int, col: int) -> int | None:
    """The variable number of a ``#n`` under the cursor."""
    file = model.source(path)
    token = token_at(file.line(line + 1), col) if file else None
    return parameter_number(token.text[1:]) if token is not None and token.kind == "param" else None


def _where(use: Use | Candidate) -> str:
    return f"{file_name(use.path)}:{use.line}"


def hover_text(model: LanguageModel, path: str, line: int, col: int) -> str | None:
    """``#1552 thread_major_diameter``: the name, where it comes from, the kind and the writers."""
    number = _number_at(model, path, line, col)
    varmap = _map(model, path) if number is not None else None
    if number is None or varmap is None:
        return None
    best = varmap.names.best(number)
    if best is None or best.source == MANUAL:  # the knowledge base's hover says what the manual says
        head = f"**#{number}** (no name: add `{annotation_line(number, 'name')}`)" if best is None else None
    else:
        head = f"**#{number} {best.name}**: from the {best.source} at {_where(best)}"
        if best.description:
            head += f"\n\n{best.description}"
    writers = varmap.uses.writers.get(number, [])
    parts = [head] if head else []
    parts.append(f"Kind: {kind_of(number)}")
    if writers:
        shown = ", ".join(f"{w.sub or 'top level'} ({_where(w)})" for w in writers[:MAX_WRITERS_SHOWN])
        more = f" and {len(writers) - MAX_WRITERS_SHOWN} more" if len(writers) > MAX_WRITERS_SHOWN else ""
        parts.append(f"Written by: {shown}{more}")
    return "\n\n".join(parts)


def inlay_hints(model: LanguageModel, path: str, first: int, last: int) -> list[Hint]:
    """The name beside every ``#n`` of lines ``first``..``last`` that has one (comments left alone)."""
    file = model.source(path)
    varmap = _map(model, path) if file else None
    if file is None or varmap is None:
        return []
    found: list[Hint] = []
    names: dict[int, str | None] = {}
    for line in range(max(first, 0), min(last, len(file.lines) - 1) + 1):
        text = file.lines[line]
        if "#" not in text:
            continue
        for token in tokens(text):
            if token.kind != "param":
                continue
            number = parameter_number(token.text[1:])
            if number is None:  # digits no parameter has (a 5,000-digit #...)
                continue
            if number not in names:
                names[number] = varmap.names.name(number)
            name = names[number]
            if name:
                found.append(Hint(line, token.end, name))
    return found


def complete_names(model: LanguageModel, path: str, line: int, col: int) -> list[Item]:
    """Typing part of a name (``thread_``) offers the numbers it names (``#1552``)."""
    file = model.source(path)
    text = file.line(line + 1) if file else ""
    token = token_at(text, col)
    if token is not None and token.kind in ("comment", "string") and token.start < col:
        return []
    match = _TYPED_NAME.search(text[:col])
    varmap = _map(model, path) if match else None
    if match is None or varmap is None:
        return []
    typed = match.group(1).lower()
    items = []
    for number, found in sorted(varmap.names.candidates.items()):
        best = found[0]
        key = identifier(best.name)
        if typed in key:
            items.append(Item(key, "variable", f"#{number} ({best.source}, {_where(best)})",
                              best.description, match.start(1), insert=f"#{number}"))
    return items


def definition(model: LanguageModel, path: str, line: int, col: int) -> Place | None:
    """``#n``: its annotation (or sidecar entry) if it has one, else its first writer."""
    number = _number_at(model, path, line, col)
    varmap = _map(model, path) if number is not None else None
    if number is None or varmap is None:
        return None
    explicit = next((c for c in varmap.names.candidates.get(number, ()) if c.source == EXPLICIT), None)
    if explicit is not None:
        return Place(explicit.path, explicit.line - 1, explicit.col - 1, explicit.col - 1 + len(explicit.name))
    writers = varmap.uses.writers.get(number)
    if not writers:
        return None
    first = min(writers, key=lambda w: (w.path != path, w.path, w.line, w.col))
    return Place(first.path, first.line - 1, first.col - 1, first.col - 1 + len(str(number)) + 1)


def workspace_symbols(model: LanguageModel, query: str) -> list[tuple[str, Place]]:
    """Variables whose name contains ``query`` (ignoring case), in the workspace's files."""
    files = model.workspace()
    names = Names((source_of(f.path, f.lines, f.body) for f in files), (sidecar_of(f.path) for f in files))
    wanted = query.lower()
    found = []
    for number, candidates in sorted(names.candidates.items()):
        best = candidates[0]
        if wanted in best.name.lower() or wanted in identifier(best.name):
            found.append((f"#{number} {best.name}", Place(best.path, best.line - 1, best.col - 1, best.col - 1)))
    return found


def annotation_name_at(model: LanguageModel, path: str, line: int, col: int) -> Place | None:
    """The name of the ``;@var`` annotation under the cursor: what rename edits."""
    file = model.source(path)
    text = file.line(line + 1) if file else ""
    match = ANNOTATION.match(text) if MARKER.match(text) else None
    if match is None or not match.start("name") <= col <= match.end("name"):
        return None
    return Place(path, line, match.start("name"), match.end("name"))


def check_new_name(name: str) -> str | None:
    """Why ``name`` cannot name a variable, or None."""
    if NAME.match(name):
        return None
    return f"{name!r} is not a name: use letters, digits and _ (not starting with a digit)"


def annotation_fixes(model: LanguageModel, path: str, lines: Sequence[str], line: int, col: int,
                     finding: ShownDiagnostic | None = None) -> list[Fix]:
    """``;@var #n name`` added near the top of the file, for the ``#n`` at the cursor (or a V305
    finding's number), named after what the map infers."""
    number = _number_from(finding) if finding is not None else _number_at(model, path, line, col)
    varmap = _map(model, path) if number is not None else None
    if number is None or varmap is None or kind_of(number) in ("invalid",):
        return []
    candidates = varmap.names.candidates.get(number, [])
    if any(c.source == EXPLICIT for c in candidates):
        return []
    name = identifier(candidates[0].name) if candidates else f"var_{number}"
    text = annotation_line(number, name)
    return [Fix(f"Name #{number}: add {text}", (_insert_line(lines, _annotation_line(lines), text),),
                preferred=finding is not None)]


def _number_from(finding: ShownDiagnostic) -> int | None:
    match = _NUMBER_IN_V305.match(finding.message) if finding.code == "V305" else None
    return int(match.group(1)) if match else None


def _annotation_line(lines: Sequence[str]) -> int:
    """Where a new annotation goes: after the ``@unit`` line and the annotations below it."""
    at = 1 if lines and _UNIT.match(lines[0]) else 0
    while at < len(lines) and MARKER.match(lines[at]):
        at += 1
    return at

