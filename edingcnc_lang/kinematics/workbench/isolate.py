"""Running a compiled plug-in's check in a child process, so a crash in the library is a finding.

The child records every library call (which function, which pose) in a small shared file just
before making it; when the child dies from a signal or hangs, the parent reads that record and
names the call and the pose.  The child's report comes back as JSON on its standard output.
"""
from __future__ import annotations

import contextlib
import json
import os
import signal
import subprocess
import sys
import tempfile
from collections.abc import Callable, Iterator, Mapping
from typing import Any

import numpy as np

from edingcnc_lang.errors import PluginError
from edingcnc_lang.kinematics.workbench.findings import KinsFinding, Report

CALLS = ("KinematicsInverse", "KinematicsForward", "KinematicsControl", "KinematicsType", "KinematicsVersion")
RECORD = 8  # doubles: call number, then six pose or joint values (or the control ID), then a counter
TIMEOUT = 300.0


@contextlib.contextmanager
def _guard_file() -> Iterator[str]:
    """The small file a child records each library call in before making it (removed afterwards)."""
    fd, guard = tempfile.mkstemp(prefix="ecnc-kins-guard-")
    try:
        os.write(fd, bytes(8 * RECORD))
        os.close(fd)
        yield guard
    finally:
        os.unlink(guard)


def run_isolated(command: str, payload: Mapping[str, Any], fallback: Report, timeout: float = TIMEOUT) -> dict:
    """Run ``child.py COMMAND PAYLOAD GUARD``; return its JSON report, or ``fallback`` with the crash in it."""
    with _guard_file() as guard:
        argv = [sys.executable, "-m", "edingcnc_lang.kinematics.workbench.child", command, json.dumps(payload), guard]
        try:
            done = subprocess.run(argv, capture_output=True, text=True, timeout=timeout, check=False)
        except subprocess.TimeoutExpired:
            fallback.findings.append(_last_call(guard, "K604", f"did not return within {timeout:g} s"))
            return fallback.to_json()
        if done.returncode in (0, 1, 2) and done.stdout.strip():
            result = json.loads(done.stdout)
            if "error" in result:  # the plug-in could not be loaded: an error, as in-process
                raise PluginError(result["error"])
            return result
        if done.returncode < 0:
            name = signal.Signals(-done.returncode).name
            fallback.findings.append(_last_call(guard, "K602", f"crashed the process ({name})"))
        else:
            tail = (done.stderr or "").strip().splitlines()[-1:] or ["no message"]
            fallback.findings.append(_last_call(guard, "K602", f"ended the process with exit {done.returncode}: "
                                                               f"{tail[0]}"))
        return fallback.to_json()


GUARD_VARIABLE = "_ECNC_KINS_GUARD"  # set in the child of run_command_isolated: the file calls are recorded in


def run_command_isolated(argv: list[str], plugin: str, timeout: float = TIMEOUT) -> tuple[int, str, str]:
    """``ecnc ARGV`` in a child process that records the plug-in's calls (``ecnc kins inverse|forward``
    on a compiled plug-in): (exit status, stdout, stderr); a crash or a hang in the library is a
    PluginError naming the call and the pose, as ``ecnc kins check`` reports it (K602, K604)."""
    with _guard_file() as guard:
        try:
            done = subprocess.run([sys.executable, "-m", "edingcnc_lang", *argv], capture_output=True, text=True,
                                  check=False, env={**os.environ, GUARD_VARIABLE: guard}, timeout=timeout)
        except subprocess.TimeoutExpired:
            finding = _last_call(guard, "K604", f"did not return within {timeout:g} s")
        else:
            if done.returncode >= 0:
                return done.returncode, done.stdout, done.stderr
            finding = _last_call(guard, "K602", f"crashed the process ({signal.Signals(-done.returncode).name})")
    raise PluginError(f"kinematics plug-in {plugin!r}: {crash_text(finding)}")


def crash_text(finding: KinsFinding) -> str:
    """A K602/K604 finding as an error's text: the call, what happened and where."""
    from edingcnc_lang.kinematics.workbench.findings import format_joints, format_pose

    where = (f" at {format_pose(finding.pose)}" if finding.pose is not None else
             f" at {format_joints(finding.joints)}" if finding.joints is not None else "")
    return finding.message + where


def _last_call(guard: str, code: str, what: str) -> KinsFinding:
    record = np.fromfile(guard, dtype=np.float64, count=RECORD)
    call = int(record[0])
    if not 1 <= call <= len(CALLS):
        return KinsFinding(code, f"the plug-in {what} before its first call")
    name = CALLS[call - 1]
    values = tuple(float(v) for v in record[1:7])
    if name == "KinematicsControl":
        return KinsFinding(code, f"{name}(id {values[0]:g}) {what}")
    if name == "KinematicsForward":
        return KinsFinding(code, f"{name} {what}", joints=values)
    if name == "KinematicsInverse":
        return KinsFinding(code, f"{name} {what}", pose=values)
    return KinsFinding(code, f"{name}() {what}")


def guard_calls(kins: Any, guard: str) -> None:
    """Wrap a ``CompiledKinematics``'s library functions so each call is recorded before it is made."""
    record = np.memmap(guard, dtype=np.float64, mode="r+", shape=(RECORD,))
    for number, name in enumerate(CALLS, start=1):
        fn = kins._fn[name]
        kins._fn[name] = _recorder(fn, number, record)


def _recorder(fn: Callable[..., Any], number: int, record: np.memmap) -> Callable[..., Any]:
    def call(*args: Any) -> Any:
        record[0] = number
        first = args[0] if args else None
        fields = getattr(first, "_fields_", None)
        if fields is not None:
            record[1:7] = [getattr(first, f) for f, *_ in fields]
        elif isinstance(first, int):
            record[1] = first
        record[7] += 1
        return fn(*args)
    return call
