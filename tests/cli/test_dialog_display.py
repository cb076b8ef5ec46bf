"""Issue 21 item 8, on the command line: dialogs answered with --answer are shown; MDI history."""
from __future__ import annotations

from pathlib import Path

import pytest

from tests.cli_runner import invoke

JOB = 'dlgmsg "Insert tool 3" "Tool length" 1001 "Speed" 1002\nmsg "after"\ndlgmsg "Second"\n'


def test_a_dialog_answered_with_answer_is_shown_on_stderr(tmp_path: Path) -> None:
    (tmp_path / "job.nc").write_text(JOB)
    result = invoke("run", "--answer", "ok:#1001=12.5", tmp_path / "job.nc")
    assert result.exit_code == 0
    lines = result.stderr.splitlines()
    at = lines.index(f"{tmp_path / 'job.nc'}:1: dialog: Insert tool 3")
    assert lines[at + 1:at + 4] == ["    Tool length (#1001) = 0 -> 12.5", "    Speed (#1002) = 0",
                                    "    answer: ok (--answer)"]
    assert f"{tmp_path / 'job.nc'}:3: dialog: Second" in lines  # with no --answer left: said too
    assert "    answer: ok, values unchanged (no --answer left)" in lines
    assert lines.index(f"{tmp_path / 'job.nc'}:2: msg: after") > at  # in the order they happen


def test_a_cancelled_dialog_says_so_and_changes_nothing(tmp_path: Path) -> None:
    (tmp_path / "job.nc").write_text(JOB)
    result = invoke("run", "--answer", "cancel", tmp_path / "job.nc")
    assert "    Tool length (#1001) = 0\n    Speed (#1002) = 0\n    answer: cancel (--answer)" in result.stderr


def test_json_keeps_stderr_quiet(tmp_path: Path) -> None:
    (tmp_path / "job.nc").write_text(JOB)
    assert "dialog" not in invoke("run", "--json", "--answer", "ok", tmp_path / "job.nc").stderr


def test_mdi_history_keeps_commands_not_dialog_answers(monkeypatch: pytest.MonkeyPatch) -> None:
    readline = pytest.importorskip("readline")
    from edingcnc_lang.cli.mdi_cmd import ask_dialog
    from edingcnc_lang.host import DialogField

    typed = iter(["12.5", "y"])

    def input_with_history(_prompt: str) -> str:  # what input() does when readline is loaded
        line = next(typed)
        readline.add_history(line)
        return line

    monkeypatch.setattr("builtins.input", input_with_history)
    readline.clear_history()
    readline.add_history("G0 X10")
    answer = ask_dialog("Tool length", [DialogField("Length", 1001, 0.0)])
    assert answer.ok and dict(answer.values) == {1001: 12.5}
    history = [readline.get_history_item(i) for i in range(1, readline.get_current_history_length() + 1)]
    readline.clear_history()
    assert history == ["G0 X10"]
