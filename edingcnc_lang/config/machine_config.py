"""Machine configuration: what the keys of EdingCNC's ``cnc.ini`` mean, with their defaults.

``MachineConfig.default()`` is the machine without an ini; ``load_config`` reads one through
``ini.py`` (loaded only then: most runs have no ini), checks the values the toolchain uses and
reports bad ones at their ini line.  ``save_variables`` writes the persisted parameters back.
See docs/configuration.md for the keys and the project decisions.
"""
from __future__ import annotations

import os
import re
from collections.abc import Callable, Mapping
from dataclasses import replace
from pathlib import Path
from types import MappingProxyType
from typing import TYPE_CHECKING, Any

from edingcnc_lang.diagnostics import Diagnostic
from edingcnc_lang.errors import ConfigError
from edingcnc_lang.syntax.input_limits import MAX_AXIS_RATE, MIN_AXIS_RATE
from edingcnc_lang.records import record

if TYPE_CHECKING:
    from edingcnc_lang.config.ini import IniFile

AXES = "XYZABC"

_WIDE_LIMIT = 1e6             # mm: nothing a job does should reach it
_WIDE_VELOCITY = 1000.0       # mm/s
_WIDE_ACCELERATION = 10000.0  # mm/s^2

# dialect.md section 10, "Persisted across runs": the parameters kept in [VARIABLES].
PERSISTED: tuple[range, ...] = (
    range(4000, 5000),
    range(5008, 5009),
    range(5013, 5015),
    range(5161, 5167),
    range(5181, 5187),
    range(5211, 5217),
    range(5220, 5221),
    range(5221, 5387),
    range(5390, 5394),
)


def is_persisted(n: int) -> bool:
    """True if parameter ``n`` survives between runs (stored in ``[VARIABLES]``)."""
    return any(n in r for r in PERSISTED)



# --------------------------------------------------------------------------- machine model

@record(frozen=True)
class JointConfig:
    """One motor (``[JOINT_n]``): limits in mm or degrees, velocities in units per second."""

    name: str
    positive_limit: float
    negative_limit: float
    max_velocity: float
    max_acceleration: float
    home_velocity: float
    home_velocity_slow: float
    home_position: float
    resolution: float
    visible: bool


@record(frozen=True)
class ToolConfig:
    """One tool table entry (``[TOOL_n]``).

    On a lathe ``length`` is the Z offset and ``width`` the X offset (radius) of the tool tip;
    ``z_delta``/``x_delta`` are their wear corrections (#5900+n / #5800+n).
    """

    number: int
    length: float
    diameter: float
    width: float
    x_delta: float
    z_delta: float
    orientation: int
    description: str


@record(frozen=True)
class TanKnifeConfig:
    """Tangential knife settings from ``[INTERPRETER]`` (angles in degrees, distances in mm)."""

    angle_for_lift_up: float
    blend_angle: float
    blend_distance: float
    lift_up_distance: float
    bending_angle: float
    z_hi: float
    z_lo: float
    rewind_turns: int


# [SYSTEM] machineType: the values of the controller's CNC_MACHINE_TYPE (cnc_types.h of its API).
MILLING, TURNING, TURNING_BACK_X, FOAMCUTTER, PLASMACUTTER, PRINTING_3D, LASER = range(7)
MACHINE_TYPES: Mapping[int, str] = MappingProxyType({
    MILLING: "milling", TURNING: "turning", TURNING_BACK_X: "turning, back tool lathe",
    FOAMCUTTER: "4-axis foam cutter", PLASMACUTTER: "plasma cutter", PRINTING_3D: "3D printer", LASER: "laser",
})
LATHES = frozenset({TURNING, TURNING_BACK_X})


SPINDLE_CONFIGS = 5  # [SPINDLE_0]..[SPINDLE_4] (manual 3.7.2)


