"""How long a job takes: the totals the planner adds up, as the API and ``--json`` report them.

Pure Python (no numpy): the CLI formats the summary line and the JSON from it.
"""
from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any


@dataclass
class ToolTime:
    """Time and distance while one tool was in the spindle."""

    seconds: float = 0.0
    feed_seconds: float = 0.0
    rapid_seconds: float = 0.0
    feed_distance: float = 0.0

    def to_json(self) -> dict[str, float]:
        return {"seconds": self.seconds, "feed_seconds": self.feed_seconds, "rapid_seconds": self.rapid_seconds,
                "feed_distance": self.feed_distance}


@dataclass
class Estimate:
    """The planned duration of a run and where it goes.

    ``seconds`` = ``rapid_seconds`` + ``feed_seconds`` + ``dwell_seconds`` (rapids include homing;
    feeds include arcs and probing).  Distances are mm along the XYZ path.  ``per_tool`` maps the
    tool number in the spindle to its share.
    """

    seconds: float = 0.0
    rapid_seconds: float = 0.0
    feed_seconds: float = 0.0
    dwell_seconds: float = 0.0
    rapid_distance: float = 0.0
    feed_distance: float = 0.0
    moves: int = 0
    per_tool: dict[int, ToolTime] = field(default_factory=dict)
    notes: list[str] = field(default_factory=list)  # what the time leaves out (waits for the operator)

    def add_moves(self, tool: int, rapid_seconds: float, feed_seconds: float, rapid_distance: float,
                  feed_distance: float, count: int) -> None:
        self.rapid_seconds += rapid_seconds
        self.feed_seconds += feed_seconds
        self.rapid_distance += rapid_distance
        self.feed_distance += feed_distance
        self.seconds += rapid_seconds + feed_seconds
        self.moves += count
        if not (rapid_seconds or feed_seconds or rapid_distance or feed_distance):
            return  # moves of zero length (a tool change macro already where it goes): no share for the tool
        share = self.per_tool.setdefault(tool, ToolTime())
        share.seconds += rapid_seconds + feed_seconds
        share.rapid_seconds += rapid_seconds
        share.feed_seconds += feed_seconds
        share.feed_distance += feed_distance

    def add_dwell(self, tool: int, seconds: float) -> None:
        self.dwell_seconds += seconds
        self.seconds += seconds
        self.per_tool.setdefault(tool, ToolTime()).seconds += seconds

    def add_note(self, note: str) -> None:
        """Something the planned time cannot hold, as a line for people (``notes`` in ``--json``)."""
        self.notes.append(note)

    def to_json(self) -> dict[str, Any]:
        return {
            "seconds": self.seconds,
            "rapid_seconds": self.rapid_seconds,
            "feed_seconds": self.feed_seconds,
            "dwell_seconds": self.dwell_seconds,
            "distance": {"rapid": self.rapid_distance, "feed": self.feed_distance},
            "per_tool": {str(tool): share.to_json() for tool, share in sorted(self.per_tool.items())},
            **({"notes": list(self.notes)} if self.notes else {}),
        }

    def summary(self) -> str:
        """One line for people: ``2,431 moves, 1 h 12 min 5 s, 84.2 m``."""
        moves = f"{self.moves:,} move{'' if self.moves == 1 else 's'}"
        waits = f", {len(self.notes)} wait{'' if len(self.notes) == 1 else 's'} for the operator not counted" \
            if self.notes else ""
        return f"{moves}, {format_duration(self.seconds)}, {format_distance(self.rapid_distance + self.feed_distance)}" \
            + waits


def format_duration(seconds: float) -> str:
    """``1 h 12 min 5 s``; under a minute with one decimal (``7.3 s``)."""
    if seconds < 59.95:
        return f"{seconds:.1f} s"
    whole = round(seconds)
    hours, rest = divmod(whole, 3600)
    minutes, secs = divmod(rest, 60)
    parts = [f"{hours} h"] if hours else []
    return " ".join([*parts, f"{minutes} min", f"{secs} s"])


def format_distance(mm: float) -> str:
    """Metres with one decimal from 1 m on, else millimetres."""
    return f"{mm / 1000.0:,.1f} m" if mm >= 1000.0 else f"{mm:.1f} mm"
