"""What is under the cursor on one line: a G/M code, a parameter, a command, a sub name, a comment.

Hover and completion work on the line as typed, also while it does not parse yet, so
this is a small scanner rather than the parser.  Columns are 0-based string indices.
"""
from __future__ import annotations

import re
from dataclasses import dataclass

from edingcnc_lang import knowledge
from edingcnc_lang.knowledge.command_texts import FUNCTIONS

_FUNCTION_NAMES = "|".join(sorted((re.escape(row[0]) for row in FUNCTIONS), key=len, reverse=True))
_HEAD = re.compile(r"\s*(?:/\s*)?([A-Za-z_][A-Za-z0-9_]*)")
SUB_NAME = re.compile(r"\s*(?:/\s*)?(?:sub|gosub)\s+([A-Za-z0-9_]+)", re.IGNORECASE)
_PIECES = re.compile(rf"""
    (?P<string>"[^"]*"?)
  | (?P<comment>;.*|\([^)]*\)?)
  | (?P<param>\#[0-9]+)
  | (?P<function>(?:{_FUNCTION_NAMES})(?=\s*\[))
  | (?P<code>[GM]\s*[0-9]+(?:\.[0-9]+)?)
  | (?P<number>[0-9]+(?:\.[0-9]*)?|\.[0-9]+)
  | (?P<other>[A-Za-z_]{{2,}}[A-Za-z0-9_]*|[A-Za-z][-+]?[\d.]*|.)
""", re.IGNORECASE | re.VERBOSE)


@dataclass(frozen=True)
class Token:
    """A piece of a line: its kind, its text and where it is (end exclusive)."""

    # "code" | "param" | "number" | "function" | "keyword" | "command" | "sub" | "string" | "comment" | "other"
    kind: str
    text: str
    start: int
    end: int

    def contains(self, col: int) -> bool:
        return self.start <= col < self.end


def tokens(line: str) -> list[Token]:
    """The line cut into tokens; the first word is a keyword or command when the table knows it."""
    found: list[Token] = []
    pos = 0
    head = _HEAD.match(line)
    entry = knowledge.word(head.group(1)) if head else None
    if head and entry and entry.kind in ("keyword", "command"):
        found.append(Token(entry.kind, head.group(1), head.start(1), head.end(1)))
        pos = head.end(1)
        name = SUB_NAME.match(line)
        if name:
            found.append(Token("sub", name.group(1), name.start(1), name.end(1)))
            pos = name.end(1)
    for match in _PIECES.finditer(line, pos):
        kind = match.lastgroup or "other"
        if kind == "other" and match.group().isspace():
            continue
        found.append(Token(kind, match.group(), match.start(), match.end()))
    return found


def token_at(line: str, col: int) -> Token | None:
    """The token the cursor is in (or right after, as when typing)."""
    pieces = tokens(line)
    for token in pieces:
        if token.contains(col):
            return token
    for token in pieces:
        if token.end == col:
            return token
    return None


def code_number(token: Token) -> tuple[str, float]:
    """``G 38.2`` -> ("G", 38.2) for a code token."""
    return token.text[0].upper(), float(token.text[1:].strip())
