"""The explicit names an author gives: ``;@var`` annotations and the ``variables.toml`` sidecar.

The controller ignores both (a comment line, a file it never opens); both win over every name
the map infers.  An annotation is a comment line of its own::

    ;@var #1552 thread_major_diameter "diameter A of the thread"

(the description in double quotes is optional).  The sidecar sits beside the macro files and
names numbers in a table each, or with a bare string::

    [1552]
    name = "thread_major_diameter"
    description = "diameter A of the thread"

    [1554]
    name = "thread_pitch"

A name is an identifier (letters, digits, ``_``; not starting with a digit), so the editor can
complete it and rename it.
"""
from __future__ import annotations

import os
import re
import sys
from collections.abc import Iterator, Sequence

from edingcnc_lang.records import record
from edingcnc_lang.machine.tables import FIRST_PARAM, LAST_PARAM

SIDECAR = "variables.toml"
NAME = re.compile(r"[A-Za-z_][A-Za-z0-9_]*\Z")
# ``;@var`` anywhere a comment line starts (after any ``;``s and blanks): the marker of an annotation
MARKER = re.compile(r"^\s*;+\s*@var\b", re.IGNORECASE)
ANNOTATION = re.compile(r'^\s*;+\s*@var\s+#(?P<number>\d+)\s+(?P<name>\S+)(?:\s+"(?P<text>[^"]*)")?\s*$',
                        re.IGNORECASE)
_TOML_WHERE = re.compile(r"\(at line (\d+), column (\d+)\)")


@record(frozen=True)
class Explicit:
    """A name given on purpose: where it is written (the annotation's line, or the sidecar's)."""

    number: int
    name: str
    description: str
    path: str
    line: int
    col: int  # of the name, so rename edits it in place


@record(frozen=True)
class Problem:
    """A malformed annotation or sidecar: FILE:LINE:COL and what is wrong."""

    path: str
    line: int
    col: int
    message: str


def annotation_line(number: int, name: str, description: str = "") -> str:
    """The comment line that names ``#number`` (the editor's quick fix inserts it)."""
    text = f' "{description}"' if description else ""
    return f";@var #{number} {name}{text}"


def identifier(text: str) -> str:
    """A label or comment as a name the editor can complete: ``"diameter A [mm]"`` -> ``diameter_a_mm``."""
    found = re.sub(r"[^0-9a-z]+", "_", text.lower()).strip("_")
    return f"v_{found}" if found[:1].isdigit() else found or "unnamed"


def _checked(number: int, name: str) -> str | None:
    """What is wrong with an explicit name, if anything."""
    if not FIRST_PARAM <= number <= LAST_PARAM:
        return f"#{number} does not exist: parameters are numbered {FIRST_PARAM}..{LAST_PARAM}"
    if not NAME.match(name):
        return f"{name!r} is not a name: use letters, digits and _ (not starting with a digit)"
    return None


def annotations_in(path: str, lines: Sequence[str]) -> Iterator[Explicit | Problem]:
    """The ``;@var`` annotations of a file's lines, and the malformed ones as problems."""
    for lineno, text in enumerate(lines, 1):
        if "@" not in text or not MARKER.match(text):
            continue
        match = ANNOTATION.match(text)
        if match is None:
            yield Problem(path, lineno, text.index("@") + 1,
                          'an annotation is ;@var #NUMBER name "optional description"')
            continue
        number, name, col = int(match["number"]), match["name"], match.start("name") + 1
        wrong = _checked(number, name)
        if wrong:
            yield Problem(path, lineno, col, wrong)
        else:
            yield Explicit(number, name, match["text"] or "", path, lineno, col)


def sidecar_of(source: str) -> str:
    """The sidecar that names the variables of ``source``: ``variables.toml`` in its folder."""
    return os.path.join(os.path.dirname(os.path.abspath(source)), SIDECAR)


def sidecar(path: str) -> list[Explicit | Problem]:
    """The names of a ``variables.toml`` (nothing if there is none)."""
    try:
        with open(path, encoding="utf-8") as handle:
            text = handle.read()
    except FileNotFoundError:
        return []
    except (OSError, UnicodeDecodeError) as err:
        return [Problem(path, 0, 0, f"cannot read: {getattr(err, 'strerror', None) or err}")]
    if sys.version_info >= (3, 11):  # imported here: only a folder with a sidecar pays for it
        import tomllib
    else:  # Python 3.10: the same parser, as a package (a dependency there)
        import tomli as tomllib

    try:
        data = tomllib.loads(text)
    except tomllib.TOMLDecodeError as err:
        where = _TOML_WHERE.search(str(err))
        line, col = (int(where[1]), int(where[2])) if where else (0, 0)
        return [Problem(path, line, col, _TOML_WHERE.sub("", str(err)).strip())]
    lines = text.splitlines()
    return [_entry(path, lines, key, value) for key, value in data.items()]


def _entry(path: str, lines: list[str], key: str, value: object) -> Explicit | Problem:
    """One table (or string) of the sidecar, placed on the line that names its number."""
    line, col = _line_of(lines, key)
    if isinstance(value, str):
        name, description = value, ""
    elif isinstance(value, dict) and isinstance(value.get("name"), str):
        name, description = value["name"], str(value.get("description", ""))
    else:
        return Problem(path, line, col, f"[{key}] needs a name: name = \"...\"")
    if not key.isdigit():
        return Problem(path, line, col, f"{key!r} is not a variable number")
    if isinstance(value, dict):
        line, col = _name_line(lines, line)
    wrong = _checked(int(key), name)
    return Problem(path, line, col, wrong) if wrong else Explicit(int(key), name, description, path, line, col)


def _line_of(lines: list[str], key: str) -> tuple[int, int]:
    """The line (and column) where the sidecar names ``key``: its ``[key]`` header or ``key =``."""
    pattern = re.compile(rf'^\s*(\[\s*"?{re.escape(key)}"?\s*\]|"?{re.escape(key)}"?\s*=)')
    for lineno, text in enumerate(lines, 1):
        if pattern.match(text):
            found = text.find('"', text.index("=") + 1) if "=" in text and "[" not in text else -1
            return lineno, found + 2 if found >= 0 else len(text) - len(text.lstrip()) + 1
    return 1, 1


def _name_line(lines: list[str], start: int) -> tuple[int, int]:
    """The ``name = "..."`` line of a table that starts on line ``start``: where rename edits."""
    for lineno in range(start, len(lines) + 1):
        text = lines[lineno - 1]
        if lineno > start and text.lstrip().startswith("["):
            break
        match = re.match(r'^\s*name\s*=\s*"', text)
        if match:
            return lineno, match.end() + 1
    return start, 1
