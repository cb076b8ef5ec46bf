"""Every lint case file yields exactly the findings marked in it, and nothing else.

A case marks its expected findings on the offending line with ``; expect: CODE``
(or ``CODE, CODE``), or on the line before with ``; expect-next-line: CODE`` when
a comment on the line itself would change what is found.  Files in ``clean/``,
the packaged stdlib and the examples must produce no findings at all.
"""
from __future__ import annotations

import re
from collections import Counter
from pathlib import Path

import pytest

from edingcnc_lang.codes import CODES
from edingcnc_lang.lint import LintOptions, lint_paths

HERE = Path(__file__).parent
ROOT = HERE.parent.parent
CASES = sorted(p for p in (HERE / "cases").rglob("*") if p.is_file())
_EXPECT = re.compile(r";\s*expect(-next-line)?:\s*([A-Z]\d{3}(?:\s*,\s*[A-Z]\d{3})*)")


def expected(path: Path) -> Counter[tuple[int, str]]:
    found: Counter[tuple[int, str]] = Counter()
    for number, line in enumerate(path.read_text(encoding="utf-8").splitlines(), 1):
        match = _EXPECT.search(line)
        if match:
            target = number + 1 if match.group(1) else number
            found.update((target, code.strip()) for code in match.group(2).split(","))
    return found


_INI = re.compile(r"^;\s*lint-ini:\s*(\S+)")  # first line: lint with that cnc.ini of the cases (--ini)


def actual(path: Path) -> Counter[tuple[int, str]]:
    first = path.read_text(encoding="utf-8").split("\n", 1)[0] if path.suffix == ".nc" else ""
    ini = _INI.match(first)
    options = LintOptions(ini=path.parent / ini.group(1)) if ini else LintOptions()
    return Counter((d.line, d.code) for d in lint_paths([path], options) if not ini or d.path == str(path))


@pytest.mark.parametrize("case", CASES, ids=[str(p.relative_to(HERE / "cases")) for p in CASES])
def test_case_reports_exactly_what_it_marks(case: Path) -> None:
    want, got = expected(case), actual(case)
    assert got == want, (f"missing: {sorted((want - got).elements())}, "
                         f"unexpected: {sorted((got - want).elements())}")


def test_every_code_has_a_case_with_the_fault() -> None:
    marked = {code for case in CASES for _, code in expected(case)}
    assert sorted(set(CODES) - marked) == []


def test_clean_cases_exist() -> None:
    assert len([p for p in CASES if "clean" in p.parts]) >= 3
    assert all(not expected(p) for p in CASES if "clean" in p.parts)


def test_stdlib_lints_clean() -> None:
    assert lint_paths([ROOT / "stdlib"]) == []


EXAMPLES = sorted((ROOT / "examples").rglob("*.nc"))


@pytest.mark.parametrize("example", EXAMPLES, ids=[str(p.relative_to(ROOT)) for p in EXAMPLES])
def test_example_lints_clean(example: Path) -> None:
    assert [f"{d.line}: {d.code}" for d in lint_paths([example])] == []


def test_findings_are_sorted_by_file_and_line() -> None:
    found = lint_paths([HERE / "cases"])
    keys = [(d.path, d.line, d.col) for d in found]
    assert keys == sorted(keys)
    assert len({d.path for d in found}) > 10


def test_every_code_is_documented() -> None:
    doc = (ROOT / "docs" / "lint.md").read_text(encoding="utf-8")
    assert [c for c in CODES if f"| {c} |" not in doc] == []
