"""Tool shapes on the rotary axis: ring grooves of a ball, bull and vee cutter against their closed
forms, every part's stamp against point sampling of its solid, and the shank and holder findings."""
from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest

from edingcnc_lang.sim.rotary import simulate_cylinder
from edingcnc_lang.sim.rotary_stamp import parts_of, stamps
from edingcnc_lang.sim.round_stock import RoundStock
from edingcnc_lang.sim.tools import Tool

R = 20.0


def ring(folder: Path, tool: Tool, depth: float, resolution: float = 0.1) -> tuple[RoundStock, list]:
    job = folder / "job.nc"
    job.write_text(f"G21 G90 G17\nS10000 M3\nG0 Z25\nG0 X70 Y0 A0\nG1 Z{R - depth} F300\nG1 A360 F2000\n"
                   "G0 Z25\nM30\n")
    stock = RoundStock.cylinder(2 * R, 100, 20, resolution)
    result = simulate_cylinder(job, stock, tools={0: tool}, first_tool=0)
    assert result.error is None
    return stock, result.findings


def _rounded_bottom(r0: float, rc: float, w: float) -> float:
    """∫ π (R² - (c - sqrt(rc² - t²))²) dt over -w..w, c = r0 + rc: a round corner turned about the axis."""
    c = r0 + rc
    return math.pi * ((R * R - c * c - rc * rc) * 2 * w + 2 * w ** 3 / 3
                      + 2 * c * (w * math.sqrt(rc * rc - w * w) + rc * rc * math.asin(w / rc)))


def test_a_ball_ring_groove(tmp_path: Path) -> None:
    d, radius = 2.0, 4.0  # the sphere's section reaches the surface at w from its centre
    w = math.sqrt(radius ** 2 - (radius - d) ** 2)
    expected = _rounded_bottom(R - d, radius, w)
    stock, _ = ring(tmp_path, Tool(0, "ball", 2 * radius), d, resolution=0.2)
    assert stock.removed_volume == pytest.approx(expected, rel=2e-3)


def test_a_bull_ring_groove(tmp_path: Path) -> None:
    d, radius, corner = 1.0, 4.0, 2.0
    flat = radius - corner
    w = math.sqrt(corner ** 2 - (corner - d) ** 2)
    expected = 2 * math.pi * (R * R - (R - d) ** 2) * flat + _rounded_bottom(R - d, corner, w)
    stock, _ = ring(tmp_path, Tool(0, "bull", 2 * radius, corner_radius=corner), d, resolution=0.2)
    assert stock.removed_volume == pytest.approx(expected, rel=2e-3)


def test_a_vee_ring_groove(tmp_path: Path) -> None:
    """A 90° vee 2 mm deep: the groove's wall r = R - d + |t| turned about the axis."""
    d, k = 2.0, 1.0
    w = d / k
    expected = 2 * math.pi * (R * R * w - ((R - d + k * w) ** 3 - (R - d) ** 3) / (3 * k))
    stock, _ = ring(tmp_path, Tool(0, "vee", 10.0, angle=90.0), d, resolution=0.2)
    assert stock.removed_volume == pytest.approx(expected, rel=3e-3)


@pytest.mark.parametrize("tool", [Tool(0, "ball", 8.0), Tool(0, "bull", 10.0, corner_radius=2.0),
                                  Tool(0, "vee", 8.0, angle=60.0),
                                  Tool(0, "ball", 8.0, flute_length=3.0, shank_diameter=5.0, holder_diameter=20.0,
                                       holder_length=6.0),
                                  Tool(0, "ball", 8.0, flute_length=2.0)],
                         ids=["ball", "bull", "vee", "ball with shank and holder", "ball with flutes below its centre"])
def test_each_part_agrees_with_point_sampling(tool: Tool) -> None:
    """Random poses: each ray's interval inside each part against points along the ray."""
    rng = np.random.default_rng(7)
    stock = RoundStock.cylinder(40, 20, 0, 1.0)
    rho = np.linspace(-5, 60, 26001)
    checked = 0
    for part in parts_of(tool):
        for _ in range(12):
            pose = np.array([[rng.uniform(0, 20), rng.uniform(-12, 12), rng.uniform(-5, 19), rng.uniform(0, 360)]])
            _, cell, low, high = stamps(stock, pose, part.radius, part)
            slice_, angle = np.divmod(cell, stock.shape[1])
            dx = stock.centres()[slice_] - pose[0, 0]
            phi = np.radians((angle + 0.5) * stock.angle_step() + pose[0, 3])
            for k in range(0, len(cell), max(1, len(cell) // 40)):
                u = rho * math.cos(phi[k]) - pose[0, 1]
                height = rho * math.sin(phi[k]) - pose[0, 2]
                d = np.sqrt(dx[k] ** 2 + u * u)
                floor = part.bottom + (part.cutter.profile(np.minimum(d, part.radius)) if part.cutter else 0.0)
                inside = (d <= part.radius) & (height >= floor) & (height <= part.top) & (rho >= 0)
                if not inside.any():  # a ray that misses the part: nothing of the bar is in its interval
                    assert not max(low[k], 0.0) < min(high[k], 20.0) - 0.02
                else:
                    checked += 1
                    assert max(low[k], 0.0) == pytest.approx(rho[inside].min(), abs=0.01)
                    # past the bar's surface (radius 20) the interval only has to reach beyond it
                    assert min(high[k], 21.0) == pytest.approx(min(rho[inside].max(), 21.0), abs=0.01)
    assert checked > 100


@pytest.mark.parametrize(("tool", "kinds"), [
    (Tool(0, diameter=6.0, flute_length=2.0), [("shank", 6)]),  # the plunge: the cutter clears its way
    (Tool(0, diameter=6.0, flute_length=2.0, holder_diameter=20.0, holder_length=2.5),
     [("holder", 5), ("shank", 6), ("holder", 6)]),
    (Tool(0, diameter=6.0, flute_length=5.0, holder_diameter=20.0, holder_length=8.0), []),
])
def test_shank_and_holder_findings_at_their_line(tmp_path: Path, tool: Tool, kinds: list) -> None:
    """A ring groove 3 mm deep (the plunge on line 5, A turning on line 6): deeper than 2 mm of flutes
    (the shank), with the holder 2.5 mm up."""
    stock, found = ring(tmp_path, tool, 3.0, resolution=0.25)
    # (the holder plunging in may also show the shank on line 5: on the rays the plunge's side left)
    assert set(kinds) <= {(f.kind, f.line) for f in found} and bool(kinds) == bool(found)
    if not kinds:  # the whole groove cut, nothing more
        assert stock.removed_volume == pytest.approx(math.pi * (R * R - 17.0 ** 2) * 6.0, rel=2e-3)