@record(frozen=True)
class MachineConfig:
    """Everything the interpreter, kinematics and simulator need from ``cnc.ini``."""

    path: str | None
    machine_type: int              # MILLING or TURNING
    diameter_programming: bool     # lathe: X words and X positions are diameters
    spindle_max_rpm: float         # 0: no limit of the machine's own
    spindle_min_rpm: float
    initial_string: str
    g4_in_milliseconds: bool
    inch_mode: bool
    absolute_center_coords: bool
    reverse_g2g3: bool
    full_circle_theta_epsilon: float
    g64_p: float
    g64_active: bool
    macro_file: Path | None
    user_macro_file: Path | None
    tanknife: TanKnifeConfig
    joints: tuple[JointConfig, ...]
    interpolation_time: float
    g0_velocity_factor: float
    g0_acceleration_factor: float
    laf_angle: float
    laf_arcfeed_factor: float
    min_circle_segment_size: float
    kinematics_name: str
    kinematics_settings: Mapping[str, str]
    cartesian_positive_limits: tuple[float, ...]
    cartesian_negative_limits: tuple[float, ...]
    cartesian_max_velocity: tuple[float, ...]
    cartesian_max_acceleration: tuple[float, ...]
    tca_positive: tuple[float, ...]        # tool-change area, machine X Y Z (A B C unused); all 0: none
    tca_negative: tuple[float, ...]
    user_output_start: int
    user_output_count: int
    tools: Mapping[int, ToolConfig]
    variables: Mapping[int, float]
    sections: frozenset[str] = frozenset()  # the ini's section names, lower case: which ones it GAVE
    warnings: tuple[Diagnostic, ...] = ()  # values accepted with a caveat (an unknown machineType, ...)
    # [SPINDLE_1]..[SPINDLE_4] xOffset yOffset zOffset: where each alternate spindle (M91..M93, the probe
    # M95, the camera M97) is relative to [SPINDLE_0] (manual 3.7.2); index 0 is the standard spindle
    spindle_offsets: tuple[tuple[float, float, float], ...] = ((0.0, 0.0, 0.0),) * SPINDLE_CONFIGS

    @property
    def folder(self) -> Path | None:
        """The ini's folder: where plug-in and macro files named in it are looked for (None without an ini)."""
        return Path(self.path).parent if self.path else None

    def gives_cartesian_limits(self, axis: int) -> bool:
        """Whether ``[KINEMATICS]`` sets both positiveLimit and negativeLimit of ``axis`` (else defaults)."""
        letter = AXES[axis].lower()
        return all(f"{side}limit{letter}" in self.kinematics_settings for side in ("positive", "negative"))

    @property
    def gives_joint_sections(self) -> bool:
        """Whether the ini has any ``[JOINT_n]`` section (else the joints are the wide defaults)."""
        return any(name.startswith("joint_") for name in self.sections)

    @property
    def lathe(self) -> bool:
        """A turning machine (``machineType`` 1, or 2 for a back tool lathe): G18, X-first homing
        moves, X+Z tool offsets.  The back tool lathe's mirrored X changes only how the controller's
        screen draws it, not the coordinates a job programs."""
        return self.machine_type in LATHES

    @property
    def diameter_mode(self) -> bool:
        """X is programmed and reported as a diameter (only ever on a lathe)."""
        return self.lathe and self.diameter_programming

    def axis_limits(self) -> tuple[list[float], list[float]]:
        """Lower and upper travel of the axes X..C: the joints' limits on a trivial machine, the
        ``[KINEMATICS]`` Cartesian limits with a kinematics plug-in (joints are not axes there)."""
        if self.kinematics_name.lower() in ("", "trivial"):
            return [j.negative_limit for j in self.joints], [j.positive_limit for j in self.joints]
        return list(self.cartesian_negative_limits), list(self.cartesian_positive_limits)

    @classmethod
    def default(cls) -> MachineConfig:
        """The machine used without an ini: trivial kinematics, wide limits, 200 Hz, homed at 0."""
        return cls(
            path=None,
            machine_type=MILLING,
            diameter_programming=False,
            spindle_max_rpm=0.0,
            spindle_min_rpm=0.0,
            initial_string="",
            g4_in_milliseconds=False,
            inch_mode=False,
            absolute_center_coords=False,
            reverse_g2g3=False,
            full_circle_theta_epsilon=1e-6,
            g64_p=0.0,
            g64_active=True,
            macro_file=None,
            user_macro_file=None,
            tanknife=TanKnifeConfig(angle_for_lift_up=5.0, blend_angle=1.0, blend_distance=0.0,
                                    lift_up_distance=3.0, bending_angle=0.0, z_hi=0.0, z_lo=0.0,
                                    rewind_turns=0),
            joints=tuple(
                JointConfig(name=axis, positive_limit=_WIDE_LIMIT, negative_limit=-_WIDE_LIMIT,
                            max_velocity=_WIDE_VELOCITY, max_acceleration=_WIDE_ACCELERATION,
                            home_velocity=-20.0, home_velocity_slow=2.0, home_position=0.0,
                            resolution=1000.0, visible=True)
                for axis in AXES),
            interpolation_time=0.005,
            g0_velocity_factor=1.0,
            g0_acceleration_factor=1.0,
            laf_angle=5.0,
            laf_arcfeed_factor=1.0,
            min_circle_segment_size=0.0,
            kinematics_name="trivial",
            kinematics_settings=MappingProxyType({}),
            cartesian_positive_limits=(_WIDE_LIMIT,) * len(AXES),
            cartesian_negative_limits=(-_WIDE_LIMIT,) * len(AXES),
            cartesian_max_velocity=(_WIDE_VELOCITY,) * len(AXES),
            cartesian_max_acceleration=(_WIDE_ACCELERATION,) * len(AXES),
            tca_positive=(0.0,) * len(AXES),
            tca_negative=(0.0,) * len(AXES),
            user_output_start=0,
            user_output_count=0,
            tools=MappingProxyType({}),
            variables=MappingProxyType({}),
        )


