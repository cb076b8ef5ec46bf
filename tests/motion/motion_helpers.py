"""Helpers of the motion tests: small CRLF ini files and the outcome of ``ecnc run``."""
from __future__ import annotations

import csv
import json
from collections.abc import Mapping
from dataclasses import dataclass
from pathlib import Path
from typing import Any

REPO = Path(__file__).resolve().parents[2]
HOME = 416.5063509  # the seed's delta home switch position (L = 250, R = 125, 200 mm travel)

Sections = Mapping[str, Mapping[str, object]]


def ini_text(sections: Sections) -> str:
    """An ini file as EdingCNC writes it (CRLF line ends)."""
    lines = []
    for name, keys in sections.items():
        lines.append(f"[{name}]")
        lines += [f"{key} = {value}" for key, value in keys.items()]
    return "\r\n".join(lines) + "\r\n"


def joints(limits: tuple[float, float] = (-1000.0, 1000.0), velocity: float = 500.0,
           acceleration: float = 5000.0, **extra: object) -> dict[str, dict[str, object]]:
    """Six [JOINT_n] sections with the same settings."""
    keys = {"negativeLimit": limits[0], "positiveLimit": limits[1], "maxVelocity": velocity,
            "maxAcceleration": acceleration, **extra}
    return {f"JOINT_{i}": dict(keys) for i in range(6)}


def delta_machine(**kinematics: object) -> dict[str, dict[str, object]]:
    """The seed's delta robot: L = 250, R = 125, home switches at 416.5063509 mm."""
    sections = joints((0.0, 420.0), 200.0, 2000.0, homeVelocity=20.0, homePosition=HOME)
    sections["KINEMATICS"] = {"kinematicsDLLName": "deltakins.dll", "linDeltaRadius": "125.000000",
                              "linDeltaArmLength": "250.000000", **kinematics}
    return sections


DELTA_HOME = "PrepareLinDeltaHome\nhome x\nhome y\nhome z\nKIN ON\n"


@dataclass
class Outcome:
    code: int
    out: str
    err: str

    @property
    def json(self) -> dict[str, Any]:
        return json.loads(self.out)

    def pose(self, key: str) -> list[float]:
        return [self.json[key][axis] for axis in "xyzabc"]

    def var(self, number: int) -> float:
        return self.json["variables"][str(number)]


def _value(text: str) -> float | str:
    try:
        return float(text)
    except ValueError:
        return text


def read_csv(path: Path) -> tuple[list[str], list[list[Any]]]:
    """Header and rows of a trace or samples file, numbers as floats."""
    with open(path, newline="") as handle:
        rows = list(csv.reader(handle))
    return rows[0], [[_value(v) for v in row] for row in rows[1:]]
