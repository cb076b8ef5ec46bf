"""Hover: what a G/M code, parameter, command, function or sub under the cursor means.

Codes, parameters, commands and functions come from the knowledge table (the same text
as ``ecnc`` help); a sub shows the comment lines that start it; a ``#n`` that the file
and its macro files only ever set to one constant shows that value.
"""
from __future__ import annotations

import re

from edingcnc_lang import knowledge
from edingcnc_lang.syntax import nodes as n
from edingcnc_lang.lint.evaluate import evaluate
from edingcnc_lang.lint.model import SourceFile
from edingcnc_lang.machine.tables import m_code_sub
from edingcnc_lang.lint.walk import dialog_fields, literal_index
from edingcnc_lang.syntax.printer import format_number
from edingcnc_lang.machine.tables import ARG_PARAMS, is_read_only
from edingcnc_lang.lsp.lexer import Token, code_number, token_at, tokens
from edingcnc_lang.lsp.model import LanguageModel, file_name

_COMMENT = re.compile(r"\s*(?:;(?P<semi>.*)|\((?P<paren>[^)]*)\)\s*)$")
_AFTER_NAME = re.compile(r"\s*(?:/\s*)?sub\s+[A-Za-z0-9_]+\s*(?P<rest>.*)$", re.IGNORECASE)
MAX_DOC_LINES = 12
_NUMBERS_ARE_VARIABLES = frozenset({"dlgmsg", "gettoolinfo", "getjobdistance"})


def hover_text(model: LanguageModel, path: str, line: int, col: int) -> str | None:
    """Markdown for the token at 0-based ``line``/``col`` of ``path``, or None."""
    file = model.source(path)
    if file is None:
        return None
    token = token_at(file.line(line + 1), col)
    if token is None:
        return None
    if token.kind == "code":
        return _code(model, path, token)
    if token.kind == "param":
        return _param(model, path, token.text[1:])
    if token.kind == "number" and token.text.isdigit() and _names_variables(file.line(line + 1)):
        return _param(model, path, token.text)
    if token.kind in ("function", "keyword", "command"):
        entry = knowledge.word(token.text)
        return entry.markdown() if entry else None
    if token.kind == "sub":
        found = model.resolve(path, token.text)
        return sub_markdown(*found) if found else None
    return None


def _names_variables(text: str) -> bool:
    """A command whose bare numbers are parameter numbers: ``dlgmsg "Width" 27``, ``GetToolInfo next 40``."""
    head = tokens(text)
    return bool(head) and head[0].kind == "command" and head[0].text.lower() in _NUMBERS_ARE_VARIABLES


def _code(model: LanguageModel, path: str, token: Token) -> str | None:
    letter, number = code_number(token)
    entry = knowledge.code(letter, number)
    parts = [entry.markdown()] if entry else []
    key = knowledge.code_key_of(number)
    if letter == "M" and key is not None:
        name = m_code_sub(key)
        found = model.resolve(path, name) if name else None
        if found:
            parts.append(("Runs " if entry is None else "Redefined by ") + sub_markdown(*found))
    return "\n\n---\n\n".join(parts) or None


def _param(model: LanguageModel, path: str, digits: str) -> str | None:
    number = knowledge.parameter_number(digits)
    entry = knowledge.variable(number) if number is not None else None
    shown = digits if len(digits) <= knowledge.MAX_LOOKUP_DIGITS else digits[:knowledge.MAX_LOOKUP_DIGITS] + "…"
    parts = [entry.markdown()] if entry else [f"**#{shown}**: not a valid parameter (1..5999)"]
    if number is None:
        return parts[0]
    value = constant_value(model, path, number)
    if value is not None:
        parts.append(f"Always set to `{format_number(value)}` in this file and its macro files.")
    return "\n\n".join(parts)


def constant_value(model: LanguageModel, path: str, number: int) -> float | None:
    """The one constant every assignment of ``#number`` gives, in the file and its macro files.

    None when any assignment is not a constant, when two differ, when something else may write
    it (a dialog field, an assignment through a computed index), and for the M-code arguments
    and the variables the machine sets.
    """
    if number in ARG_PARAMS or is_read_only(number):
        return None
    found = model.project(path)
    if found is None:
        return None
    file, project = found
    values: set[float] = set()
    for source in project.files:
        for stmt, _scope in project.walked(source):
            if isinstance(stmt, n.Dialog) and any(index == number for index, _ in dialog_fields(stmt)):
                return None
            for assign in stmt.assigns if isinstance(stmt, n.Block) else ():
                index = literal_index(assign.target)
                if index is None:
                    return None
                if index == number:
                    value = evaluate(assign.value)
                    if value is None:
                        return None
                    values.add(value)
    return values.pop() if len(values) == 1 else None


def sub_markdown(file: SourceFile, sub: n.Sub) -> str:
    """``Sub name`` with where it is and the comment lines that describe it."""
    head = f"**Sub {sub.name}** ({file_name(file.path)}, line {sub.span.line})"
    doc = sub_comments(file, sub)
    return head + ("\n\n" + verbatim(doc) if doc else "")


def verbatim(lines: list[str]) -> str:
    """The author's comment lines as a plain-text block: markdown would run them into one paragraph
    and an editor would hide ``<rpm>`` in ``; M101 P<rpm>`` as an HTML tag."""
    longest = max((len(run) for text in lines for run in re.findall(r"`+", text)), default=0)
    fence = "`" * max(3, longest + 1)
    return f"{fence}text\n" + "\n".join(lines) + f"\n{fence}"


def sub_comments(file: SourceFile, sub: n.Sub) -> list[str]:
    """The comment after the name and the comment lines right below it, else those right above."""
    found: list[str] = []
    rest = _AFTER_NAME.match(file.line(sub.span.line))
    if rest:
        _comment_into(found, rest.group("rest"))
    line = sub.span.line + 1
    while len(found) < MAX_DOC_LINES and _comment_into(found, file.line(line)):
        line += 1
    if found:
        return found
    line = sub.span.line - 1
    while line > 0 and len(found) < MAX_DOC_LINES and _comment_into(found, file.line(line)):
        line -= 1
    return found[::-1]


def _comment_into(found: list[str], text: str) -> bool:
    match = _COMMENT.match(text) if text.strip() else None
    if match is None:
        return False
    body = (match.group("semi") if match.group("semi") is not None else match.group("paren")).strip(";*-=# \t")
    if body.lower().startswith("@unit"):
        return False
    if body:  # a line of only dashes or stars is decoration
        found.append(body)
    return True
