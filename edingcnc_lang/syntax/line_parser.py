"""Parsing one source line: the fast paths, the Lark grammar, and errors in the user's terms.

Plain word lines (most CAM output) take a regular-expression fast path that builds exactly the
Block the grammar would; common macro lines take ``fastparse.py``; the rest go to the grammar.
Lark trees never leave this module and ``tree_builder.py``, which turns them into AST nodes.
``parser.py`` streams lines through ``parse_line`` and assembles the multi-line blocks.
"""
from __future__ import annotations

import os
import re
from functools import lru_cache
from pathlib import Path
from typing import TYPE_CHECKING

from edingcnc_lang.syntax import nodes as n
from edingcnc_lang.syntax.fastparse import (
    COMPILED_READER,
    GIVE_UP,
    compiled_block,
    compiled_statement,
    paren_before_comment,
    parse_fast,
)
from edingcnc_lang.syntax.input_limits import (
    LINE_NUMBER_DIGITS,
    MAX_GCODE_LINE,
    MAX_LINE_LENGTH,
    SHORTEST_PROBLEM,
    line_problem,
)
from edingcnc_lang.syntax.blocks import LineResult
from edingcnc_lang.syntax.plain_words import FAST_LINE, word_matches
from edingcnc_lang.syntax.prose import PROSE_MESSAGE, looks_like_prose
from edingcnc_lang.syntax.tree_builder import (
    Builder as _Builder,
    LineError as _LineError,
    make_block as _make_block,
)

if TYPE_CHECKING:  # lark is imported when a line first needs the grammar (start-up time)
    from lark import Lark
    from lark.exceptions import UnexpectedInput


GRAMMAR = Path(__file__).resolve().parent / "grammar" / "macro.lark"

_EMPTY_LINE = re.compile(r"^\s*(?:\((?!\s*msg\b)[^)\n]*\)\s*)*(?:;.*)?$", re.IGNORECASE)


@lru_cache(maxsize=1)
def _lark() -> Lark:
    """The line parser, built once per process from the packaged grammar files."""
    import hashlib
    import tempfile

    from lark import Lark

    # Lark's own cache file is named by macro.lark alone and trusts the imported gcode.lark of
    # whichever checkout wrote it first; named by both grammars, each version gets its own.
    digest = hashlib.sha256(b"".join(path.read_bytes() for path in sorted(GRAMMAR.parent.glob("*.lark"))))
    cache = os.path.join(tempfile.gettempdir(), f".ecnc_lark_{digest.hexdigest()[:32]}.tmp")
    return Lark.open(str(GRAMMAR), parser="lalr", lexer="contextual",
                     propagate_positions=True, maybe_placeholders=False, cache=cache)



def _fast_block(text: str, path: str, line: int) -> n.Block:
    """The Block for a line of plain ``letter number`` words, without Lark."""
    words = []
    for match in word_matches(text):
        col, end = match.start() + 1, match.end() + 1
        span = n.Span(path, line, col, line, end)
        num_span = n.Span(path, line, match.start(2) + 1, line, end)
        words.append(n.Word(match.group(1).upper(), n.Number(float(match.group(2)), num_span), span))
    first, last = words[0].span, words[-1].span
    return _make_block(words, [], None, False, n.Span(path, line, first.col, line, last.end_col))





# --------------------------------------------------------------------------- errors

# What is skipped whole while scanning delimiters: (closing character, code, message if it is missing).
_ENCLOSED = {
    '"': ('"', "E104", "unterminated string: the '\"' at column {col} has no closing '\"'"),
    "(": (")", "E103", "unclosed '(' comment opened at column {col}"),
}


def _scan_delimiters(text: str) -> _LineError | None:
    """Explain unbalanced quotes, comments and brackets, which Lark reports poorly."""
    opens: list[int] = []
    i = 0
    while i < len(text):
        ch = text[i]
        if ch in _ENCLOSED:
            end, code, message = _ENCLOSED[ch]
            close = text.find(end, i + 1)
            if close < 0:
                return _LineError(code, message.format(col=i + 1), i + 1)
            inner = text.find("(", i + 1, close) if ch == "(" else -1
            if inner >= 0:  # manual 3.4.4: comments do not nest (Vectric's "( T1: End Mill (6 mm) )")
                return _LineError("E116", f"nested comment: the '(' at column {inner + 1} is inside the comment "
                                  f"opened at column {i + 1}; comments do not nest: leave out the inner parentheses", inner + 1)
            i = close + 1
            continue
        if ch == ";":
            break
        if ch == "[":
            opens.append(i + 1)
        elif ch == "]":
            if not opens:
                return _LineError("E102", f"unbalanced ']' at column {i + 1} has no matching '['", i + 1)
            opens.pop()
        i += 1
    if opens:
        return _LineError("E101", f"unclosed '[' opened at column {opens[-1]}", opens[-1])
    return None


_WORD_BEFORE = re.compile(r"([A-Za-z])[ \t]*[^\sA-Za-z;(]*$")
CONDITION_LINE = re.compile(r"^\s*(if|while)(?![a-z0-9_])", re.IGNORECASE)


