"""Control flow and subs: If/Else, While, GoSub, M-code subs, M6 and change_tool, macro files,
the step budget, program ends inside subs, and operator messages."""
from __future__ import annotations

from pathlib import Path

import pytest

from edingcnc_lang.canon import Event
from edingcnc_lang.errors import MachineError
from edingcnc_lang.host import Host
from edingcnc_lang.runner import RunOptions, RunResult, run_string

DATA = Path(__file__).parent / "data"
EMPTY_MACRO = DATA / "empty_macro.cnc"
MAIN_MACRO = DATA / "macros" / "main_macro.cnc"
USER_MACRO = DATA / "macros" / "user_macro.cnc"
ABSENT = -1e10


def run(source: str, **options: object) -> RunResult:
    options.setdefault("macro", EMPTY_MACRO)
    return run_string(source, RunOptions(**options), path="job.nc")  # type: ignore[arg-type]


def run_with_events(source: str, **options: object) -> tuple[RunResult, list[Event]]:
    events: list[Event] = []
    return run(source, on_event=events.append, **options), events


def error_of(source: str, **options: object) -> MachineError:
    with pytest.raises(MachineError) as info:
        run(source, **options)
    return info.value


# ------------------------------------------------------------------ If / While

IF_CASES = [
    ("If [1]\n#100 = 1\nElse\n#100 = 2\nEndIf\n", 1.0),
    ("If [0]\n#100 = 1\nElse\n#100 = 2\nEndIf\n", 2.0),
    ("#100 = 5\nIf [#100 > 9]\n#100 = 1\nEndIf\n", 5.0),
    ("IF [[1 == 1] AND [2 > 1]] THEN\n#100 = 3\nENDIF\n", 3.0),
    ("if [0.001]\n  if [0]\n    #100 = 1\n  else\n    #100 = 4\n  endif\nendif\n", 4.0),
]


@pytest.mark.parametrize(("source", "expected"), IF_CASES)
def test_if_else(source: str, expected: float) -> None:
    assert run(source).variables[100] == expected


def test_nested_while_with_counters() -> None:
    result = run("#1 = 0\n#2 = 0\n"
                 "While [#1 < 3]\n  #3 = 0\n  While [#3 < 4]\n    #2 = [#2 + 1]\n    #3 = [#3 + 1]\n  EndWhile\n"
                 "  #1 = [#1 + 1]\nEndWhile\n")
    assert (result.variables[1], result.variables[2], result.variables[3]) == (3.0, 12.0, 4.0)


def test_while_that_never_starts() -> None:
    result = run("#1 = 5\nWhile [#1 < 3]\n  #1 = 99\nEndWhile\n")
    assert result.variables[1] == 5.0


def test_while_moves_in_a_loop() -> None:
    result = run("#1 = 0\nWhile [#1 < 5]\n  #1 = [#1 + 1]\n  G1 X[#1 * 10] F1000\nEndWhile\n")
    assert result.moves == 5 and result.position[0] == 50.0


# ------------------------------------------------------------------ GoSub

def test_gosub_is_case_insensitive_and_subs_may_follow_m30() -> None:
    result = run("gosub Set_Value\nGOSUB set_value\nM30\nSub SET_VALUE\n  #100 = [#100 + 1]\nEndSub\n")
    assert result.variables[100] == 2.0
    assert result.ended_by == "M30"


def test_statements_after_m30_do_not_run() -> None:
    result = run("#100 = 1\nM30\n#100 = 2\n")
    assert result.variables[100] == 1.0


def test_recursion_with_a_counter() -> None:
    result = run("#100 = 0\nGoSub down\nM30\nSub down\n  #100 = [#100 + 1]\n  If [#100 < 10]\n    GoSub down\n"
                 "  EndIf\nEndSub\n")
    assert result.variables[100] == 10.0


def test_endless_recursion_stops_at_the_depth_limit() -> None:
    err = error_of("GoSub loop\nSub loop\n  GoSub loop\nEndSub\n")
    assert str(err.location) == "job.nc:3:3"
    assert "64" in err.message and "loop" in err.message
    assert err.notes[-1] == "in Sub loop, called from job.nc:1"


def test_unknown_sub_names_the_line_and_the_call_stack() -> None:
    err = error_of("G0 X1\nGoSub outer\nM30\nSub outer\n  GoSub inner\nEndSub\nSub inner\n  GoSub missing_sub\n"
                   "EndSub\n")
    assert err.format().splitlines()[0].startswith("job.nc:8:3: error: GoSub missing_sub")
    assert err.notes == ("in Sub inner, called from job.nc:5", "in Sub outer, called from job.nc:2")


