"""``ecnc kins compare A B``: two plug-ins on the same seeded poses, e.g. a C port and its Python original.

For each joint, the largest difference of the inverse and the pose where it happens; the same for
each axis of the forward (on A's joints); and the poses that one reaches and the other does not.
"""
from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any

import numpy as np

from edingcnc_lang.kinematics.base import Kinematics
from edingcnc_lang.kinematics.workbench import check
from edingcnc_lang.kinematics.workbench.calls import call_each
from edingcnc_lang.canon import AXES, format_pose
from edingcnc_lang.kinematics.workbench.findings import JOINT_NAMES
from edingcnc_lang.kinematics.workbench.geometry_checks import tolerance
from edingcnc_lang.kinematics.workbench.plugin_checks import switch_on


@dataclass
class Difference:
    """The largest |A - B| of one joint or axis, and where."""

    name: str
    largest: float
    pose: tuple[float, ...] | None
    a: float | None
    b: float | None

    def to_json(self) -> dict[str, Any]:
        return {"name": self.name, "largest": self.largest, "pose": self.pose, "a": self.a, "b": self.b}


@dataclass
class Comparison:
    a: str
    b: str
    box_source: str
    seed: int
    samples: int
    tolerance: float
    inverse: list[Difference] = field(default_factory=list)
    forward: list[Difference] = field(default_factory=list)
    reach_differs: int = 0
    reach_example: tuple[float, ...] | None = None
    reach_note: str = ""

    @property
    def ok(self) -> bool:
        return self.reach_differs == 0 and all(d.largest <= self.tolerance for d in self.inverse + self.forward)

    def to_json(self) -> dict[str, Any]:
        return {"a": self.a, "b": self.b, "box_source": self.box_source, "seed": self.seed,
                "samples": self.samples, "tolerance": self.tolerance,
                "inverse": [d.to_json() for d in self.inverse], "forward": [d.to_json() for d in self.forward],
                "reach_differs": self.reach_differs, "reach_example": self.reach_example, "ok": self.ok}

    def format(self) -> str:
        lines = [f"kins compare {self.a} (A) with {self.b} (B): {self.samples} poses, seed {self.seed}, "
                 f"workspace from {self.box_source}, tolerance {self.tolerance:.3g}"]
        for title, rows in (("inverse, per joint", self.inverse), ("forward on A's joints, per axis", self.forward)):
            lines.append(f"  {title}:")
            for d in rows:
                mark = "  " if d.largest <= self.tolerance else "!!"
                where = f" at {format_pose(d.pose)} (A {d.a:.9g}, B {d.b:.9g})" if d.pose is not None else ""
                lines.append(f"    {mark} {d.name:<3} largest |A - B| {d.largest:.3g}{where}")
        if self.reach_differs:
            lines.append(f"  !! {self.reach_differs} poses reached by one and not the other, e.g. "
                         f"{format_pose(self.reach_example)} ({self.reach_note})")
        lines.append("result: the same within the tolerance" if self.ok else "result: they differ")
        return "\n".join(lines)


def compare_plugins(a: str, b: str, options: check.CheckOptions = check.CheckOptions()) -> Comparison:
    """Load both (compiled ones out of process, so a crash is an error, not the end of ``ecnc``) and compare."""
    machine = check.read_machine(options.ini)
    if options.isolate and (check.is_compiled_file(a, machine) or check.is_compiled_file(b, machine)):
        from edingcnc_lang.errors import PluginError
        from edingcnc_lang.kinematics.workbench.findings import report_from_json
        from edingcnc_lang.kinematics.workbench.isolate import crash_text, run_isolated

        frame = check._crash_report(f"{a} / {b}", options)
        result = run_isolated("compare", {"a": a, "b": b, "options": options.to_json()}, fallback=frame)
        if "findings" in result:  # the child crashed: the frame came back with the crash in it
            raise PluginError("; ".join(crash_text(f) for f in report_from_json(result).findings))
        return _from_json(result)
    return compare_loaded(check.load_plugin(a, machine), check.load_plugin(b, machine), a, b, options, machine)


def compare_loaded(ka: Kinematics, kb: Kinematics, a: str, b: str, options: check.CheckOptions,
                   machine: check.Machine) -> Comparison:
    space = check.workspace_for(ka, options, machine)
    for kins in (ka, kb):
        switch_on(kins, space.centre)
    poses = space.random(options.samples, np.random.default_rng(options.seed))
    out_a, out_b = call_each(ka.inverse, poses), call_each(kb.inverse, poses)
    result = Comparison(a, b, space.source, options.seed, len(poses), tolerance(space, options.tolerance))
    both = out_a.ok & out_b.ok
    result.inverse = _largest(out_a.values[both], out_b.values[both], poses[both], JOINT_NAMES)
    joints = out_a.values[both]
    fwd_a, fwd_b = call_each(ka.forward, joints), call_each(kb.forward, joints)
    fine = fwd_a.ok & fwd_b.ok
    result.forward = _largest(fwd_a.values[fine], fwd_b.values[fine], poses[both][fine], AXES)
    differs = out_a.ok != out_b.ok
    result.reach_differs = int(differs.sum()) + int((fwd_a.ok != fwd_b.ok).sum())
    if differs.any():
        i = int(np.flatnonzero(differs)[0])
        result.reach_example = tuple(float(v) for v in poses[i])
        result.reach_note = f"{'A' if out_a.ok[i] else 'B'} reaches it"
    return result


def _largest(va: np.ndarray, vb: np.ndarray, poses: np.ndarray, names: tuple[str, ...] | str) -> list[Difference]:
    rows = []
    for k, name in enumerate(names):
        if not len(va):
            rows.append(Difference(name, 0.0, None, None, None))
            continue
        diff = np.abs(va[:, k] - vb[:, k])
        i = int(np.argmax(diff))
        rows.append(Difference(name, float(diff[i]), tuple(float(v) for v in poses[i]), float(va[i, k]),
                               float(vb[i, k])))
    return rows


def _from_json(data: dict[str, Any]) -> Comparison:
    def rows(items: list[dict[str, Any]]) -> list[Difference]:
        return [Difference(d["name"], d["largest"], None if d["pose"] is None else tuple(d["pose"]), d["a"], d["b"])
                for d in items]

    result = Comparison(data["a"], data["b"], data["box_source"], data["seed"], data["samples"], data["tolerance"],
                        rows(data["inverse"]), rows(data["forward"]), data["reach_differs"],
                        None if data["reach_example"] is None else tuple(data["reach_example"]))
    return result
