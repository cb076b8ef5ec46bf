"""Offsets changed under G68 never move the machine: the pivot moves with the work offsets, so the
current point is re-expressed about it (G5x, G10 L2, G43, G92.x) or solved through the rotation
(G92 and G10 L20 make it read what they say)."""
from __future__ import annotations

from pathlib import Path

import pytest

from edingcnc_lang.runner import RunOptions, run_string
from tests.interpreter.test_scaling import EMPTY_MACRO, trace_rows

START = "G10 L2 P2 X7 Y-3\nG10 L1 P1 Z-12\nG0 X10 Y0 Z5\nG68 X2 Y1 R90\nG0 Z20\n#1 = #5071 #2 = #5072\n"
AFTER = "#3 = #5071 #4 = #5072 #5 = #5001 #6 = #5002\nG0 Z10\nG1 Z2 F100\nG0 Z30\nM30\n"

CHANGES = {
    "G92": ("G92 X0 Y0", (0.0, 0.0)),
    "G92 X only": ("G92 X4", (4.0, None)),
    "G10 L20 P0": ("G10 L20 P0 X1 Y2", (1.0, 2.0)),
    "G10 L20 P1": ("G10 L20 P1 X-1 Y0", (-1.0, 0.0)),
    "G10 L2 active": ("G10 L2 P1 X3 Y4", None),
    "G54 to G55": ("G55", None),
    "G43": ("G43 H1", None),
    "G92 then G92.1": ("G92 X0 Y0\nG92.1", None),
    "macro writes #5221": ("#5221 = 6", None),
    "with G51 too": ("G51 P2\nG92 X0 Y0", (0.0, 0.0)),
}


def source(change: str) -> str:
    return START + change + "\n" + AFTER


@pytest.mark.parametrize("name", CHANGES)
def test_no_move_after_an_offset_change_under_g68_moves_x_or_y(tmp_path: Path, name: str) -> None:
    rows = trace_rows(tmp_path, source(CHANGES[name][0]))
    assert [row[0] for row in rows][:2] == [3, 5] and len(rows) == 5
    assert {row[1:3] for row in rows} == {(10.0, 0.0)}  # every later line programs Z only


@pytest.mark.parametrize("name", CHANGES)
def test_the_machine_position_stays_and_g92_g10_l20_read_what_they_say(name: str) -> None:
    change, reading = CHANGES[name]
    result = run_string(source(change), RunOptions(macro=EMPTY_MACRO), path="job.nc")
    v = result.variables
    assert (v[1], v[2]) == pytest.approx((10.0, 0.0)) and (v[3], v[4]) == pytest.approx((10.0, 0.0))
    for axis, wanted in enumerate(reading or ()):
        if wanted is not None:
            assert v[5 + axis] == pytest.approx(wanted)


def test_g43_under_g68_shifts_only_z() -> None:
    result = run_string(source("G43 H1"), RunOptions(macro=EMPTY_MACRO), path="job.nc")
    assert result.machine == pytest.approx((10.0, 0.0, 18.0, 0.0, 0.0, 0.0))  # Z30 with a -12 mm tool


def test_g10_l20_of_another_system_reads_what_it_says_once_selected() -> None:
    result = run_string(source("G10 L20 P2 X1 Y2\nG55"), RunOptions(macro=EMPTY_MACRO), path="job.nc")
    v = result.variables
    assert (v[3], v[4], v[5], v[6]) == pytest.approx((10.0, 0.0, 1.0, 2.0))


def test_g92_x_only_keeps_the_y_reading_and_the_next_move_runs_in_the_turned_frame(tmp_path: Path) -> None:
    # machine (10, 0) reads work (1, -7) about the pivot (2, 1); after G92 X4 it reads (4, -7), and
    # G1 X6 goes 2 along the turned X, which is machine +Y
    rows = trace_rows(tmp_path, "G0 X10 Y0\nG68 X2 Y1 R90\nG92 X4\nG1 X6 F100\nM30\n")
    assert rows[-1] == (4, 10.0, 2.0, 0.0)