def test_m2_inside_a_sub_ends_the_whole_program() -> None:
    result = run("GoSub finish\n#100 = 2\nM30\nSub finish\n  #100 = 1\n  M2\n  #100 = 3\nEndSub\n")
    assert result.variables[100] == 1.0


def test_m2_is_reported_as_the_end_of_the_program() -> None:
    assert run("G0 X1\nM2\nG0 X5\n").ended_by == "M2"


def test_m30_inside_a_nested_sub_ends_the_whole_program() -> None:
    result = run("GoSub a\n#100 = 2\nSub a\n  GoSub b\n  #100 = 3\nEndSub\nSub b\n  M30\nEndSub\n")
    assert 100 not in result.variables
    assert result.ended_by == "M30"


def test_end_of_file_without_m30() -> None:
    assert run("G0 X1\n").ended_by == "end of file"


# ------------------------------------------------------------------ step budget

def test_step_budget_stops_an_endless_while() -> None:
    err = error_of("#1 = 0\nWhile [1]\n  #1 = [#1 + 1]\nEndWhile\n", max_steps=200)
    assert err.location is not None and err.location.line in (2, 3)
    assert "step budget of 200" in err.message
    partial: RunResult = err.result  # type: ignore[attr-defined]
    assert 90 <= partial.variables[1] <= 200


def test_step_budget_stops_endless_subs_in_a_while() -> None:
    err = error_of("While [1]\n  GoSub tick\nEndWhile\nSub tick\n  G4 P0.1\nEndSub\n", max_steps=50)
    assert "step budget" in err.message


class TooManyMoves(Exception):
    """Raised by the test's move callback to stop a run the step budget let through."""


def test_step_budget_also_stops_a_runaway_canned_cycle() -> None:
    moves = 0

    def count(_move: object, _joints: object) -> None:
        nonlocal moves
        moves += 1
        if moves > 10_000:
            raise TooManyMoves()

    err = error_of("G0 Z5\nG81 X1 Z-1 R1 F100 L[10**9]\n", max_steps=1000, on_move=count)
    assert "step budget" in err.message


def test_a_peck_depth_too_small_to_finish_is_an_error() -> None:
    err = error_of("G0 Z5\nG83 X1 Z-1000 R1 Q[10**-9] F100\n")
    assert "pecks" in err.message


def test_a_job_within_its_step_budget_runs() -> None:
    assert run("#1 = 0\nWhile [#1 < 10]\n  #1 = [#1 + 1]\nEndWhile\n", max_steps=100).variables[1] == 10.0


# ------------------------------------------------------------------ macro files

def test_user_macro_subs_win_over_macro_cnc_and_both_are_callable() -> None:
    result = run("GoSub shared\nGoSub only_main\nGoSub only_user\n", macro=MAIN_MACRO, user_macro=USER_MACRO)
    v = result.variables
    assert (v[300], v[301], v[302]) == (2.0, 1.0, 1.0)


def test_macro_top_level_statements_run_once_at_load() -> None:
    result = run("GoSub shared\nGoSub shared\nM100\n", macro=MAIN_MACRO, user_macro=USER_MACRO)
    assert (result.variables[250], result.variables[251]) == (1.0, 7.0)


def test_macro_files_named_in_the_ini_are_found_beside_it(tmp_path: Path) -> None:
    (tmp_path / "macro.cnc").write_bytes(MAIN_MACRO.read_bytes())
    (tmp_path / "user_macro.cnc").write_bytes(USER_MACRO.read_bytes())
    ini = tmp_path / "cnc.ini"
    ini.write_bytes(b'[INTERPRETER]\r\nmacroFileName = "C:\\CNC4.03\\macro.cnc"\r\n'
                    b'userMacroFileName = "C:\\CNC4.03\\user_macro.cnc"\r\n')
    result = run_string("GoSub shared\nGoSub only_main\n", RunOptions(ini=ini), path="job.nc")
    assert (result.variables[300], result.variables[301]) == (2.0, 1.0)


def test_macro_option_overrides_the_ini(tmp_path: Path) -> None:
    (tmp_path / "macro.cnc").write_bytes(MAIN_MACRO.read_bytes())
    ini = tmp_path / "cnc.ini"
    ini.write_bytes(b'[INTERPRETER]\r\nmacroFileName = "macro.cnc"\r\n')
    with pytest.raises(MachineError, match="only_main"):
        run_string("GoSub only_main\n", RunOptions(ini=ini, macro=EMPTY_MACRO), path="job.nc")


def test_packaged_macro_is_the_default() -> None:
    result = run_string("GoSub user_4\n", RunOptions(), path="job.nc")  # user_4 stores the park position
    assert (result.variables[4003], result.variables[4004]) == (0.0, 0.0)


