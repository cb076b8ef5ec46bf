"""The rotary sim takes the tool's pose from the machine's joints: a ``KIN Y2A`` mapping and a
plug-in that wraps Y onto A cut a ring groove where the job writes a straight line along Y; an ini
that shows B and hides A turns the bar about Y."""
from __future__ import annotations

import json
import math
from pathlib import Path

import pytest

from edingcnc_lang.runner import RunOptions
from edingcnc_lang.sim.rotary import rotary_axis, simulate_cylinder
from edingcnc_lang.sim.round_stock import RoundStock
from edingcnc_lang.sim.tools import Tool
from edingcnc_lang.config.machine_config import load_config
from tests.cli_runner import invoke

EXAMPLE_INI = Path(__file__).resolve().parents[2] / "examples" / "cylinder" / "cnc.ini"
R, DEPTH, TOOL = 20.0, 3.0, 6.0
RING = math.pi * (R * R - (R - DEPTH) ** 2) * TOOL  # a ring groove DEPTH deep, TOOL wide
WRAP = 2 * math.pi * 25.0  # the ini's aAxisCalibratedCilinderRadius: a Y move of one turn

PLUGIN = '''
import math
from edingcnc_lang.kinematics import KinematicsPlugin

class Wrap(KinematicsPlugin):
    """Y wrapped onto the A motor about the rotation point Y200 (as KIN Y2A with r = 25)."""
    name = "wrap"
    KIN_TYPE = 18
    VERSION = "WRAP 1.0"

    def inverse(self, pos, tool_length=0.0):
        x, y, z, a, b, c = pos
        return (x, 200.0, z, (y - 200.0) * 180.0 / (math.pi * 25.0), b, c)

    def forward(self, joints, tool_length=0.0):
        return (joints[0], 200.0 + joints[3] * math.pi * 25.0 / 180.0, joints[2], 0.0, joints[4], joints[5])
'''


def ini(folder: Path, *, kinematics: str = "trivial", extra: str = "") -> Path:
    text = EXAMPLE_INI.read_text().replace("kinematicsDLLName = trivial", f"kinematicsDLLName = {kinematics}{extra}")
    path = folder / "cnc.ini"
    path.write_text(text)
    return path


def job(folder: Path, body: str) -> Path:
    path = folder / "job.nc"
    path.write_text("G17 G21 G90 G94\nG10 L2 P1 X0 Y200 Z-60 A0 B0\nG54\nS12000 M3\nG0 Z30\n" + body.strip()
                    + "\nG0 Z30\nM5\nM30\n")
    return path


def cut(folder: Path, ini_path: Path, body: str) -> tuple[RoundStock, list]:
    stock = RoundStock.cylinder(2 * R, 100, 20, 0.2)
    result = simulate_cylinder(job(folder, body), stock, RunOptions(ini=ini_path), {0: Tool(0, diameter=TOOL)}, 0)
    assert result.error is None, result.error
    return stock, result.findings


@pytest.mark.parametrize("switch", ["KIN Y2A", "KIN ON"], ids=["KIN Y2A", "a plug-in"])
def test_a_mapping_wraps_a_line_along_y_into_a_ring_groove(tmp_path: Path, switch: str) -> None:
    (tmp_path / "wrap.py").write_text(PLUGIN)
    path = ini(tmp_path, kinematics="wrap.py" if switch == "KIN ON" else "trivial")
    stock, found = cut(tmp_path, path, f"G0 X70 Y0\n{switch}\nG1 Z{R - DEPTH} F300\nG1 Y{WRAP} F2000\nG0 Z30\nKIN OFF")
    assert stock.removed_volume == pytest.approx(RING, rel=1e-3)
    assert found == []


def test_without_the_mapping_the_same_line_cuts_across_the_top(tmp_path: Path) -> None:
    stock, _ = cut(tmp_path, ini(tmp_path), f"G0 X70 Y-30\nG1 Z{R - DEPTH} F300\nG1 Y30 F2000")
    chord = R * R * math.acos((R - DEPTH) / R) - (R - DEPTH) * math.sqrt(2 * R * DEPTH - DEPTH ** 2)
    assert stock.removed_volume == pytest.approx(chord * TOOL, rel=0.02)  # a flat 3 deep, the tool's width


def test_a_rapid_wrapped_into_the_bar_is_found_at_its_line(tmp_path: Path) -> None:
    _stock, found = cut(tmp_path, ini(tmp_path), f"G0 X70 Y0\nKIN Y2A\nG1 Z{R - DEPTH} F300\nG0 Y30\nKIN OFF")
    assert [(f.kind, f.line) for f in found] == [("rapid_into_stock", 9)]


B_INI = "\naVisible = 0\nbVisible = 1"


def test_the_ini_names_the_rotary_axis(tmp_path: Path) -> None:
    assert rotary_axis(load_config(ini(tmp_path))).letter == "A"
    assert rotary_axis(load_config(ini(tmp_path, extra=B_INI))).letter == "B"


def test_b_about_y_a_ring_groove_and_a_flat(tmp_path: Path) -> None:
    """The bar along Y from Y20; B through 360 degrees at Y70 is a ring groove; a cut along Y at B90 a
    flat on the bar's side that stood at -X (its own angle 0 is at -X, turning towards +Z)."""
    path = ini(tmp_path, extra=B_INI)
    stock, found = cut(tmp_path, path, f"G0 X0 Y70 B0\nG1 Z{R - DEPTH} F300\nG1 B360 F2000")
    assert stock.removed_volume == pytest.approx(RING, rel=1e-3) and found == []
    stock, _ = cut(tmp_path, path, f"G0 X0 Y0 B90\nG1 Z{R - DEPTH} F300\nG1 Y140 F2000")
    depth = R - stock.outer.astype(float)
    assert depth.max() == pytest.approx(DEPTH, abs=0.02)
    deepest = (depth[250].argmax() + 0.5) * stock.angle_step()
    assert abs(deepest - 0.0) < 3.0 or abs(deepest - 360.0) < 3.0


def test_b_findings_in_work_coordinates_and_the_json(tmp_path: Path) -> None:
    path = ini(tmp_path, extra=B_INI)
    (tmp_path / "tools.toml").write_text("[tool.0]\ndiameter = 6\n")
    result = invoke("sim", job(tmp_path, "G0 X0 Y50\nG0 Z15"), "--ini", path, "--stock", "cylinder:40,100,20",
                    "--resolution", "0.25", "--tools", tmp_path / "tools.toml", "--tool", "0", "--json")
    assert result.exit_code == 1, result.output
    doc = json.loads(result.stdout)
    assert doc["stock"]["axis"] == "B"
    (finding,) = doc["collisions"]
    assert finding["kind"] == "rapid_into_stock" and finding["line"] == 7
    x, y, z = finding["position"]  # where the rapid, straight down at X0 Y50, removed the most
    assert (x, y) == pytest.approx((0, 50), abs=1e-6) and 15 <= z < 20
