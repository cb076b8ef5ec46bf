"""The kinematics interface every built-in, Python plug-in and compiled plug-in offers.

The interpreter only talks to ``Kinematics``; ``KinematicsPlugin`` gives Python
plug-ins sensible defaults so a user only has to write ``inverse`` and ``forward``.
numpy is imported by the batch methods, not here: a run with the trivial kinematics never needs it.
"""
from __future__ import annotations

import contextlib
import sys
from collections.abc import Callable, Iterable, Mapping, Sequence
from typing import TYPE_CHECKING, Any, ClassVar, Protocol, runtime_checkable

from edingcnc_lang.errors import ConfigError, EcncError, Location, MachineError, PluginError
from edingcnc_lang.kinematics import abi

if TYPE_CHECKING:
    import numpy as np

Pose = tuple[float, ...]  # six values (x y z a b c, or the joints): the same Pose as canon.Pose
AXES = ("x", "y", "z", "a", "b", "c")
JOINTS = ("jx", "jy", "jz", "ja", "jb", "jc")
# What a user plug-in may raise that is its failure, not ecnc's: any exception, and sys.exit() (which
# would otherwise end ecnc silently with the plug-in's status).  Ctrl-C (KeyboardInterrupt) still stops.
PLUGIN_FAILURES: tuple[type[BaseException], ...] = (Exception, SystemExit)


# The methods of a Python plug-in that run its code, guarded when it is loaded (guard_python_plugin).
_GUARDED = ("inverse", "forward", "inverse_many", "forward_many", "control", "user_output")


def guard_python_plugin(kins: object, label: str) -> None:
    """Make a loaded Python plug-in's calls safe for every caller (run, kins, the workbench):
    what it prints goes to stderr, never into a ``--json`` document on stdout; whatever it raises
    (``SystemExit``, a ``BaseException`` of its own, ``RecursionError``) is a PluginError naming it,
    Ctrl-C and ecnc's own errors (KinematicsDomainError) pass; ``inverse``/``forward`` must return
    six numbers (a 2-tuple, None or a generator is that error, not partial joints)."""
    for name in _GUARDED:
        method = getattr(kins, name, None)
        if callable(method):
            setattr(kins, name, _guarded(kins, method, label, name))


def _guarded(kins: object, method: Callable[..., Any], label: str, name: str) -> Callable[..., Any]:
    pose = name in ("inverse", "forward")

    def call(*args: Any, **kwargs: Any) -> Any:
        try:
            with contextlib.redirect_stdout(sys.stderr):
                result = method(*args, **kwargs)
        except (KeyboardInterrupt, EcncError):
            raise
        except BaseException as err:  # noqa: BLE001 - a user plug-in may raise anything
            shown = getattr(kins, "name", "") or label
            raise PluginError(f"kinematics plug-in {shown} failed: {type(err).__name__}: {err}") from None
        return _six_numbers(result, getattr(kins, "name", "") or label, name) if pose else result
    return call


def _six_numbers(result: object, label: str, call: str) -> Pose:
    try:  # a tuple, a list or a numpy array; not a generator, which would be used up
        values = tuple(float(v) for v in result) if isinstance(result, (tuple, list)) or (
            hasattr(result, "shape") and isinstance(result, Iterable)) else ()
    except (TypeError, ValueError):
        values = ()
    if len(values) != 6:
        text = repr(result)
        raise PluginError(f"kinematics plug-in {label}: {call} returned {type(result).__name__} "
                          f"{text[:60]}{'...' if len(text) > 60 else ''}, not six numbers (x y z a b c)")
    return values


class KinematicsDomainError(MachineError):
    """A position the machine cannot reach; ``sample`` is the index within an ``inverse_many`` batch."""

    def __init__(self, message: str, location: Location | None = None,
                 notes: tuple[str, ...] = (), sample: int | None = None) -> None:
        super().__init__(message, location, notes)
        self.sample = sample


@runtime_checkable
class Kinematics(Protocol):
    """What the interpreter needs from a kinematics, whatever it is implemented in."""

    name: str

    def kin_type(self) -> int: ...
    def version(self) -> str: ...
    def inverse(self, pos: Pose, tool_length: float = 0.0) -> Pose: ...
    def forward(self, joints: Pose, tool_length: float = 0.0) -> Pose: ...
    def control(self, control_id: int, data: list[float]) -> int: ...
    def inverse_many(self, pos: np.ndarray, tool_length: float = 0.0) -> np.ndarray: ...
    def user_output(self) -> Sequence[float]: ...


def setting_float(settings: Mapping[str, str], key: str, default: float) -> float:
    """Read a number from the raw ``[KINEMATICS]`` section; an empty or missing value gives ``default``."""
    raw = settings.get(key.lower(), "").strip()
    if not raw:
        return default
    try:
        return float(raw)
    except ValueError:
        raise ConfigError(f"[KINEMATICS] {key} = {raw!r} is not a number") from None


def as_pose(values: Sequence[float]) -> Pose:
    """Six plain floats (numpy scalars would leak into JSON and user variables otherwise)."""
    x, y, z, a, b, c = (float(v) for v in values)
    return (x, y, z, a, b, c)


def as_rows(pos: np.ndarray) -> np.ndarray:
    """Validate an (N, 6) batch and return it as a float array."""
    import numpy as np

    rows = np.asarray(pos, dtype=float)
    if rows.ndim != 2 or rows.shape[1] != 6:
        raise ValueError(f"expected an (N, 6) array of poses, got shape {rows.shape}")
    return rows


