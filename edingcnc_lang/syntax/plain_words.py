"""The one tokenizer for plain lines: ``letter number`` words, comments and nothing else (``G1 X10 Y-2.5 F300``).

CAM output is mostly such lines.  The line parser turns them into nodes without Lark, the check
pass and the run's bulk path read them with the same word grammar, so a plain line is read one way
everywhere.  This module needs nothing but the syntax tree's node types: the machine may use it to
execute plain lines straight from their text without importing the parser.
"""
from __future__ import annotations

import re

from edingcnc_lang.syntax import nodes as n
from edingcnc_lang.syntax.input_limits import INTEGER_DIGITS, MAX_NUMBER_DIGITS

# A number the fast paths take: ASCII digits only (a regex \d would also take Arabic-Indic or
# fullwidth digits), at most INTEGER_DIGITS before the point, so always a finite double, and at most the
# limit after it (a longer one is left to the parser, which reports it).  An optional part is
# written "(?:...|)", not "(?:...)?": the same pattern, which Python's engine runs a third faster.
FAST_NUMBER = rf"(?:[0-9]{{1,{INTEGER_DIGITS}}}(?:\.[0-9]{{0,{MAX_NUMBER_DIGITS}}}|)|\.[0-9]{{1,{MAX_NUMBER_DIGITS}}})(?![0-9])"
# (an N of six digits or more is left to the parser, which refuses it: manual 3.4.1)
FAST_WORD = rf"(?![Nn][ \t]*[+-]?[0-9]{{6}})[A-Za-z][ \t]*[+-]?{FAST_NUMBER}"
# A ( ) comment among the words, which the grammar drops (PAREN_COMMENT), CAM output has them on many
# lines.  Not an operator message ("(msg ...)", MSG_COMMENT, a statement of its own), decided on ASCII
# alone: where a control or non-ASCII character follows the '(' and its blanks, or "msg" without a
# letter, digit or '_' after it, the line is left to the parser.  _speedups.c's skip_comment is the same.
FAST_COMMENT = r"\((?![ \t]*(?:[^\x20-\x7e\t]|[mM][sS][gG](?![A-Za-z0-9_])))[^)\n]*\)"
_GAP = rf"[ \t]*(?:(?:{FAST_COMMENT}[ \t]*)+|)"
PLAIN_LINE = rf"{_GAP}(?:{FAST_WORD}{_GAP})+(?:;.*|)"  # a whole plain line, for patterns of several lines
FAST_LINE = re.compile(rf"^{PLAIN_LINE}$")
# A plain line's words: its numbers are whole FAST_NUMBERs already (the line is a FAST_LINE: no digit or point
# follows one), so a run of digits and points reads the same words, faster (tests/interpreter/test_plain_runs.py).
_FAST_WORDS = re.compile(r"([A-Za-z])[ \t]*([+-]?[0-9.]+)")
_FAST_TOKENS = re.compile(rf"{FAST_COMMENT}|;|([A-Za-z])[ \t]*([+-]?{FAST_NUMBER})")


def word_matches(text: str) -> list[re.Match[str]]:
    """The ``letter number`` words of a plain line, its comments left out."""
    if "(" in text:  # a ';' may stand inside a ( ) comment: read the line token by token
        words = []
        for match in _FAST_TOKENS.finditer(text):
            if match.group(1) is not None:
                words.append(match)
            elif match.group(0) == ";":
                break
        return words
    semicolon = text.find(";")
    return list(_FAST_WORDS.finditer(text, 0, semicolon if semicolon >= 0 else len(text)))


def plain_block(text: str, path: str, line: int) -> n.PlainBlock:
    """The PlainBlock for a line of plain words: one node per line instead of one per word."""
    matches = word_matches(text)
    words = [(m.group(1).upper(), float(m.group(2)), m.start() + 1) for m in matches]
    line_number = None
    if words[0][0] == "N":
        line_number = int(words[0][1])
        del words[0]
    span = n.Span(path, line, matches[0].start() + 1, line, matches[-1].end() + 1)
    return n.PlainBlock(tuple(words), line_number, span)


def plain_words(text: str) -> list[tuple[str, str]]:
    """(letter, number text) pairs of a plain word line, comments excluded."""
    if "(" in text:
        return [(match.group(1), match.group(2)) for match in word_matches(text)]
    semicolon = text.find(";")
    return _FAST_WORDS.findall(text, 0, semicolon if semicolon >= 0 else len(text))


def is_fast_line(text: str) -> bool:
    """True when the fast path handles this line (used by the equivalence tests)."""
    return FAST_LINE.match(text) is not None
