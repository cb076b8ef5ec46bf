"""examples/tests: the tests of the packaged macro.cnc pass, and their coverage is what they claim."""
from __future__ import annotations

from pathlib import Path

import pytest

from edingcnc_lang.testing.coverage import summarise
from edingcnc_lang.testing.session import run_cases
from edingcnc_lang.testing.spec import discover, load_file

ROOT = Path(__file__).resolve().parents[2]
EXAMPLES = ROOT / "examples" / "tests"


def test_the_example_tests_pass_and_reach_the_tool_change_and_probing_subs(monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.chdir(ROOT)
    files = [load_file(path) for path in discover([EXAMPLES.relative_to(ROOT)])]
    summary = run_cases(files, coverage=True)
    assert [r.text for r in summary.results if not r.passed] == []
    assert summary.line == f"{len(summary.results)} passed, 0 failed" and len(summary.results) >= 15
    assert summary.coverage is not None
    (macro,) = summarise(summary.coverage)
    assert macro.path == "edingcnc_lang/stdlib/macro.cnc"  # the packaged one, which every example test runs
    for tested in ("change_tool", "measure_tool", "user_1", "user_2", "user_11", "start"):
        assert tested not in macro.subs_never_run
    assert "home_all" in macro.subs_never_run
