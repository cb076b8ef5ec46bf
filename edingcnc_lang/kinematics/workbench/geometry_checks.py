"""The checks on the maps themselves: round trip, domain, continuity and singularities.

Each takes the plug-in, the workspace and the sample poses and returns a summary ``Section`` and its
findings.  Tolerances are relative to the size of the workspace (``Workspace.size``), so a 2 m gantry
and a 200 mm delta are judged alike.
"""
from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass

import numpy as np

from edingcnc_lang.kinematics.base import PLUGIN_FAILURES, Kinematics
from edingcnc_lang.kinematics.workbench.calls import Outcome, Status, call_each
from edingcnc_lang.canon import format_pose
from edingcnc_lang.kinematics.workbench.findings import KinsFinding, Section
from edingcnc_lang.kinematics.workbench.workspace import Workspace

RELATIVE_TOLERANCE = 1e-6
JUMP_FACTOR = 10.0        # a step whose joint change is this many times the segment's median is suspect
BISECTIONS = 40           # halvings of a suspect step: a true jump keeps its size, a steep slope does not
SINGULAR_CONDITION = 1e4  # Jacobian condition numbers above this (and far above the median) are singular
TURNS = (360.0, 2.0 * np.pi)


@dataclass
class PoseSamples:
    """The sample poses with the inverse's outcome on them, shared by the checks."""

    poses: np.ndarray
    inverse: Outcome
    joint_limits: Sequence[tuple[float, float]] | None = None  # the ini's: beyond them is not reached

    @property
    def reached(self) -> np.ndarray:
        return self.poses[self.inverse.ok]


def tolerance(space: Workspace, override: float | None) -> float:
    return override if override is not None else RELATIVE_TOLERANCE * space.size


def _tup(row: np.ndarray) -> tuple[float, ...]:
    return tuple(float(v) for v in row)


def domain(samples: PoseSamples, space: Workspace) -> tuple[Section, list[KinsFinding]]:
    """NaN/infinity and stray exceptions are findings; the reachable share of the box is reported."""
    out, findings = samples.inverse, []
    n = len(samples.poses)
    for status, code, what in ((Status.NON_FINITE, "K401", "inverse returned NaN or infinite joints"),
                               (Status.RAISED, "K402", "inverse raised")):
        first = out.first(status)
        if first is not None:
            detail = out.messages.get(status, "")
            message = f"{what}{': ' + detail if detail else ''}; raise KinematicsDomainError for poses out of reach"
            findings.append(KinsFinding(code, message, pose=_tup(samples.poses[first]),
                                    joints=_tup(out.values[first]) if status == Status.NON_FINITE else None,
                                    count=int((out.status == status).sum())))
    reached = int(out.ok.sum())
    unreachable = out.status == Status.UNREACHABLE
    figures: dict[str, object] = {"reachable_fraction": reached / n if n else 0.0}
    summary = f"reachable {100.0 * reached / n:.1f}% of the box"
    if unreachable.any():
        bad = samples.poses[unreachable]
        lows, highs = bad.min(axis=0), bad.max(axis=0)
        figures["unreachable_box"] = [[float(lo), float(hi)] for lo, hi in zip(lows, highs)]
        summary += (f"; unreachable poses lie within {_box_text(lows, highs, space)} "
                    f"(e.g. {format_pose(bad[0])}: {out.messages.get(Status.UNREACHABLE, '')})")
    beyond = out.status == Status.JOINT_LIMIT
    if beyond.any():
        figures["beyond_joint_limits_fraction"] = int(beyond.sum()) / n
        summary += (f"; {100.0 * beyond.sum() / n:.1f}% the plug-in reaches but the ini's joint limits do not "
                    f"allow (e.g. {format_pose(samples.poses[beyond][0])}: {out.messages.get(Status.JOINT_LIMIT, '')})")
    if reached == 0:
        findings.append(KinsFinding("K403", "no sample pose of the workspace is reachable; check the box and the "
                                "plug-in's settings", pose=_tup(samples.poses[0]), count=n))
    return Section("domain", ("ok, " if not findings else "") + summary, figures), findings


