"""Lathe keys of cnc.ini: machine type, diameter programming, spindle limits, lathe tool offsets."""
from __future__ import annotations

from pathlib import Path

import pytest

from edingcnc_lang.config.machine_config import MILLING, TURNING, MachineConfig, load_config
from edingcnc_lang.errors import ConfigError

EXAMPLE = Path(__file__).resolve().parents[2] / "examples" / "lathe" / "cnc.ini"


def write(tmp_path: Path, text: str) -> Path:
    path = tmp_path / "cnc.ini"
    path.write_bytes(text.replace("\n", "\r\n").encode("latin-1"))
    return path


def test_defaults_are_a_mill() -> None:
    config = MachineConfig.default()
    assert config.machine_type == MILLING and not config.lathe and not config.diameter_mode
    assert config.spindle_max_rpm == 0.0


def test_example_lathe_ini() -> None:
    config = load_config(EXAMPLE)
    assert config.machine_type == TURNING and config.lathe and config.diameter_mode
    assert (config.spindle_max_rpm, config.spindle_min_rpm) == (3200.0, 120.0)   # [SPINDLE_0], as V4.03 writes it
    tool = config.tools[3]
    assert (tool.length, tool.width, tool.z_delta, tool.x_delta, tool.orientation) == (18.905, -30.512, -0.02, 0.0, 6)
    assert config.variables[5008] == 3 and config.variables[5014] == -15.256
    assert config.macro_file is not None and config.macro_file.name == "macro.cnc"


def test_diameter_programming_needs_a_lathe(tmp_path: Path) -> None:
    config = load_config(write(tmp_path, "[SYSTEM]\nmachineType = 0\n[INTERPRETER]\ndiameterProgramming = 1\n"))
    assert config.diameter_programming and not config.diameter_mode


@pytest.mark.parametrize("text, where, message", [
    ("[SYSTEM]\nmachineType = lathe\n", 2, "machineType in [SYSTEM]: expected a whole number"),  # 2: a lathe now
    ("[SPINDLE]\nspindleNmax = -5\n", 2, "spindleNmax = -5 in [SPINDLE]"),
    ("[SPINDLE]\nspindleNmax = 1000\nspindleNmin = 2000\n", 3, "no higher than spindleNmax"),
    ("[SPINDLE]\nspindleNmax = fast\n", 2, "expected a number, got 'fast'"),
])
def test_bad_values_name_their_line(tmp_path: Path, text: str, where: int, message: str) -> None:
    with pytest.raises(ConfigError) as info:
        load_config(write(tmp_path, text))
    assert message in info.value.format()
    assert f"cnc.ini:{where}:" in info.value.format()
