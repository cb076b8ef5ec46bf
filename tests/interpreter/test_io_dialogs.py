"""Simulated I/O (M54..M57), dialogs (dlgmsg) with host answers, log files, and the Exec guard."""
from __future__ import annotations

import sys
from collections.abc import Sequence
from pathlib import Path

import pytest

from edingcnc_lang.diagnostics import SyntaxErrors
from edingcnc_lang.errors import MachineError
from edingcnc_lang.host import DialogAnswer, DialogField, Host, scripted_dialogs
from edingcnc_lang.machine.state import format_value
from edingcnc_lang.runner import RunOptions, RunResult, run_file, run_string

EMPTY_MACRO = Path(__file__).parent / "data" / "empty_macro.cnc"


def run(source: str, **options: object) -> RunResult:
    options.setdefault("macro", EMPTY_MACRO)
    return run_string(source, RunOptions(**options), path="job.nc")  # type: ignore[arg-type]


def answering(*answers: str) -> Host:
    return Host(dialog=scripted_dialogs([DialogAnswer.parse(a) for a in answers]))


def error_of(source: str, **options: object) -> MachineError:
    with pytest.raises(MachineError) as info:
        run(source, **options)
    return info.value


# ------------------------------------------------------------------ outputs and inputs

def test_outputs_set_clear_and_read_back() -> None:
    v = run("M54 P3\nM57 P3\n#100 = #5399\nM55 P3\nM57 P3\n#101 = #5399\nM57 P4\n#102 = #5399\n"
            "M54 E2 Q500\nM57 E2\n#103 = #5399\n").variables
    assert (v[100], v[101], v[102], v[103]) == (1.0, 0.0, 0.0, 500.0)  # a PWM output reads back its value


def test_inputs_come_from_the_host() -> None:
    asked: list[int] = []

    def read_input(port: int) -> float:
        asked.append(port)
        return 1.0 if port == 4 else 0.0

    v = run("M56 P4\n#100 = #5399\nM56 P5\n#101 = #5399\n", host=Host(read_input=read_input)).variables
    assert (v[100], v[101]) == (1.0, 0.0)
    assert asked == [4, 5]


WAITS = [
    # (line, input level, #5399): L1 waits for high, L2 for low; -1 when the wait times out
    ("M56 P1 L1 Q2", 1.0, 1.0),
    ("M56 P1 L1 Q2", 0.0, -1.0),
    ("M56 P1 L2 Q2", 0.0, 0.0),
    ("M56 P1 L2", 1.0, -1.0),
    ("M56 P1 L0", 1.0, 1.0),
]


@pytest.mark.parametrize(("line", "level", "expected"), WAITS)
def test_input_waits(line: str, level: float, expected: float) -> None:
    result = run(f"{line}\n#100 = #5399\n", host=Host(read_input=lambda _port: level))
    assert result.variables[100] == expected


def test_inputs_read_low_without_a_host_callback() -> None:
    assert run("M56 P7\n#100 = #5399\n").variables[100] == 0.0


# ------------------------------------------------------------------ dialogs

DIALOG = '#27 = 3\n#28 = 4\ndlgmsg "Setup" "Width" 27 "Depth" 28\n#100 = #5398\n'


def test_dialog_ok_with_new_values() -> None:
    v = run(DIALOG, host=answering("ok:#27=5,#28=-1.5")).variables
    assert (v[27], v[28], v[100]) == (5.0, -1.5, 1.0)


def test_dialog_cancel_keeps_values_and_sets_5398_to_minus_1() -> None:
    v = run(DIALOG, host=answering("cancel")).variables
    assert (v[27], v[28], v[100]) == (3.0, 4.0, -1.0)


def test_dialog_without_answer_is_ok_unchanged() -> None:
    v = run(DIALOG + 'dlgmsg "Again" "Width" 27\n#101 = #5398\n', host=answering("ok:#27=9")).variables
    assert (v[27], v[28], v[100], v[101]) == (9.0, 4.0, 1.0, 1.0)


def test_dialog_callback_sees_title_labels_and_current_values() -> None:
    seen: list[tuple[str, tuple[DialogField, ...]]] = []

    def dialog(title: str, fields: Sequence[DialogField]) -> DialogAnswer:
        seen.append((title, tuple(fields)))
        return DialogAnswer(True, {28: 8.0})

    result = run(DIALOG, host=Host(dialog=dialog))
    assert seen == [("Setup", (DialogField("Width", 27, 3.0), DialogField("Depth", 28, 4.0)))]
    assert result.variables[28] == 8.0
    dialog_events = [m for m in result.messages if m.kind == "dialog"]
    assert [(m.data["text"], m.data["ok"], m.line) for m in dialog_events] == [("Setup", True, 3)]


def test_dialog_answer_for_a_parameter_that_is_not_a_field_is_an_error() -> None:
    assert "#29" in error_of(DIALOG, host=answering("ok:#29=1")).message


@pytest.mark.parametrize("value", [float("inf"), float("nan")])
def test_a_host_answering_a_non_finite_value_is_an_error_at_the_dlgmsg(value: float) -> None:
    host = Host(dialog=scripted_dialogs([DialogAnswer(True, {27: value})]))
    err = error_of(DIALOG, host=host)
    assert "#27" in err.message and "not a finite number" in err.message and str(err.location) == "job.nc:3:1"


def test_non_finite_values_format_as_inf_and_nan() -> None:
    assert [format_value(v) for v in (float("inf"), float("-inf"), float("nan"), 2.0, 0.5)] == [
        "inf", "-inf", "nan", "2", "0.5"]