# Which ini key feeds which field, and as what type: (field, ini key, "str" | "bool" | "int" | "float").
_Kind = str  # which IniFile.get_<kind> reads the value
_SYSTEM_FIELDS: tuple[tuple[str, str, _Kind], ...] = (
    ("machine_type", "machineType", "int"),
)
_SPINDLE_FIELDS: tuple[tuple[str, str, _Kind], ...] = (
    ("spindle_max_rpm", "spindleNmax", "float"),
    ("spindle_min_rpm", "spindleNmin", "float"),
)
_INTERPRETER_FIELDS: tuple[tuple[str, str, _Kind], ...] = (
    ("diameter_programming", "diameterProgramming", "bool"),
    ("initial_string", "initialString", "str"),
    ("g4_in_milliseconds", "g4InMilliseconds", "bool"),
    ("inch_mode", "inchModeActive", "bool"),
    ("absolute_center_coords", "absoluteCenterCoords", "bool"),
    ("reverse_g2g3", "reverseG2G3", "bool"),
    ("full_circle_theta_epsilon", "fullCircleThetaEpsilon", "float"),
    ("g64_p", "g64pvalue", "float"),
    ("g64_active", "g64Active", "bool"),
)
_TANKNIFE_FIELDS: tuple[tuple[str, str, _Kind], ...] = (
    ("angle_for_lift_up", "tanKnifeAngleForLiftUp", "float"),
    ("blend_angle", "tanKnifeBlendAngle", "float"),
    ("blend_distance", "tanKnifeBlendDistance", "float"),
    ("lift_up_distance", "tanKnifeLiftUpDistance", "float"),
    ("bending_angle", "tanknifeBendingAngle", "float"),
    ("z_hi", "tanknifeZhi", "float"),
    ("z_lo", "tanknifeZlo", "float"),
    ("rewind_turns", "tanknifeRewindTurns", "int"),
)
_JOINT_FIELDS: tuple[tuple[str, str, _Kind], ...] = (
    ("name", "name", "str"),
    ("positive_limit", "positiveLimit", "float"),
    ("negative_limit", "negativeLimit", "float"),
    ("max_velocity", "maxVelocity", "float"),
    ("max_acceleration", "maxAcceleration", "float"),
    ("home_velocity", "homeVelocity", "float"),
    ("home_velocity_slow", "homeVelocitySlow", "float"),
    ("home_position", "homePosition", "float"),
    ("resolution", "resolution", "float"),
    ("visible", "visible", "bool"),
)
_TRAJECTORY_FIELDS: tuple[tuple[str, str, _Kind], ...] = (
    ("interpolation_time", "interpolationTime", "float"),
    ("g0_velocity_factor", "g0VelocityFactor", "float"),
    ("g0_acceleration_factor", "g0AccelelerationFactor", "float"),  # sic: EdingCNC's spelling
    ("laf_angle", "lafAngle", "float"),
    ("laf_arcfeed_factor", "lafArcfeedFactor", "float"),
    ("min_circle_segment_size", "minCircleSegmentSize", "float"),
)
_KINEMATICS_FIELDS: tuple[tuple[str, str, _Kind], ...] = (
    ("kinematics_name", "kinematicsDLLName", "str"),
    ("user_output_start", "userOutputStartVariable", "int"),
    ("user_output_count", "userOutputNumVariables", "int"),
)
# Per-axis Cartesian values in [KINEMATICS]: the key is the prefix plus the axis letter.
_CARTESIAN_FIELDS = (
    ("cartesian_positive_limits", "positiveLimit"),
    ("cartesian_negative_limits", "negativeLimit"),
    ("cartesian_max_velocity", "maxVelocity"),
    ("cartesian_max_acceleration", "maxAcceleration"),
    ("tca_positive", "positiveLimitTCA"),  # the tool-change area (TCAGuard): X Y Z used
    ("tca_negative", "negativeLimitTCA"),
)
_TOOL_DEFAULT = ToolConfig(number=0, length=0.0, diameter=0.0, width=0.0, x_delta=0.0, z_delta=0.0,
                           orientation=0, description="")
