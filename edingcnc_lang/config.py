"""Machine configuration: read EdingCNC's ``cnc.ini`` and write persisted variables back.

Users bring the ``cnc.ini`` of their real controller: thousands of lines written by a Windows
program, full of keys this project never uses.  The reader is therefore lenient about the file
as a whole (unknown sections, keys and odd lines are ignored) and strict only about the values
the toolchain uses, which are reported at their ini line when they do not parse.
See docs/configuration.md for the keys and the project decisions.
"""
from __future__ import annotations

import contextlib
import math
import os
import re
import stat
from collections.abc import Callable, Mapping
from dataclasses import dataclass
from pathlib import Path
from types import MappingProxyType
from typing import Any

from edingcnc_lang.errors import ConfigError, Location

AXES = "XYZABC"

_BOM = b"\xef\xbb\xbf"
_WIDE_LIMIT = 1e6             # mm: nothing a job does should reach it
_WIDE_VELOCITY = 1000.0       # mm/s
_WIDE_ACCELERATION = 10000.0  # mm/s^2
_NUMBER = re.compile(r"[+-]?(?:\d+\.?\d*|\.\d+)(?:[eE][+-]?\d+)?")
_INTEGER = re.compile(r"[+-]?\d+")
_SECTION = re.compile(r"\[([^\]]*)\]")
_VARIABLE_KEY = re.compile(r"#(\d+)")

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


# --------------------------------------------------------------------------- ini syntax

@dataclass(frozen=True)
class IniValue:
    """A value as written in the ini (quotes and trailing comment removed) and its 1-based line."""

    text: str
    line: int


@dataclass(frozen=True)
class _Entry:
    """A ``key = value`` line; ``start:end`` is where the raw value (quotes included) sits."""

    key: str
    value: str
    start: int
    end: int


def _split_lines(text: str) -> list[tuple[str, str]]:
    """Split into (body, line ending) pairs whose concatenation is exactly ``text``."""
    pieces = text.split("\n")
    lines = [(p[:-1], "\r\n") if p.endswith("\r") else (p, "\n") for p in pieces[:-1]]
    if pieces[-1]:
        lines.append((pieces[-1], ""))
    return lines


def _parse_entry(body: str) -> _Entry | None:
    """Parse ``key = value ;comment``; a ``;`` inside a double-quoted value is text."""
    if body.lstrip().startswith(";") or "=" not in body:
        return None
    eq = body.index("=")
    key = body[:eq].strip()
    if not key:
        return None
    start = eq + 1
    while start < len(body) and body[start] in " \t":
        start += 1
    if body.startswith('"', start):
        close = body.find('"', start + 1)
        end = close + 1 if close >= 0 else len(body.rstrip())
        return _Entry(key, body[start + 1:close if close >= 0 else end], start, end)
    comment = body.find(";", start)
    end = max(start, len(body[:comment if comment >= 0 else len(body)].rstrip()))
    return _Entry(key, body[start:end], start, end)


def _classify(lines: list[tuple[str, str]]) -> list[tuple[str | None, _Entry | None]]:
    """For every line: the lower-cased section it belongs to and its entry, if any."""
    section: str | None = None
    result: list[tuple[str | None, _Entry | None]] = []
    for body, _ in lines:
        stripped = body.strip()
        header = _SECTION.match(stripped) if stripped.startswith("[") else None
        if header:
            section = header.group(1).strip().lower()
            result.append((section, None))
        else:
            result.append((section, _parse_entry(body)))
    return result


def _read_bytes(path: Path) -> bytes:
    try:
        return path.read_bytes()
    except OSError as exc:
        raise ConfigError(f"cannot read machine configuration: {exc.strerror or exc}",
                          Location(str(path))) from exc


def _decode(raw: bytes) -> str:
    """UTF-8 (BOM stripped), else Latin-1, which decodes any byte string."""
    raw = raw.removeprefix(_BOM)
    try:
        return raw.decode("utf-8")
    except UnicodeDecodeError:
        return raw.decode("latin-1")


def _display(section: str) -> str:
    return f"[{section.upper()}]"


