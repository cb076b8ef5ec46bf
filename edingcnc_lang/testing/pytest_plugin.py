"""The pytest side of ``ecnc test`` (registered through the ``pytest11`` entry point).

* ``test_*.toml`` files are collected: one pytest item per ``[[test]]``, failing with the same text
  ``ecnc test`` prints; a file that does not load is a collection error ``FILE:LINE: error: ...``.
  Only files named ``test_*.toml`` that hold a ``[[test]]`` table are collected, so other TOML files
  (pyproject.toml, a project's ``test_settings.toml`` data) are left alone; ``-p no:ecnc`` turns
  the plugin off.
* The ``ecnc`` fixture runs a macro from a Python test::

      def test_probe(ecnc):
          result = ecnc.run(job="GoSub user_1\\nM30\\n", simulation=False, probe=[{"z": -3}],
                            vars={4000: 20, 4001: 100, 4002: 5})
          assert result.position["z"] == 10

  Its keywords are the keys of a ``[[test]]`` table; paths are relative to the test module's folder.

Nothing heavy is imported until a test runs, so pytest starts as fast with the plugin as without.
"""
from __future__ import annotations

import os
import re
from collections.abc import Iterator, Mapping
from pathlib import Path
from typing import TYPE_CHECKING, Any

import pytest

from edingcnc_lang.testing.coverage import display_path
from edingcnc_lang.testing.spec import TEST_GLOB

if TYPE_CHECKING:
    from edingcnc_lang.testing.execute import Outcome
    from edingcnc_lang.testing.session import TestResult
    from edingcnc_lang.testing.spec import TestCase


def pytest_collect_file(parent: pytest.Collector, file_path: Path) -> pytest.Collector | None:
    """A ``test_*.toml`` file that holds a ``[[test]]`` table: another project's data file that
    happens to be called ``test_settings.toml`` is left alone."""
    if file_path.match(TEST_GLOB) and _has_tests(file_path):
        return MacroTestFile.from_parent(parent, path=file_path)
    return None


def _has_tests(path: Path) -> bool:
    try:
        text = path.read_bytes().decode("utf-8", errors="replace")
    except OSError:
        return True  # let the collector report what cannot be read
    return re.search(r"^\s*\[\[\s*test\s*\]\]", text, re.MULTILINE) is not None


class MacroTestFile(pytest.File):
    """A ``test_*.toml`` file: its tests, read and checked before any runs."""

    def collect(self) -> Iterator[pytest.Item]:
        from edingcnc_lang.testing.spec import TestFileError, load_file

        try:
            cases = load_file(display_path(os.fspath(self.path)))
        except TestFileError as err:
            raise self.CollectError(err.format()) from None
        for case in cases:
            yield MacroTestItem.from_parent(self, name=case.name, case=case)


class MacroTestFailure(Exception):
    """A macro test that failed; pytest shows its text, not a traceback."""

    def __init__(self, result: TestResult) -> None:
        super().__init__(result.text)
        self.result = result


class MacroTestItem(pytest.Item):
    def __init__(self, *, case: TestCase, **kwargs: Any) -> None:
        super().__init__(**kwargs)
        self.case = case

    def runtest(self) -> None:
        from edingcnc_lang.testing.session import check

        result = check(self.case)
        if not result.passed:
            raise MacroTestFailure(result)

    def repr_failure(self, excinfo: pytest.ExceptionInfo[BaseException],
                     style: Any = None) -> str | Any:
        if isinstance(excinfo.value, MacroTestFailure):
            return excinfo.value.result.text
        return super().repr_failure(excinfo)

    def reportinfo(self) -> tuple[os.PathLike[str] | str, int | None, str]:
        return self.path, self.case.line - 1, f"{self.case.file}::{self.case.name}"


class MacroRunner:
    """What the ``ecnc`` fixture hands a Python test."""

    def __init__(self, folder: Path, name: str) -> None:
        self.folder = folder
        self.name = name

    def run(self, job: str | None = None, **keys: Any) -> Outcome:
        """Run ``job`` (G-code text; or ``job_file=``) with the keys of a ``[[test]]`` table and return
        the outcome: ``var(n)``, ``position``, ``machine``, ``messages``, ``moves``, ``error``.

        With ``expect=`` or ``forbid=`` the test fails (with the text ``ecnc test`` prints) when
        they are not met; otherwise nothing is judged here, not even an error that stopped the run.
        """
        from edingcnc_lang.testing.checks import failures
        from edingcnc_lang.testing.execute import run_case
        from edingcnc_lang.testing.spec import TestFileError, from_mapping

        given = {k: _toml_like(v) for k, v in keys.items()}
        if job is not None:
            given["job"] = job
        try:
            case = from_mapping(given, self.folder, self.name)
        except TestFileError as err:
            pytest.fail(err.format(), pytrace=False)
        outcome = run_case(case, keep_moves=True)
        if "expect" in keys or "forbid" in keys:
            found = failures(outcome)
            if found:
                pytest.fail("; ".join(found), pytrace=False)
        return outcome


@pytest.fixture
def ecnc(request: pytest.FixtureRequest) -> MacroRunner:
    """Runs macros for a Python test: ``ecnc.run(job=..., macro=..., answers=[...], probe=[...])``."""
    return MacroRunner(Path(request.path).parent, request.node.nodeid)


def _toml_like(value: Any) -> Any:
    """Python values as TOML gives them: parameter numbers as keys become text, paths text."""
    if isinstance(value, Mapping):
        return {str(k): _toml_like(v) for k, v in value.items()}
    if isinstance(value, (list, tuple)):
        return [_toml_like(v) for v in value]
    if isinstance(value, os.PathLike):
        return os.fspath(value)
    return value

