"""What kind of variable a number is, and the name the manual gives it.

The ranges are the machine's (``machine/tables.py``: read-only, reserved, arguments, volatile)
and the knowledge base's (``knowledge``: the manual's rows and the persistent numbers); this
module only names the kinds, so the map, the linter and the editor agree on them.
"""
from __future__ import annotations

from functools import lru_cache

from edingcnc_lang.knowledge import PERSISTENT, variable
from edingcnc_lang.machine.tables import (
    ARG_PARAMS, FIRST_PARAM, LAST_PARAM, RESERVED_PARAMS, TOOL_LENGTH, VOLATILE_PARAMS, is_read_only,
)

ARGUMENT = "argument"  # #1..#26: the letters of an M-code sub's calling line
USER = "user"  # #27..#3999: volatile
PERSISTENT_USER = "persistent"  # #4000..#4999: kept in cnc.ini
SCRATCH = "macro scratch"  # #5016..#5050: free for the tool change and stock macros
READ_ONLY = "system read-only"
WRITABLE = "system writable"
TOOL_TABLE = "tool table"
RESERVED = "reserved"  # #5000.. numbers the manual reserves or gives no meaning
INVALID = "invalid"  # outside 1..5999
KINDS = (ARGUMENT, USER, PERSISTENT_USER, SCRATCH, READ_ONLY, WRITABLE, TOOL_TABLE, RESERVED, INVALID)

SCRATCH_PARAMS = range(5016, 5051)


@lru_cache(maxsize=None)  # a few thousand numbers at most; asked for again and again
def kind_of(number: int) -> str:
    """The kind of ``#number`` (one of ``KINDS``)."""
    if not FIRST_PARAM <= number <= LAST_PARAM:
        return INVALID
    if number in ARG_PARAMS:
        return ARGUMENT
    if number in VOLATILE_PARAMS:
        return USER
    if number < 5000 and any(number in r for r in PERSISTENT):
        return PERSISTENT_USER
    if any(number in r for r in RESERVED_PARAMS) or variable(number) is None:
        return RESERVED
    if number in SCRATCH_PARAMS:
        return SCRATCH
    if is_read_only(number):
        return READ_ONLY
    if number > TOOL_LENGTH:
        return TOOL_TABLE
    return WRITABLE


def manual_name(number: int) -> str | None:
    """The manual's name of a system variable or an M-code argument; None for user and scratch
    numbers (the manual names only their range) and for reserved ones."""
    if kind_of(number) in (USER, PERSISTENT_USER, SCRATCH, RESERVED, INVALID):
        return None
    entry = variable(number)
    return entry.title if entry is not None else None