class KinematicsPlugin:
    """Base class of Python kinematics: ON/OFF bookkeeping, user output via control 5, batch fallback.

    Subclasses set ``name``, ``KIN_TYPE`` and ``VERSION`` and implement ``inverse``/``forward``;
    ``control`` handles the standard IDs and returns -1 for the rest, so an override handles
    its own IDs and delegates to ``super().control``.
    """

    name: str = ""          # the loader fills in the plug-in name when a subclass leaves it empty
    KIN_TYPE: ClassVar[int] = abi.KinType.CUSTOM_1
    VERSION: ClassVar[str] = "0"
    # What each joint is, for pictures and reports: a SCARA declares ("rotary", "rotary", "linear", ...).
    JOINT_KINDS: ClassVar[tuple[str, ...] | None] = None  # None: by the joint's name (A B C rotary)

    def __init__(self, settings: Mapping[str, str]) -> None:
        self.settings = settings
        self.enabled = False

    def setting(self, key: str, default: float) -> float:
        """A number from ``[KINEMATICS]`` (key as spelled in cnc.ini, matched case-insensitively)."""
        return setting_float(self.settings, key, default)

    def kin_type(self) -> int:
        return int(self.KIN_TYPE)

    def version(self) -> str:
        return self.VERSION

    def inverse(self, pos: Pose, tool_length: float = 0.0) -> Pose:
        raise NotImplementedError

    def forward(self, joints: Pose, tool_length: float = 0.0) -> Pose:
        raise NotImplementedError

    def control(self, control_id: int, data: list[float]) -> int:
        if control_id in (abi.OPEN, abi.CLOSE):
            return 0
        if control_id in (abi.ON, abi.OFF):
            self.enabled = control_id == abi.ON
            return 0
        if control_id == abi.USER_OUTPUT:
            values = list(self.user_output())[:abi.USER_OUTPUT_LEN]
            data[:abi.USER_OUTPUT_LEN] = values + [0.0] * (abi.USER_OUTPUT_LEN - len(values))
            return 0
        return -1

    def inverse_many(self, pos: np.ndarray, tool_length: float = 0.0) -> np.ndarray:
        """Fallback for plug-ins without a vectorised inverse: one scalar call per sample."""
        import numpy as np

        rows = as_rows(pos)
        out = np.empty_like(rows)
        for i, row in enumerate(rows):
            try:
                out[i] = self.inverse(as_pose(row), tool_length)
            except KinematicsDomainError as err:
                raise KinematicsDomainError(err.message, err.location, err.notes, sample=i) from None
        return out

    def user_output(self) -> Sequence[float]:
        return ()


class VectorisedKinematics(KinematicsPlugin):
    """A plug-in whose maths is written once on (N, 6) arrays; the scalar calls use a one-row batch."""

    def inverse_rows(self, pos: np.ndarray, tool_length: float) -> np.ndarray:
        raise NotImplementedError

    def forward_rows(self, joints: np.ndarray, tool_length: float) -> np.ndarray:
        raise NotImplementedError

    def inverse(self, pos: Pose, tool_length: float = 0.0) -> Pose:
        import numpy as np

        try:
            return as_pose(self.inverse_rows(np.array([pos], dtype=float), tool_length)[0])
        except KinematicsDomainError as err:
            raise KinematicsDomainError(err.message, err.location, err.notes) from None

    def forward(self, joints: Pose, tool_length: float = 0.0) -> Pose:
        import numpy as np

        return as_pose(self.forward_rows(np.array([joints], dtype=float), tool_length)[0])

    def inverse_many(self, pos: np.ndarray, tool_length: float = 0.0) -> np.ndarray:
        return self.inverse_rows(as_rows(pos), tool_length)

    def forward_many(self, joints: np.ndarray, tool_length: float = 0.0) -> np.ndarray:
        """Batch forward kinematics (handy for plotting joint logs)."""
        return self.forward_rows(as_rows(joints), tool_length)


JOINT_KIND_NAMES = ("linear", "rotary")


def declared_joint_kinds(kins: object) -> tuple[str, ...] | None:
    """A plug-in's ``JOINT_KINDS`` (six of "linear"/"rotary"), None when it declares none (compiled
    plug-ins cannot); a malformed declaration is the plug-in's error."""
    kinds = getattr(kins, "JOINT_KINDS", None)
    if kinds is None:
        return None
    if not isinstance(kinds, (tuple, list)) or len(kinds) != len(JOINTS) or \
            any(kind not in JOINT_KIND_NAMES for kind in kinds):
        from edingcnc_lang.errors import PluginError

        raise PluginError(f"kinematics plug-in {getattr(kins, 'name', '')!r}: JOINT_KINDS must be six of "
                          f"{' or '.join(map(repr, JOINT_KIND_NAMES))}, got {kinds!r}")
    return tuple(kinds)


def checked_rows(joints: object, count: int) -> np.ndarray:
    """A plug-in's inverse_many result as an (N, 6) float array of finite numbers."""
    import numpy as np

    rows = np.asarray(joints, dtype=float)
    if rows.shape != (count, 6):
        raise ValueError(f"inverse_many returned shape {rows.shape}, expected ({count}, 6)")
    if not np.isfinite(rows).all():
        raise ValueError("inverse_many returned a joint that is not a finite number")
    return rows
