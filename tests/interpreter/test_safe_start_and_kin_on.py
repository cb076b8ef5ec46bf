"""Issue 21 item 8: what a new user tripped on, in the interpreter (safe-start line, KIN ON)."""
from __future__ import annotations

from pathlib import Path

import pytest

from edingcnc_lang import EcncError, Move, RunOptions, run_string
from tests.cli_runner import invoke

SAFE_START = "G0 G90 G40 G21 G17 G94 G80\n"


def moves(source: str, **options: object) -> list[Move]:
    found: list[Move] = []
    run_string(source, RunOptions(on_move=lambda move, _joints: found.append(move), **options))  # type: ignore[arg-type]
    return found


def test_the_cam_safe_start_line_runs_and_means_g0() -> None:
    """rs274 lets G80 give way to the other motion code on its line: G0 stays the motion mode."""
    found = moves(SAFE_START + "X5 Y5\n")
    assert [m.kind for m in found] == ["rapid"]


@pytest.mark.parametrize("line", ["G80 G1 X2 F100\n", "G1 G80 X2 F100\n"])
def test_g80_gives_way_in_either_order(line: str) -> None:
    assert [m.kind for m in moves(line)] == ["linear"]


def test_two_real_motion_codes_still_conflict() -> None:
    with pytest.raises(EcncError, match="same modal group"):
        moves("G0 G1 X3\n")


def test_lint_accepts_the_safe_start_line(tmp_path: Path) -> None:
    (tmp_path / "job.nc").write_text(SAFE_START + "G0 G1 X3\n")
    out = invoke("lint", "--no-source", tmp_path / "job.nc").stdout
    assert ":1:" not in out and ":2:4: G500" in out


DELTA = Path(__file__).resolve().parents[2] / "examples" / "delta" / "cnc.ini"


def test_kin_on_outside_the_cartesian_limits_is_an_error_there(tmp_path: Path) -> None:
    """Not homed, the delta's effector is far below Z 0: KIN ON says so, not the next move."""
    (tmp_path / "job.nc").write_text("G0 X100 Y100 Z100\nKIN ON\nG0 Z60\n")
    result = invoke("run", "--ini", DELTA, tmp_path / "job.nc")
    assert result.exit_code == 70
    assert f"{tmp_path / 'job.nc'}:2:1: error: KIN ON (deltakins) finds the tool at X0.0000 Y0.0000 Z-116.5064" \
        in result.stderr
    assert "Z is outside the Cartesian limits [0, 200] of [KINEMATICS]" in result.stderr
    assert "home the machine" in result.stderr and "negativeLimitZ/positiveLimitZ" in result.stderr


def test_kin_on_exactly_at_a_limit_is_fine() -> None:
    """The homed delta's effector is at Z 200, the upper limit: the example job runs."""
    job = DELTA.parent / "job.nc"
    assert invoke("run", "--ini", DELTA, job).exit_code == 0