_TOOL_FIELDS: tuple[tuple[str, str, _Kind], ...] = (
    ("length", "length", "float"),
    ("diameter", "diameter", "float"),
    ("width", "width", "float"),
    ("x_delta", "xDelta", "float"),
    ("z_delta", "zDelta", "float"),
    ("orientation", "orientation", "int"),
    ("description", "description", "str"),
)
_TOOL_NUMBERS = range(1, 100)


def _read_fields(ini: IniFile, section: str, table: tuple[tuple[str, str, _Kind], ...],
                 defaults: object) -> dict[str, Any]:
    return {name: getattr(ini, f"get_{kind}")(section, key, getattr(defaults, name)) for name, key, kind in table}


def _read_cartesian(ini: IniFile, base: MachineConfig) -> dict[str, Any]:
    return {name: tuple(ini.get_float("KINEMATICS", prefix + axis, default)
                        for axis, default in zip(AXES, getattr(base, name)))
            for name, prefix in _CARTESIAN_FIELDS}


def _read_tools(ini: IniFile) -> Mapping[int, ToolConfig]:
    tools = {n: ToolConfig(number=n, **_read_fields(ini, f"TOOL_{n}", _TOOL_FIELDS, _TOOL_DEFAULT))
             for n in _TOOL_NUMBERS if f"tool_{n}" in ini.sections}
    return MappingProxyType(tools)


def _read_spindle_offset(ini: IniFile, number: int) -> tuple[float, float, float]:
    x, y, z = (ini.get_float(f"SPINDLE_{number}", f"{axis}Offset", 0.0) for axis in "xyz")
    return (x, y, z)


START_COORD_SYSTEM = 5220  # the work offset selected when the machine starts (manual 3.3)


def _read_variables(ini: IniFile) -> Mapping[int, float]:
    """Persisted parameters from ``#n = value`` lines; other numbers are ignored like unknown keys."""
    from edingcnc_lang.config.ini import VARIABLE_KEY

    values: dict[int, float] = {}
    for key in ini.sections.get("variables", {}):
        match = VARIABLE_KEY.fullmatch(key)
        if match and is_persisted(int(match.group(1))):
            values[int(match.group(1))] = ini.get_float("VARIABLES", key, 0.0)
            if int(match.group(1)) == START_COORD_SYSTEM and values[START_COORD_SYSTEM] not in range(1, 10):
                # manual 3.3 (p. 7): "Es ist ein Fehler, dass der Wert von Parameter 5220 alles andere als eine
                # ganze Zahl zwischen eins und neun ist"
                raise ConfigError(f"#5220 = {ini.get_str('VARIABLES', key, '')} in [VARIABLES]: the coordinate system "
                                  "the machine starts in must be a whole number 1..9 (1 = G54 .. 9 = G59.3)",
                                  ini.location("VARIABLES", key))
    return MappingProxyType(values)


