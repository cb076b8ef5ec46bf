"""Compiled kinematics plug-ins: a shared library with the five EdingCNC functions, via ctypes.

The structs are packed (``#pragma pack(1)`` in Eding's headers) and passed by value as the
first argument, exactly as the controller does, so a plug-in written for the controller runs
here unchanged apart from the build.
"""
from __future__ import annotations

import ctypes
import math
import sys
from collections.abc import Mapping, Sequence
from pathlib import Path
from typing import Any

from edingcnc_lang.canon import format_pose
from edingcnc_lang.errors import PluginError
from edingcnc_lang.kinematics import abi
from edingcnc_lang.kinematics.base import KinematicsDomainError, KinematicsPlugin, Pose, as_pose

class CncCartDouble(ctypes.Structure):
    _pack_ = 1
    _fields_ = [(n, ctypes.c_double) for n in ("x", "y", "z", "a", "b", "c")]


class CncJointDouble(ctypes.Structure):
    _pack_ = 1
    _fields_ = [(n, ctypes.c_double) for n in ("jx", "jy", "jz", "ja", "jb", "jc")]


class CncVector(ctypes.Structure):
    _pack_ = 1
    _fields_ = [(n, ctypes.c_double) for n in ("x", "y", "z")]


class KinControlData(ctypes.Union):
    _pack_ = 1
    _fields_ = [("dData", ctypes.c_double * 12), ("iData", ctypes.c_int * 12), ("cData", ctypes.c_char * 64)]


Flags = ctypes.c_uint
_P = ctypes.POINTER
_CART, _JOINT = CncCartDouble, CncJointDouble

# name -> (restype, argtypes); the five every plug-in must export.
REQUIRED_EXPORTS: dict[str, tuple[object, list[object]]] = {
    "KinematicsInverse": (ctypes.c_int, [_CART, _P(_JOINT), _P(Flags), _P(Flags), ctypes.c_double]),
    "KinematicsForward": (ctypes.c_int, [_JOINT, _P(_CART), _P(Flags), _P(Flags), ctypes.c_double]),
    "KinematicsControl": (ctypes.c_int, [ctypes.c_int, _P(KinControlData)]),
    "KinematicsType": (ctypes.c_int, []),
    "KinematicsVersion": (ctypes.c_char_p, []),
}
OPTIONAL_EXPORTS: dict[str, tuple[object, list[object]]] = {
    "KinematicsInverseMaxFeed": (ctypes.c_int, [_CART, _CART, _P(_CART), _P(_CART), ctypes.c_double]),
    "KinematicsInverseMaxFeedArc": (ctypes.c_int, [_CART, _CART, CncVector, CncVector, ctypes.c_int,
                                                   _P(_CART), _P(_CART), ctypes.c_double]),
}


def _values(struct: ctypes.Structure) -> Pose:
    """The six doubles of a CNC_CART_DOUBLE or CNC_JOINT_DOUBLE as a Pose."""
    return as_pose([getattr(struct, name) for name, *_ in struct._fields_])


def _load_library(path: Path) -> ctypes.CDLL:
    """``__stdcall`` exports on Windows, the platform default elsewhere.

    Always by absolute path: a bare ``polar.so`` would send the dynamic loader to the system's
    library search path instead of the file that was found.
    """
    loader = ctypes.WinDLL if sys.platform == "win32" else ctypes.CDLL  # type: ignore[attr-defined]
    return loader(str(Path(path).resolve()))


def missing_exports(path: Path) -> list[str]:
    """The required functions a built library does not export (``ecnc kins build`` checks its output)."""
    try:
        lib = _load_library(path)
    except OSError as err:
        raise PluginError(f"kinematics plug-in {path}: cannot load the library: {err}") from None
    return [export for export in REQUIRED_EXPORTS if getattr(lib, export, None) is None]


