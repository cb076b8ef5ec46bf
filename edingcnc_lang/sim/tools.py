"""The cutters a simulation cuts with: shapes, sizes and the parts that must not touch the stock.

A tool is read from ``--tools FILE.toml`` (``[tool.N]`` tables) or, without that file, from the
ini's tool table as a flat end mill whose flute length is unknown (then no shank or holder can be
checked, and the report says so).  Lengths in mm, the vee angle in degrees (included angle).
"""
from __future__ import annotations

import math
from collections.abc import Mapping
from dataclasses import dataclass
from pathlib import Path
from typing import Any

from edingcnc_lang.config.machine_config import MachineConfig
from edingcnc_lang.errors import EXIT_USAGE, EcncError, Location

from edingcnc_lang.syntax import toml_input
from edingcnc_lang.syntax.input_limits import MAX_SIM_LENGTH, MIN_SIM_SIZE, MIN_VEE_ANGLE

SHAPES = ("flat", "ball", "bull", "vee", "insert")  # insert: a lathe tool (``ecnc sim --bar``)
FIELDS = ("shape", "diameter", "corner_radius", "angle", "flute_length", "shank_diameter",
          "holder_diameter", "holder_length", "nose_radius", "orientation", "insert_angle", "insert_size",
          "holder_width")
INSERT_ONLY = ("nose_radius", "orientation", "insert_angle", "insert_size", "holder_width")  # a lathe tool's
DEFAULT_DIAMETER = 3.0  # mm: a tool the ini does not size still cuts something visible


class ToolFileError(EcncError):
    """A tools file that cannot be used: the user's input (exit 2)."""

    exit_code = EXIT_USAGE
    kind = "usage"


@dataclass(frozen=True)
class Tool:
    """One cutter.  ``flute_length`` None: unknown (no shank/holder check); ``holder_length`` is how
    far the tool sticks out of the holder (tip to holder face), None without a holder."""

    number: int
    shape: str = "flat"
    diameter: float = DEFAULT_DIAMETER
    corner_radius: float = 0.0
    angle: float = 90.0
    flute_length: float | None = None
    shank_diameter: float | None = None
    holder_diameter: float | None = None
    holder_length: float | None = None
    nose_radius: float | None = None  # an insert's nose (its controlled point: ``orientation``, 1..9)
    orientation: int | None = None
    insert_angle: float | None = None  # the insert's included angle, degrees (80 a C insert): sim/insert.py
    insert_size: float | None = None   # its cutting edges' length, mm (ISO's size: CNMG 12.. is 12)
    holder_width: float | None = None  # the holder behind it, mm
    source: str = "ini"  # "ini", "default" or the tools file

    @property
    def radius(self) -> float:
        return self.diameter / 2.0

    @property
    def shank_radius(self) -> float:
        return (self.shank_diameter if self.shank_diameter is not None else self.diameter) / 2.0

    @property
    def cone_slope(self) -> float:
        """Rise per mm of radius of a vee tool's cone (1 for a 90° bit)."""
        return 1.0 / math.tan(math.radians(self.angle) / 2.0)

    def profile(self, d: Any) -> Any:
        """Height of the cutting edge above the tip at radial distance ``d`` (array or float, d <= radius)."""
        import numpy as np

        d = np.asarray(d)
        if self.shape == "ball":
            return self.radius - np.sqrt(np.maximum(self.radius ** 2 - d * d, 0.0))
        if self.shape == "vee":
            return self.cone_slope * d
        if self.shape == "bull":
            flat = self.radius - self.corner_radius
            out = np.maximum(d - flat, 0.0)
            return self.corner_radius - np.sqrt(np.maximum(self.corner_radius ** 2 - out * out, 0.0))
        return np.zeros_like(d)


def ini_tool(config: MachineConfig, number: int) -> Tool:
    """The ini's tool ``number`` as a flat end mill of its diameter (flute length unknown)."""
    entry = config.tools.get(number)
    if entry is None or entry.diameter <= 0.0:
        return Tool(number, source="default")
    return Tool(number, diameter=entry.diameter)


