"""An arc becomes a full circle only when its ends meet (issue 28, item 7): fullCircleThetaEpsilon
applies to an I/J arc whose ends coincide at the program's precision, never to an R arc and never
to an arc whose ends differ; the interpreter decides once and every stage after it (timing,
sampling, limits, pictures) follows that decision."""
from __future__ import annotations

import math

import pytest

from edingcnc_lang.canon import Move
from edingcnc_lang.runner import RunOptions, run_string


def arcs(job: str) -> tuple[list[Move], object]:
    moves: list[Move] = []
    result = run_string("G17 G0 X0 Y0\n" + job + "\nM30\n", RunOptions(on_move=lambda m, _j: moves.append(m)))
    return [m for m in moves if m.kind == "arc"], result


@pytest.mark.parametrize("line", ["G2 X0.000001 Y0 R5 F100", "G2 X10 Y0 R10000000 F100", "G2 X0.001 Y0 I0.0005 J-5 F100"])
def test_an_arc_whose_ends_differ_is_never_a_full_circle(line: str) -> None:
    found, result = arcs(line)
    assert found[0].arc is not None and found[0].arc.full_turns == 0
    assert result.estimate is not None and result.estimate.feed_distance < 11  # not 31 mm round


def test_an_ij_arc_whose_ends_meet_is_a_full_circle() -> None:
    found, result = arcs("G2 X0 Y0 I5 J0 F100")
    assert found[0].arc is not None and found[0].arc.full_turns == 1
    assert result.estimate.feed_distance == pytest.approx(10 * math.pi)


def test_the_epsilon_still_closes_an_ij_circle_rounded_at_the_last_digit() -> None:
    found, _ = arcs("G2 X0.0000001 Y0 I5 J0 F100")  # 2e-8 rad: below the ini's 1e-6
    assert found[0].arc is not None and found[0].arc.full_turns == 1


def test_a_huge_radius_arc_stays_inside_the_limits() -> None:
    _, result = arcs("G2 X10 Y0 R10000000 F100")
    assert result.error is None
