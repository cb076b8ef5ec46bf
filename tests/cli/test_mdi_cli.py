"""``ecnc mdi`` from a pipe (no prompt, output per line) and the ``MdiSession`` API under it."""
from __future__ import annotations

import subprocess
import sys
from pathlib import Path

import pytest

from edingcnc_lang.errors import MachineError
from edingcnc_lang.mdi import MdiSession, open_blocks
from edingcnc_lang.runner import RunOptions
from tests.cli_runner import invoke


def mdi(text: str, *args: object) -> tuple[int, list[str], str]:
    result = invoke("mdi", *args, input=text)
    return result.exit_code, result.stdout.splitlines(), result.stderr


def test_moves_print_the_work_and_machine_position() -> None:
    code, out, err = mdi("G10 L2 P1 X5\nG54\nG0 X1 Y2\nG91 G1 Z-1 F100\n")
    assert (code, err) == (0, "")
    assert out == ["work    X1.0000 Y2.0000 Z0.0000 A0.0000 B0.0000 C0.0000",
                   "machine X6.0000 Y2.0000 Z0.0000 A0.0000 B0.0000 C0.0000",
                   "work    X1.0000 Y2.0000 Z-1.0000 A0.0000 B0.0000 C0.0000",
                   "machine X6.0000 Y2.0000 Z-1.0000 A0.0000 B0.0000 C0.0000"]


def test_expressions_and_parameters_print_their_value() -> None:
    code, out, _ = mdi("#100 = 2.5\n#100\n[#100 * 2]\nSIN[30] + 1\nG0 X3\n#5001\n")
    assert code == 0
    assert out[:3] == ["= 2.5", "= 5", "= 1.5"] and out[-1] == "= 3"
    code, out, _ = mdi("-#5001\n[ATAN[1]]\n")
    assert (code, out) == (0, ["= 0", "= 45"])  # never "-0"


def test_an_error_prints_its_message_and_the_session_goes_on() -> None:
    code, out, err = mdi("G0 X1\n#1 = [1 / 0]\nG0 X[1\nG0 X2\n")
    assert code == 70  # from a pipe: the status of the first failing line
    assert err.splitlines()[0].startswith("<mdi>:2:") and "division by zero" in err
    assert "<mdi>:3:5: error: unclosed '['" in err
    assert out[-2] == "work    X2.0000 Y0.0000 Z0.0000 A0.0000 B0.0000 C0.0000"


def test_an_errmsg_is_printed_once_and_the_session_goes_on() -> None:
    code, out, err = mdi('errmsg "spindle not ready " 3\nG0 X2\n')
    assert code == 70
    assert err.splitlines() == ["<mdi>:1: error: spindle not ready 3"]
    assert out[0] == "work    X2.0000 Y0.0000 Z0.0000 A0.0000 B0.0000 C0.0000"


def test_blocks_are_read_until_closed_and_subs_can_be_called(tmp_path: Path) -> None:
    macro = tmp_path / "macro.cnc"
    macro.write_text("Sub park\n  G0 Z5\nEndSub\n")
    text = "#1 = 0\nWhile [#1 < 3]\n  #1 = [#1 + 1]\nEndWhile\n#1\nIf [#1 == 3]\n  msg \"three\"\nEndIf\nGoSub park\n"
    code, out, err = mdi(text, "--macro", macro)
    assert code == 0 and out[0] == "= 3"
    assert err == "<mdi>:7: msg: three\n"
    assert out[1] == "work    X0.0000 Y0.0000 Z5.0000 A0.0000 B0.0000 C0.0000"


def test_exit_ends_the_session_and_an_open_block_at_the_end_is_reported() -> None:
    code, out, _ = mdi("G0 X1\nexit\nG0 X2\n")
    assert code == 0 and len(out) == 2
    code, _, err = mdi("If [1]\nG0 X1\n")
    assert code == 65 and "input ended inside a block" in err


def test_mdi_as_a_real_pipe() -> None:
    done = subprocess.run([sys.executable, "-m", "edingcnc_lang", "mdi"], input="G0 X1\n#5001\n", text=True,
                          capture_output=True, check=False)
    assert done.returncode == 0 and done.stdout.splitlines()[-1] == "= 1" and "MDI>" not in done.stdout


def test_the_session_api() -> None:
    session = MdiSession(RunOptions())
    outcome = session.execute("G0 X2 Y1")
    assert outcome.moved and outcome.position[:2] == (2.0, 1.0) and outcome.value is None
    assert session.execute("[#5001 + #5002]").value == 3.0
    with pytest.raises(MachineError):
        session.execute("errmsg \"no\"")
    assert session.execute("M30").ended
    session.close()


@pytest.mark.parametrize(("lines", "depth"), [(["If [1]"], 1), (["If [1]", "While [1]", "EndWhile"], 1),
                                              (["Sub a", "EndSub"], 0), (["N10 if [1]"], 1), (["G0 X1"], 0)])
def test_open_blocks(lines: list[str], depth: int) -> None:
    assert open_blocks(lines) == depth


def test_a_dialog_at_the_prompt_asks_each_field(monkeypatch: pytest.MonkeyPatch,
                                                capsys: pytest.CaptureFixture[str]) -> None:
    from edingcnc_lang.cli.mdi_cmd import ask_dialog
    from edingcnc_lang.host import DialogField

    typed = iter(["", "x", "2.5", "y"])
    monkeypatch.setattr("builtins.input", lambda _prompt: next(typed))
    answer = ask_dialog("Setup", [DialogField("Width", 27, 10.0), DialogField("Length", 28, 5.0)])
    assert (answer.ok, dict(answer.values)) == (True, {28: 2.5})
    assert "'x' is not a number" in capsys.readouterr().out

    def interrupted(_prompt: str) -> str:
        raise KeyboardInterrupt

    monkeypatch.setattr("builtins.input", interrupted)
    assert not ask_dialog("Setup", [DialogField("Width", 27, 10.0)]).ok


def test_the_machine_line_says_where_the_machine_is_under_g51() -> None:
    code, out, _ = mdi("G51 P2\nG1 X10 Y0 F600\n#5071\nG50\n#5071\n#5001\n")
    assert code == 0
    assert out == ["work    X10.0000 Y0.0000 Z0.0000 A0.0000 B0.0000 C0.0000",
                   "machine X20.0000 Y0.0000 Z0.0000 A0.0000 B0.0000 C0.0000",
                   "= 20", "= 20", "= 20"]