# ------------------------------------------------------------------ M-code subs

def test_m_code_sub_gets_letter_arguments_and_absent_letters_read_minus_1e10() -> None:
    result = run("M100 P3 Q1.5\n", macro=MAIN_MACRO)
    v = result.variables
    assert (v[311], v[312]) == (3.0, 1.5)
    assert (v[310], v[313]) == (ABSENT, ABSENT)


def test_m_code_sub_arguments_may_be_expressions() -> None:
    result = run("#50 = 2\nM100 A[#50 * 4] Z-1\n", macro=MAIN_MACRO)
    assert (result.variables[310], result.variables[313], result.variables[311]) == (8.0, -1.0, ABSENT)


def test_builtin_m_code_inside_its_own_override_runs_the_builtin() -> None:
    result, events = run_with_events("M3\nM5\nM3\n", macro=MAIN_MACRO)
    assert result.variables[320] == 2.0  # the override ran for each M3 of the job, not recursively
    spindle = [(e.data["m"], e.line) for e in events if e.kind == "spindle"]
    assert spindle == [(3, 35), (5, 2), (3, 35)]  # M3 events come from the sub's line 35
    assert result.variables[5152] == 1.0


def test_speed_on_a_line_calling_an_overridden_m3_is_kept() -> None:
    _result, events = run_with_events("S12000 M3\n", macro=MAIN_MACRO)
    assert [e.data["speed"] for e in events if e.kind == "spindle"] == [12000.0]


def test_m_code_sub_line_may_not_hold_g_words() -> None:
    err = error_of("G0 M100 P1\n", macro=MAIN_MACRO)
    assert str(err.location).startswith("job.nc:1")
    assert "M100" in err.message


# ------------------------------------------------------------------ M6 and change_tool

def test_m6_calls_change_tool_which_commits_with_m6_t() -> None:
    result, events = run_with_events("T7 M6\n", macro=MAIN_MACRO)
    v = result.variables
    assert (v[200], v[201], v[202]) == (7.0, 0.0, 0.0)   # #5011 new, #5008 old, #5015 cleared
    assert (v[203], v[5015], result.tool) == (7.0, 1.0, 7)
    changes = [(e.line, dict(e.data)) for e in events if e.kind == "tool_change"]
    assert changes == [(12, {"tool": 7, "previous": 0})]


def test_second_m6_sees_the_tool_in_the_spindle() -> None:
    result = run("T2 M6\nT5 M6\n", macro=MAIN_MACRO)
    assert (result.variables[200], result.variables[201], result.tool) == (5.0, 2.0, 5)


def test_m6_without_change_tool_sub_changes_the_tool_and_reads_the_tool_table() -> None:
    result = run("T1 M6\n#100 = #5009 #101 = #5010\n", ini=DATA / "machine.ini")
    assert result.tool == 1
    assert (result.variables[100], result.variables[101]) == (3.0, 40.5)


def test_packaged_change_tool_moves_z_up_first_in_machine_coordinates() -> None:
    moves = []
    result = run_string("G0 X10 Y10 Z-5\nT3 M6\n", RunOptions(on_move=lambda m, _j: moves.append(m)), path="job.nc")
    assert result.tool == 3
    assert moves[1].end[2] == 0.0 and moves[1].end[:2] == (10.0, 10.0)


# ------------------------------------------------------------------ messages

def test_messages_are_collected_with_kind_file_and_line() -> None:
    heard: list[tuple[str, str, str, int]] = []
    host = Host(message=lambda kind, text, path, line: heard.append((kind, text, path, line)))
    result = run('G0 X1.5\nmsg "at X"#5001" now"\nwarnmsg "check ""the clamp"\n(MSG change the belt)\n'
                 'msg "val "[1/4]\n', host=host)
    expected = [("msg", "at X1.5 now", "job.nc", 2), ("warn", "check the clamp", "job.nc", 3),
                ("msg", "change the belt", "job.nc", 4), ("msg", "val 0.25", "job.nc", 5)]
    assert heard == expected
    assert [(e.kind, e.data["text"], e.path, e.line) for e in result.messages] == expected


def test_errmsg_aborts_with_its_text() -> None:
    err = error_of('G0 X1\nIf [#5001 > 0]\n  errmsg "X is "#5001", stop"\nEndIf\nG0 X2\n')
    assert err.format() == "job.nc:3:3: error: X is 1, stop"
    partial: RunResult = err.result  # type: ignore[attr-defined]
    assert partial.position[0] == 1.0
    assert [(m.kind, m.data["text"]) for m in partial.messages] == [("error", "X is 1, stop")]