def _resolve_macro(ini: IniFile, key: str, folder: Path) -> Path | None:
    """The named macro file as written if it exists, else its file name in the ini's folder.

    Relative names are taken relative to the ini's folder, so a configuration keeps working
    wherever it is run from; Windows paths such as ``C:\\CNC4.03\\macro.cnc`` fall back to
    ``macro.cnc`` beside the ini.
    """
    raw = ini.get_str("INTERPRETER", key, "").strip()
    if not raw:
        return None
    as_written = folder / raw.replace("\\", "/")  # an absolute path replaces the folder
    beside_ini = folder / re.split(r"[\\/]", raw)[-1]
    return next((p for p in (as_written, beside_ini) if p.is_file()), None)


SPINDLE = "SPINDLE"  # in _CHECKS: the section the main spindle's keys were read from (_spindle_section)
# Checks made after reading: (section, key to report at, passes?, what the value must be).
_CHECKS: tuple[tuple[str, str, Callable[[MachineConfig], bool], str], ...] = (
    (SPINDLE, "spindleNmax", lambda c: c.spindle_max_rpm >= 0, "must be 0 (no limit) or a speed in rpm"),
    (SPINDLE, "spindleNmin", lambda c: 0 <= c.spindle_min_rpm and (
        c.spindle_max_rpm == 0 or c.spindle_min_rpm <= c.spindle_max_rpm),
     "must be 0 or a speed in rpm no higher than spindleNmax"),
    ("TRAJECTORY", "interpolationTime", lambda c: c.interpolation_time > 0,
     "must be greater than 0 seconds"),
    ("TRAJECTORY", "g0VelocityFactor", lambda c: c.g0_velocity_factor > 0, "must be greater than 0"),
    ("TRAJECTORY", "g0AccelelerationFactor", lambda c: c.g0_acceleration_factor > 0, "must be greater than 0"),
    ("TRAJECTORY", "lafArcfeedFactor", lambda c: c.laf_arcfeed_factor > 0, "must be greater than 0"),
    ("TRAJECTORY", "lafAngle", lambda c: 0 <= c.laf_angle <= 180, "must be 0..180 degrees"),
    ("INTERPRETER", "g64pvalue", lambda c: c.g64_p >= 0, "must be 0 or more (mm)"),
    ("INTERPRETER", "tanknifeBendingAngle", lambda c: c.tanknife.bending_angle in (-90.0, 0.0, 90.0),
     "must be +90, -90 or 0 (no bend)"),
    ("KINEMATICS", "userOutputStartVariable",
     lambda c: c.user_output_start == 0 or 1 <= c.user_output_start <= 3979,
     "must be 0 (off) or a variable number 1..3979"),
    ("KINEMATICS", "userOutputNumVariables", lambda c: 0 <= c.user_output_count <= 12,
     "must be 0..12"),
    ("KINEMATICS", "userOutputStartVariable",
     lambda c: c.user_output_start == 0 or c.user_output_count > 0,
     "is set but userOutputNumVariables is 0, so nothing would be written (set it to 1..12)"),
    # a joint or axis that may not move or speed up is a broken configuration, not "no limit"
    *((f"JOINT_{i}", key, lambda c, i=i, name=name: MIN_AXIS_RATE <= getattr(c.joints[i], name) <= MAX_AXIS_RATE,
       f"must be {MIN_AXIS_RATE:g} to {MAX_AXIS_RATE:g} ({unit})")
      for i in range(len(AXES))
      for name, key, unit in (("max_velocity", "maxVelocity", "mm/s"), ("max_acceleration", "maxAcceleration", "mm/s^2"))),
    *(("KINEMATICS", prefix + axis, lambda c, i=i, name=name: MIN_AXIS_RATE <= getattr(c, name)[i] <= MAX_AXIS_RATE,
       f"must be {MIN_AXIS_RATE:g} to {MAX_AXIS_RATE:g} ({unit})")
      for name, prefix, unit in (("cartesian_max_velocity", "maxVelocity", "mm/s"),
                                 ("cartesian_max_acceleration", "maxAcceleration", "mm/s^2"))
      for i, axis in enumerate(AXES)),
)


