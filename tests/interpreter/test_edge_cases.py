"""Edge cases found in review: state after a refused move, step counting, unsupported codes, I/O errors."""
from __future__ import annotations

import json
import subprocess
import sys
from pathlib import Path

import pytest

from edingcnc_lang import EcncError, Move, RunOptions, run_file, run_string
from tests.cli_runner import invoke

INI = "[JOINT_0]\npositiveLimit = 600\nnegativeLimit = 0\n"


@pytest.mark.parametrize("source", ["G1 X10 F100\nX700\n", "G1 X10 F100\nIf [1]\nX700\nEndIf\n"],
                         ids=["bulk path", "general path"])
def test_a_move_out_of_limits_leaves_the_machine_where_it_was(tmp_path: Path, source: str) -> None:
    (tmp_path / "cnc.ini").write_text(INI)
    job = tmp_path / "job.nc"
    job.write_text(source)
    result = invoke("run", "--ini", tmp_path / "cnc.ini", "--json", job)
    assert result.exit_code == 70
    state = json.loads(result.stdout[: result.stdout.rindex("}") + 1])
    assert state["machine"]["x"] == state["joints"]["x"] == 10.0
    assert state["moves"] == 1
    assert "G1" in state["modal"]


def test_the_step_budget_counts_lines_the_same_in_files_and_strings(tmp_path: Path) -> None:
    source = "G1 X10 F100\nX20\nX30\n"
    job = tmp_path / "job.nc"
    job.write_text(source)
    for budget in range(1, 7):
        outcomes = []
        for run in (lambda o: run_file(job, o), lambda o: run_string(source, o, path=str(job))):
            try:
                outcomes.append(run(RunOptions(max_steps=budget)).moves)
            except EcncError as err:
                outcomes.append(err.format())
        assert outcomes[0] == outcomes[1], budget
    assert outcomes[0] == 3


def test_g74_and_g87_run_as_cycles_never_as_probe_moves() -> None:
    moves: list[Move] = []
    run_string("M4 S100 G0 Z5\nG74 X1 Z-1 R1 F1\nG87 X1 Z-1 R1 K0 F100\n",  # both need the spindle turning
               RunOptions(on_move=lambda m, _j: moves.append(m)))
    assert "probe" not in {m.kind for m in moves} and {m.line for m in moves} == {1, 2, 3}
    with pytest.raises(EcncError) as info:
        run_string("G0 Z5\nG87 X1 Z-1 R1 F100\n")
    assert "G87 needs K" in info.value.message


def test_feed_per_revolution_in_inches_is_converted() -> None:
    moves: list[Move] = []
    # G20 on its own line: within a line F is read before the units change (order of execution)
    run_string("G20\nG95 F0.01 S1000 M3\nG1 X1\n", RunOptions(on_move=lambda m, _j: moves.append(m)))
    assert moves[-1].feed == pytest.approx(254.0)


def test_g43_1_takes_the_length_from_k() -> None:
    result = run_string("G43.1 K5\nG0 Z0\n")
    assert result.variables[5013] == 5.0
    assert result.machine[2] == 5.0


def test_g28_makes_no_zero_length_move() -> None:
    moves: list[Move] = []
    run_string("#5161=10\n#5163=-20\nG0 X5 Z5\nG28 Z7\nG28\n", RunOptions(on_move=lambda m, _j: moves.append(m)))
    assert [m.end[:3] for m in moves if m.line == 4] == [(5.0, 0.0, 7.0), (10.0, 0.0, 7.0), (10.0, 0.0, -20.0)]
    assert [m for m in moves if m.line == 5] == []  # already home: nothing moves


def test_an_unwritable_trace_is_an_error_not_a_traceback(tmp_path: Path) -> None:
    job = tmp_path / "job.nc"
    job.write_text("G0 X1\n")
    result = subprocess.run([sys.executable, "-m", "edingcnc_lang", "run", str(job), "--trace", "/dev/full"],
                            check=False, capture_output=True, text=True)
    assert result.returncode == 70
    assert "error: cannot write" in result.stderr and "Traceback" not in result.stderr


def test_brackets_up_to_the_limit_parse_and_deeper_ones_are_refused(tmp_path: Path) -> None:
    job = tmp_path / "deep.nc"
    # (in an If condition: a G-code line holds at most 256 characters, manual 3.4, E114)
    job.write_text("If [" + "[" * 199 + "1" + "]" * 199 + "]\nEndIf\n")
    result = invoke("parse", job)
    assert result.exit_code == 0, result.output
    job.write_text("If [" + "[" * 200 + "1" + "]" * 200 + "]\nEndIf\n")
    result = invoke("parse", job)
    assert result.exit_code == 65
    assert result.output.startswith(f"{job}:1:204: error: brackets nested more than 200 deep")
