"""Kinematics: the plug-in interface, the loader, the built-ins and path sampling.

See docs/kinematics.md.  The interpreter uses ``load_kinematics`` and the ``Kinematics``
protocol; plug-in authors subclass ``KinematicsPlugin``.

The names below are imported on first use (PEP 562): a submodule such as ``kinematics.base`` can
be imported without loading the loader, the samplers or numpy.
"""
from __future__ import annotations

import importlib
from typing import TYPE_CHECKING, Any

if TYPE_CHECKING:
    from edingcnc_lang.kinematics import abi
    from edingcnc_lang.kinematics.base import (
        Kinematics,
        KinematicsDomainError,
        KinematicsPlugin,
        Pose,
        VectorisedKinematics,
        setting_float,
    )
    from edingcnc_lang.kinematics.builtin import (
        CoreXYKinematics,
        CylinderMapping,
        TrivialKinematics,
        bend_knife_correction,
    )
    from edingcnc_lang.kinematics.loader import available_kinematics, load_kinematics
    from edingcnc_lang.kinematics.sampling import sample_arc, sample_line

# public name -> the submodule that defines it
_EXPORTS: dict[str, str] = {
    **dict.fromkeys(("Kinematics", "KinematicsDomainError", "KinematicsPlugin", "Pose", "VectorisedKinematics",
                     "setting_float"), "base"),
    **dict.fromkeys(("CoreXYKinematics", "CylinderMapping", "TrivialKinematics", "bend_knife_correction"), "builtin"),
    **dict.fromkeys(("available_kinematics", "load_kinematics"), "loader"),
    **dict.fromkeys(("sample_arc", "sample_line"), "sampling"),
}

__all__ = [
    "abi", "Kinematics", "KinematicsDomainError", "KinematicsPlugin", "Pose", "VectorisedKinematics",
    "setting_float", "CoreXYKinematics", "CylinderMapping", "TrivialKinematics", "bend_knife_correction",
    "available_kinematics", "load_kinematics", "sample_arc", "sample_line",
]


def __getattr__(name: str) -> Any:
    """Import the submodule behind a public name the first time the name is asked for."""
    if name == "abi":
        return importlib.import_module(f"{__name__}.abi")
    module = _EXPORTS.get(name)
    if module is None:
        raise AttributeError(f"module {__name__!r} has no attribute {name!r}")
    value = getattr(importlib.import_module(f"{__name__}.{module}"), name)
    globals()[name] = value
    return value


def __dir__() -> list[str]:
    return sorted({*globals(), *__all__})
