"""Lathe threading: the passes of the G76 cycle, as plain moves in the XZ plane.

Data in, moves out, like ``cycles.py``: the interpreter checks the words it owns (plane, axis
words, I's sign), converts lengths to mm and X positions to radii, and turns each ``ThreadMove``
into a machine move.  The words are read as the EdingCNC manual (3.6.18) defines them; the pass
pattern is the one LinuxCNC's G76 makes (the manual's text is LinuxCNC's), see docs/lathe.md:

- the drive line is the current X, from the current Z to the Z word;
- I is the thread's crest, an X position (the manual: the thread's diameter, always positive);
  the drive line outside it (or on it) makes an outside thread, inside it an inside thread;
- J is the first cut's depth beyond the crest, K the full thread depth, both radial;
- pass n cuts to J * n**(1/R) beyond the crest until K is reached, then K once more and H
  spring passes;
- Q is the compound angle: each pass starts (depth - crest) * tan(Q) further back along Z;
- E and L add a taper of length E at the entry (L1), the exit (L2) or both (L3).
"""
from __future__ import annotations

import math
from collections.abc import Mapping


from edingcnc_lang.syntax.input_limits import MAX_THREAD_PASSES
from edingcnc_lang.records import record

class ThreadError(ValueError):
    """G76 words that describe no thread; the message is for the user."""


@record(frozen=True, slots=True)
class ThreadMove:
    """One move of the cycle: a rapid, or a spindle-synchronised cut advancing ``pitch`` per rev.

    ``pitch`` is the path length per spindle revolution (a taper cut runs longer per turn so its
    Z lead stays the thread's pitch), as LinuxCNC synchronises it.
    """

    kind: str  # "rapid" | "sync"
    x: float
    z: float
    pitch: float = 0.0


@record(frozen=True, slots=True)
class G76Words:
    """The cycle's words in mm; ``i`` the crest's X position (a radius, machine coordinates), ``j``
    and ``k`` radial depths; ``None`` = not on the line."""

    p: float | None
    z: float | None
    i: float | None
    j: float | None
    k: float | None
    r: float | None = None
    q: float | None = None
    h: float | None = None
    e: float | None = None
    l: float | None = None


def _check(w: G76Words, start_z: float, written: Mapping[str, float]) -> None:
    """Refuse words that describe no thread, quoting them as the program wrote them (``written``:
    before inch and diameter conversion, so ``J-0.3`` in diameter mode is not reported as J-0.15)."""
    def shown(letter: str) -> str:
        value = getattr(w, letter.lower())
        return f"{letter}{written.get(letter, value):g}"

    for letter in "PZIJK":
        if getattr(w, letter.lower()) is None:
            raise ThreadError(f"G76 needs {letter} (P pitch, Z end, I crest diameter, J first cut, K depth)")
    assert w.p is not None and w.z is not None and w.i is not None and w.j is not None and w.k is not None
    if w.p <= 0:
        raise ThreadError(f"G76 {shown('P')}: the pitch must be greater than 0")
    if w.j <= 0:
        raise ThreadError(f"G76 {shown('J')}: the first cut depth must be greater than 0")
    if w.k <= 0:
        raise ThreadError(f"G76 {shown('K')}: the thread depth must be greater than 0")
    if w.k <= w.j:
        raise ThreadError(f"G76 {shown('K')} must be greater than {shown('J')} (the first cut)")
    if w.h is not None and (w.h < 0 or w.h != int(w.h)):
        raise ThreadError(f"G76 {shown('H')}: the number of spring passes must be a whole number >= 0")
    if w.r is not None and w.r < 1.0:
        raise ThreadError(f"G76 {shown('R')}: the depth degression must be at least 1")
    if w.l is not None and w.l not in (0, 1, 2, 3):
        raise ThreadError(f"G76 {shown('L')}: the taper must be 0 (none), 1 (entry), 2 (exit) or 3 (both)")
    if w.e is not None and w.e < 0:
        raise ThreadError(f"G76 {shown('E')}: the taper length must not be negative")
    drive = abs(w.z - start_z)
    if drive == 0:
        raise ThreadError("G76 Z is where the tool already is: the thread has no length")
    if w.e is not None and w.e > drive / 2:
        unit = written.get("E", w.e) / w.e  # the drive line in the program's units, as E is
        raise ThreadError(f"G76 {shown('E')} is longer than half the drive line ({drive / 2 * unit:g})")


def _depths(w: G76Words) -> list[float]:
    """Cut depths below the crest, pass by pass, the last repeated for the spring passes."""
    assert w.j is not None and w.k is not None
    degression = w.r if w.r is not None else 1.0
    depths = []
    n = 1
    depth = w.j
    while depth < w.k:
        depths.append(depth)
        n += 1
        if n > MAX_THREAD_PASSES:
            raise ThreadError(f"G76 J{w.j:g} K{w.k:g} R{degression:g} needs more than {MAX_THREAD_PASSES:,} passes "
                              "(the limit)")
        depth = w.j * n ** (1.0 / degression)
    spring = w.h or 0.0
    if len(depths) + 1 + spring > MAX_THREAD_PASSES:  # counted before the list is made
        raise ThreadError(f"G76 H{spring:g}: {len(depths) + 1} cut passes and {spring:g} spring passes are more "
                          f"than {MAX_THREAD_PASSES:,} passes (the limit)")
    return depths + [w.k] * (1 + int(spring))


def g76(w: G76Words, start_x: float, start_z: float,
        written: Mapping[str, float] | None = None) -> list[ThreadMove]:
    """Every move of the cycle from (start_x, start_z); the last one returns to the drive line at Z.

    ``written``: the words as programmed (letter -> value), for the error messages.
    """
    _check(w, start_z, written or {})
    assert w.p is not None and w.z is not None and w.i is not None and w.k is not None
    crest = w.i                            # the thread's crest line
    inward = -1.0 if start_x >= crest else 1.0  # from outside the crest: an outside thread, cut towards -X
    forward = -1.0 if w.z < start_z else 1.0  # direction of the cut along Z
    tan_q = math.tan(math.radians(w.q or 0.0))
    taper = w.e or 0.0
    flags = int(w.l or 0)
    taper_pitch = w.p * math.hypot(taper, w.k) / taper if taper > 0 else w.p
    end_z = w.z - forward * w.k * tan_q   # where a full-depth pass ends along the compound angle
    moves: list[ThreadMove] = []
    for cut in _depths(w):
        shift = forward * cut * tan_q      # the compound angle moves each deeper pass along Z
        z0, z1 = start_z + shift, end_z + shift
        x = crest + inward * cut
        x_clear = start_x - inward * (w.k - cut)   # retracted: the thread depth back from the cut
        x_taper = crest + inward * (cut - w.k)     # where a taper starts or ends
        moves.append(ThreadMove("rapid", x_clear, z0))
        if taper and flags & 1:
            moves.append(ThreadMove("sync", x_taper, z0, taper_pitch))
            moves.append(ThreadMove("sync", x, z0 + forward * taper, taper_pitch))
        else:
            moves.append(ThreadMove("rapid", x, z0))
        if taper and flags & 2:
            moves.append(ThreadMove("sync", x, z1 - forward * taper, w.p))
            moves.append(ThreadMove("sync", x_taper, z1, taper_pitch))
        else:
            moves.append(ThreadMove("sync", x, z1, w.p))
        moves.append(ThreadMove("rapid", x_clear, z1))
    moves.append(ThreadMove("rapid", start_x, w.z))
    return moves
