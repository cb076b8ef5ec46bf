"""The language knowledge base: G/M codes, parameters, commands and functions, as data.

Hover, completion and ``ecnc`` help texts all read these records; the rows live in
``gm.py``, ``variables.py`` and ``command_texts.py``, the modal groups and read-only ranges
in ``tables.py``.  ``describe("G38.2")``, ``describe("#5067")``, ``describe("dlgmsg")``
give the explanation as plain text.
"""
from __future__ import annotations

import math
import re
from collections.abc import Iterator, Mapping
from dataclasses import dataclass
from functools import cache

from edingcnc_lang.canon import AXES
from edingcnc_lang.machine.tables import G_GROUPS, LETTER_ARGS, M_GROUPS, code_key, code_name, is_read_only
from edingcnc_lang.knowledge import command_texts as commands, gm, variables

# Numbers cnc.ini [VARIABLES] keeps from run to run besides #4000..#4999 (dialect reference, section 10).
PERSISTENT = (range(4000, 5000), range(5008, 5009), range(5013, 5015), range(5161, 5167), range(5181, 5187),
              range(5211, 5217), range(5220, 5387), range(5390, 5394))


@dataclass(frozen=True)
class Entry:
    """One thing the language knows: its name as written, a title, its words or arguments, details."""

    kind: str  # "G" | "M" | "variable" | "keyword" | "command" | "function"
    name: str
    title: str
    words: str = ""
    detail: str = ""
    facts: tuple[str, ...] = ()  # short extra lines: the modal group, read-only, persistent

    @property
    def usage(self) -> str:
        """How it is written: ``dlgmsg "title" ...``, ``SQRT[x]``; the words a code takes."""
        if self.kind in ("G", "M"):
            return self.words
        return f"{self.name}{self.words}" if self.kind == "function" else f"{self.name} {self.words}".strip()

    def text(self) -> str:
        """Plain text for a terminal: ``G38.2: straight probe`` and the details below."""
        lines = [f"{self.name}: {self.title}"]
        if self.words:
            lines.append(("Words: " if self.kind in ("G", "M") else "Usage: ") + self.usage)
        lines += list(self.facts)
        if self.detail:
            lines.append(self.detail)
        return "\n".join(lines)

    def markdown(self) -> str:
        """The same for an editor's hover: the name in bold, then the lines."""
        lines = [f"**{self.name}**: {self.title}"]
        if self.words:
            lines.append(("Words: " if self.kind in ("G", "M") else "Usage: ") + f"`{self.usage}`")
        lines += list(self.facts)
        if self.detail:
            lines.append(self.detail)
        return "\n\n".join(lines)


def _group_fact(groups: Mapping[int, str], key: int) -> tuple[str, ...]:
    group = groups.get(key)
    return (f"Modal group: {group.replace('_', ' ')}",) if group else ()


@cache
def _codes() -> dict[tuple[str, int], Entry]:
    found: dict[tuple[str, int], Entry] = {}
    for letter, rows, groups in (("G", gm.G_ROWS, G_GROUPS), ("M", gm.M_ROWS, M_GROUPS)):
        for number, title, words, detail in rows:
            key = code_key(number)
            found[letter, key] = Entry(letter, code_name(letter, key), title, words, detail, _group_fact(groups, key))
    return found


# A code or parameter number with more digits than this names nothing the tables know (they stop
# at #5999 and G/M 999), so it is never converted: "G" and 310 nines is infinity as a float, and
# int() refuses 5,000 digits.  Help, hover, completion and rename all look numbers up through here.
MAX_LOOKUP_DIGITS = 9


def code_key_of(number: float) -> int | None:
    """``code_key`` of a G or M number, None for one no code has (infinite, NaN, or more than
    MAX_LOOKUP_DIGITS digits)."""
    return code_key(number) if math.isfinite(number) and abs(number) < 10**MAX_LOOKUP_DIGITS else None


def parameter_number(digits: str) -> int | None:
    """The number of ``#digits`` (``5067``), None for digits no parameter has: more than
    MAX_LOOKUP_DIGITS of them (leading zeros aside) or any that is not an ASCII digit."""
    if not (digits.isascii() and digits.isdigit()):
        return None
    significant = digits.lstrip("0")
    return int(significant or "0") if len(significant) <= MAX_LOOKUP_DIGITS else None


def code(letter: str, number: float) -> Entry | None:
    """The G or M code ``letter number`` (G38.2, M6); M codes without a row of their own are None."""
    key = code_key_of(number)
    return _codes().get((letter.upper(), key)) if key is not None else None


def codes() -> Iterator[Entry]:
    """Every documented G and M code, G first, in numeric order."""
    return iter(_codes().values())


def variable(number: int) -> Entry | None:
    """Parameter ``#number`` with its name; None outside 1..5999 or for numbers with no meaning."""
    for first, last, name, detail in variables.ROWS:
        if first <= number <= last:
            offset = number - first
            title = name.format(axis=AXES[offset % len(AXES)], n=offset + 1,
                                letter=LETTER_ARGS[offset % len(LETTER_ARGS)])
            facts = []
            if is_read_only(number):
                facts.append("Read-only: the machine sets it.")
            elif any(number in r for r in PERSISTENT):
                facts.append("Persistent: kept in cnc.ini [VARIABLES].")
            return Entry("variable", f"#{number}", title, "", detail, tuple(facts))
    return None


def named_variables() -> Iterator[Entry]:
    """Every system variable (#5000 and up) with its name, for completion lists."""
    for first, last, _name, _detail in variables.ROWS:
        if first >= 5000:
            for number in range(first, last + 1):
                yield variable(number)  # type: ignore[misc]


@cache
def _words() -> dict[str, Entry]:
    found: dict[str, Entry] = {}
    tables = (("keyword", commands.KEYWORDS), ("command", commands.COMMANDS), ("function", commands.FUNCTIONS))
    for kind, rows in tables:
        for name, title, args, detail in rows:
            found[name.lower()] = Entry(kind, name, title, args, detail)
    return found


def word(name: str) -> Entry | None:
    """A keyword, command or function by name, ignoring case (``dlgmsg``, ``GoSub``, ``sqrt``)."""
    return _words().get(name.lower())


def words(kind: str) -> Iterator[Entry]:
    """Every entry of one kind: ``keyword``, ``command`` or ``function``."""
    return (entry for entry in _words().values() if entry.kind == kind)


_CODE = re.compile(r"([GM])\s*([0-9]+(?:\.[0-9])?)", re.IGNORECASE)
_VARIABLE = re.compile(r"#?\s*([0-9]+)")


def lookup(topic: str) -> Entry | None:
    """The entry a user means by ``topic``: ``G38.2``, ``m6``, ``#5067``, ``5067``, ``dlgmsg``, ``SQRT``."""
    text = topic.strip()
    match = _CODE.fullmatch(text)
    if match:
        return code(match.group(1), float(match.group(2)))
    match = _VARIABLE.fullmatch(text)
    if match:
        number = parameter_number(match.group(1))
        return variable(number) if number is not None else None
    return word(text)


def describe(topic: str) -> str | None:
    """Plain-text explanation of a code, variable, command or function; None if unknown."""
    entry = lookup(topic)
    return entry.text() if entry else None


__all__ = ["Entry", "code", "code_key_of", "codes", "describe", "lookup", "named_variables", "parameter_number",
           "variable", "word", "words"]
