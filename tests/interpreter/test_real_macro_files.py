"""Macro files as users have them: tolerant loading, one-operand ATAN, %d in messages."""
from __future__ import annotations

from datetime import datetime
from pathlib import Path

import pytest

from edingcnc_lang.diagnostics import Diagnostic, SyntaxErrors
from edingcnc_lang.host import Host
from edingcnc_lang.runner import RunOptions, RunResult, run_file, run_string

MACRO = """;@unit mm
Sub good
  #100 = ATAN[1]
  #101 = ATAN[-1]/[-1]
  #102 = ATAN[1]/2
EndSub

This add-on draws a circle pocket.
Use it from the menu: F-key 3, then OK.
If the probe does not trip, check the wiring first.

Sub bad
  G0 X1
  G1 X10+5
EndSub

Sub guarded
  If [#5380 == 1]
    msg "simulation"
  Else
    This line is a note nobody commented out.
  EndIf
EndSub
"""


def run_with_macro(tmp_path: Path, job: str, **options: object) -> tuple[RunResult, list[Diagnostic]]:
    macro = tmp_path / "macro.cnc"
    macro.write_bytes(MACRO.replace("\n", "\r\n").encode("latin-1"))
    warnings: list[Diagnostic] = []
    job_path = tmp_path / "job.nc"
    job_path.write_text(job, encoding="utf-8")
    result = run_file(job_path, RunOptions(macro=macro, on_warning=warnings.append, **options))  # type: ignore[arg-type]
    return result, warnings


def test_unreached_lines_that_do_not_parse_are_warnings_listed_once(tmp_path: Path) -> None:
    result, warnings = run_with_macro(tmp_path, "GoSub good\nGoSub guarded\n")
    assert [(w.line, w.severity.value) for w in warnings] == [(8, "warning"), (9, "warning"), (10, "warning"),
                                                                (14, "warning"), (21, "warning")]
    assert [w.format(with_source=False) for w in result.warnings] == [w.format(with_source=False) for w in warnings]
    assert result.variables[100] == pytest.approx(45.0)
    assert result.variables[101] == pytest.approx(-135.0)
    assert result.variables[102] == pytest.approx(22.5)
    assert [m.data["text"] for m in result.messages] == ["simulation"]


def test_a_bad_line_is_the_same_error_when_the_run_reaches_it(tmp_path: Path) -> None:
    with pytest.raises(SyntaxErrors) as info:
        run_with_macro(tmp_path, "GoSub bad\n")
    err = info.value
    assert err.exit_code == 65
    assert err.format().startswith(f"{tmp_path / 'macro.cnc'}:14:6: error: expression needs brackets")
    assert err.result.machine[0] == 1.0  # type: ignore[attr-defined]  (G0 X1 ran first)


def test_strict_refuses_the_file_at_load(tmp_path: Path) -> None:
    with pytest.raises(SyntaxErrors) as info:
        run_with_macro(tmp_path, "GoSub good\n", strict=True)
    lines = [d.line for d in info.value.diagnostics]
    assert lines[:3] == [8, 9, 10] and 14 in lines and 21 in lines  # (strict: "If the ..." opens a block too)


def test_a_broken_if_head_in_a_macro_file_keeps_its_block_and_fails_when_reached(tmp_path: Path) -> None:
    macro = tmp_path / "m.cnc"
    macro.write_text("Sub s\n  If [#1 > 0\n    G0 X5\n  EndIf\n  G0 Y2\nEndSub\nSub t\n  G0 Z1\nEndSub\n")
    result = run_string("GoSub t\n", RunOptions(macro=macro))
    assert result.machine[2] == 1.0 and len(result.warnings) == 1
    with pytest.raises(SyntaxErrors) as info:
        run_string("GoSub s\n", RunOptions(macro=macro))
    assert info.value.diagnostics[0].line == 2


def test_a_dlgmsg_the_controller_refuses_is_a_bad_line_in_a_macro_file(tmp_path: Path) -> None:
    """G1167 (a value between the strings, a label without its number) in a macro file: a warning at
    load, the same syntax error (exit 65) when reached, refused at load under strict."""
    macro = tmp_path / "m.cnc"
    macro.write_text('Sub s\n  dlgmsg "Setup" #27 "Width" 27\nEndSub\nSub t\n  dlgmsg "T" "Depth"\n'
                     '  G0 Z1\nEndSub\nSub u\n  G0 Y1\nEndSub\n')
    result = run_string("GoSub u\n", RunOptions(macro=macro))
    assert result.machine[1] == 1.0
    assert [(w.line, w.code, w.severity.value) for w in result.warnings] == [(2, "D402", "warning"),
                                                                             (5, "D402", "warning")]
    for sub, line in (("s", 2), ("t", 5)):
        with pytest.raises(SyntaxErrors) as info:
            run_string(f"GoSub {sub}\n", RunOptions(macro=macro))
        assert info.value.exit_code == 65 and info.value.diagnostics[0].line == line
        assert "EdingCNC G1167" in info.value.diagnostics[0].message
    with pytest.raises(SyntaxErrors) as info:
        run_string("GoSub u\n", RunOptions(macro=macro, strict=True))
    assert [d.line for d in info.value.diagnostics] == [2, 5]


def test_jobs_are_still_checked_in_full_before_the_first_move() -> None:
    moves: list[object] = []
    with pytest.raises(SyntaxErrors):
        run_string("G0 X1\nThis is prose\n", RunOptions(on_move=lambda m, j: moves.append(m)))
    assert moves == []


def test_percent_d_shows_the_date_and_time() -> None:
    clock = lambda: datetime(2026, 3, 4, 5, 6, 7)  # noqa: E731
    result = run_string('msg "started " %d "!"\n', RunOptions(host=Host(clock=clock)))
    assert result.messages[0].data["text"] == "started 2026-03-04 05:06:07!"


@pytest.mark.parametrize("text, value", [
    ("ATAN[1]", 45.0), ("ATAN[0]", 0.0), ("ATAN[-1]", -45.0), ("ATAN[1]/[0]", 90.0), ("ATAN[1]/2", 22.5),
    ("[ATAN[1] / [2]]", 26.56505117707799), ("[2 * ATAN[1]]", 90.0), ("ATAN[100000000]", 89.99999942704220),
])
def test_atan_one_and_two_operands(text: str, value: float) -> None:
    assert run_string(f"#1 = {text}\n").variables[1] == pytest.approx(value)
