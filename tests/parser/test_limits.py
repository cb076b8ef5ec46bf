"""The input limits (edingcnc_lang/syntax/input_limits.py): each refused with a clear error by parse, lint and run,
and input right at every limit goes through every stage (parse, JSON, print, run, lint)."""
from __future__ import annotations

import json
from pathlib import Path

import pytest

from edingcnc_lang import run_string
from edingcnc_lang.syntax.input_limits import (
    MAX_BLOCK_DEPTH,
    MAX_BRACKET_DEPTH,
    MAX_LINE_LENGTH,
    MAX_LINE_OPERATORS,
    line_problem,
)
from edingcnc_lang.lint import lint_paths
from edingcnc_lang.syntax.parser import parse_text
from edingcnc_lang.syntax.printer import program_text
from edingcnc_lang.syntax.serialize import to_data
from edingcnc_lang.syntax.source import iter_file_lines
from tests.cli_runner import invoke

PAST_THE_LIMITS = [  # (source, line, code, start of the message): the reproductions among them
    pytest.param("#1 = " + "-" * 1000 + "1\n", 1, "E111", "expression too complex", id="1000 signs"),
    pytest.param("#1 = " + "SQRT[" * 500 + "1" + "]" * 500 + "\n", 1, "E111", "expression too complex",
                 id="500 nested SQRT"),
    pytest.param("#1 = " + "#" * 1000 + "1\n", 1, "E111", "expression too complex", id="1000 #"),
    pytest.param("#1 = " + "[" * 100_000 + "1" + "]" * 100_000 + "\n", 1, "E110", "line is longer",
                 id="100000 brackets"),
    pytest.param("#1 = " + "[" * 20_000 + "1" + "]" * 20_000 + "\n", 1, "E111", "brackets nested",
                 id="20000 brackets"),
    pytest.param("#1 = " + "+".join(["1"] * 5000) + "\n", 1, "E111", "expression too complex",
                 id="5000-term sum"),
    pytest.param("G0 X1\nG0 X" + "9" * 10_000_000 + "\n", 2, "E110", "line is longer", id="10M digits"),
    pytest.param("G0 X" + "9" * 401 + "\n", 1, "E113", "number with more than 400 digits", id="401 digits"),
    pytest.param("G0 X0." + "1" * 401 + "\n", 1, "E113", "number with more than 400 digits",
                 id="401 decimals"),
    pytest.param("If [1]\n" * 3000 + "G0 X1\n" + "EndIf\n" * 3000, 51, "E112", "blocks nested more than 50",
                 id="3000 nested If"),
]


@pytest.mark.parametrize(("source", "line", "code", "message"), PAST_THE_LIMITS)
def test_input_past_a_limit_is_a_clear_error_in_every_command(tmp_path: Path, source: str, line: int,
                                                             code: str, message: str) -> None:
    job = tmp_path / "job.nc"
    job.write_text(source)
    for command in ("parse", "run"):
        result = invoke(command, job)
        assert (result.exit_code, result.stdout) == (65, ""), command
        assert result.stderr.startswith(f"{job}:{line}:"), command
        assert f"error: {message}" in result.stderr.splitlines()[0], command
    assert (line, code) in [(d.line, d.code) for d in lint_paths([job])]


def _at_the_limits() -> list[str]:
    k = MAX_LINE_OPERATORS - 1  # "If [" holds one (and one bracket)
    brackets = MAX_BRACKET_DEPTH - 1
    return ["+".join(["1"] * (k + 1)), "-" * k + "1", "#" * k + "1", "SQRT[" * k + "1" + "]" * k,
            "[1+" * k + "1" + "]" * k, "[" * brackets + "1" + "]" * brackets,
            " EQ ".join(["1"] * (k + 1)), " and ".join(["1"] * (k + 1)), "**".join(["1"] * (k + 1))]


@pytest.mark.parametrize("expression", _at_the_limits(), ids=lambda e: e[:12])
def test_input_at_every_limit_goes_through_every_stage(tmp_path: Path, expression: str) -> None:
    # in an If condition: a G-code line holds at most 256 characters (manual 3.4, E114), a macro statement more
    depth = MAX_BLOCK_DEPTH - 1
    text = "If [0]\n" + "If [1]\n" * (depth - 1) + "If [" + expression + "]\nEndIf\n" + "EndIf\n" * depth + "M30\n"
    program = parse_text(text)
    printed = program_text(program)
    assert program_text(parse_text(printed)) == printed
    json.dumps(to_data(program))
    run_string(text)
    job = tmp_path / "job.nc"
    job.write_text(text)
    assert {d.code for d in lint_paths([job])} <= {"F601"}  # long lines: the only finding


def test_a_word_with_calls_prints_back_within_the_limits() -> None:
    calls = 49  # as many as a G-code line of 256 characters holds with the printer's bracket (manual 3.4)
    text = "G1 A " + "SIN[" * calls + "0" + "]" * calls + "\n"
    printed = program_text(parse_text(text))
    assert printed.startswith("G1 A[SIN[")  # the printer's bracket is not an operator
    assert program_text(parse_text(printed)) == printed


def test_a_huge_line_is_read_only_up_to_the_limit(tmp_path: Path) -> None:
    job = tmp_path / "job.nc"
    job.write_bytes(b"G0 X1\n" + b"x" * (8 << 20) + b"\r\nG0 X2\n" + b"y" * (3 << 20))
    lines = list(iter_file_lines(job))
    assert [len(line) > MAX_LINE_LENGTH for line in lines] == [False, True, False, True]
    assert max(map(len, lines)) <= 4 * (MAX_LINE_LENGTH + 1)
    assert (lines[0], lines[2]) == ("G0 X1", "G0 X2")


def test_the_limits_leave_long_real_lines_alone(tmp_path: Path) -> None:
    # a macro statement of 30,000 characters, a G-code line of the manual's 256 (3.4) with a long expression
    message = 'msg "' + " ".join(f"X{i}.125" for i in range(3000)) + '"'
    assert len(message) < MAX_LINE_LENGTH
    code = "#1 = [[#2 + 1] * [#3 - 2]] / SQRT[#4 + 16] ; "
    parse_text(message + "\n" + code + "-" * (256 - len(code)) + "\n")



def test_the_length_guard_of_line_problem_is_exact() -> None:
    """A line of MAX_LINE_OPERATORS characters cannot pass a limit; one more operator can."""
    assert line_problem("#" * MAX_LINE_OPERATORS) is None
    problem = line_problem("#" * (MAX_LINE_OPERATORS + 1))
    assert problem is not None and problem[0] == "E111"
