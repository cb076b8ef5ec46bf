"""Feed and rapid overrides, as the operator's knobs and the job's M48/M49/M50 set them.

``ecnc run --feed-override PCT --rapid-override PCT`` turn the knobs.  In the job, ``M49``
disables the feed and speed overrides and ``M48`` enables them again; ``M50 P0`` disables the
feed override alone and ``M50`` (or ``M50 P1``) enables it; ``M51`` does the same for the spindle
speed override, which the estimate does not depend on (except through G95, see docs/planner.md).
While the feed override is disabled, feed moves run at their programmed feed.  The rapid knob is
not switched by these codes: on EdingCNC it acts on G0 moves whatever the job says.
"""
from __future__ import annotations

from dataclasses import dataclass

from edingcnc_lang.events import OverrideEvent
from edingcnc_lang.errors import EcncError

MAX_FEED_OVERRIDE = 1000.0  # percent; more is almost certainly a typo


@dataclass
class Overrides:
    """The override state of one run; the motion stage and the planner read ``feed_factor``/``rapid_factor``."""

    feed_percent: float = 100.0
    rapid_percent: float = 100.0
    feed_enabled: bool = True
    spindle_enabled: bool = True

    def __post_init__(self) -> None:
        if not 0.0 < self.feed_percent <= MAX_FEED_OVERRIDE:
            raise EcncError(f"--feed-override {self.feed_percent:g}: must be more than 0 and at most "
                            f"{MAX_FEED_OVERRIDE:g} percent")
        if not 0.0 < self.rapid_percent <= 100.0:
            raise EcncError(f"--rapid-override {self.rapid_percent:g}: must be more than 0 and at most 100 percent")

    @property
    def feed_factor(self) -> float:
        """What the programmed feed is multiplied by now."""
        return self.feed_percent / 100.0 if self.feed_enabled else 1.0

    @property
    def rapid_factor(self) -> float:
        return self.rapid_percent / 100.0

    def apply(self, event: OverrideEvent) -> None:
        """Follow an override event (M48..M51; ``p`` is the P word when the line had one)."""
        code = event.m
        enable = event.p is None or event.p != 0.0
        if code == 48:
            self.feed_enabled = self.spindle_enabled = True
        elif code == 49:
            self.feed_enabled = self.spindle_enabled = False
        elif code == 50:
            self.feed_enabled = enable
        elif code == 51:
            self.spindle_enabled = enable
