"""Formatting with the canonical printer, line by line, and only when it is safe.

Each statement is printed as ``ecnc``'s printer writes it (``G01 x.5`` -> ``G1 X0.5``),
indented by its block depth; comments stay where they are (a line with a ``( )``
comment inside its code keeps its code as written, only re-indented).  The result is
parsed again: unless it gives the same tree, nothing is changed.  In a file with syntax
errors (``partial``, the editor's case: a file is formatted while it is being written) the
lines with an error are kept exactly as written and the others are formatted, each only if it
parses to the same statement as before and the file's errors stay the same.
"""
from __future__ import annotations

from collections.abc import Sequence
from dataclasses import replace

from edingcnc_lang.syntax import nodes as n
from edingcnc_lang.syntax.line_parser import parse_line
from edingcnc_lang.syntax.blocks import Close, Open
from edingcnc_lang.syntax.parser import StatementReader
from edingcnc_lang.syntax.printer import INDENT, bracketed, stmt_lines
from edingcnc_lang.syntax.source import iter_text_lines

def split_comment(line: str) -> tuple[str, str, bool]:
    """(code, ``;`` comment, whether the code holds a ``( )`` comment), strings respected."""
    in_string = False
    paren = False
    for i, ch in enumerate(line):
        if ch == '"':
            in_string = not in_string
        elif not in_string and ch == ";":
            return line[:i], line[i:], paren
        elif not in_string and ch == "(":
            paren = True
    return line, "", paren


Parsed = tuple[tuple[n.Stmt, ...], "str | None"]  # a file's statements and its @unit


def _parsed(lines: Sequence[str]) -> Parsed | None:
    reader = StatementReader(lines, "<format>")
    body = tuple(reader)
    return None if reader.diagnostics else (body, reader.unit)


def _errors(lines: Sequence[str]) -> list[tuple[int, str]]:
    """(1-based line, code) of each syntax error of the lines."""
    reader = StatementReader(lines, "<format>")
    for _ in reader:
        pass
    return sorted((d.line, d.code) for d in reader.diagnostics)


def _same_statement(old: str, new: str) -> bool:
    """Whether two texts of one line parse alike (a line that fails alone is never changed)."""
    try:
        first, second = parse_line(old), parse_line(new)
    except Exception:  # noqa: BLE001 - see _printed
        return False
    if isinstance(first, (Open, Close)) and isinstance(second, (Open, Close)):  # markers keep their span
        return replace(first, span=n.NO_SPAN) == replace(second, span=n.NO_SPAN)
    return first == second


def _printed(code: str) -> tuple[str | None, int]:
    """The canonical text of one line's code (None: keep it as written) and how it moves the depth."""
    try:
        result = parse_line(code)
    except Exception:  # noqa: BLE001 - the whole file parsed, so a line that fails alone is left as is
        return None, 0
    if isinstance(result, Open):
        if result.kind == "Sub":
            return f"Sub {result.name}", 1
        if result.extra or result.cond is None:  # printing would drop the stray ']' (a V304 to fix first)
            return None, 1
        return f"{result.kind} {bracketed(result.cond)}", 1
    if isinstance(result, Close):
        return result.kind, -1
    if result is None:
        return None, 0
    return stmt_lines(result, 0)[0], 0


def format_lines(lines: Sequence[str], indent: str = INDENT, parsed: Parsed | None = None,
                 partial: bool = False) -> list[str] | None:
    """The formatted lines (one for each line), or None when formatting is not safe.

    ``indent`` is one level (the editor's tab size); a comment after code stays in its column
    when the code still ends before it.  ``parsed`` is the lines' tree when the caller has it
    (parsed without errors).  With ``partial`` a file with syntax errors is formatted too, its
    lines with an error left as written (see the module's docstring).
    """
    before = parsed if parsed is not None else _parsed(lines)
    errors = _errors(lines) if before is None and partial else []
    if before is None and not errors:
        return None
    broken = {line - 1 for line, _code in errors}
    out: list[str] = []
    depth = 0
    for number, line in enumerate(lines):
        code, comment, paren = split_comment(line)
        stripped = code.strip()
        if number in broken or (number == 0 and (before is None or before[1] is not None)
                                and (not stripped or stripped.startswith("@"))):
            out.append(line if number in broken else line.rstrip())
            continue
        printed, step = _printed(stripped) if stripped else (None, 0)
        if printed and before is None and not _same_statement(stripped, printed):
            printed = None
        text = printed if printed and not paren else stripped
        is_else = printed == "Else"
        if step < 0:
            depth = max(depth - 1, 0)
        new = indent * depth + text if text else ""
        if comment:
            new = (new + " " * max(len(code) - len(new), 1) if new else indent * depth) + comment.rstrip()
        out.append(new)
        if step > 0 or is_else:
            depth += 1
    if before is None:
        return out if _errors(out) == errors else None
    after = _parsed(out)
    return out if after == before else None


def format_text(text: str, indent: str = INDENT) -> str | None:
    """The whole text formatted (LF line ends), or None when formatting is not safe."""
    formatted = format_lines(list(iter_text_lines(text)), indent)
    return None if formatted is None else "\n".join(formatted) + "\n"
