"""The lathe lint rules and run warnings: G76 in LinuxCNC's words (G520) and spindle speeds the
ini's limits change (G521), through the API and ``ecnc lint``/``ecnc run``."""
from __future__ import annotations

from pathlib import Path

import pytest

from edingcnc_lang import RunOptions, run_string
from edingcnc_lang.diagnostics import Diagnostic
from edingcnc_lang.errors import EcncError
from edingcnc_lang.lint.driver import LintOptions, lint_paths
from tests.cli_runner import invoke

EXAMPLE = Path(__file__).resolve().parents[2] / "examples" / "lathe"
INI = EXAMPLE / "cnc.ini"   # [SPINDLE_0] spindleNmin = 120, spindleNmax = 3200
JOB = "G97 S8000 M3\nS100\nS1000\nG96 S100 D9000\nS100\nG97 S50\nG76 P1 Z-10 I-2 J0.1 K0.6\nS[#1]\n"


def _lint(tmp_path: Path, text: str, ini: Path | None = INI) -> list[tuple[int, str]]:
    job = tmp_path / "job.nc"
    job.write_text(text)
    return [(d.line, d.code) for d in lint_paths([job], LintOptions(ini=ini))]


def test_lint_reports_constant_speeds_the_ini_changes_and_g76_in_linuxcnc_words(tmp_path: Path) -> None:
    assert _lint(tmp_path, JOB) == [(1, "G521"), (2, "G521"), (4, "G521"), (6, "G521"), (7, "G520")]
    assert _lint(tmp_path, JOB, ini=None) == [(7, "G520")]   # no ini: no range known


def test_run_warns_at_each_line_a_limit_changed(tmp_path: Path) -> None:
    warnings: list[Diagnostic] = []
    job = "G0 X20 Z5\nG97 S8000 M3\nS100\nS1000\nG96 S100 D9000\nG97 S50\n"
    run_string(job, RunOptions(ini=INI, macro=EXAMPLE / "macro.cnc", on_warning=warnings.append))
    found = [(w.line, w.severity.value, w.message) for w in warnings]
    assert found == [
        (2, "warning", "S8000: the spindle turns at 3200 rpm, the machine's spindleNmax (cnc.ini), not the 8000 rpm written"),
        (3, "warning", "S100: the spindle turns at 120 rpm, the machine's spindleNmin (cnc.ini), not the 100 rpm written"),
        (5, "warning", "G96 D9000: the spindle turns at most 3200 rpm, the machine's spindleNmax (cnc.ini)"),
        (6, "warning", "S50: the spindle turns at 120 rpm, the machine's spindleNmin (cnc.ini), not the 50 rpm written"),
    ]


def test_a_loop_warns_once_per_line(tmp_path: Path) -> None:
    warnings: list[Diagnostic] = []
    job = "#1 = 0\nWhile [#1 < 3]\n    S9000 M3\n    #1 = [#1 + 1]\nEndWhile\n"
    run_string(job, RunOptions(ini=INI, macro=EXAMPLE / "macro.cnc", on_warning=warnings.append))
    assert [w.line for w in warnings] == [3]


def test_cli_run_prints_the_warning_and_lint_the_finding(tmp_path: Path) -> None:
    job = tmp_path / "job.nc"
    job.write_text("G97 S8000 M3\nM30\n")
    result = invoke("run", "--ini", INI, job)
    assert result.exit_code == 0
    assert f"{job}:1:1: warning: S8000: the spindle turns at 3200 rpm" in result.stderr
    result = invoke("lint", "--ini", INI, job)
    assert result.exit_code == 1 and f"{job}:1:5: G521 S8000" in result.stdout


def test_negative_i_stops_the_run_saying_what_edingcnc_reads() -> None:
    with pytest.raises(EcncError) as info:
        run_string("G97 S500 M3\nG0 X14 Z3\nG76 P1.5 Z-20 I-2 J0.4 K1.84\n", RunOptions(ini=INI, macro=EXAMPLE / "macro.cnc"))
    text = info.value.format()
    assert text.startswith("<string>:3:1: error: G76 I-2: EdingCNC reads I as the thread's crest diameter")
    assert "write the crest diameter I12" in text
