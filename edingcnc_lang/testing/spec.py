"""Test files (``test_*.toml``): finding them, reading them, and what one test asks for.

A test file holds an optional ``[defaults]`` table and one ``[[test]]`` table per test
(docs/testing.md).  Everything is checked when the file is read, so a mistake in a test file
(an unknown key, a path that does not exist, a bad answer) is ``FILE:LINE: error: ...`` before
anything runs, never a failing test.  The same checks serve the pytest fixture, which builds a
test from keyword arguments instead of TOML (``from_mapping``).
"""
from __future__ import annotations

import os
import re
from collections.abc import Callable, Iterable, Mapping, Sequence
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

from edingcnc_lang.errors import EXIT_SYNTAX, EcncError, Location
from edingcnc_lang.host import DialogAnswer

from edingcnc_lang.syntax import toml_input

AXES = "xyzabc"
EQUAL_TOLERANCE = 1e-6  # a bare number in expect: equal within this
TEST_GLOB = "test_*.toml"

TEST_KEYS = frozenset({"name", "job", "job_file", "ini", "macro", "user_macro", "vars", "answers", "probe",
                       "simulation", "max_steps", "expect", "forbid"})
EXPECT_KEYS = frozenset({"vars", "position", "messages", "error"})
FORBID_KEYS = frozenset({"rapid_below_z", "outside", "feed_with_spindle_off"})
MERGED_TABLES = ("vars", "expect", "forbid")
MAX_COUNT = 2**63 - 1  # max_steps: far past any run, and a machine integer wherever it is counted


class TestFileError(EcncError):
    """A test file that cannot be read or asks for something impossible: exit 65, nothing runs."""

    __test__ = False  # not a pytest test class, whatever its name
    exit_code = EXIT_SYNTAX
    kind = "syntax"


@dataclass(frozen=True)
class Approx:
    """An expected number: ``value`` within ``tol``."""

    value: float
    tol: float = EQUAL_TOLERANCE

    def matches(self, got: float) -> bool:
        return abs(got - self.value) <= self.tol

    def __str__(self) -> str:
        return shown(self.value) if self.tol == EQUAL_TOLERANCE else f"{shown(self.value)} ± {shown(self.tol)}"


@dataclass(frozen=True)
class Expect:
    vars: Mapping[int, Approx] = field(default_factory=dict)
    position: Mapping[str, Approx] = field(default_factory=dict)  # work position, axis letter (lower case)
    messages: tuple[str, ...] = ()
    error: str | None = None


@dataclass(frozen=True)
class Forbid:
    rapid_below_z: float | None = None
    outside: tuple[float, ...] | None = None  # x0 y0 z0 x1 y1 z1, work coordinates
    feed_with_spindle_off: bool = False


ProbeStep = Mapping[str, float] | None  # where the probe trips (work coordinates, named axes), None: no contact


@dataclass(frozen=True)
class TestCase:
    """One ``[[test]]``, with its defaults applied and its paths made absolute."""

    __test__ = False  # not a pytest test class, whatever its name

    name: str
    file: str            # the test file, as found
    line: int            # the line of its [[test]] header
    job: str | None = None
    job_file: Path | None = None
    ini: Path | None = None
    macro: Path | None = None
    user_macro: Path | None = None
    vars: Mapping[int, float] = field(default_factory=dict)
    answers: tuple[DialogAnswer, ...] = ()
    probe: tuple[ProbeStep, ...] = ()
    simulation: bool = True
    max_steps: int | None = None
    expect: Expect = field(default_factory=Expect)
    forbid: Forbid = field(default_factory=Forbid)

    @property
    def where(self) -> str:
        return f"{self.file}:{self.line}"


def discover(paths: Iterable[str | os.PathLike[str]]) -> list[Path]:
    """The test files: a file given is taken as it is; a folder is searched for ``test_*.toml``
    (hidden folders such as ``.venv`` and ``.git`` left out), in sorted order."""
    found: list[Path] = []
    for given in paths:
        path = Path(given)
        if not path.is_dir():
            found.append(path)
            continue
        below: list[Path] = []
        for folder, dirs, files in os.walk(path):
            dirs[:] = [d for d in dirs if not d.startswith(".") and d != "__pycache__"]
            below.extend(Path(folder, f) for f in files if Path(f).match(TEST_GLOB))
        found.extend(sorted(below))
    return list(dict.fromkeys(found))


