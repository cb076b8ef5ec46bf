#!/usr/bin/python3
"""Regenerate tests/golden/lineardelta/cases.json from LinuxCNC's ``lineardeltakins``.

The module ships with Debian's ``linuxcnc-uspace`` and is importable only from the system
Python (``/usr/bin/python3``), so run this script with that interpreter. The poses are fixed
by a seed, so running it again gives a byte-identical file; the test suite only reads the JSON.
"""

from __future__ import annotations

import argparse
import json
import math
import random
import sys
from dataclasses import dataclass
from pathlib import Path
from typing import Any

R = 125.0
L = 250.0
SEED = 20240601
OUT = Path(__file__).resolve().parent.parent / "tests" / "golden" / "lineardelta" / "cases.json"

Vec3 = tuple[float, float, float]


@dataclass(frozen=True)
class Kins:
    """The three module functions, passed around so the pose generators stay pure."""

    inverse: Any
    forward: Any


def load_kins() -> Kins:
    """Import LinuxCNC's module with our geometry, or stop with a message naming the fix."""
    try:
        import lineardeltakins  # type: ignore[import-not-found]
    except ImportError:
        sys.exit(
            "lineardeltakins is not importable: install Debian's linuxcnc-uspace and run this "
            "script with /usr/bin/python3"
        )
    lineardeltakins.set_geometry(R, L)
    if tuple(lineardeltakins.get_geometry()) != (R, L):
        sys.exit(f"set_geometry({R}, {L}) did not take effect")
    return Kins(inverse=lineardeltakins.inverse, forward=lineardeltakins.forward)


def tower(index: int) -> tuple[float, float]:
    """Tower positions as observed from the module (see docs/goldens.md)."""
    s60, c60 = math.sin(math.pi / 3), math.cos(math.pi / 3)
    return ((0.0, R), (-R * s60, -R * c60), (R * s60, -R * c60))[index]


def fixed_poses() -> list[Vec3]:
    """Hand-picked poses: the centre at two heights and each tower's foot point."""
    feet = [(*tower(i), 0.0) for i in range(3)]
    return [(0.0, 0.0, 0.0), (0.0, 0.0, 200.0), (0.0, 0.0, -50.0), *feet]


def grid_poses() -> list[Vec3]:
    """A coarse grid clipped to the disc of radius L - R, where every tower is in reach."""
    steps = (-100.0, -50.0, 0.0, 50.0, 100.0)
    return [(x, y, z) for z in (0.0, 120.0) for x in steps for y in steps if math.hypot(x, y) <= L - R]


def random_poses(rng: random.Random, count: int) -> list[Vec3]:
    """Uniform poses in a disc of radius 120 mm, inside the always-reachable disc of radius L - R."""
    poses = []
    for _ in range(count):
        radius = 120.0 * math.sqrt(rng.random())
        angle = rng.uniform(0.0, 2 * math.pi)
        poses.append(
            (
                round(radius * math.cos(angle), 4),
                round(radius * math.sin(angle), 4),
                round(rng.uniform(-80.0, 300.0), 4),
            )
        )
    return poses


def near_limit_poses(kins: Kins) -> list[Vec3]:
    """Poses whose horizontal distance to one tower is just below L (the reach limit)."""
    poses = []
    for index in range(3):
        tx, ty = tower(index)
        for distance in (L - 2.0, L - 0.5, L - 0.01):
            for degrees in range(-60, 61, 20):
                # Directions fanning out from the tower through the centre of the base.
                heading = math.atan2(-ty, -tx) + math.radians(degrees)
                pose = (
                    round(tx + distance * math.cos(heading), 6),
                    round(ty + distance * math.sin(heading), 6),
                    25.0 * index,
                )
                if kins.inverse(*pose) is not None:
                    poses.append(pose)
    return poses


def unreachable_poses() -> list[Vec3]:
    """Poses farther than L from some tower: the module answers None for these."""
    return [(0.0, R - (L + 0.01), 0.0), (300.0, 0.0, 0.0), (0.0, -260.0, 10.0)]


def build(kins: Kins) -> dict[str, Any]:
    """Evaluate all poses; every reachable pose becomes an inverse case."""
    rng = random.Random(SEED)
    poses = fixed_poses() + grid_poses() + random_poses(rng, 125) + near_limit_poses(kins)
    cases = []
    for pose in poses:
        joints = kins.inverse(*pose)
        if joints is None:
            sys.exit(f"pose {pose} unexpectedly out of reach")
        cases.append({"pos": list(pose), "joints": list(joints)})
    forward_joints = [case["joints"] for case in cases[:: len(cases) // 10]]
    forward_joints += [[200.0, 210.0, 220.0], [300.0, 250.0, 260.0]]
    forward = [{"joints": list(j), "pos": list(kins.forward(*j))} for j in forward_joints]
    unreachable = unreachable_poses()
    for pose in unreachable:
        if kins.inverse(*pose) is not None:
            sys.exit(f"pose {pose} was expected to be out of reach")
    return {
        "R": R,
        "L": L,
        "source": "LinuxCNC lineardeltakins Python module (linuxcnc-uspace, Debian 12), "
        f"set_geometry({R}, {L}); scripts/regen_lineardelta_goldens.py seed {SEED}",
        "cases": cases,
        "forward": forward,
        "unreachable": [list(p) for p in unreachable],
    }


def main() -> None:
    """Write the golden file and print a one-line summary."""
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--output", type=Path, default=OUT)
    args = parser.parse_args()
    data = build(load_kins())
    args.output.parent.mkdir(parents=True, exist_ok=True)
    args.output.write_text(json.dumps(data, indent=1, sort_keys=True) + "\n")
    print(
        f"wrote {args.output}: {len(data['cases'])} inverse cases, {len(data['forward'])} forward "
        f"cases, {len(data['unreachable'])} unreachable poses"
    )


if __name__ == "__main__":
    main()
