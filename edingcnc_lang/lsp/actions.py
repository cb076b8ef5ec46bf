"""Quick fixes for lint findings with an obvious repair, and ``; noqa`` for any finding.

Each fixer reads the finding (code, line, column, message) and the source line and returns
text edits; the table ``FIXERS`` maps codes to fixers, so a new fix is one function and one
row.  Lines and columns here are 0-based.
"""
from __future__ import annotations

import re
from collections.abc import Callable, Sequence
from dataclasses import dataclass

from edingcnc_lang.lint.driver import NOQA
from edingcnc_lang.syntax.line_parser import parse_line
from edingcnc_lang.lsp.formatting import split_comment

_UNCLOSED = re.compile(r"(?:Sub \S+|If|While) \(line (\d+)\) has no (EndSub|EndIf|EndWhile)( before)?")
_BRACKETS = re.compile(r"write (\S+)\)$")
_FRAGMENT = re.compile(r"brackets: (\S+) \(")
_EXTRA = re.compile(r"^(\d+) extra")
_INDENT = re.compile(r"[ \t]*")
_CONDITION = re.compile(r"\s*(if|while)\s+(.*?)(?:\s+then)?\s*$", re.IGNORECASE)


@dataclass(frozen=True)
class Edit:
    """Replace columns ``start``..``end`` of ``line`` (0-based) with ``text``."""

    line: int
    start: int
    end: int
    text: str


@dataclass(frozen=True)
class ShownDiagnostic:
    """What a code action knows about one diagnostic the editor shows."""

    code: str
    line: int
    col: int
    message: str


@dataclass(frozen=True)
class Fix:
    title: str
    edits: tuple[Edit, ...]
    preferred: bool = True


Fixer = Callable[[ShownDiagnostic, Sequence[str]], list[Fix]]


def _insert_line(lines: Sequence[str], before: int, text: str) -> Edit:
    """A new line ``text`` before 0-based line ``before`` (at the end of the file when past it)."""
    if before < len(lines):
        return Edit(before, 0, 0, text + "\n")
    last = len(lines) - 1
    if last < 0:
        return Edit(0, 0, 0, text + "\n")
    return Edit(last, len(lines[last]), len(lines[last]), "\n" + text)


def _close_block(finding: ShownDiagnostic, lines: Sequence[str]) -> list[Fix]:
    match = _UNCLOSED.match(finding.message)
    if not match:
        return []
    opener, closer, before_this = int(match.group(1)) - 1, match.group(2), match.group(3)
    indent = _INDENT.match(lines[opener]).group() if opener < len(lines) else ""  # type: ignore[union-attr]
    where = finding.line if before_this else len(lines)
    return [Fix(f"Add the missing {closer}", (_insert_line(lines, where, indent + closer),))]


def _end_sub_first(finding: ShownDiagnostic, lines: Sequence[str]) -> list[Fix]:
    return [Fix("Add EndSub before this Sub", (_insert_line(lines, finding.line, "EndSub"),))]


def _drop_hash(finding: ShownDiagnostic, lines: Sequence[str]) -> list[Fix]:
    text = lines[finding.line] if finding.line < len(lines) else ""
    if finding.col < len(text) and text[finding.col] == "#":
        edit = Edit(finding.line, finding.col, finding.col + 1, "")
        return [Fix("Remove the '#' (dlgmsg fields are bare numbers)", (edit,))]
    return []


def _add_brackets(finding: ShownDiagnostic, lines: Sequence[str]) -> list[Fix]:
    fragment, better = _FRAGMENT.search(finding.message), _BRACKETS.search(finding.message)
    text = lines[finding.line] if finding.line < len(lines) else ""
    if not fragment or not better or not text.startswith(fragment.group(1), finding.col):
        return []
    end = finding.col + len(fragment.group(1))
    return [Fix(f"Write {better.group(1)}", (Edit(finding.line, finding.col, end, better.group(1)),))]


def _drop_extra_brackets(finding: ShownDiagnostic, lines: Sequence[str]) -> list[Fix]:
    count = _EXTRA.match(finding.message)
    text = lines[finding.line] if finding.line < len(lines) else ""
    if not count:
        return []
    extra = re.search(r"\]{%d}(?=\s*(?:then\s*)?(?:[;(].*)?$)" % int(count.group(1)), text, re.IGNORECASE)
    if not extra:
        return []
    return [Fix("Remove the extra ']'", (Edit(finding.line, extra.start(), extra.end(), ""),))]


def _bracket_condition(finding: ShownDiagnostic, lines: Sequence[str]) -> list[Fix]:
    text = lines[finding.line] if finding.line < len(lines) else ""
    code, _comment, _paren = split_comment(text)
    match = _CONDITION.match(code)
    if not match:
        return []
    fixed = f"[{match.group(2)}]"
    try:
        parse_line(code[:match.start(2)] + fixed + code[match.end(2):])
    except Exception:  # noqa: BLE001 - brackets alone do not repair this line: offer nothing
        return []
    return [Fix(f"Write {match.group(1)} {fixed}", (Edit(finding.line, match.start(2), match.end(2), fixed),))]


def _unit_line(finding: ShownDiagnostic, lines: Sequence[str]) -> list[Fix]:
    return [Fix(f"Add ';@unit {unit}' as the first line", (Edit(0, 0, 0, f";@unit {unit}\n"),), unit == "mm")
            for unit in ("mm", "inch")]


def _comment_out(finding: ShownDiagnostic, lines: Sequence[str]) -> list[Fix]:
    text = lines[finding.line] if finding.line < len(lines) else ""
    start = len(_INDENT.match(text).group())  # type: ignore[union-attr]
    return [Fix("Make the line a comment", (Edit(finding.line, start, start, "; "),))]


FIXERS: dict[str, Fixer] = {
    "S204": _close_block,
    "S205": _end_sub_first,
    "D403": _drop_hash,
    "E105": _add_brackets,
    "E106": _bracket_condition,
    "V304": _drop_extra_brackets,
    "F600": _unit_line,
    "F603": _comment_out,
}


def line_end(text: str | None) -> str:
    """The line end a document uses (its first one), so that a fix adding a line writes the same:
    the fixers write ``\n``, and a CRLF file edited in a client that does not convert (Neovim, Kate)
    would otherwise get mixed line ends."""
    first = (text or "").find("\n")
    return "\r\n" if first > 0 and text[first - 1] == "\r" else "\n"  # type: ignore[index]


def fixes(finding: ShownDiagnostic, lines: Sequence[str]) -> list[Fix]:
    """The repairs for one finding, then the ``; noqa`` that silences it on its line."""
    fixer = FIXERS.get(finding.code)
    return (fixer(finding, lines) if fixer else []) + _noqa(finding, lines)


def _noqa(finding: ShownDiagnostic, lines: Sequence[str]) -> list[Fix]:
    if finding.line >= len(lines) or not finding.code:
        return []
    text = lines[finding.line]
    listed = NOQA.search(text)  # the comment exactly as the linter reads it
    if listed and listed.group(1) is None:  # a bare ; noqa already silences every finding
        return []
    if listed:
        edit = Edit(finding.line, listed.end(1), listed.end(1), f",{finding.code}")
    else:
        edit = Edit(finding.line, len(text), len(text), f"{' ' if text else ''}; noqa: {finding.code}")
    return [Fix(f"Silence {finding.code} on this line (; noqa)", (edit,), False)]
