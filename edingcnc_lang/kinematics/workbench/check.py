"""``ecnc kins check``: prove a plug-in over a workspace and report every finding with its pose.

Compiled plug-ins are checked in a child process (``isolate.py``) so that a crash in the library is a
finding naming the call and the pose, not the end of ``ecnc``.
"""
from __future__ import annotations

from collections.abc import Mapping, Sequence
from dataclasses import asdict, dataclass
from pathlib import Path

import numpy as np

from edingcnc_lang.errors import PluginError
from edingcnc_lang.kinematics.base import PLUGIN_FAILURES, Kinematics
from edingcnc_lang.kinematics.workbench import geometry_checks as geo
from edingcnc_lang.kinematics.workbench import plugin_checks as plug
from edingcnc_lang.kinematics.workbench.calls import call_each
from edingcnc_lang.kinematics.workbench.findings import KinsFinding, Report, report_from_json
from edingcnc_lang.kinematics.workbench.workspace import (
    Workspace,
    default_workspace,
    from_cartesian_limits,
    turning_rotaries,
    from_joint_limits,
    parse_box,
)


@dataclass(frozen=True)
class CheckOptions:
    """How hard to look: the workspace, the seed, how many poses, the tolerance (default: relative)."""

    ini: str | None = None
    box: tuple[float, ...] | None = None
    seed: int = 0
    samples: int = 2000
    segments: int = 200
    tolerance: float | None = None
    speed: bool = True
    isolate: bool = True

    def to_json(self) -> dict[str, object]:
        return asdict(self)


@dataclass(frozen=True)
class Machine:
    """What the ini says about the plug-in: its settings, where plug-in files are, the limits it GAVE."""

    settings: Mapping[str, str]
    search_dirs: tuple[Path, ...]
    joint_limits: tuple[tuple[float, float], ...] | None  # None: the ini has no [JOINT_n] section
    cartesian: Workspace | None = None                    # None: the ini does not limit X, Y and Z


def read_machine(ini: str | None) -> Machine:
    """The ini read once by ``load_config`` (so its values are checked as a run checks them)."""
    if ini is None:
        return Machine({}, (), None)
    from edingcnc_lang.config.machine_config import load_config

    config = load_config(ini)
    limits = tuple((j.negative_limit, j.positive_limit) for j in config.joints)
    return Machine(config.kinematics_settings, (config.folder,) if config.folder else (),
                   limits if config.gives_joint_sections else None, from_cartesian_limits(config))


def load_plugin(name: str, machine: Machine) -> Kinematics:
    from edingcnc_lang.kinematics.loader import load_kinematics

    return load_kinematics(name, machine.settings, machine.search_dirs)


def is_compiled_file(name: str, machine: Machine) -> bool:
    """Whether ``name`` resolves to a shared library (checked out of process)."""
    from edingcnc_lang.kinematics.loader import is_compiled_plugin

    return is_compiled_plugin(name, machine.search_dirs)


def workspace_for(kins: Kinematics, options: CheckOptions, machine: Machine) -> Workspace:
    if options.box is not None:
        return parse_box(options.box)
    space = machine.cartesian
    if space is None and machine.joint_limits is not None:
        space = from_joint_limits(kins, machine.joint_limits, options.seed)
    space = space or default_workspace()
    try:  # ON as the checks will switch it, so that a virtual axis is active while it is tried
        plug.switch_on(kins, space.centre)
    except PLUGIN_FAILURES:  # the control check reports it
        return space
    return turning_rotaries(kins, space)


def check_plugin(name: str, options: CheckOptions = CheckOptions()) -> Report:
    """Load ``name`` (a registered name or a .py/.so path, settings from ``options.ini``) and prove it."""
    machine = read_machine(options.ini)
    if options.isolate and is_compiled_file(name, machine):
        from edingcnc_lang.kinematics.workbench.isolate import run_isolated

        return report_from_json(run_isolated("check", {"name": name, "options": options.to_json()},
                                             fallback=_crash_report(name, options)))
    try:
        kins = load_plugin(name, machine)
    except PluginError as err:
        if not is_compiled_file(name, machine):
            raise
        report = _crash_report(name, options)
        report.findings.append(KinsFinding("K601", err.message))
        return report
    return check_loaded(kins, name, options, machine)


def _crash_report(name: str, options: CheckOptions) -> Report:
    """The frame of a report when the plug-in could not be run at all."""
    box = parse_box(options.box) if options.box else None
    return Report(name, None, None, box.source if box else "not reached", box.box if box else ((0.0, 0.0),) * 6,
                  options.seed, 0)


def check_loaded(kins: Kinematics, label: str, options: CheckOptions, machine: Machine) -> Report:
    """Every check on an already loaded plug-in, in the order a plug-in author would want them."""
    space = workspace_for(kins, options, machine)
    at = space.centre
    rc = plug.switch_on(kins, at)
    rng = np.random.default_rng(options.seed)
    poses = space.random(options.samples, rng)
    samples = geo.PoseSamples(poses, call_each(kins.inverse, poses, machine.joint_limits), machine.joint_limits)
    tol = geo.tolerance(space, options.tolerance)
    report = Report(label, kins.kin_type(), kins.version(), space.source, space.box, options.seed, len(poses))
    if rc != 0:
        report.findings.append(KinsFinding("K501", f"KIN ON (control ID 4) returned {rc}"))
    steps = [lambda: geo.domain(samples, space),
             lambda: geo.round_trip(kins, samples, space, tol),
             lambda: geo.continuity(kins, samples, space, rng, segments=options.segments),
             lambda: geo.singularities(kins, samples, space),
             lambda: plug.control_and_state(kins, samples, tol, at),
             lambda: plug.compiled_abi(kins)]
    for step in steps:
        section, findings = step()
        report.sections.append(section)
        report.findings.extend(findings)
    if options.speed:
        report.sections.append(plug.speed(kins, samples))
    return report


def options_from_json(data: Mapping[str, object]) -> CheckOptions:
    values = dict(data)
    if values.get("box") is not None:
        values["box"] = tuple(float(v) for v in values["box"])  # type: ignore[attr-defined]  # JSON: a list
    return CheckOptions(**values)  # type: ignore[arg-type]


def box_values(values: Sequence[float] | None) -> tuple[float, ...] | None:
    """Validate ``--box`` numbers early, so a typo is a usage error before any plug-in runs."""
    if values is None:
        return None
    parse_box(values)
    return tuple(float(v) for v in values)
