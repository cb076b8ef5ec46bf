"""G68 through the rotation stage: what stays in machine coordinates, and what follows the offsets."""
from __future__ import annotations

from pathlib import Path

import pytest

from edingcnc_lang.canon import Move, Pose
from edingcnc_lang.host import Host
from edingcnc_lang.runner import RunOptions, RunResult, run_string

EMPTY_MACRO = Path(__file__).parent / "data" / "empty_macro.cnc"


def run(source: str, host: Host | None = None) -> tuple[RunResult, list[tuple[float, float]]]:
    moves: list[Move] = []
    result = run_string(source, RunOptions(macro=EMPTY_MACRO, host=host or Host(),
                                           on_move=lambda m, _j: moves.append(m)), path="job.nc")
    return result, [(round(m.end[0], 6) + 0.0, round(m.end[1], 6) + 0.0) for m in moves]


def test_g53_g28_and_homing_stay_in_machine_coordinates() -> None:
    result, moves = run("#5161 = 7 #5162 = 8\nG68 R90\nG0 X10 Y0\nG53 G0 X3\nG28 X3 Y0\n#1 = #5071 #2 = #5001\n")
    # (10, 0) turned is (0, 10); G53 X3 keeps the machine Y; G28 X3 Y0 goes via (0, 3) turned to (-3, 3)
    assert moves == [(0.0, 10.0), (3.0, 10.0), (0.0, 3.0), (7.0, 8.0)]
    assert result.machine[:2] == pytest.approx((7.0, 8.0)) and result.variables[1] == pytest.approx(7.0)
    assert result.variables[2] == pytest.approx(8.0)  # work X of machine (7, 8) turned back by 90 degrees


def test_the_probe_host_sees_machine_coordinates() -> None:
    seen: list[tuple[Pose, Pose]] = []

    def probe(start: Pose, target: Pose) -> Pose:
        seen.append((start, target))
        return target

    result, _ = run("G68 R90\nG38.2 X10 F100\n#1 = #5061 #2 = #5051 #3 = #5052\n", Host(probe=probe))
    assert seen[0][1][:2] == pytest.approx((0.0, 10.0))
    v = result.variables
    assert (v[1], v[2], v[3]) == pytest.approx((10.0, 0.0, 10.0))


def test_the_pivot_follows_a_later_g92() -> None:
    # G68 keeps the machine at X5 (work point (10, 5) in the turned frame); G92 X0 makes that point read
    # (0, 5) without moving the machine, so the pivot (work (10, 0)) sits at machine (5, 10); work
    # (20, 0) is 20 along the turned X (machine +Y) and 5 back along the turned Y (machine +X): (10, 20)
    result, moves = run("G0 X5\nG68 X10 Y0 R90\nG92 X0\n#1 = #5071 #2 = #5072 #3 = #5001 #4 = #5002\n"
                        "G0 X20 Y0\n")
    v = result.variables
    assert (v[1], v[2], v[3], v[4]) == pytest.approx((5.0, 0.0, 0.0, 5.0))
    assert moves[-1] == pytest.approx((10.0, 20.0))
