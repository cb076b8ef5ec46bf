"""G76 passes (thread_passes.py): the pass pattern against hand-checked LinuxCNC numbers (the words
read as EdingCNC defines them: I the crest position, J and K radial), and the cycle's errors."""
from __future__ import annotations

import math

import pytest
from hypothesis import given
from hypothesis import strategies as st

from edingcnc_lang.machine.thread_passes import G76Words, ThreadError, ThreadMove, g76


def words(**changes: float | None) -> G76Words:
    base = dict(p=1.5, z=-20.0, i=12.0, j=0.15, k=0.75)  # crest radius 12, from X 12.5: outside
    return G76Words(**{**base, **changes})  # type: ignore[arg-type]


def test_first_pass_matches_linuxcnc() -> None:
    # rs274 -g, G7 G76 P1.5 Z-20 I-1 J0.3 K1.5 R2 Q29.5 H2 E1 L2 from X25 Z5 (radius 12.5): the crest at
    # radius 12 and radial depths 0.15 and 0.75, which EdingCNC writes G76 P1.5 Z-20 I24 J0.15 K0.75 ...
    moves = g76(words(r=2, q=29.5, h=2, e=1, l=2), 12.5, 5.0)
    expect = [("rapid", 13.1, 4.9151), ("rapid", 11.85, 4.9151), ("sync", 11.85, -18.6605),
              ("sync", 12.6, -19.6605), ("rapid", 13.1, -19.6605)]
    for move, (kind, x, z) in zip(moves, expect):
        assert (move.kind, round(move.x, 4), round(move.z, 4)) == (kind, x, z)
    assert moves[2].pitch == 1.5
    assert moves[3].pitch == pytest.approx(1.5 * math.hypot(1.0, 0.75))
    assert moves[-1] == ThreadMove("rapid", 12.5, -20.0)
    # 1 + spring passes at full depth, ending exactly at the exit taper
    assert [round(m.x, 4) for m in moves[-6:-1]] == [12.5, 11.25, 11.25, 12.0, 12.5]


def test_pass_depths_follow_the_degression() -> None:
    moves = g76(words(i=9.5, j=0.1, k=0.4, r=1.0), 10.0, 0.0)
    cuts = [round(10.0 - 0.5 - m.x, 6) for m in moves if m.kind == "sync"]
    assert cuts == [0.1, 0.2, 0.3, 0.4]
    moves = g76(words(i=9.5, j=0.1, k=0.4, r=2.0), 10.0, 0.0)
    cuts = [round(10.0 - 0.5 - m.x, 6) for m in moves if m.kind == "sync"]
    assert cuts == [round(0.1 * n ** 0.5, 6) for n in range(1, 16)] + [0.4]


def test_inside_thread_cuts_outwards_and_positive_z_reverses_the_compound() -> None:
    moves = g76(words(i=5.5, z=20.0, q=30.0), 5.0, 0.0)  # from inside the crest: an inside thread
    first_cut = next(m for m in moves if m.kind == "sync")
    assert first_cut.x == pytest.approx(5.0 + 0.5 + 0.15)
    assert moves[0].z == pytest.approx(0.15 * math.tan(math.radians(30)))
    assert moves[0].x == pytest.approx(5.0 - 0.75 + 0.15)  # retracted towards the centre


@pytest.mark.parametrize("change, message", [
    (dict(p=None), "needs P"),
    (dict(p=-1.0), "pitch must be greater than 0"),
    (dict(j=-0.1), "first cut depth must be greater than 0"),
    (dict(k=-1.0), "thread depth must be greater than 0"),
    (dict(k=0.1), "must be greater than J"),
    (dict(h=-1.0), "spring passes"),
    (dict(r=0.5), "degression must be at least 1"),
    (dict(e=13.0), "longer than half the drive line"),
    (dict(e=-1.0), "must not be negative"),
    (dict(l=4.0), "taper must be 0"),
    (dict(z=5.0), "no length"),
])
def test_errors(change: dict, message: str) -> None:
    with pytest.raises(ThreadError, match=message):
        g76(words(**change), 12.5, 5.0)


def test_pass_budget() -> None:
    with pytest.raises(ThreadError, match="more than"):
        g76(words(j=1e-6, k=1.0, r=5.0), 12.5, 5.0)


@given(j=st.floats(0.05, 0.5), extra=st.floats(0.01, 2.0), r=st.floats(1.0, 2.0), q=st.floats(0, 45),
       h=st.integers(0, 3))
def test_every_pass_stays_between_crest_and_depth(j: float, extra: float, r: float, q: float, h: int) -> None:
    k = j + extra
    moves = g76(words(i=19.5, j=j, k=k, r=r, q=q, h=h), 20.0, 0.0)
    cuts = [m for m in moves if m.kind == "sync"]
    crest = 19.5
    assert all(crest - k - 1e-9 <= m.x <= crest - j + 1e-9 for m in cuts)
    assert [round(c.x, 9) for c in cuts] == sorted((round(c.x, 9) for c in cuts), reverse=True)
    full = sum(1 for c in cuts if abs(c.x - (crest - k)) < 1e-9)
    assert h + 1 <= full <= h + 2  # a last degression pass may land within rounding of K


def test_the_side_comes_from_the_start_against_the_crest() -> None:
    """On the crest (the turning macros' external cycle starts at X = I) and outside it: outside
    threads; inside it (their internal cycle starts in the bore): an inside thread. Every retract
    stays on the start's side of the crest, out of the material."""
    for start in (6.0, 7.0):
        moves = g76(words(i=6.0, j=0.08, k=0.6135), start, 0.0)
        assert all(6.0 - 0.6135 - 1e-9 <= m.x <= 6.0 for m in moves if m.kind == "sync")
        assert all(m.x >= 6.0 for n, m in enumerate(moves) if n % 4 in (0, 3))  # each pass: in, cut, out
    moves = g76(words(i=5.4585, j=0.08, k=0.5415), 4.9585, 0.0)
    assert all(5.4585 <= m.x <= 6.0 + 1e-9 for m in moves if m.kind == "sync")
    assert all(m.x <= 5.4585 for n, m in enumerate(moves) if n % 4 in (0, 3))