def _box_text(lows: np.ndarray, highs: np.ndarray, space: Workspace) -> str:
    return " ".join(f"{'XYZABC'[i]}{lows[i]:.4g}..{highs[i]:.4g}" for i in space.varying)


def round_trip(kins: Kinematics, samples: PoseSamples, space: Workspace,
               tol: float) -> tuple[Section, list[KinsFinding]]:
    """forward(inverse(p)) == p and inverse(forward(j)) == j, each pair called back to back."""
    poses, joints = samples.poses[samples.inverse.ok], samples.inverse.values[samples.inverse.ok]
    findings: list[KinsFinding] = []
    if not len(poses):
        return Section("round trip", "not run: nothing reachable"), findings
    pos_err = np.full(len(poses), np.nan)
    joint_err = np.full(len(poses), np.nan)
    forward_failed: list[tuple[int, str]] = []
    for i, pose in enumerate(poses):
        # inverse again right before forward: a plug-in may remember its last inverse (rotatekins' C angle)
        fresh = call_each(kins.inverse, pose[None, :])
        joint = fresh.values[0]
        back = call_each(kins.forward, fresh.values)
        if back.status[0] != Status.OK:
            forward_failed.append((i, next(iter(back.messages.values()), "non-finite result")))
            continue
        pos_err[i] = np.max(np.abs(back.values[0] - pose))
        again = call_each(kins.inverse, back.values)
        if again.status[0] == Status.OK:
            joint_err[i] = np.max(np.abs(again.values[0] - joint))
    joint_tol = tol * max(1.0, float(np.nanmax(np.abs(joints))) / space.size) if len(joints) else tol
    worst_p = int(np.nanargmax(pos_err)) if np.isfinite(pos_err).any() else None
    worst_j = int(np.nanargmax(joint_err)) if np.isfinite(joint_err).any() else None
    if worst_p is not None and pos_err[worst_p] > tol:
        kins.inverse(_tup(poses[worst_p]))
        found = kins.forward(_tup(joints[worst_p]))
        findings.append(KinsFinding("K101", f"forward(inverse(p)) is {pos_err[worst_p]:.6g} away from p "
                                f"(tolerance {tol:.3g}); forward gives {format_pose(found)}",
                                pose=_tup(poses[worst_p]), joints=_tup(joints[worst_p]),
                                value=float(pos_err[worst_p]), count=int((pos_err > tol).sum())))
    if worst_j is not None and joint_err[worst_j] > joint_tol:
        findings.append(KinsFinding("K102", f"inverse(forward(j)) is {joint_err[worst_j]:.6g} away from j "
                                f"(tolerance {joint_tol:.3g})", pose=_tup(poses[worst_j]),
                                joints=_tup(joints[worst_j]), value=float(joint_err[worst_j]),
                                count=int((joint_err > joint_tol).sum())))
    if forward_failed:
        i, message = forward_failed[0]
        findings.append(KinsFinding("K103", f"forward failed: {message}", pose=_tup(poses[i]), joints=_tup(joints[i]),
                                count=len(forward_failed)))
    worst_pos = float(np.nanmax(pos_err)) if worst_p is not None else float("nan")
    worst_joint = float(np.nanmax(joint_err)) if worst_j is not None else float("nan")
    summary = (f"worst |forward(inverse(p)) - p| {worst_pos:.3g}, |inverse(forward(j)) - j| {worst_joint:.3g} "
               f"(tolerance {tol:.3g}) over {len(poses)} poses")
    return (Section("round trip", ("ok, " if not findings else "") + summary,
                    {"worst_position_error": worst_pos, "worst_joint_error": worst_joint, "tolerance": tol}),
            findings)


