"""Run errors checked by their exact text, as golden data (in the manner of starlark-go's tests).

Each file in ``data/`` holds cases separated by lines of ``---``.  A case is a job; the line after
the one that must fail is a comment ``;### LINE:COL: message`` with the error's place (in the case's
own lines) and its whole message.  A case may start with ``;% ini=FILE`` (a cnc.ini in ``data/``);
every case runs with the empty macro file, as ``job.nc``.  ``--regen-goldens`` rewrites the
``;###`` lines from what the interpreter says now (review the diff before committing).
"""
from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path

import pytest

from edingcnc_lang import EcncError, RunOptions, run_string

DATA = Path(__file__).parent / "data"
EMPTY_MACRO = Path(__file__).parent.parent / "interpreter" / "data" / "empty_macro.cnc"
EXPECT = ";### "
OPTION = ";% "


@dataclass
class Case:
    file: Path
    first: int   # the case's first line in its file (1-based)
    lines: list[str]

    @property
    def options(self) -> dict[str, str]:
        return dict(line[len(OPTION):].strip().split("=", 1) for line in self.lines if line.startswith(OPTION))

    @property
    def expected(self) -> str | None:
        found = [f"{i}:{line[len(EXPECT):]}" for i, line in enumerate(self.lines) if line.startswith(EXPECT)]
        assert len(found) <= 1, f"{self.file.name}:{self.first}: one expected error per case"
        return found[0] if found else None  # the ;### line's index is the failing line's number

    def run(self, logs: Path) -> str:
        """``LINE:COL: message`` of the error the case stops with, or ``no error``; the job's own
        files go to ``logs``, written ``LOGS`` in the message."""
        ini = self.options.get("ini")
        options = RunOptions(macro=EMPTY_MACRO, ini=DATA / ini if ini else None, log_dir=logs)
        try:
            run_string(self._numbered(), options, path="job.nc")
        except EcncError as err:
            where = err.location
            assert where is not None and where.path == "job.nc", f"{err.format()} is not located in the job"
            return f"{where.line}:{where.col}: {err.message}".replace(str(logs), "LOGS")
        return "no error"

    def _numbered(self) -> str:
        """The job with the ;### line kept as an empty comment, so line numbers match the file's case."""
        return "".join(";\n" if line.startswith(EXPECT) else line + "\n" for line in self.lines)


def cases(path: Path) -> list[Case]:
    found: list[Case] = []
    current: list[str] = []
    first = 1
    for number, line in enumerate(path.read_text(encoding="utf-8").splitlines(), 1):
        if line == "---":
            if any(not part.startswith(";") for part in current):
                found.append(Case(path, first, current))
            current, first = [], number + 1
        else:
            current.append(line)
    if any(not part.startswith(";") for part in current):
        found.append(Case(path, first, current))
    return found


ALL = [case for path in sorted(DATA.glob("*.nc")) for case in cases(path)]


def test_every_case_expects_an_error(request: pytest.FixtureRequest) -> None:
    if request.config.getoption("--regen-goldens"):
        pytest.skip("the cases are being rewritten")
    assert ALL and all(case.expected is not None for case in ALL)


@pytest.mark.parametrize("case", ALL, ids=[f"{c.file.stem}:{c.first}" for c in ALL])
def test_error_text(case: Case, request: pytest.FixtureRequest, tmp_path: Path) -> None:
    actual = case.run(tmp_path)
    if request.config.getoption("--regen-goldens"):
        regenerate(case, actual)
        return
    assert actual == case.expected, f"{case.file.name}:{case.first}"


def regenerate(case: Case, actual: str) -> None:
    """Rewrite the case's ;### line after the line the error names (the file is read again: an
    earlier case's rewrite may have moved this one)."""
    ordinal = [c.first for c in ALL if c.file == case.file].index(case.first)  # the n-th case of its file
    case = cases(case.file)[ordinal]
    lines = case.file.read_text(encoding="utf-8").splitlines()
    start = case.first - 1
    body = [line for line in case.lines if not line.startswith(EXPECT)]
    if actual != "no error":
        where = int(actual.split(":", 1)[0])
        body.insert(where, EXPECT + actual.split(":", 1)[1])
    lines[start:start + len(case.lines)] = body
    case.file.write_text("\n".join(lines) + "\n", encoding="utf-8")