def _explain(text: str, exc: UnexpectedInput) -> _LineError:
    """Turn a Lark error on ``text`` into a message in the user's terms."""
    from lark.exceptions import UnexpectedCharacters, UnexpectedEOF, UnexpectedToken

    col = getattr(exc, "column", 0) or len(text) + 1
    condition = CONDITION_LINE.match(text)
    if condition:
        delim = _scan_delimiters(text)
        if delim and delim.code != "E102":
            return delim
        keyword = condition.group(1).capitalize()
        return _LineError("E106", f"{keyword} condition must be one bracketed expression, e.g. "
                          f"{keyword} [[#1 > 0] and [#2 < 5]] (EdingCNC error G1171)", col)
    delim = _scan_delimiters(text)
    if delim:
        return delim
    ch = text[col - 1] if 0 < col <= len(text) else ""
    if isinstance(exc, UnexpectedEOF) or (isinstance(exc, UnexpectedToken) and exc.token.type == "$END"):
        word = _WORD_BEFORE.search(text.rstrip())
        if word and not text.rstrip()[word.end(1):].strip():
            return _LineError("E108", f"word '{word.group(1).upper()}' needs a value", word.start(1) + 1)
        return _LineError("E100", "line ends too early", col)
    if ch in "+-*/" or text[col - 1:col + 2].lower() in ("mod", "and", "xor") or text[col - 1:col + 1].lower() == "or":
        word = _WORD_BEFORE.search(text[:col - 1])
        if word:
            start = word.start(1)
            end = len(text)
            for stop in (" ", "\t", ";", "("):
                pos = text.find(stop, col)
                if pos >= 0:
                    end = min(end, pos)
            fragment = text[start:end]
            return _LineError("E105", f"expression needs brackets: {fragment} (write "
                              f"{fragment[0]}[{fragment[1:].strip()}])", start + 1)
    if looks_like_prose(text):
        return _LineError("F603", PROSE_MESSAGE, len(text) - len(text.lstrip()) + 1)
    glued = col > 1 and text[col - 2].isalpha()
    if ch.isalpha() and glued:  # 'arameter': the P was taken as a word letter
        start = len(text[:col - 1].rstrip(_LETTERS))
        name = _NAME_AT.match(text, start).group()  # type: ignore[union-attr]
        return _LineError("E100", f"'{name}' is neither a word (a letter and a value, like X10) nor a keyword; "
                          "a note must be a comment: start it with ';'", start + 1)
    lone = _LONE_LETTER.search(text[:col - 1].rstrip())
    if ch.isalpha() and lone:  # G1 X30 Y O30: the Y has no value
        return _LineError("E108", f"word '{lone.group(1).upper()}' needs a value", lone.start(1) + 1)
    if ch == "\r":  # a file with lone CRs (classic Mac) reads as one long line
        return _LineError("E100", "carriage return without a line feed: lines end in LF or CRLF", col)
    if isinstance(exc, UnexpectedCharacters):
        return _LineError("E100", f"unexpected character '{ch}'", col)
    token = str(exc.token) if isinstance(exc, UnexpectedToken) else ch
    return _LineError("E100", f"unexpected '{token}'", col)


_LETTERS = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz"
_LONE_LETTER = re.compile(r"(?:^|[\s\d.\]])([A-Za-z])$")  # a word letter with nothing after it
_NAME_AT = re.compile(r"[A-Za-z0-9_]+")


# --------------------------------------------------------------------------- one line

# The line number's digits, where the first word of a block is N (after a '/', blanks and ( ) comments)
_LINE_NUMBER = re.compile(r"[ \t]*(?:/[ \t]*)?(?:\([^)\n]*\)[ \t]*)*[Nn][ \t]*[+-]?((?:[ \t]*[0-9])+)")


def parse_line(text: str, path: str = "<string>", line: int = 1) -> LineResult:
    """Parse one source line; raises _LineError on a syntax error or a line past the limits."""
    result = _parse_line(text, path, line)
    if isinstance(result, (n.Block, n.PlainBlock)):
        if len(text) > MAX_GCODE_LINE:
            raise _LineError("E114", f"a G-code line holds at most {MAX_GCODE_LINE} characters, this one "
                             f"{len(text)} (manual 3.4; rs274 refuses it too): split it", MAX_GCODE_LINE + 1)
        if result.line_number is not None:
            digits = _LINE_NUMBER.match(text)
            if digits is not None and sum(c.isdigit() for c in digits.group(1)) > LINE_NUMBER_DIGITS:
                raise _LineError("E115", f"a line number has at most {LINE_NUMBER_DIGITS} digits (manual 3.4.1: "
                                 "N0..N99999; rs274 refuses more too)", digits.start(1) + 1)
    return result


def _parse_line(text: str, path: str, line: int) -> LineResult:
    if len(text) > MAX_LINE_LENGTH:
        raise _LineError("E110", f"line is longer than {MAX_LINE_LENGTH} characters, the limit for one line "
                         "(EdingCNC itself reads at most 1055): split it", MAX_LINE_LENGTH + 1)
    if COMPILED_READER and len(text) <= SHORTEST_PROBLEM and ("(" not in text or not paren_before_comment(text)):
        # A line this short passes every limit, and without '(' (but in its ';' comment) it holds no
        # ( ) comment: the compiled reader may answer first.  It builds what the paths below build (the Block of a
        # plain line as _fast_block, the rest as parse_fast), and gives up on anything else.
        found = compiled_statement(text, path, line)
        if found is not GIVE_UP:
            return found  # type: ignore[return-value]
    if FAST_LINE.match(text):  # the compiled reader builds the same Block faster, when it is built
        return compiled_block(text, path, line) or _fast_block(text, path, line)
    if _EMPTY_LINE.match(text):  # blank or comments only
        return None
    problem = line_problem(text)
    if problem is not None:
        raise _LineError(*problem)
    result = parse_fast(text, path, line)
    return parse_line_grammar(text, path, line) if result is GIVE_UP else result  # type: ignore[return-value]


def parse_line_grammar(text: str, path: str = "<string>", line: int = 1) -> LineResult:
    """Parse one line with the Lark grammar only (the reference for the fast path)."""
    from lark.exceptions import UnexpectedInput

    try:
        tree = _lark().parse(text)
    except UnexpectedInput as exc:
        raise _explain(text, exc) from None
    return _Builder(path, line).statement(tree)