class CompiledKinematics(KinematicsPlugin):
    """A shared library behind the ``Kinematics`` interface (scalar calls; batches loop)."""

    def __init__(self, path: Path | str, settings: Mapping[str, str] | None = None) -> None:
        super().__init__(settings or {})
        self.path = Path(path)
        self.name = self.path.stem
        try:
            lib = _load_library(self.path)
        except OSError as err:
            raise PluginError(f"kinematics plug-in {self.path}: cannot load the library: {err}") from None
        self._fn: dict[str, Any] = {}
        for export, (restype, argtypes) in {**REQUIRED_EXPORTS, **OPTIONAL_EXPORTS}.items():
            fn = getattr(lib, export, None)
            if fn is None:
                if export in REQUIRED_EXPORTS:
                    raise PluginError(f"kinematics plug-in {self.path}: it does not export {export}")
                continue
            fn.restype, fn.argtypes = restype, argtypes
            self._fn[export] = fn
        self._lib = lib
        self._pass_settings()

    def _pass_settings(self) -> None:
        """Hand each ``[KINEMATICS]`` setting to the library: control ID 100 with the lower-case key in
        cData and the value as a number in dData[8] (NaN if it is not one); the answer is ignored, so a
        plug-in that does not know the ID (it returns -1) is not bothered."""
        for key, raw in self.settings.items():
            name = key.encode("utf-8", "replace")
            if len(name) > abi.SETTING_KEY_BYTES:
                continue
            block = KinControlData()
            block.cData = name
            try:
                block.dData[abi.SETTING_VALUE] = float(raw.strip())
            except ValueError:
                block.dData[abi.SETTING_VALUE] = math.nan
            self._fn["KinematicsControl"](abi.SETTING, ctypes.byref(block))

    def has_export(self, export: str) -> bool:
        """Whether an optional function such as ``KinematicsInverseMaxFeed`` is present."""
        return export in self._fn

    def kin_type(self) -> int:
        return int(self._fn["KinematicsType"]())

    def version(self) -> str:
        raw = self._fn["KinematicsVersion"]()
        return raw.decode("utf-8", "replace") if raw else ""

    def inverse(self, pos: Pose, tool_length: float = 0.0) -> Pose:
        joints = CncJointDouble()
        rc = self._fn["KinematicsInverse"](CncCartDouble(*pos), ctypes.byref(joints), ctypes.byref(Flags(0)),
                                           ctypes.byref(Flags(0)), tool_length)
        if rc != 0:
            raise KinematicsDomainError(f"{self.name}: {format_pose(pos)} is out of reach (KinematicsInverse returned {rc})")
        return _values(joints)

    def forward(self, joints: Pose, tool_length: float = 0.0) -> Pose:
        pos = CncCartDouble()
        rc = self._fn["KinematicsForward"](CncJointDouble(*joints), ctypes.byref(pos), ctypes.byref(Flags(0)),
                                           ctypes.byref(Flags(0)), tool_length)
        if rc != 0:
            raise KinematicsDomainError(f"{self.name}: KinematicsForward returned {rc} for joints {joints}")
        return _values(pos)

    def control(self, control_id: int, data: list[float]) -> int:
        block = KinControlData()
        for i, value in enumerate(data[:abi.CONTROL_DATA_LEN]):
            block.dData[i] = value
        rc = int(self._fn["KinematicsControl"](control_id, ctypes.byref(block)))
        data[:abi.CONTROL_DATA_LEN] = list(block.dData)
        return rc

    def user_output(self) -> Sequence[float]:
        """Asked through control ID 5; a plug-in that does not know it has no user output."""
        data = [0.0] * abi.CONTROL_DATA_LEN
        return tuple(data) if self.control(abi.USER_OUTPUT, data) == 0 else ()

    def inverse_max_feed(self, start: Pose, end: Pose, tool_length: float = 0.0) -> tuple[Pose, Pose] | None:
        """Per-axis Cartesian (max velocity, max acceleration) for a line, if the plug-in exports it."""
        fn = self._fn.get("KinematicsInverseMaxFeed")
        if fn is None:
            return None
        vel, acc = CncCartDouble(), CncCartDouble()
        if fn(CncCartDouble(*start), CncCartDouble(*end), ctypes.byref(vel), ctypes.byref(acc), tool_length):
            return None
        return _values(vel), _values(acc)

    def inverse_max_feed_arc(self, start: Pose, end: Pose, center: Sequence[float], normal: Sequence[float],
                             turn: int, tool_length: float = 0.0) -> tuple[Pose, Pose] | None:
        """The same for an arc, if the plug-in exports ``KinematicsInverseMaxFeedArc``."""
        fn = self._fn.get("KinematicsInverseMaxFeedArc")
        if fn is None:
            return None
        vel, acc = CncCartDouble(), CncCartDouble()
        if fn(CncCartDouble(*start), CncCartDouble(*end), CncVector(*center), CncVector(*normal), turn,
              ctypes.byref(vel), ctypes.byref(acc), tool_length):
            return None
        return _values(vel), _values(acc)
