"""What ``ecnc kins check`` reports: stable finding codes (data), finding records and the report.

Codes are public names, like the lint codes: scripts filter on them.  The first digit groups them by
check: K1 round trip, K2 continuity, K3 singularities, K4 domain, K5 control and state, K6 compiled.
"""
from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass, field
from typing import Any

from edingcnc_lang.canon import AXES, format_pose
from edingcnc_lang.codes import KINS_CODES

FINDING_CODES = KINS_CODES  # the registry's K group (codes.py)

JOINT_NAMES = ("jX", "jY", "jZ", "jA", "jB", "jC")


def format_joints(values: Sequence[float] | None) -> str:
    return format_pose(values, JOINT_NAMES)


@dataclass(frozen=True)
class KinsFinding:
    """One problem, with where it happens: the pose (and joints) that show it."""

    code: str
    message: str
    pose: tuple[float, ...] | None = None
    joints: tuple[float, ...] | None = None
    other_pose: tuple[float, ...] | None = None
    other_joints: tuple[float, ...] | None = None
    value: float | None = None
    count: int = 1

    @property
    def check(self) -> str:
        return FINDING_CODES[self.code][0]

    def to_json(self) -> dict[str, Any]:
        out: dict[str, Any] = {"code": self.code, "check": self.check, "message": self.message,
                               "count": self.count}
        for key in ("pose", "joints", "other_pose", "other_joints"):
            value = getattr(self, key)
            out[key] = None if value is None else [_json_float(v) for v in value]
        out["value"] = None if self.value is None else _json_float(self.value)
        return out

    def format(self) -> str:
        lines = [f"{self.code} {self.check}: {self.message}" + (f" ({self.count} cases)" if self.count > 1 else "")]
        if self.pose is not None:
            lines.append(f"    at {format_pose(self.pose)}" + (f"  ->  {format_joints(self.joints)}"
                                                              if self.joints is not None else ""))
        if self.other_pose is not None:
            lines.append(f"    and {format_pose(self.other_pose)}" + (
                f"  ->  {format_joints(self.other_joints)}" if self.other_joints is not None else ""))
        return "\n".join(lines)


def _json_float(value: float) -> float | str:
    """JSON has no NaN or infinity: those are written as strings, so a report always parses."""
    value = float(value)
    return value if math.isfinite(value) else str(value)


@dataclass
class Section:
    """One check's summary line (``ok``, a figure or two) for the text report and the JSON."""

    name: str
    summary: str
    figures: dict[str, Any] = field(default_factory=dict)


@dataclass
class Report:
    """Everything ``check`` learned: the plug-in, the workspace, the per-check summaries, the findings."""

    plugin: str
    kin_type: int | None
    version: str | None
    box_source: str
    box: tuple[tuple[float, float], ...]
    seed: int
    samples: int
    sections: list[Section] = field(default_factory=list)
    findings: list[KinsFinding] = field(default_factory=list)

    @property
    def ok(self) -> bool:
        return not self.findings

    def to_json(self) -> dict[str, Any]:
        return {
            "plugin": self.plugin, "type": self.kin_type, "version": self.version,
            "box": {"source": self.box_source,
                    **{axis.lower(): [lo, hi] for axis, (lo, hi) in zip(AXES, self.box)}},
            "seed": self.seed, "samples": self.samples,
            "checks": {s.name: {"summary": s.summary, **{k: _jsonable(v) for k, v in s.figures.items()}}
                       for s in self.sections},
            "findings": [f.to_json() for f in self.findings],
            "ok": self.ok,
        }

    def format(self) -> str:
        head = f"kins check {self.plugin}"
        if self.kin_type is not None:
            head += f" (type {self.kin_type}, {self.version!r})"
        box = "  ".join(f"{a} {lo:g}..{hi:g}" for a, (lo, hi) in zip(AXES, self.box) if lo != hi)
        fixed = " ".join(f"{a}{lo:g}" for a, (lo, hi) in zip(AXES, self.box) if lo == hi)
        lines = [head, f"workspace ({self.box_source}): {box}" + (f"; fixed {fixed}" if fixed else ""),
                 f"seed {self.seed}, {self.samples} sample poses"] if self.samples else [
                     head, "the check ended before it reached the workspace"]
        width = max((len(s.name) for s in self.sections), default=0)
        lines += [f"  {s.name.ljust(width)}  {s.summary}" for s in self.sections]
        lines += [f.format() for f in self.findings]
        count = len(self.findings)
        lines.append("result: no findings" if not count else f"result: {count} finding{'s' * (count != 1)}")
        return "\n".join(lines)


def _jsonable(value: Any) -> Any:
    if isinstance(value, float):
        return _json_float(value)
    if isinstance(value, (list, tuple)):
        return [_jsonable(v) for v in value]
    if isinstance(value, dict):
        return {k: _jsonable(v) for k, v in value.items()}
    return value


def _floats(values: Sequence[float | str] | None) -> tuple[float, ...] | None:
    return None if values is None else tuple(float(v) for v in values)


def finding_from_json(data: dict[str, Any]) -> KinsFinding:
    return KinsFinding(data["code"], data["message"], _floats(data.get("pose")), _floats(data.get("joints")),
                   _floats(data.get("other_pose")), _floats(data.get("other_joints")),
                   None if data.get("value") is None else float(data["value"]), int(data.get("count", 1)))


def report_from_json(data: dict[str, Any]) -> Report:
    """The inverse of ``Report.to_json`` (a compiled plug-in's report comes back from a child process)."""
    box = data["box"]
    report = Report(data["plugin"], data["type"], data["version"], box["source"],
                    tuple((float(box[a][0]), float(box[a][1])) for a in "xyzabc"), int(data["seed"]),
                    int(data["samples"]))
    for name, values in data["checks"].items():
        figures = {k: v for k, v in values.items() if k != "summary"}
        report.sections.append(Section(name, values["summary"], figures))
    report.findings = [finding_from_json(f) for f in data["findings"]]
    return report
