"""Canned drilling cycles (G73, G74, G81-G89) expanded into plain moves.

Works along the drilling axis only: given the hole position and the
clearance, R and bottom levels it returns the sequence of (kind, depth)
steps that the EdingCNC manual (3.6.20) prescribes, so every plane and both
distance modes share one implementation.
"""
from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass

from edingcnc_lang.syntax.input_limits import MAX_CYCLE_PECKS

PECK_CLEARANCE_MM = 0.254  # G83 re-entry above the last depth, G73 chip-break retract (0.010 inch)


@dataclass(frozen=True)
class Step:
    """One action at the hole: a rapid or feed along the drilling axis, a dwell, or a spindle switch."""

    # "rapid" | "feed" | "tap" (synchronised: F per revolution) | "dwell" | "pause" (for the operator) |
    # "spindle_stop" | "spindle_start" | "spindle_reverse" | "shift" | "center"
    kind: str
    level: float = 0.0  # drilling-axis coordinate (rapid/feed/tap); seconds for dwell


class CycleError(ValueError):
    """Cycle words that describe no sensible hole; the message is for the user."""


def _pecks(r: float, bottom: float, q: float) -> list[float]:
    if (r - bottom) / q > MAX_CYCLE_PECKS:
        raise CycleError(f"Q{q:g} would drill {r - bottom:g} mm in more than {MAX_CYCLE_PECKS} pecks")
    depths = []
    depth = r - q
    while depth > bottom:
        depths.append(depth)
        depth -= q
    return depths


def g81(r: float, bottom: float, clear: float, p: float, q: float) -> list[Step]:
    return [Step("feed", bottom), Step("rapid", clear)]


def g82(r: float, bottom: float, clear: float, p: float, q: float) -> list[Step]:
    return [Step("feed", bottom), Step("dwell", p), Step("rapid", clear)]


def g83(r: float, bottom: float, clear: float, p: float, q: float) -> list[Step]:
    steps: list[Step] = []
    for depth in _pecks(r, bottom, q):
        steps += [Step("feed", depth), Step("rapid", r), Step("rapid", depth + PECK_CLEARANCE_MM)]
    return steps + [Step("feed", bottom), Step("rapid", clear)]


def g73(r: float, bottom: float, clear: float, p: float, q: float) -> list[Step]:
    steps: list[Step] = []
    for depth in _pecks(r, bottom, q):
        steps += [Step("feed", depth), Step("rapid", depth + PECK_CLEARANCE_MM)]
    return steps + [Step("feed", bottom), Step("rapid", clear)]


def g84(r: float, bottom: float, clear: float, p: float, q: float) -> list[Step]:
    # 3.6.20.6/7 rigid tapping (G74 alike, the spindle turning the other way): in synchronised with the
    # spindle, reversed at the bottom, out at the same pitch to the clear level, turned back
    return [Step("tap", bottom), Step("spindle_reverse"), Step("tap", clear), Step("spindle_start")]


g74 = g84


def g87(r: float, bottom: float, clear: float, p: float, q: float) -> list[Step]:
    # 3.6.20.10 back boring (q is the level bored up to): shifted by I J past the bar, oriented stop, down
    # below the part, back on centre, spindle on, bore up to K and back down, stop, shift, out, centre, on
    return [Step("shift"), Step("spindle_stop"), Step("rapid", bottom), Step("center"), Step("spindle_start"),
            Step("feed", q), Step("feed", bottom), Step("spindle_stop"), Step("shift"), Step("rapid", clear),
            Step("center"), Step("spindle_start")]


def g85(r: float, bottom: float, clear: float, p: float, q: float) -> list[Step]:
    return [Step("feed", bottom), Step("feed", r), Step("rapid", clear)]


def g86(r: float, bottom: float, clear: float, p: float, q: float) -> list[Step]:
    return [Step("feed", bottom), Step("dwell", p), Step("spindle_stop"), Step("rapid", clear),
            Step("spindle_start")]


def g88(r: float, bottom: float, clear: float, p: float, q: float) -> list[Step]:
    # 3.6.20.11: the program stops for the operator to retract by hand; no automatic move
    return [Step("feed", bottom), Step("dwell", p), Step("spindle_stop"), Step("pause"), Step("spindle_start")]


def g89(r: float, bottom: float, clear: float, p: float, q: float) -> list[Step]:
    return [Step("feed", bottom), Step("dwell", p), Step("feed", r), Step("rapid", clear)]


CycleFn = Callable[[float, float, float, float, float], list[Step]]

# Keyed by G number in integer tenths; the flags say which cycles need Q > 0.
CYCLES: dict[int, CycleFn] = {730: g73, 740: g74, 810: g81, 820: g82, 830: g83, 840: g84, 850: g85, 860: g86,
                              870: g87, 880: g88, 890: g89}
NEEDS_Q = frozenset({730, 830})
# The cycles that need the spindle turning when they start (3.6.20.9 says so of G86; the taps feed per
# revolution; G87 and G88 start it again "in the direction it went", as rs274 requires for all of them).
NEEDS_SPINDLE = frozenset({740, 840, 860, 870, 880})
TAPPING = frozenset({740, 840})
# The cycles whose holes are straight moves alone (no dwell, spindle switch, tap or shift): a run of their
# holes is read in bulk (canned.py, ``_steady_holes``).
STRAIGHT = frozenset({730, 810, 830, 850})