@dataclass(frozen=True)
class IniFile:
    """A parsed ini: section and key names lower-cased; the last of duplicate keys wins."""

    path: str
    sections: Mapping[str, Mapping[str, IniValue]]

    def get(self, section: str, key: str) -> IniValue | None:
        return self.sections.get(section.lower(), {}).get(key.lower())

    def get_str(self, section: str, key: str, default: str) -> str:
        value = self.get(section, key)
        return default if value is None else value.text

    def get_float(self, section: str, key: str, default: float) -> float:
        """An empty value counts as absent; anything but a plain decimal number is an error."""
        value = self._present(section, key)
        if value is None:
            return default
        if not _NUMBER.fullmatch(value.text):
            raise self._bad(section, key, value, "a number")
        return float(value.text)

    def get_int(self, section: str, key: str, default: int) -> int:
        """Whole numbers; ``2.000000`` is accepted as 2 since Eding writes some counts that way."""
        value = self._present(section, key)
        if value is None:
            return default
        if _INTEGER.fullmatch(value.text):
            return int(value.text)
        if _NUMBER.fullmatch(value.text) and float(value.text).is_integer():
            return int(float(value.text))
        raise self._bad(section, key, value, "a whole number")

    def get_bool(self, section: str, key: str, default: bool) -> bool:
        """Flags are written as 0/1; any non-zero whole number is true."""
        return self.get_int(section, key, int(default)) != 0

    def section(self, name: str) -> Mapping[str, str]:
        """The raw texts of one section by lower-cased key (empty if the section is absent)."""
        values = self.sections.get(name.lower(), {})
        return MappingProxyType({key: value.text for key, value in values.items()})

    def location(self, section: str, key: str) -> Location:
        """Where a key is written (the file alone if it is not)."""
        value = self.get(section, key)
        return Location(self.path, value.line if value else 0)

    def _present(self, section: str, key: str) -> IniValue | None:
        value = self.get(section, key)
        return value if value is not None and value.text.strip() else None

    def _bad(self, section: str, key: str, value: IniValue, expected: str) -> ConfigError:
        return ConfigError(f"{key} in {_display(section)}: expected {expected}, got {value.text!r}",
                           Location(self.path, value.line))


def read_ini(path: str | os.PathLike[str]) -> IniFile:
    """Read an ini file; a missing or unreadable file is a ConfigError."""
    text = _decode(_read_bytes(Path(path)))
    lines = _split_lines(text)
    sections: dict[str, dict[str, IniValue]] = {}
    for number, (section, entry) in enumerate(_classify(lines), start=1):
        if section is None:
            continue  # keys before the first section header belong to nothing
        values = sections.setdefault(section, {})
        if entry is not None:
            values[entry.key.lower()] = IniValue(entry.value, number)
    frozen = {name: MappingProxyType(values) for name, values in sections.items()}
    return IniFile(os.fspath(path), MappingProxyType(frozen))


# --------------------------------------------------------------------------- machine model

@dataclass(frozen=True)
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


@dataclass(frozen=True)
class ToolConfig:
    """One tool table entry (``[TOOL_n]``)."""

    number: int
    length: float
    diameter: float
    x_delta: float
    z_delta: float
    orientation: int
    description: str


@dataclass(frozen=True)
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


@dataclass(frozen=True)
class MachineConfig:
    """Everything the interpreter, kinematics and simulator need from ``cnc.ini``."""

    path: str | None
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
    kinematics_name: str
    kinematics_settings: Mapping[str, str]
    cartesian_positive_limits: tuple[float, ...]
    cartesian_negative_limits: tuple[float, ...]
    cartesian_max_velocity: tuple[float, ...]
    cartesian_max_acceleration: tuple[float, ...]
    user_output_start: int
    user_output_count: int
    tools: Mapping[int, ToolConfig]
    variables: Mapping[int, float]

    @classmethod
    def default(cls) -> MachineConfig:
        """The machine used without an ini: trivial kinematics, wide limits, 200 Hz, homed at 0."""
        return cls(
            path=None,
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
            kinematics_name="trivial",
            kinematics_settings=MappingProxyType({}),
            cartesian_positive_limits=(_WIDE_LIMIT,) * len(AXES),
            cartesian_negative_limits=(-_WIDE_LIMIT,) * len(AXES),
            cartesian_max_velocity=(_WIDE_VELOCITY,) * len(AXES),
            cartesian_max_acceleration=(_WIDE_ACCELERATION,) * len(AXES),
            user_output_start=0,
            user_output_count=0,
            tools=MappingProxyType({}),
            variables=MappingProxyType({}),
        )


