"""No quadratic parsing, no whole echo (issue 28, items 2 and 7): a 65,000-letter line, and long
names after Sub, GoSub, GoTo, logfile and ZHCS, are parsed, linted and run in linear time (they
took 47 s each; the operator count tried a function call at every letter); a message quotes a long
name or a 309-digit number shortened, and shows a long line only around its column."""
from __future__ import annotations

from pathlib import Path

import pytest

from edingcnc_lang.diagnostics import Diagnostic
from edingcnc_lang.errors import EcncError, MachineError, shortened
from edingcnc_lang.syntax.input_limits import MAX_LINE_LENGTH, line_problem
from edingcnc_lang.lint import lint_paths
from edingcnc_lang.runner import RunOptions, run_string
from tests.cli_runner import invoke

N = MAX_LINE_LENGTH - 1000
NAME = "a" * N
LINES = ["A" * N, f"Sub {NAME}\nEndSub", f"GoSub {NAME}", f"GoTo {NAME}", f"logfile {NAME} 0",
         f"ZHCINIT 10 2 2\nZHCS {NAME}", f"#1 = [{NAME}]", f"G1 X1 {'x' * N}"]


def test_the_operator_count_reads_a_long_name_once() -> None:
    assert line_problem("SIN" * (N // 3)) is None
    assert line_problem("a" * N + "[") is None  # one function call, however long its name
    assert line_problem("ab[" * 101)[0] == "E111"  # a call still counts


@pytest.mark.parametrize("text", LINES, ids=["letters", "sub", "gosub", "goto", "logfile", "zhcs", "expr", "word"])
def test_a_long_line_runs_and_lints_and_says_so_briefly(tmp_path: Path, text: str) -> None:
    job = tmp_path / "j.nc"
    job.write_text(text + "\nM30\n")
    result = invoke("run", job)
    assert result.exit_code in (0, 65, 70) and "Traceback" not in result.output
    assert len(result.output) < 2000
    result = invoke("lint", job)
    assert result.exit_code in (0, 1) and len(result.output) < 6000


def test_a_246_digit_number_is_not_echoed_whole() -> None:
    # (246 digits: a G-code line holds at most 256 characters, manual 3.4, E114)
    with pytest.raises(MachineError) as err:
        run_string(f"G1 X{'9' * 246} F100\n")
    assert "1e+246" in err.value.message and "9999999999" not in err.value.format()


def test_every_error_and_finding_shortens_what_it_quotes() -> None:
    assert shortened(f"no Sub {NAME} here") == f"no Sub {'a' * 60}…{'a' * 20} ({N:,} characters) here"
    assert shortened("value 123456789012345678901234.5 too big") == "value 1.23457e+23 too big"
    assert shortened("line 12 at 4.5") == "line 12 at 4.5"
    assert len(EcncError(f"x {NAME}").format()) < 200
    finding = Diagnostic.make("F602", f"about {NAME}", "j.nc", 1, N, source=NAME)
    assert len(finding.format()) < 500 and finding.format().endswith("^")
    assert finding.format().splitlines()[1].startswith("    …")


def test_the_caret_still_points_at_the_column_of_a_long_line() -> None:
    line = "x" * 1000 + "Y" + "x" * 1000
    shown, caret = Diagnostic.make("F602", "m", "j.nc", 1, 1001, source=line).format().splitlines()[1:]
    assert shown[caret.index("^")] == "Y"


def test_lint_api_on_a_long_name(tmp_path: Path) -> None:
    job = tmp_path / "j.nc"
    job.write_text(f"Sub {NAME}\nEndSub\nGoSub {NAME}b\n")
    findings = list(lint_paths([job]))
    assert {d.code for d in findings} >= {"S208", "F602"}