def continuity(kins: Kinematics, samples: PoseSamples, space: Workspace, rng: np.random.Generator,
               segments: int = 200, steps: int = 32) -> tuple[Section, list[KinsFinding]]:
    """Lines through the workspace: a joint must not jump between neighbouring poses.

    Half the lines cross the whole box parallel to an axis (so a wrap or branch line inside the box
    is always crossed); the other half are short segments in random directions from reached poses.
    """
    starts = samples.reached
    findings: list[KinsFinding] = []
    if not len(starts):
        return Section("continuity", "not run: nothing reachable"), findings
    jumps: list[KinsFinding] = []
    checked = 0
    for line in _lines(space, starts, rng, segments, steps):
        out = call_each(kins.inverse, line, samples.joint_limits)
        values = np.where(out.ok[:, None], out.values, np.nan)  # beyond the joint limits: never driven there
        deltas = np.max(np.abs(np.diff(values, axis=0)), axis=1)  # NaN where an end is unreachable
        if not np.isfinite(deltas).any():
            continue
        checked += 1
        typical = float(np.nanmedian(deltas))
        suspects = np.flatnonzero(deltas > JUMP_FACTOR * typical + 1e-9 * space.size)
        for s in suspects[:2]:
            jump = _bisect(kins, line[s], line[s + 1], float(deltas[s]))
            if jump is not None:
                jumps.append(jump)
    for code in ("K202", "K201"):
        group = [j for j in jumps if j.code == code]
        if group:
            worst = max(group, key=lambda j: j.value or 0.0)
            findings.append(KinsFinding(worst.code, worst.message, worst.pose, worst.joints, worst.other_pose,
                                    worst.other_joints, worst.value, count=len(group)))
    summary = f"{checked} lines (across the box along each axis, and short random ones)"
    return Section("continuity", ("ok, " if not findings else "") + summary, {"lines": checked}), findings