# Which ini key feeds which field, and how it is read: (field, ini key, reader).
_Reader = Callable[[IniFile, str, str, Any], Any]
_INTERPRETER_FIELDS: tuple[tuple[str, str, _Reader], ...] = (
    ("initial_string", "initialString", IniFile.get_str),
    ("g4_in_milliseconds", "g4InMilliseconds", IniFile.get_bool),
    ("inch_mode", "inchModeActive", IniFile.get_bool),
    ("absolute_center_coords", "absoluteCenterCoords", IniFile.get_bool),
    ("reverse_g2g3", "reverseG2G3", IniFile.get_bool),
    ("full_circle_theta_epsilon", "fullCircleThetaEpsilon", IniFile.get_float),
    ("g64_p", "g64pvalue", IniFile.get_float),
    ("g64_active", "g64Active", IniFile.get_bool),
)
_TANKNIFE_FIELDS: tuple[tuple[str, str, _Reader], ...] = (
    ("angle_for_lift_up", "tanKnifeAngleForLiftUp", IniFile.get_float),
    ("blend_angle", "tanKnifeBlendAngle", IniFile.get_float),
    ("blend_distance", "tanKnifeBlendDistance", IniFile.get_float),
    ("lift_up_distance", "tanKnifeLiftUpDistance", IniFile.get_float),
    ("bending_angle", "tanknifeBendingAngle", IniFile.get_float),
    ("z_hi", "tanknifeZhi", IniFile.get_float),
    ("z_lo", "tanknifeZlo", IniFile.get_float),
    ("rewind_turns", "tanknifeRewindTurns", IniFile.get_int),
)
_JOINT_FIELDS: tuple[tuple[str, str, _Reader], ...] = (
    ("name", "name", IniFile.get_str),
    ("positive_limit", "positiveLimit", IniFile.get_float),
    ("negative_limit", "negativeLimit", IniFile.get_float),
    ("max_velocity", "maxVelocity", IniFile.get_float),
    ("max_acceleration", "maxAcceleration", IniFile.get_float),
    ("home_velocity", "homeVelocity", IniFile.get_float),
    ("home_velocity_slow", "homeVelocitySlow", IniFile.get_float),
    ("home_position", "homePosition", IniFile.get_float),
    ("resolution", "resolution", IniFile.get_float),
    ("visible", "visible", IniFile.get_bool),
)
_TRAJECTORY_FIELDS: tuple[tuple[str, str, _Reader], ...] = (
    ("interpolation_time", "interpolationTime", IniFile.get_float),
    ("g0_velocity_factor", "g0VelocityFactor", IniFile.get_float),
)
_KINEMATICS_FIELDS: tuple[tuple[str, str, _Reader], ...] = (
    ("kinematics_name", "kinematicsDLLName", IniFile.get_str),
    ("user_output_start", "userOutputStartVariable", IniFile.get_int),
    ("user_output_count", "userOutputNumVariables", IniFile.get_int),
)
# Per-axis Cartesian values in [KINEMATICS]: the key is the prefix plus the axis letter.
_CARTESIAN_FIELDS = (
    ("cartesian_positive_limits", "positiveLimit"),
    ("cartesian_negative_limits", "negativeLimit"),
    ("cartesian_max_velocity", "maxVelocity"),
    ("cartesian_max_acceleration", "maxAcceleration"),
)
_TOOL_DEFAULT = ToolConfig(number=0, length=0.0, diameter=0.0, x_delta=0.0, z_delta=0.0,
                           orientation=0, description="")
_TOOL_FIELDS: tuple[tuple[str, str, _Reader], ...] = (
    ("length", "length", IniFile.get_float),
    ("diameter", "diameter", IniFile.get_float),
    ("x_delta", "xDelta", IniFile.get_float),
    ("z_delta", "zDelta", IniFile.get_float),
    ("orientation", "orientation", IniFile.get_int),
    ("description", "description", IniFile.get_str),
)
_TOOL_NUMBERS = range(1, 100)


def _read_fields(ini: IniFile, section: str, table: tuple[tuple[str, str, _Reader], ...],
                 defaults: object) -> dict[str, Any]:
    return {name: read(ini, section, key, getattr(defaults, name)) for name, key, read in table}


def _read_cartesian(ini: IniFile, base: MachineConfig) -> dict[str, tuple[float, ...]]:
    return {name: tuple(ini.get_float("KINEMATICS", prefix + axis, default)
                        for axis, default in zip(AXES, getattr(base, name)))
            for name, prefix in _CARTESIAN_FIELDS}


def _read_tools(ini: IniFile) -> Mapping[int, ToolConfig]:
    tools = {n: ToolConfig(number=n, **_read_fields(ini, f"TOOL_{n}", _TOOL_FIELDS, _TOOL_DEFAULT))
             for n in _TOOL_NUMBERS if f"tool_{n}" in ini.sections}
    return MappingProxyType(tools)


def _read_variables(ini: IniFile) -> Mapping[int, float]:
    """Persisted parameters from ``#n = value`` lines; other numbers are ignored like unknown keys."""
    values: dict[int, float] = {}
    for key in ini.sections.get("variables", {}):
        match = _VARIABLE_KEY.fullmatch(key)
        if match and is_persisted(int(match.group(1))):
            values[int(match.group(1))] = ini.get_float("VARIABLES", key, 0.0)
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