def load_file(path: str | os.PathLike[str]) -> list[TestCase]:
    """Every test of one file; a file that does not load raises ``TestFileError``."""
    name = os.fspath(path)
    try:
        text = toml_input.decode(Path(path).read_bytes())
        data = toml_input.parse(text)
    except OSError as err:
        raise TestFileError(f"cannot read the test file: {err.strerror or err}", Location(name)) from None
    except toml_input.TomlProblem as err:
        raise TestFileError(err.message, Location(name, err.line)) from None
    return _Reader(name, text).tests(data)


def from_mapping(keys: Mapping[str, Any], folder: Path, name: str = "<python>") -> TestCase:
    """A test from keyword arguments (the pytest fixture), checked as a ``[[test]]`` table is."""
    return _Reader(name, "", folder).test({"name": "python", **keys}, {}, 0)


class _Reader:
    """Checks the tables of one file; knows where each ``[[test]]`` starts to name lines in errors."""

    def __init__(self, name: str, text: str, folder: Path | None = None) -> None:
        self.name = name
        self.folder = folder if folder is not None else Path(name).resolve().parent
        self.lines = text.splitlines()
        self.headers = [i + 1 for i, line in enumerate(self.lines) if re.match(r"\s*\[\[\s*test\s*\]\]", line)]
        self.defaults_line = next((i + 1 for i, line in enumerate(self.lines)
                                   if re.match(r"\s*\[\s*defaults\s*\]", line)), 0)
        self.scopes: list[tuple[int, int]] = []  # line ranges to search for a key, test first

    def tests(self, data: Mapping[str, Any]) -> list[TestCase]:
        for key in data:
            if key not in ("defaults", "test"):
                raise self.error(f"unknown table or key {key!r}: a test file holds [defaults] and [[test]] tables",
                                 self._find(key, [(1, len(self.lines))]))
        defaults = data.get("defaults", {})
        if not isinstance(defaults, dict):
            raise self.error("[defaults] must be a table", self.defaults_line)
        if "name" in defaults:
            raise self.error("[defaults] cannot give a name: every test names itself", self._in_defaults("name"))
        tests = data.get("test", [])
        if not isinstance(tests, list) or not tests:
            raise self.error("no [[test]] table: write one [[test]] per test", 1)
        cases = [self.test(table, defaults, index) for index, table in enumerate(tests)]
        seen: dict[str, TestCase] = {}
        for case in cases:
            if case.name in seen:
                raise self.error(f"two tests are called {case.name!r} (the first at line {seen[case.name].line})",
                                 case.line)
            seen[case.name] = case
        return cases

    # --- one test ---------------------------------------------------------------------------

    def test(self, table: Any, defaults: Mapping[str, Any], index: int) -> TestCase:
        header = self.headers[index] if index < len(self.headers) else 0
        end = self.headers[index + 1] - 1 if index + 1 < len(self.headers) else len(self.lines)
        self.scopes = [(header, end)]
        if self.defaults_line:
            self.scopes.append((self.defaults_line, len(self.lines)))
        if not isinstance(table, dict):
            raise self.error("[[test]] must be a table", header)
        merged = dict(defaults)
        for key, value in table.items():
            if key in MERGED_TABLES and isinstance(value, dict) and isinstance(merged.get(key), dict):
                value = {**merged[key], **value}
            merged[key] = value
        for key in merged:
            if key not in TEST_KEYS:
                raise self.error(f"unknown key {key!r} (a test takes {_listed(TEST_KEYS)})", self.line_of(key))
        name = merged.get("name")
        if not isinstance(name, str) or not name.strip():
            raise self.error("every [[test]] needs a name = \"...\"", header)
        if ("job" in merged) == ("job_file" in merged):
            raise self.error(f"test {name!r}: give the G-code to run as job = \"...\" or job_file = \"FILE\" "
                             "(one of them)", header)
        return TestCase(
            name=name.strip(), file=self.name, line=header,
            job=self.string(merged, "job") if "job" in merged else None,
            job_file=self.path(merged, "job_file"),
            ini=self.path(merged, "ini"), macro=self.path(merged, "macro"), user_macro=self.path(merged, "user_macro"),
            vars={k: v for k, v in self.params(merged.get("vars", {}), "vars", self.number).items()},
            answers=self.answers(merged.get("answers", [])),
            probe=self.probes(merged.get("probe", [])),
            simulation=self.boolean(merged, "simulation", True),
            max_steps=self.count(merged, "max_steps"),
            expect=self.expect(merged.get("expect", {})),
            forbid=self.forbid(merged.get("forbid", {})),
        )

    def expect(self, table: Any) -> Expect:
        table = self.table(table, "expect", EXPECT_KEYS)
        messages = table.get("messages", [])
        if not isinstance(messages, list) or not all(isinstance(m, str) for m in messages):
            raise self.error("expect.messages must be a list of texts", self.line_of("messages"))
        error = table.get("error")
        if error is not None and not isinstance(error, str):
            raise self.error("expect.error must be a text (part of the error message)", self.line_of("error"))
        return Expect(vars=self.params(table.get("vars", {}), "expect.vars", self.approx),
                      position=self.position(table.get("position", {})), messages=tuple(messages), error=error)

    def forbid(self, table: Any) -> Forbid:
        table = self.table(table, "forbid", FORBID_KEYS)
        below = table.get("rapid_below_z")
        if below is not None:
            below = self.number(below, "forbid.rapid_below_z")
        outside = table.get("outside")
        if outside is not None:
            if not isinstance(outside, list) or len(outside) != 6:
                raise self.error("forbid.outside must be [x0, y0, z0, x1, y1, z1] (the work box)",
                                 self.line_of("outside"))
            outside = tuple(self.number(v, "forbid.outside") for v in outside)
            if any(outside[i] > outside[i + 3] for i in range(3)):
                raise self.error("forbid.outside: each lower corner value must not exceed the upper one",
                                 self.line_of("outside"))
        return Forbid(rapid_below_z=below, outside=outside,
                      feed_with_spindle_off=self.boolean(table, "feed_with_spindle_off", False))

    def position(self, table: Any) -> dict[str, Approx]:
        table = self.table(table, "expect.position", frozenset(AXES))
        return {axis: self.approx(table[axis], f"expect.position.{axis}") for axis in AXES if axis in table}

    def answers(self, items: Any) -> tuple[DialogAnswer, ...]:
        if not isinstance(items, list):
            raise self.error("answers must be a list such as [\"ok\", \"ok:#4100=5\", \"cancel\"]",
                             self.line_of("answers"))
        result = []
        for item in items:
            if not isinstance(item, str):
                raise self.error(f"answers: {item!r} is not a text such as \"ok\"", self.line_of("answers"))
            try:
                result.append(DialogAnswer.parse(item))
            except ValueError as err:
                raise self.error(str(err), self.line_of("answers")) from None
        return tuple(result)

    def probes(self, items: Any) -> tuple[ProbeStep, ...]:
        if not isinstance(items, list):
            raise self.error("probe must be a list such as [{ z = -42.5 }, \"miss\"]", self.line_of("probe"))
        steps: list[ProbeStep] = []
        for item in items:
            if item == "miss":
                steps.append(None)
            elif isinstance(item, dict) and item:
                table = self.table(item, "probe", frozenset(AXES))
                steps.append({axis: self.number(table[axis], f"probe {axis}") for axis in AXES if axis in table})
            else:
                raise self.error(f"probe: {item!r} is neither \"miss\" nor a point such as {{ z = -42.5 }}",
                                 self.line_of("probe"))
        return tuple(steps)

    # --- values ----------------------------------------------------------------------------

    def params(self, table: Any, what: str, value: Callable[[Any, str], Any]) -> dict[int, Any]:
        if not isinstance(table, dict):
            raise self.error(f"{what} must be a table such as {{ \"4520\" = 2 }}", self.line_of(what.split(".")[-1]))
        result = {}
        for key, item in table.items():
            number = toml_input.whole_number(key.strip().lstrip("#"))  # ASCII digits: "²" and "٥٠٠٨" are not
            if number is None or not 1 <= number <= 5999:
                raise self.error(f"{what}: {key!r} is not a parameter number (1..5999)",
                                 self.line_of(key))
            result[number] = value(item, f"{what} #{number}")
        if what == "vars":
            from edingcnc_lang.machine.tables import is_read_only

            for index in result:
                if is_read_only(index):
                    hint = " (use simulation = false for #5380)" if index == 5380 else ""
                    raise self.error(f"vars: #{index} is a read-only system variable{hint}", self.line_of(str(index)))
        return result

    def approx(self, item: Any, what: str) -> Approx:
        if isinstance(item, dict):
            table = self.table(item, what, frozenset({"approx", "tol"}))
            if "approx" not in table:
                raise self.error(f"{what}: write {{ approx = VALUE, tol = TOLERANCE }}", self.line_of("approx"))
            tol = self.number(table.get("tol", EQUAL_TOLERANCE), f"{what} tol")
            if tol < 0:
                raise self.error(f"{what}: tol must not be negative", self.line_of("tol"))
            return Approx(self.number(table["approx"], what), tol)
        return Approx(self.number(item, what))

    def number(self, item: Any, what: str) -> float:
        value = toml_input.number(item)  # a 400-digit integer is no double: an error, not OverflowError
        if value is None:
            raise self.error(f"{what}: {item!r} is not a number",
                             self.line_of(what.split()[0].split(".")[-1]))
        return value

    def string(self, table: Mapping[str, Any], key: str) -> str:
        value = table[key]
        if not isinstance(value, str):
            raise self.error(f"{key} must be a text", self.line_of(key))
        return value

    def path(self, table: Mapping[str, Any], key: str) -> Path | None:
        if key not in table:
            return None
        path = Path(os.path.abspath(self.folder / self.string(table, key)))
        if not path.is_file():
            raise self.error(f"{key} {table[key]!r}: no such file ({path})", self.line_of(key))
        return path

    def boolean(self, table: Mapping[str, Any], key: str, default: bool) -> bool:
        value = table.get(key, default)
        if not isinstance(value, bool):
            raise self.error(f"{key} must be true or false", self.line_of(key))
        return value

    def count(self, table: Mapping[str, Any], key: str) -> int | None:
        value = table.get(key)
        if value is not None and (isinstance(value, bool) or not isinstance(value, int) or not 1 <= value <= MAX_COUNT):
            raise self.error(f"{key} must be a whole number from 1 to {MAX_COUNT}", self.line_of(key))
        return value

    def table(self, item: Any, what: str, known: frozenset[str]) -> dict[str, Any]:
        if not isinstance(item, dict):
            raise self.error(f"{what} must be a table", self.line_of(what.split(".")[-1]))
        for key in item:
            if key not in known:
                raise self.error(f"unknown key {key!r} in {what} (it takes {_listed(known)})", self.line_of(key))
        return item

    # --- where ----------------------------------------------------------------------------

    def line_of(self, key: str) -> int:
        """The line that writes ``key`` in the current test, else in [defaults], else the test's header."""
        return self._find(key, self.scopes) or (self.scopes[0][0] if self.scopes else 0)

    def _in_defaults(self, key: str) -> int:
        return self._find(key, [(self.defaults_line, len(self.lines))]) or self.defaults_line

    def _find(self, key: str, scopes: Sequence[tuple[int, int]]) -> int:
        pattern = re.compile(rf"""(^|[\s.{{,\[])["']?{re.escape(key)}["']?\s*[=.\]]""")
        for start, end in scopes:
            for number in range(max(start, 1), end + 1):
                if pattern.search(self.lines[number - 1]):
                    return number
        return 0

    def error(self, message: str, line: int) -> TestFileError:
        return TestFileError(message, Location(self.name, line))


def _listed(keys: Iterable[str]) -> str:
    return ", ".join(sorted(keys))


def shown(value: float) -> str:
    """A number in a report: plain, to ten significant digits (2, 20.005, -42.5)."""
    return f"{value:.10g}"