def _lines(space: Workspace, starts: np.ndarray, rng: np.random.Generator, count: int,
           steps: int) -> list[np.ndarray]:
    axes = space.varying
    lows, highs = space.lows, space.lows + space.extents
    lines = []
    across = max(4, count // (2 * max(1, len(axes))))
    for axis in axes:
        for _ in range(across):
            start = lows + rng.random(6) * space.extents
            start[axis], end = lows[axis], start.copy()
            end[axis] = highs[axis]
            lines.append(start + np.linspace(0.0, 1.0, 4 * steps + 1)[:, None] * (end - start))
    for _ in range(max(0, count - len(lines))):
        start = starts[rng.integers(len(starts))]
        direction = np.zeros(6)
        direction[axes] = rng.normal(size=len(axes))
        direction /= np.linalg.norm(direction) or 1.0
        end = np.clip(start + direction * 0.05 * space.extents * np.sqrt(len(axes)), lows, highs)
        lines.append(start + np.linspace(0.0, 1.0, steps + 1)[:, None] * (end - start))
    return lines


def _bisect(kins: Kinematics, a: np.ndarray, b: np.ndarray, delta: float) -> KinsFinding | None:
    """Halve the step [a, b] towards the larger joint change; a jump keeps its size as the step vanishes."""
    ja, jb = np.asarray(kins.inverse(_tup(a))), np.asarray(kins.inverse(_tup(b)))
    for _ in range(BISECTIONS):
        mid = (a + b) / 2.0
        try:
            jm = np.asarray(kins.inverse(_tup(mid)), dtype=float)
        except PLUGIN_FAILURES:  # an unreachable gap inside a reachable step: not a continuity question
            return None
        if np.max(np.abs(jm - ja)) >= np.max(np.abs(jb - jm)):
            b, jb = mid, jm
        else:
            a, ja = mid, jm
    change = np.abs(jb - ja)
    size = float(change.max())
    if not size > 0.25 * delta or not np.isfinite(size):
        return None
    joint = int(change.argmax())
    names = ("jX", "jY", "jZ", "jA", "jB", "jC")
    # one or two whole turns, closely: 213.6 degrees is not "34 turns of 2 pi"
    turn = next((t for t in TURNS if round(size / t) in (1, 2) and abs(size / t - round(size / t)) < 0.002), None)
    gap = float(np.linalg.norm(b - a))
    if turn is not None:
        turns = round(size / turn)
        message = (f"joint {names[joint]} wraps by {size:.6g} ({turns} turn{'s' * (turns > 1)}) between two poses "
                   f"{gap:.2g} apart: keep the angle continuous (unwrap it) inside the workspace")
        code = "K202"
    else:
        message = (f"joint {names[joint]} jumps by {size:.6g} between two poses {gap:.2g} apart "
                   f"(a branch switch or a discontinuity)")
        code = "K201"
    return KinsFinding(code, message, pose=_tup(a), joints=_tup(ja), other_pose=_tup(b), other_joints=_tup(jb),
                   value=size)


def jacobian_conditions(kins: Kinematics, poses: np.ndarray, space: Workspace,
                        axes: list[int]) -> np.ndarray:
    """Condition number of d(joints)/d(pose) over ``axes`` by central differences (NaN where undefined).

    Where the one-sided differences disagree the joints jump at that pose (continuity reports it),
    so the pose is left out rather than mistaken for a singularity.
    """
    conds = np.full(len(poses), np.nan)
    steps = np.maximum(space.extents, 1.0) * 1e-6
    for i, pose in enumerate(poses):
        columns = []
        for axis in axes:
            shift = np.zeros(6)
            shift[axis] = steps[axis]
            trio = call_each(kins.inverse, np.array([pose + shift, pose, pose - shift]))
            if not trio.ok.all():
                break
            ahead = (trio.values[0] - trio.values[1]) / steps[axis]
            behind = (trio.values[1] - trio.values[2]) / steps[axis]
            if np.linalg.norm(ahead - behind) > 0.5 * max(np.linalg.norm(ahead), np.linalg.norm(behind)) + 1e-6:
                break
            columns.append((ahead + behind) / 2.0)
        else:
            singular = np.linalg.svd(np.column_stack(columns), compute_uv=False)
            conds[i] = singular[0] / singular[-1] if singular[-1] > 0.0 else np.inf
    return conds


def singularities(kins: Kinematics, samples: PoseSamples, space: Workspace,
                  count: int = 300) -> tuple[Section, list[KinsFinding]]:
    """Poses where the Jacobian loses rank; axes that never reach the joints (virtual axes) are set aside."""
    poses = samples.reached[:count]
    findings: list[KinsFinding] = []
    if not len(poses):
        return Section("singularity", "not run: nothing reachable"), findings
    axes = list(space.varying)
    conds = jacobian_conditions(kins, poses, space, axes)
    virtual: list[int] = []
    # an axis whose removal makes the typical pose regular is structural (a virtual axis), not a singularity
    while len(axes) > 1 and _median(conds) > SINGULAR_CONDITION:
        trial = {axis: jacobian_conditions(kins, poses[:20], space, [a for a in axes if a != axis])
                 for axis in axes if axis >= 3}
        best = min(trial, key=lambda a: _median(trial[a]), default=None)
        if best is None or _median(trial[best]) > SINGULAR_CONDITION:
            break
        axes.remove(best)
        virtual.append(best)
        conds = jacobian_conditions(kins, poses, space, axes)
    median = _median(conds)
    limit = max(SINGULAR_CONDITION, 1e3 * median) if np.isfinite(median) else SINGULAR_CONDITION
    bad = np.flatnonzero(~(conds <= limit) & ~np.isnan(conds))
    figures: dict[str, object] = {"median_condition": median,
                                  "worst_condition": float(np.nanmax(conds)) if np.isfinite(conds).any() or
                                  np.isinf(conds).any() else float("nan"),
                                  "virtual_axes": ["XYZABC"[a] for a in virtual]}
    if len(bad):
        worst = bad[np.argmax(np.nan_to_num(conds[bad], posinf=np.finfo(float).max))]
        region = poses[bad]
        findings.append(KinsFinding("K301", f"the Jacobian's condition number reaches {conds[worst]:.3g} (median "
                                f"{median:.3g}); singular poses lie within "
                                f"{_box_text(region.min(axis=0), region.max(axis=0), space)}",
                                pose=_tup(poses[worst]), value=float(conds[worst]), count=len(bad)))
    summary = f"condition number median {median:.3g}, worst {figures['worst_condition']:.3g} over {len(poses)} poses"
    if virtual:
        summary += f"; {', '.join('XYZABC'[a] for a in virtual)} does not reach the joints (virtual axis)"
    return Section("singularity", ("ok, " if not findings else "") + summary, figures), findings


def _median(values: np.ndarray) -> float:
    finite = values[~np.isnan(values)]
    return float(np.median(finite)) if len(finite) else float("nan")
