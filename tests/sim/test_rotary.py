"""A bar on a mill's rotary A axis (``ecnc sim --stock cylinder:``): volumes against closed forms
(a flat across the bar, a ring groove by turning A through 360 degrees, a wrapped helix), the
findings, the stamp against point sampling, and the command line."""
from __future__ import annotations

import json
import math
from pathlib import Path

import numpy as np
import pytest

from edingcnc_lang.sim.rotary import simulate_cylinder, stamps
from edingcnc_lang.sim.round_stock import RoundStock
from edingcnc_lang.sim.tools import Tool
from tests.cli_runner import invoke

R = 20.0  # the bar: 40 mm, from X20 to X120


def mill(folder: Path, body: str, diameter: float, resolution: float = 0.2) -> tuple[RoundStock, list]:
    job = folder / "job.nc"
    job.write_text("G21 G90 G17\nS10000 M3\nG0 Z25\n" + body.strip() + "\nG0 Z25\nM30\n")
    stock = RoundStock.cylinder(2 * R, 100, 20, resolution)
    result = simulate_cylinder(job, stock, tools={0: Tool(0, diameter=diameter)}, first_tool=0)
    assert result.error is None
    return stock, result.findings


@pytest.mark.slow
def test_a_flat_of_depth_d_across_the_bar(tmp_path: Path) -> None:
    d = 3.0
    stock, found = mill(tmp_path, f"G0 X0 Y0\nG1 Z{R - d} F500\nG1 X140", diameter=30)
    segment = R * R * math.acos((R - d) / R) - (R - d) * math.sqrt(2 * R * d - d * d)
    assert stock.removed_volume == pytest.approx(segment * 100, rel=1e-3)
    assert found == []


@pytest.mark.slow
def test_an_indexed_second_flat_on_the_far_side(tmp_path: Path) -> None:
    d = 2.0
    stock, _ = mill(tmp_path, f"G0 X0 Y0\nG1 Z{R - d} F500\nG1 X140\nG0 Z25\nG0 X0 A180\nG1 Z{R - d}\nG1 X140",
                    diameter=30)
    segment = R * R * math.acos((R - d) / R) - (R - d) * math.sqrt(2 * R * d - d * d)
    assert stock.removed_volume == pytest.approx(2 * segment * 100, rel=1e-3)


def test_a_ring_groove_by_turning_a_through_360_degrees(tmp_path: Path) -> None:
    d, tool = 3.0, 6.0
    stock, _ = mill(tmp_path, f"G0 X70 Y0 A0\nG1 Z{R - d} F500\nG1 A360 F2000", diameter=tool)
    assert stock.removed_volume == pytest.approx(math.pi * (R * R - (R - d) ** 2) * tool, rel=1e-3)


def test_a_wrapped_helical_groove(tmp_path: Path) -> None:
    """X and A together, one turn over 60 mm: each slice's groove bottom is centred where the helix passed it (the
    bar's angle 90 - A), as deep as the tool went; the volume is the ring groove's spread over the
    groove's width along X (the tool's width over the sine of the helix's angle to X), within 6%."""
    d, tool, pitch = 2.0, 4.0, 60.0
    stock, _ = mill(tmp_path, f"G0 X40 Y0 A0\nG1 Z{R - d} F500\nG1 X{40 + pitch} A360 F2000", diameter=tool,
                    resolution=0.1)
    depth = R - stock.outer.astype(float)
    assert depth.max() == pytest.approx(d, abs=0.02)
    x = stock.centres()
    for at in (50.0, 65.0, 80.0, 95.0):
        k = int(np.searchsorted(x, at))
        bottom = np.radians((np.flatnonzero(depth[k] > d - 0.05) + 0.5) * stock.angle_step())
        deepest = math.degrees(math.atan2(np.sin(bottom).mean(), np.cos(bottom).mean()))  # the flat bottom's middle
        expected = (90.0 - 360.0 * (x[k] - 40.0) / pitch) % 360.0
        assert abs((deepest - expected + 180.0) % 360.0 - 180.0) < 3.0
    across = math.sin(math.atan(2 * math.pi * R / pitch))
    assert stock.removed_volume == pytest.approx(math.pi * (R * R - (R - d) ** 2) * tool / across, rel=0.06)