def _spindle_section(ini: IniFile) -> str:
    """Where the main spindle's keys are: ``[SPINDLE_0]`` in 4.03 files (the manual, §3.7.2),
    ``[SPINDLE]`` in older ones; the first that gives spindleNmax wins."""
    return next((name for name in ("SPINDLE_0", "SPINDLE") if ini.get(name, "spindleNmax") is not None), "SPINDLE_0")


def _validate(ini: IniFile, config: MachineConfig) -> None:
    from edingcnc_lang.config.ini import display_section

    spindle = _spindle_section(ini)
    for section, key, passes, requirement in _CHECKS:
        section = spindle if section == SPINDLE else section
        if not passes(config):
            shown = ini.get_str(section, key, "")
            raise ConfigError(f"{key} = {shown} in {display_section(section)} {requirement}",
                              ini.location(section, key))


def _warnings(ini: IniFile, config: MachineConfig) -> tuple[Diagnostic, ...]:
    """Values the controller may write that a run cannot honour fully: each a C702 warning at its line."""
    if config.machine_type in MACHINE_TYPES:
        return ()
    known = ", ".join(f"{number} ({name})" for number, name in MACHINE_TYPES.items())
    where = ini.location("SYSTEM", "machineType")
    return (Diagnostic.make("C702", f"machineType = {config.machine_type} in [SYSTEM] is not a machine type "
                            f"EdingCNC 4.03 writes ({known}); the job runs as on a milling machine",
                            where.path, max(where.line, 1), 1),)


def load_config(path: str | os.PathLike[str]) -> MachineConfig:
    """Read a ``cnc.ini``; keys that are absent keep the values of ``MachineConfig.default()``."""
    from edingcnc_lang.config.ini import read_ini

    ini = read_ini(path)
    base = MachineConfig.default()
    folder = Path(ini.path).absolute().parent
    config = MachineConfig(
        path=ini.path,
        **_read_fields(ini, "SYSTEM", _SYSTEM_FIELDS, base),
        **_read_fields(ini, _spindle_section(ini), _SPINDLE_FIELDS, base),
        **_read_fields(ini, "INTERPRETER", _INTERPRETER_FIELDS, base),
        macro_file=_resolve_macro(ini, "macroFileName", folder),
        user_macro_file=_resolve_macro(ini, "userMacroFileName", folder),
        tanknife=TanKnifeConfig(**_read_fields(ini, "INTERPRETER", _TANKNIFE_FIELDS, base.tanknife)),
        joints=tuple(JointConfig(**_read_fields(ini, f"JOINT_{i}", _JOINT_FIELDS, joint))
                     for i, joint in enumerate(base.joints)),
        **_read_fields(ini, "TRAJECTORY", _TRAJECTORY_FIELDS, base),
        **_read_fields(ini, "KINEMATICS", _KINEMATICS_FIELDS, base),
        kinematics_settings=ini.section("KINEMATICS"),
        **_read_cartesian(ini, base),
        tools=_read_tools(ini),
        variables=_read_variables(ini),
        sections=frozenset(ini.sections),
        spindle_offsets=tuple((0.0, 0.0, 0.0) if n == 0 else _read_spindle_offset(ini, n) for n in range(SPINDLE_CONFIGS)),
    )
    _validate(ini, config)
    return replace(config, warnings=_warnings(ini, config))


def save_variables(path: str | os.PathLike[str], values: Mapping[int, float]) -> None:
    """Store the persisted parameters among ``values`` in the ini's ``[VARIABLES]``.

    Only numbers for which ``is_persisted`` holds are written, so a caller may pass every
    parameter a run touched; the rest of the file is left byte for byte as it was.
    """
    from edingcnc_lang.config.ini import write_variables

    write_variables(path, {n: v for n, v in values.items() if is_persisted(n)})
