"""Nose-radius compensation on a lathe (G41/G42 in G18) with the tool's orientation 1..9: the path is
computed for the nose's centre and the machine is sent the tool's controlled point, as the manual's
figure (pp. 5-6: orientation 2 is X -r, Z -r; 9 has none) and LinuxCNC's latheorigin_x/z agree."""
from __future__ import annotations

from pathlib import Path

import pytest

from edingcnc_lang import RunOptions, run_string
from edingcnc_lang.canon import Move
from edingcnc_lang.pipeline.comp_geometry import tip_shift

RADIUS = 0.4
# turn X10 (radius) from Z1 to Z-10, then a shoulder out to X14: G42 keeps the tool above the part
TURN = "T1 M6\nG0 X12 Z2\nG42 D1\nG1 X10 Z1 F100\nG1 Z-10\nG1 X14\nG40\nG0 X16 Z2\n"
# the manual's turning example (3.6.11.2 E, diameter programming, R arcs), with the nose of T1
MANUAL = ("T1 M6\ng0 x-20 z20\ng41.1 d0.8\ng1 x-20 z10 f100\ng3 x0 z0 r10\ng1 x20\ng2 x40 z-10 r10\ng1 z-20\n"
          "g3 x60 z-30 r10\ng40\nG0 X80\n")


def _moves(tmp_path: Path, job: str, orientation: int, diameter: bool = False) -> list[Move]:
    ini = tmp_path / "cnc.ini"
    ini.write_text(f"[SYSTEM]\nmachineType = 1\n[INTERPRETER]\ndiameterProgramming = {int(diameter)}\n"
                   f"[TOOL_1]\ndiameter = {2 * RADIUS}\norientation = {orientation}\n")
    (tmp_path / "macro.cnc").write_text(";@unit mm\n")
    moves: list[Move] = []
    run_string(job, RunOptions(ini=ini, macro=tmp_path / "macro.cnc", on_move=lambda m, _j: moves.append(m)))
    return moves


def test_orientation_2_cuts_the_programmed_diameter_and_shoulder(tmp_path: Path) -> None:
    """A turning tool's tip (orientation 2) is X -r, Z -r from the nose centre: a cut along Z lies
    on the programmed X and a shoulder on the programmed Z, as if uncompensated."""
    moves = _moves(tmp_path, TURN, 2)
    turn, shoulder = moves[2], moves[3]
    assert (turn.end[0], turn.end[2]) == pytest.approx((10.0, -10.0))
    assert shoulder.end[2] == pytest.approx(-10.0)
    centre = _moves(tmp_path, TURN, 9)  # orientation 9: the nose centre itself, a radius off the contour
    assert (centre[2].end[0], centre[2].end[2]) == pytest.approx((10.4, -9.6))


@pytest.mark.parametrize("orientation", range(1, 10))
@pytest.mark.parametrize("job, diameter", [(TURN, False), (MANUAL, True)], ids=["turn", "manual"])
def test_every_compensated_point_is_the_centre_path_moved_to_the_tip(tmp_path: Path, orientation: int, job: str,
                                                                      diameter: bool) -> None:
    centre, tip = _moves(tmp_path, job, 9, diameter), _moves(tmp_path, job, orientation, diameter)
    dx, dz = tip_shift(orientation, RADIUS)
    assert len(centre) == len(tip)
    assert tip[0].end == centre[0].end and tip[1].start == centre[1].start  # up to the entry: as programmed
    for i in range(1, len(centre) - 1):  # the entry move .. the last compensated move
        assert tip[i].end[0] == pytest.approx(centre[i].end[0] + dx)
        assert tip[i].end[2] == pytest.approx(centre[i].end[2] + dz)
        if centre[i].arc is not None:
            assert tip[i].arc is not None
            assert tip[i].arc.center == pytest.approx((centre[i].arc.center[0] + dx, centre[i].arc.center[1] + dz))
    assert tip[-1].start == pytest.approx(tip[-2].end) and tip[-1].end == centre[-1].end  # exit from the tip


def test_the_table_matches_the_manuals_figure_and_linuxcnc() -> None:
    assert tip_shift(2, 1.0) == (-1.0, -1.0)       # manual: orientation 2, X -r and Z -r
    assert tip_shift(9, 1.0) == (0.0, 0.0)         # manual: no offset for 9
    assert tip_shift(0, 1.0) == (0.0, 0.0)         # a mill's tool
    assert [tip_shift(o, 1.0) for o in (1, 3, 4, 5, 6, 7, 8)] == [
        (-1.0, 1.0), (1.0, -1.0), (1.0, 1.0), (0.0, 1.0), (-1.0, 0.0), (0.0, -1.0), (1.0, 0.0)]
