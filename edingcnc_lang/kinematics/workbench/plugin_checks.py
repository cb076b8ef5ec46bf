"""The checks on the plug-in as a program: control calls and state, the compiled ABI, and speed."""
from __future__ import annotations

import ctypes
import math
import time

import numpy as np

from edingcnc_lang.kinematics import abi
from edingcnc_lang.kinematics.base import PLUGIN_FAILURES, Kinematics, KinematicsPlugin
from edingcnc_lang.kinematics.workbench.calls import call_each
from edingcnc_lang.kinematics.workbench.findings import KinsFinding, Section, format_joints
from edingcnc_lang.kinematics.workbench.geometry_checks import PoseSamples

KNOWN_TYPES = frozenset(int(t) for t in abi.KinType) | frozenset(range(18, 31))
UNKNOWN_CONTROL_ID = 99
# The header's promise (#pragma pack(1)): the sizes in bytes a compiled plug-in is called with.
HEADER_SIZES = {"CNC_CART_DOUBLE": 48, "CNC_JOINT_DOUBLE": 48, "CNC_VECTOR": 24, "KIN_CONTROLDATA": 96}


def switch_on(kins: Kinematics, at: tuple[float, ...]) -> int:
    """``KIN ON`` as the controller does it: control ID 4 with the machine position in dData[0..5]."""
    data = [*at, *[0.0] * (abi.CONTROL_DATA_LEN - len(at))]
    return kins.control(abi.ON, data)


def control_and_state(kins: Kinematics, samples: PoseSamples, tol: float,
                      at: tuple[float, ...]) -> tuple[Section, list[KinsFinding]]:
    """ON/OFF return 0, unknown IDs do not raise, user output is sane, answers do not drift."""
    findings: list[KinsFinding] = []
    for name, control_id in (("OFF", abi.OFF), ("ON", abi.ON)):
        try:
            rc = kins.control(control_id, [*at, *[0.0] * (abi.CONTROL_DATA_LEN - len(at))])
        except PLUGIN_FAILURES as err:  # a plug-in under test may fail in any way
            rc, detail = None, f"raised {type(err).__name__}: {err}"
        else:
            detail = f"returned {rc}"
        if rc != 0:
            findings.append(KinsFinding("K501", f"KIN {name} (control ID {control_id}) {detail}"))
    try:
        kins.control(UNKNOWN_CONTROL_ID, [0.0] * abi.CONTROL_DATA_LEN)
    except PLUGIN_FAILURES as err:  # must answer -1, not raise
        findings.append(KinsFinding("K501", f"control ID {UNKNOWN_CONTROL_ID} (unknown) raised {type(err).__name__}: "
                                f"{err}; return -1 for IDs the plug-in does not handle"))
    try:
        output = [float(v) for v in kins.user_output()]
    except PLUGIN_FAILURES as err:  # noqa: BLE001 - reported as a finding
        output, problem = [], f"user_output raised {type(err).__name__}: {err}"
    else:
        problem = ("" if len(output) <= abi.USER_OUTPUT_LEN and all(math.isfinite(v) for v in output)
                   else f"user output is {output}")
    if problem:
        findings.append(KinsFinding("K502", problem))
    findings += _drift(kins, samples, tol, at)
    summary = f"KIN ON/OFF, unknown control ID, user output ({len(output)} values), repeatable answers"
    return Section("control", ("ok: " if not findings else "") + summary, {"user_output": output}), findings


def _drift(kins: Kinematics, samples: PoseSamples, tol: float, at: tuple[float, ...]) -> list[KinsFinding]:
    """The first answers again, after thousands of other calls and after an OFF/ON cycle."""
    poses, first = samples.reached[:50], samples.inverse.values[samples.inverse.ok][:50]
    findings = []
    for code, what in (("K503", "after the other checks"), ("K504", "after KIN OFF and ON")):
        if code == "K504":
            kins.control(abi.OFF, [0.0] * abi.CONTROL_DATA_LEN)
            switch_on(kins, at)
        again = call_each(kins.inverse, poses)
        diff = np.max(np.abs(again.values - first), axis=1) if len(poses) else np.zeros(0)
        bad = np.flatnonzero(~(diff <= tol))
        if len(bad):
            i = int(bad[np.argmax(np.nan_to_num(diff[bad], nan=np.inf))])
            findings.append(KinsFinding(code, f"inverse of the same pose {what} differs by {diff[i]:.6g} "
                                    f"(first {format_joints(first[i])})", pose=_floats(poses[i]),
                                    joints=_floats(again.values[i]), count=len(bad)))
    return findings


