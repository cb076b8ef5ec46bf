"""Recognising a line of ordinary words (a note someone forgot to comment out).

Shared by the parser, which says so instead of "unexpected 'arameter'", and the linter (F603).
"""
from __future__ import annotations

import re

# Three or more plain words (letters, maybe ending in punctuation) that do not start with a keyword.
_PROSE = re.compile(r"^\s*[A-Za-z][A-Za-z']*[,.:!?]?(?:\s+[A-Za-z][A-Za-z'-]*[,.:!?]?){2,}\s*$")
_KEYWORDS = frozenset({"sub", "endsub", "gosub", "if", "else", "endif", "while", "endwhile", "msg",
                       "warnmsg", "errmsg", "logmsg", "dlgmsg", "logfile", "home", "hometandem",
                       "kin", "exec", "modbus"})
PROSE_MESSAGE = ("this line is plain text, not a statement: make it a comment by starting it with ';' "
                 "(or wrap it in '( )')")


def looks_like_prose(text: str) -> bool:
    """A line of ordinary words, such as a note someone forgot to comment out."""
    code = text.split(";", 1)[0]
    return bool(_PROSE.match(code)) and code.split()[0].lower() not in _KEYWORDS