def test_dialog_with_15_fields_is_fine_and_16_is_an_error() -> None:
    fields = " ".join(f'"f{i}" {30 + i}' for i in range(16))
    run(f'dlgmsg "T" {" ".join(fields.split(" ")[:30])}\n')
    err = error_of(f'dlgmsg "T" {fields}\n')
    assert "16 fields" in err.message and str(err.location) == "job.nc:1:1"


@pytest.mark.parametrize("line, code, col", [
    ('dlgmsg "T" "Width" #27', "D403", 20),       # a '#' before the field number
    ('dlgmsg "T" #27 "Width" 27', "D402", 12),    # a value between the strings
    ('dlgmsg "T" "Width" 27 "Depth"', "D402", 23),  # a label without its number
])
def test_dialog_shapes_the_controller_calls_g1167_stop_the_job_before_anything_moves(
        line: str, code: str, col: int) -> None:
    moves: list[object] = []
    with pytest.raises(SyntaxErrors) as info:
        run(f"G0 X1\n{line}\n", on_move=lambda move, joints: moves.append(move))
    diag = info.value.diagnostics[0]
    assert (diag.code, diag.line, diag.col) == (code, 2, col) and "G1167" in diag.message
    assert moves == []


def test_a_dialog_label_of_32_characters_is_refused_when_the_dialog_is_shown() -> None:
    label = "x" * 32
    err = error_of(f'G0 X1\ndlgmsg "T" "{label}" 27\n')
    assert "unnamed string too long" in err.message and err.location.line == 2  # type: ignore[union-attr]
    run(f'dlgmsg "T" "{label[:31]}" 27\n')


@pytest.mark.parametrize("text", ["ok", "OK", "cancel", "ok:#27=5", "ok: #27=5, #28=-1e3"])
def test_answer_texts_parse(text: str) -> None:
    DialogAnswer.parse(text)


@pytest.mark.parametrize("text", ["yes", "cancel:#27=1", "ok:27=5", "ok:#27", "ok:#x=1", "ok:#27=abc",
                                  "ok:#27=1e400", "ok:#27=nan", "ok:#27=-inf"])
def test_bad_answer_texts_are_refused(text: str) -> None:
    with pytest.raises(ValueError):
        DialogAnswer.parse(text)


# ------------------------------------------------------------------ log files

def test_logmsg_writes_into_the_log_dir(tmp_path: Path) -> None:
    result = run('logfile "probe.txt" 0\nlogmsg "X="[1 + 1]" done"\nlogmsg "second"\n', log_dir=tmp_path)
    assert (tmp_path / "probe.txt").read_text() == "X=2 done\nsecond\n"
    assert [(m.kind, m.data["text"]) for m in result.messages] == [("log", "X=2 done"), ("log", "second")]


def test_logfile_mode_0_truncates_and_1_appends(tmp_path: Path) -> None:
    (tmp_path / "a.txt").write_text("old\n")
    run("logfile a.txt 1\nlogmsg \"new\"\n", log_dir=tmp_path)
    assert (tmp_path / "a.txt").read_text() == "old\nnew\n"
    run("logfile a.txt 0\nlogmsg \"only\"\n", log_dir=tmp_path)
    assert (tmp_path / "a.txt").read_text() == "only\n"


@pytest.mark.parametrize("name", ["..\\..\\x.txt", "../../x.txt", "/tmp/x.txt", "C:\\temp\\x.txt", "sub/x.txt"])
def test_log_paths_never_leave_the_log_dir(tmp_path: Path, name: str) -> None:
    logs = tmp_path / "logs" / "deep"
    logs.mkdir(parents=True)
    run(f'logfile "{name}" 0\nlogmsg "hello"\n', log_dir=logs)
    written = sorted(p.relative_to(tmp_path).as_posix() for p in tmp_path.rglob("*") if p.is_file())
    assert written == ["logs/deep/x.txt"]
    assert (logs / "x.txt").read_text() == "hello\n"


def test_default_log_dir_is_the_jobs_folder(tmp_path: Path) -> None:
    job = tmp_path / "job.nc"
    job.write_text('logmsg "no logfile given"\n')
    run_file(job, RunOptions(macro=EMPTY_MACRO))
    assert [p.name for p in tmp_path.iterdir() if p.name != "job.nc"] == ["log.txt"]
    assert (tmp_path / "log.txt").read_text() == "no logfile given\n"


# ------------------------------------------------------------------ Exec

def test_exec_is_refused_without_allow_exec(tmp_path: Path) -> None:
    flag = tmp_path / "ran"
    result = run(f"Exec touch {flag}\n")
    assert not flag.exists()
    assert [m.kind for m in result.messages] == ["warn"] and "--allow-exec" in result.messages[0].data["text"]


def test_exec_runs_with_allow_exec(tmp_path: Path) -> None:
    flag = tmp_path / "ran"
    run(f"Exec touch {flag}\n", allow_exec=True)
    assert flag.exists()


def test_exec_of_a_missing_program_is_a_runtime_error() -> None:
    err = error_of("Exec no_such_program_ecnc_test\n", allow_exec=True)
    assert str(err.location) == "job.nc:1:1" and "no_such_program_ecnc_test" in err.message


def test_exec_with_a_quoted_program_path(tmp_path: Path) -> None:
    flag = tmp_path / "ran"
    run(f'Exec "{sys.executable}" -c "open(r\'{flag}\', \'w\').close()"\n', allow_exec=True)
    assert flag.exists()