def _floats(row: np.ndarray) -> tuple[float, ...]:
    return tuple(float(v) for v in row)


def compiled_abi(kins: Kinematics) -> tuple[Section, list[KinsFinding]]:
    """Exports, struct sizes and the two plain calls of a compiled plug-in; Python plug-ins skip this."""
    from edingcnc_lang.kinematics import ctypes_plugin as cp

    if not isinstance(kins, cp.CompiledKinematics):
        return Section("compiled", "not a compiled plug-in"), []
    findings: list[KinsFinding] = []
    sizes = {"CNC_CART_DOUBLE": ctypes.sizeof(cp.CncCartDouble), "CNC_JOINT_DOUBLE": ctypes.sizeof(cp.CncJointDouble),
             "CNC_VECTOR": ctypes.sizeof(cp.CncVector), "KIN_CONTROLDATA": ctypes.sizeof(cp.KinControlData)}
    wrong = {k: v for k, v in sizes.items() if HEADER_SIZES[k] != v}
    if wrong:
        findings.append(KinsFinding("K603", f"struct sizes differ from the header: {wrong}"))
    kin_type = kins.kin_type()
    if kin_type not in KNOWN_TYPES:
        findings.append(KinsFinding("K603", f"KinematicsType() returned {kin_type}, not a CNC_KINEMATICS_TYPE value"))
    raw = kins._fn["KinematicsVersion"]()  # the raw bytes: the wrapper would hide undecodable text
    if not raw:
        findings.append(KinsFinding("K603", "KinematicsVersion() returned NULL or an empty string"))
    else:
        try:
            raw.decode("ascii")
        except UnicodeDecodeError:
            findings.append(KinsFinding("K603", f"KinematicsVersion() is not plain ASCII: {raw[:40]!r}"))
    exports = sorted(cp.REQUIRED_EXPORTS) + [e for e in sorted(cp.OPTIONAL_EXPORTS) if kins.has_export(e)]
    summary = f"exports {', '.join(exports)}; struct sizes {sizes}; type {kin_type}"
    return (Section("compiled", ("ok: " if not findings else "") + summary,
                    {"exports": exports, "struct_sizes": sizes}), findings)


def speed(kins: Kinematics, samples: PoseSamples, budget: float = 0.2) -> Section:
    """Scalar inverse and forward calls per second; batch inverse samples per second where there is one."""
    poses = samples.reached
    if not len(poses):
        return Section("speed", "not run: nothing reachable")
    joints = samples.inverse.values[samples.inverse.ok]
    figures: dict[str, float | None] = {"inverse_per_second": _rate(kins.inverse, poses, budget),
               "forward_per_second": _rate(kins.forward, joints, budget)}
    vectorised = type(kins).inverse_many is not KinematicsPlugin.inverse_many
    summary = (f"scalar inverse {figures['inverse_per_second']:,.0f} calls/s, forward "
               f"{figures['forward_per_second']:,.0f} calls/s")
    if vectorised:
        batch = np.resize(poses, (100_000, 6))
        start = time.perf_counter()
        try:
            kins.inverse_many(batch)
        except PLUGIN_FAILURES:  # the sampled poses were reached one by one; a batch failure is not a speed figure
            figures["batch_inverse_per_second"] = None
        else:
            rate = len(batch) / max(time.perf_counter() - start, 1e-9)
            figures["batch_inverse_per_second"] = rate
            summary += f"; batch inverse {rate / 1e6:.3g} M samples/s"
    else:
        summary += "; no batch inverse (inverse_many loops over the scalar call)"
    return Section("speed", summary, figures)


def _rate(fn, rows: np.ndarray, budget: float) -> float:
    """Calls per second over at least ``budget`` seconds, cycling through ``rows``."""
    calls, start = 0, time.perf_counter()
    elapsed = 0.0
    while elapsed < budget:
        for row in rows[:500]:
            try:
                fn(tuple(float(v) for v in row))
            except PLUGIN_FAILURES:  # speed only; failures were reported by the other checks
                pass
        calls += min(len(rows), 500)
        elapsed = time.perf_counter() - start
    return calls / elapsed