def load_tools(path: str | Path) -> dict[int, Tool]:
    """``[tool.N]`` tables of a TOML file, checked; a bad value names the file and the tool."""
    where = Location(str(path))
    try:
        data = toml_input.parse(toml_input.decode(Path(path).read_bytes()))
    except OSError as err:
        raise ToolFileError(f"cannot read: {err.strerror or err}", where) from None
    except toml_input.TomlProblem as err:
        raise ToolFileError(f"not a TOML file: {err.message}", where) from None
    table = data.get("tool")
    if not isinstance(table, Mapping) or not table:
        raise ToolFileError("no [tool.N] tables (e.g. [tool.1] shape = \"flat\", diameter = 6)", where)
    return {_number(key, where): _tool(_number(key, where), value, str(path), where) for key, value in table.items()}


def _number(key: str, where: Location) -> int:
    number = toml_input.whole_number(key)  # ASCII digits: "²" is no tool number
    if number is None or not 0 <= number <= 99999:
        raise ToolFileError(f"[tool.{key!r}]: the tool number must be a whole number from 0 to 99999", where)
    return number


def _tool(number: int, entry: Any, source: str, where: Location) -> Tool:
    name = f"[tool.{number}]"
    if not isinstance(entry, Mapping):
        raise ToolFileError(f"{name} must be a table", where)
    unknown = sorted(set(entry) - set(FIELDS))
    if unknown:
        raise ToolFileError(f"{name}: unknown key {unknown[0]!r} (known: {', '.join(FIELDS)})", where)
    shape = entry.get("shape", "flat")
    if shape not in SHAPES:
        raise ToolFileError(f"{name}: shape must be one of {', '.join(SHAPES)}, not {shape!r}", where)
    values: dict[str, float] = {}
    if "orientation" in entry:
        orientation = entry["orientation"]
        if isinstance(orientation, bool) or not isinstance(orientation, int) or not 0 <= orientation <= 9:
            raise ToolFileError(f"{name}: orientation must be a whole number from 0 to 9 (the tool table's)", where)
        values["orientation"] = orientation
    if shape == "insert":  # a lathe insert is sized by its nose; the diameter is twice it, as the ini's
        nose = toml_input.number(entry.get("nose_radius", 0))
        if nose is None or not 0 <= nose <= MAX_SIM_LENGTH:
            raise ToolFileError(f"{name}: nose_radius must be 0 (a sharp point) or a positive number of mm, "
                                f"not {entry['nose_radius']!r}", where)
        values["nose_radius"], values["diameter"] = nose, 2 * nose
    for key in FIELDS[1:]:
        if key in entry and key not in values:
            value = toml_input.number(entry[key])  # None for a 400-digit integer too
            if value is None or not (key.endswith("angle") or MIN_SIM_SIZE <= value <= MAX_SIM_LENGTH
                                     or (value == 0 and key == "corner_radius")):  # the angle: below
                raise ToolFileError(f"{name}: {key} must be a positive number of mm ({MIN_SIM_SIZE:g} to "
                                    f"{MAX_SIM_LENGTH:g}), not {entry[key]!r}", where)
            values[key] = value
    if shape != "insert" and any(key in entry for key in INSERT_ONLY):
        raise ToolFileError(f"{name}: {', '.join(INSERT_ONLY)} are for shape = \"insert\" (a lathe tool)", where)
    if "diameter" not in values:
        raise ToolFileError(f"{name}: diameter is missing", where)
    tool = Tool(number, shape=shape, source=source, **values)  # type: ignore[arg-type]
    if shape == "bull" and not 0.0 < tool.corner_radius <= tool.radius:
        raise ToolFileError(f"{name}: a bull nose needs 0 < corner_radius <= diameter/2", where)
    for key in ("angle", "insert_angle"):
        if not MIN_VEE_ANGLE <= (getattr(tool, key) or 90.0) < 180.0:
            raise ToolFileError(f"{name}: {key} must be from {MIN_VEE_ANGLE:g} to below 180 degrees (the included "
                                "angle)", where)
    if tool.holder_length is not None and tool.flute_length is not None and tool.holder_length < tool.flute_length:
        raise ToolFileError(f"{name}: holder_length (tip to holder) is shorter than flute_length", where)
    return tool
