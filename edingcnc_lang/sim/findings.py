"""What the simulation tells the user: each hit of the stock that should not have happened.

A finding names the move's file and line, where the deepest point of it was (work coordinates of
the stock) and how deep into the material (or below the stock's bottom) it went.  Consecutive moves
of one line with the same finding (a loop in a sub, a canned cycle) are one finding, with the
deepest point of them all.
"""
from __future__ import annotations

from dataclasses import dataclass, replace
from typing import Any

KINDS = {
    "rapid_into_stock": ("error", "a rapid move (G0) removes material"),
    "shank": ("error", "the shank meets the stock: the cut is deeper than the flutes"),
    "holder": ("error", "the tool holder meets the stock"),
    "spindle_off": ("error", "material removed with the spindle stopped"),
    "plunge": ("hint", "a flat end mill plunges straight down deeper than half its diameter: ramp or helix in"),
    "outside_stock": ("hint", "the tool goes below the stock's bottom (into the table or fixture)"),
    "chuck": ("error", "the tool reaches into the chuck (--chuck: the length it grips)"),
}


@dataclass(frozen=True)
class CutFinding:
    """One finding; ``position`` is the tool tip (X, Y, Z) where the move went deepest (the first
    such place along it); ``depth`` how far into the material (or below the bottom) it went."""

    kind: str
    file: str
    line: int
    position: tuple[float, float, float]
    depth: float
    tool: int
    move: int  # index of the (first) move, in program order
    angle: float | None = None  # on a rotary axis: the bar's own angle under the tip, degrees

    @property
    def severity(self) -> str:
        return KINDS[self.kind][0]

    @property
    def message(self) -> str:
        return KINDS[self.kind][1]

    def format(self) -> str:
        """``FILE:LINE: error: TEXT [kind] (1.2 mm deep at X.. Y.. Z.., T1)``, as the linter writes."""
        x, y, z = self.position
        return (f"{self.file}:{self.line}: {self.severity}: {self.message} [{self.kind}] "
                f"({self.depth:.3g} mm deep at X{x:.4g} Y{y:.4g} Z{z:.4g}, T{self.tool})")

    def to_json(self) -> dict[str, Any]:
        return {"kind": self.kind, "severity": self.severity, "file": self.file, "line": self.line,
                "position": [round(v, 4) for v in self.position], "depth": round(self.depth, 4),
                "tool": self.tool, "message": self.message}


def merged(findings: list[CutFinding]) -> list[CutFinding]:
    """In program order; a run of findings of one kind from one file and line becomes one, the deepest."""
    out: list[CutFinding] = []
    latest: dict[str, int] = {}  # kind -> index in ``out`` of its latest finding
    for item in sorted(findings, key=lambda f: (f.move, f.kind)):
        at = latest.get(item.kind)
        if at is not None and (out[at].file, out[at].line) == (item.file, item.line):
            if item.depth > out[at].depth:
                out[at] = replace(out[at], position=item.position, depth=item.depth, angle=item.angle)
            continue
        latest[item.kind] = len(out)
        out.append(item)
    return out


def failing(findings: list[CutFinding]) -> bool:
    """Whether any finding is an error (hints alone leave the exit code 0)."""
    return any(f.severity == "error" for f in findings)
