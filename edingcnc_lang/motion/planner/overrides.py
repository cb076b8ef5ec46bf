"""Feed and rapid overrides, as the operator's knobs and the job's M48..M51 set them (manual 3.7.5, p. 61).

``ecnc run --feed-override PCT --rapid-override PCT`` turn the knobs.  In the job, ``M50 P..``
sets the feed override to P percent; a negative P switches it off (feed moves run at their
programmed feed) and keeps the value; ``M50 P0`` ("the macro does not start until the operator
turns the knob") is a wait for the operator, after which the run goes on at the knob's value;
``M50`` without P switches it on at the value it had.  ``M48`` switches the overrides on and
resets the feed override to the knob's value; ``M49`` switches them off (100 %).  ``M51`` is the
spindle's, which the interpreter applies to the spindle speed.  The rapid knob is not switched by
these codes: on EdingCNC it acts on G0 moves whatever the job says.
"""
from __future__ import annotations

from dataclasses import dataclass

from edingcnc_lang.events import OverrideEvent
from edingcnc_lang.errors import EcncError

MAX_FEED_OVERRIDE = 1000.0  # percent; more is almost certainly a typo


@dataclass
class Overrides:
    """The override state of one run; the motion stage and the planner read ``feed_factor``/``rapid_factor``.

    ``feed_percent`` is the operator's knob; ``feed_set`` the value the job set with ``M50 P..``
    (None: the knob's).
    """

    feed_percent: float = 100.0
    rapid_percent: float = 100.0
    feed_enabled: bool = True
    feed_set: float | None = None

    def __post_init__(self) -> None:
        if not 0.0 < self.feed_percent <= MAX_FEED_OVERRIDE:
            raise EcncError(f"--feed-override {self.feed_percent:g}: must be more than 0 and at most "
                            f"{MAX_FEED_OVERRIDE:g} percent")
        if not 0.0 < self.rapid_percent <= 100.0:
            raise EcncError(f"--rapid-override {self.rapid_percent:g}: must be more than 0 and at most 100 percent")

    @property
    def feed_factor(self) -> float:
        """What the programmed feed is multiplied by now."""
        if not self.feed_enabled:
            return 1.0
        return (self.feed_percent if self.feed_set is None else self.feed_set) / 100.0

    @property
    def rapid_factor(self) -> float:
        return self.rapid_percent / 100.0

    def apply(self, event: OverrideEvent) -> None:
        """Follow an override event (M48..M50; ``p`` is the P word when the line had one)."""
        code = event.m
        if code == 48:
            self.feed_enabled, self.feed_set = True, None
        elif code == 49:
            self.feed_enabled = False
        elif code == 50:
            p = event.p
            if p is None:
                self.feed_enabled = True
            elif float(p) < 0.0:
                self.feed_enabled = False
            else:  # P0 waits for the operator's knob (an operator_wait event), then runs at its value
                self.feed_enabled, self.feed_set = True, float(p) or None
