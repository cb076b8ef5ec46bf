"""G51/G50 end to end: parameters, what ends scaling, refusals, and the CLI's exit code."""
from __future__ import annotations

import json
from pathlib import Path

import pytest

from edingcnc_lang.canon import Move
from edingcnc_lang.runner import RunOptions, RunResult, run_string
from tests.cli_runner import invoke

EMPTY_MACRO = Path(__file__).parent / "data" / "empty_macro.cnc"


def run(source: str) -> tuple[RunResult, list[tuple[int, float, float]]]:
    moves: list[Move] = []
    result = run_string(source, RunOptions(macro=EMPTY_MACRO, on_move=lambda m, _j: moves.append(m)), path="job.nc")
    return result, [(m.line, round(m.end[0], 4) + 0.0, round(m.end[1], 4) + 0.0) for m in moves]


def test_g51_p_about_i_j_in_work_coordinates_sets_the_parameters() -> None:
    result, moves = run("G10 L2 P1 X100\nG51 P0.5 I10 J0\n#1 = #5200\nG1 X30 Y20 F100\nG50\n#2 = #5200\nG1 X0 Y0\n")
    assert moves == [(4, 120.0, 10.0), (7, 100.0, 0.0)]
    v = result.variables
    assert (v[1], v[2], v[5201], v[5202], v[5204], v[5205], v[5206]) == (1.0, 0.0, 10.0, 0.0, 0.5, 0.5, 1.0)


def test_per_axis_factors_in_inch_mode_and_m30_ends_scaling() -> None:
    result, moves = run("G20\nG51 X2 Y3\nG1 X1 Y1 F10\nM30\n")
    assert moves == [(3, 50.8, 76.2)] and result.variables[5200] == 0.0


def test_arcs_scale_with_p() -> None:
    _, moves = run("G51 P2\nG2 X10 Y0 I5 J0 F100\n")
    assert moves == [(2, 20.0, 0.0)]


def test_the_cli_exits_70_naming_the_line(tmp_path: Path) -> None:
    job = tmp_path / "job.nc"
    job.write_text("G51 X2 Y1\nG1 X10 F100\nG3 X0 Y0 R10\n")
    result = invoke("run", job)
    assert result.exit_code == 70 and f"{job}:3:" in result.stderr and "different factors" in result.stderr


def trace_rows(tmp_path: Path, source: str) -> list[tuple[int, float, float, float]]:
    """The ``--trace -`` rows of a job: line, machine x, y, z."""
    job = tmp_path / "job.nc"
    job.write_text(source)
    trace = tmp_path / "trace.csv"
    result = invoke("run", job, "--macro", EMPTY_MACRO, "--trace", trace)
    assert result.exit_code == 0, result.stderr
    rows = [row.split(",") for row in trace.read_text().splitlines()[1:]]
    return [(int(r[0]), round(float(r[2]), 6) + 0.0, round(float(r[3]), 6) + 0.0, float(r[4])) for r in rows]


@pytest.mark.parametrize(("source", "z_move"), [
    ("G0 X0 Y0 Z5\nG51 P2\nG1 X10 Y5 F600\nG50\nG0 Z20\nM30\n", (5, 20.0, 10.0, 20.0)),      # G51 off
    ("G0 X10 Y0 Z5\nG51 P2\nG0 Z20\nM30\n", (3, 10.0, 0.0, 20.0)),                          # G51 on
    ("G0 X10 Y0 Z5\nG68 X0 Y0 R90\nG0 Z20\nM30\n", (3, 10.0, 0.0, 20.0)),                   # G68 on
    ("G68 X0 Y0 R90\nG0 X10 Y0 Z5\nG69\nG1 Z1 F100\nM30\n", (4, 0.0, 10.0, 1.0)),           # G68 off
    ("G0 X10 Y0 Z5\nG51 P2\nG68 R90\nG51 P3\nG0 Z7\nG50\nG69\nG0 Z1\nM30\n", None),          # all at once
])
def test_switching_a_transform_never_moves_the_machine(tmp_path: Path, source: str,
                                                        z_move: tuple[int, float, float, float] | None) -> None:
    rows = trace_rows(tmp_path, source)
    if z_move is not None:
        assert rows[-1] == z_move
    assert {row[1:3] for row in rows} == {(10.0, 0.0)} or z_move is not None
    for before, after in zip(rows, rows[1:]):  # every Z-only line keeps X and Y where the machine was
        assert after[1:3] == before[1:3] or source.splitlines()[after[0] - 1].startswith("G1 X")


def test_machine_position_parameters_follow_the_machine_through_g51_g50_and_m30(tmp_path: Path) -> None:
    source = ("G0 X10 Y0\nG51 P2\n#1 = #5071 #2 = #5001\nG1 X10 Y10 F600\n#3 = #5071 #4 = #5001\n"
              "G50\n#5 = #5071 #6 = #5001\nG51 P2\nM30\n")
    result, _ = run(source)
    v = result.variables
    assert (v[1], v[2], v[3], v[4], v[5], v[6]) == (10.0, 5.0, 20.0, 10.0, 20.0, 20.0)
    assert result.machine == result.joints == result.position == (20.0, 20.0, 0.0, 0.0, 0.0, 0.0)
    job = tmp_path / "m30.nc"
    job.write_text("G51 P2\nG1 X10 Y10 F600\nM30\n")
    out = invoke("run", job, "--macro", EMPTY_MACRO, "--json")
    report = json.loads(out.stdout)
    assert report["machine"] == report["joints"] == {"x": 20.0, "y": 20.0, "z": 0.0, "a": 0.0, "b": 0.0, "c": 0.0}