# Checks made after reading: (section, key to report at, passes?, what the value must be).
_CHECKS: tuple[tuple[str, str, Callable[[MachineConfig], bool], str], ...] = (
    ("TRAJECTORY", "interpolationTime", lambda c: c.interpolation_time > 0,
     "must be greater than 0 seconds"),
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
)


def _validate(ini: IniFile, config: MachineConfig) -> None:
    for section, key, passes, requirement in _CHECKS:
        if not passes(config):
            shown = ini.get_str(section, key, "")
            raise ConfigError(f"{key} = {shown} in {_display(section)} {requirement}",
                              ini.location(section, key))


def load_config(path: str | os.PathLike[str]) -> MachineConfig:
    """Read a ``cnc.ini``; keys that are absent keep the values of ``MachineConfig.default()``."""
    ini = read_ini(path)
    base = MachineConfig.default()
    folder = Path(ini.path).absolute().parent
    config = MachineConfig(
        path=ini.path,
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
    )
    _validate(ini, config)
    return config


# --------------------------------------------------------------------------- write-back

def _line_ending(lines: list[tuple[str, str]]) -> str:
    """The file's own line ending; CRLF (what EdingCNC writes) if it has none yet."""
    return next((end for _, end in lines if end), "\r\n")


def _format(value: float) -> str:
    if not math.isfinite(value):
        raise ValueError(f"cannot persist a non-finite value: {value}")
    return f"{value:.6f}"


def _update_variables(text: str, values: Mapping[int, float]) -> str:
    """Rewrite the value text of known ``#n`` lines; append the others to ``[VARIABLES]``."""
    lines = _split_lines(text)
    classes = _classify(lines)
    written: set[int] = set()
    for i, (section, entry) in enumerate(classes):
        match = _VARIABLE_KEY.fullmatch(entry.key) if entry and section == "variables" else None
        if entry and match and int(match.group(1)) in values:
            number = int(match.group(1))
            body, end = lines[i]
            lines[i] = (body[:entry.start] + _format(values[number]) + body[entry.end:], end)
            written.add(number)
    missing = [f"#{n} = {_format(values[n])}" for n in sorted(set(values) - written)]
    if not missing:
        return "".join(body + end for body, end in lines)
    eol = _line_ending(lines)
    in_section = [i for i, (section, _) in enumerate(classes) if section == "variables"]
    if in_section:
        at = max(i for i in in_section if lines[i][0].strip()) + 1
        added = []
    else:
        at = len(lines)
        added = ([("", eol)] if lines and lines[-1][0].strip() else []) + [("[VARIABLES]", eol)]
    if at > 0 and not lines[at - 1][1]:
        lines[at - 1] = (lines[at - 1][0], eol)  # the last line had no ending
    lines[at:at] = added + [(line, eol) for line in missing]
    return "".join(body + end for body, end in lines)


def _write_atomic(path: Path, data: bytes) -> None:
    """Write beside the target and rename over it, so a failure leaves the old file intact."""
    import tempfile  # only when writing back (start-up time)

    tmp: str | None = None
    try:
        fd, tmp = tempfile.mkstemp(prefix=f".{path.name}.", suffix=".tmp", dir=path.parent)
        with os.fdopen(fd, "wb") as handle:
            handle.write(data)
            handle.flush()
            os.fsync(handle.fileno())
        os.chmod(tmp, stat.S_IMODE(path.stat().st_mode))
        os.replace(tmp, path)
    except BaseException as exc:
        if tmp is not None:
            with contextlib.suppress(OSError):
                os.unlink(tmp)
        if isinstance(exc, OSError):
            raise ConfigError(f"cannot write variables back: {exc.strerror or exc}",
                              Location(str(path))) from exc
        raise


def save_variables(path: str | os.PathLike[str], values: Mapping[int, float]) -> None:
    """Store persisted parameters in ``[VARIABLES]``, changing nothing else in the file.

    Only numbers for which ``is_persisted`` holds are written; others are skipped, so a caller
    may pass every parameter a run touched.  The file is handled as Latin-1, which maps each
    byte to one character and back, so text in any encoding survives byte for byte (the ini
    syntax itself is ASCII).
    """
    target = Path(os.path.realpath(path))
    raw = _read_bytes(target)
    bom = _BOM if raw.startswith(_BOM) else b""
    persisted = {n: v for n, v in values.items() if is_persisted(n)}
    text = _update_variables(raw[len(bom):].decode("latin-1"), persisted)
    _write_atomic(target, bom + text.encode("latin-1"))