@pytest.mark.parametrize(("body", "found"), [
    ("G0 X0 Y0\nG0 Z18\nG0 X50", [("rapid_into_stock", 6)]),
    ("M5\nG0 X0 Y0\nG1 Z18 F500\nG1 X50", [("spindle_off", 7)]),
])
def test_each_finding_at_its_line(tmp_path: Path, body: str, found: list[tuple[str, int]]) -> None:
    _stock, findings = mill(tmp_path, body, diameter=6)
    assert [(f.kind, f.line) for f in findings] == found


def test_the_stamp_agrees_with_point_sampling_of_the_tool() -> None:
    """Random poses: each ray's interval inside the tool against points along the ray."""
    rng = np.random.default_rng(3)
    stock = RoundStock.cylinder(40, 20, 0, 1.0)
    rho = np.linspace(-5, 60, 13001)
    for _ in range(20):
        pose = np.array([[rng.uniform(0, 20), rng.uniform(-15, 15), rng.uniform(-5, 19), rng.uniform(0, 360)]])
        radius = float(rng.uniform(1, 8))
        _, cell, low, high = stamps(stock, pose, radius)
        slice_, angle = np.divmod(cell, stock.shape[1])
        x = stock.centres()[slice_]
        phi = np.radians((angle + 0.5) * stock.angle_step() + pose[0, 3])
        for k in range(0, len(cell), max(1, len(cell) // 50)):
            y, z = rho * math.cos(phi[k]), rho * math.sin(phi[k])
            inside = ((x[k] - pose[0, 0]) ** 2 + (y - pose[0, 1]) ** 2 <= radius ** 2) & (z >= pose[0, 2])
            inside &= rho >= 0
            if inside.any():
                assert max(low[k], 0.0) == pytest.approx(rho[inside].min(), abs=0.02)
                assert min(high[k], 60.0) == pytest.approx(min(rho[inside].max(), 60.0), abs=0.02)


def test_the_command_line(tmp_path: Path) -> None:
    job = tmp_path / "ring.nc"
    job.write_text("G21 G90 G17\nS10000 M3\nG0 Z25\nG0 X70 Y0 A0\nG1 Z17 F500\nG1 A360 F2000\nG0 Z25\nM30\n")
    (tmp_path / "tools.toml").write_text('[tool.1]\nshape = "flat"\ndiameter = 6\n')
    result = invoke("sim", job, "--stock", "cylinder:40,100,20", "--resolution", "0.2", "--tools",
                    tmp_path / "tools.toml", "--tool", "1", "--json")
    assert result.exit_code == 0, result.output
    doc = json.loads(result.stdout)
    assert doc["stock"]["cylinder"] == [40, 100, 20] and doc["collisions"] == []
    assert doc["stock"]["removed_volume"] == pytest.approx(math.pi * (400 - 289) * 6, rel=1e-3)


@pytest.mark.parametrize(("args", "message"), [
    (["--stock", "cylinder:40"], "is not cylinder:DIAMETER,LENGTH[,X0]"),
    (["--stock", "cylinder:0,100"], "must be above 0"),
    (["--stock", "cylinder:40,100", "--chuck", "5"], "--chuck LENGTH goes with --bar"),
])
def test_usage_errors_exit_2(tmp_path: Path, args: list[str], message: str) -> None:
    job = tmp_path / "j.nc"
    job.write_text("G0 X1\nM30\n")
    result = invoke("sim", job, *args)
    assert result.exit_code == 2, result.output
    assert message in result.stderr


@pytest.mark.parametrize("size", ["cylinder:1e9,1", "cylinder:40,100"])
def test_too_many_cells_is_a_usage_error(tmp_path: Path, size: str) -> None:
    job = tmp_path / "j.nc"
    job.write_text("G0 X1\nM30\n")
    result = invoke("sim", job, "--stock", size, "--resolution", "1e-300")
    assert result.exit_code == 2 and "too many" in result.stderr
