"""The rotary part as STL (``--stl`` with ``--stock cylinder:``): a closed mesh whose volume is the
model's remaining volume to within the discretisation, on A and on B; and the shaded picture."""
from __future__ import annotations

import json
import math
from pathlib import Path

import numpy as np
import pytest

from edingcnc_lang.sim.rotary import RotaryAxis, simulate_cylinder
from edingcnc_lang.sim.rotary_output import rotary_mesh
from edingcnc_lang.sim.round_stock import RoundStock
from edingcnc_lang.sim.stl import read_stl, write_stl
from edingcnc_lang.sim.tools import Tool
from tests.cli_runner import invoke

from .test_stl import mesh_volume
from .test_stl_manifold import check_closed

JOB = ("G21 G90 G17\nS10000 M3\nG0 Z25\nG0 X0 Y0 A0\nG1 Z17 F500\nG1 X50\nG0 Z25\nG0 X70 A0\nG1 Z18\nG1 A360\n"
       "G0 Z25\nG0 X80 A0\nG1 Z19\nG1 X110 A270\nG0 Z25\nM30\n")


@pytest.mark.parametrize("axis", ["A", "B"])
def test_the_mesh_is_closed_and_holds_the_remaining_volume(tmp_path: Path, axis: str) -> None:
    job = tmp_path / "job.nc"
    job.write_text(JOB)
    if axis == "B":  # the same job along Y
        job.write_text(JOB.replace(" X", " Q").replace(" Y", " X").replace(" Q", " Y").replace("A", "B"))
    stock = RoundStock.cylinder(40, 100, 20, 0.5)
    result = simulate_cylinder(job, stock, tools={0: Tool(0, diameter=6)}, first_tool=0, axis=RotaryAxis(axis))
    assert result.error is None and stock.removed_volume > 1000
    path = tmp_path / "part.stl"
    write_stl(path, rotary_mesh(stock, axis))
    triangles = read_stl(path)
    check_closed(triangles)
    assert mesh_volume(triangles) == pytest.approx(stock.remaining_volume, rel=2e-3)
    lo, hi = triangles.reshape(-1, 3).min(axis=0), triangles.reshape(-1, 3).max(axis=0)
    along = 1 if axis == "B" else 0
    assert (lo[along], hi[along]) == pytest.approx((20, 120), abs=1e-4)


def test_a_bored_part_is_closed_too(tmp_path: Path) -> None:
    stock = RoundStock.cylinder(40, 20, 0, 0.5)
    stock.inner[:] = 5.0
    stock.outer[10:20, :50] = 15.0
    triangles = np.concatenate(list(rotary_mesh(stock)))
    check_closed(triangles)
    assert mesh_volume(triangles) == pytest.approx(stock.remaining_volume, rel=2e-3)


def test_the_command_line_writes_the_stl_and_the_picture(tmp_path: Path) -> None:
    job = tmp_path / "job.nc"
    job.write_text(JOB)
    (tmp_path / "tools.toml").write_text("[tool.1]\ndiameter = 6\n")
    result = invoke("sim", job, "--stock", "cylinder:40,100,20", "--resolution", "0.5", "--tools",
                    tmp_path / "tools.toml", "--tool", "1", "--stl", tmp_path / "part.stl", "-o", tmp_path / "part.png")
    assert result.exit_code == 0, result.output
    triangles = read_stl(tmp_path / "part.stl")
    check_closed(triangles)
    assert mesh_volume(triangles) < math.pi * 400 * 100
    assert (tmp_path / "part.png").read_bytes()[:4] == b"\x89PNG"


def cylinder_stl(path: Path, radius: float, start: float, end: float, facets: int = 256) -> None:
    """A closed cylinder along X, written independently of the simulator's mesh code."""
    theta = np.linspace(0.0, 2 * math.pi, facets + 1)[:-1]
    ring = np.stack((np.cos(theta), np.sin(theta)), axis=1) * radius
    nxt = np.roll(ring, -1, axis=0)
    tris = []
    for (y0, z0), (y1, z1) in zip(ring, nxt):
        a, b, c, d = (start, y0, z0), (end, y0, z0), (end, y1, z1), (start, y1, z1)
        tris += [(a, b, c), (a, c, d), ((end, 0, 0), c, b), ((start, 0, 0), a, d)]
    write_stl(path, [np.array(tris, dtype=np.float32)])


def test_compare_stl_finds_the_flat_as_a_gouge(tmp_path: Path) -> None:
    """Against the uncut bar as the intended part: a flat 3 mm deep is over-cut by 3 mm, nothing is
    left, and every cell is compared."""
    job = tmp_path / "job.nc"
    job.write_text("G21 G90 G17\nS10000 M3\nG0 Z25\nG0 X0 Y0 A0\nG1 Z17 F500\nG1 X140\nG0 Z25\nM30\n")
    cylinder_stl(tmp_path / "bar.stl", 20.0, 20.0, 120.0)
    (tmp_path / "tools.toml").write_text("[tool.1]\ndiameter = 30\n")
    result = invoke("sim", job, "--stock", "cylinder:40,100,20", "--resolution", "0.5", "--tools",
                    tmp_path / "tools.toml", "--tool", "1", "--compare-stl", tmp_path / "bar.stl", "--json",
                    "-o", tmp_path / "deviation.png")
    assert result.exit_code == 0, result.output
    compared = json.loads(result.stdout)["compare"]
    assert compared["max_overcut"] == pytest.approx(3.0, abs=0.01)
    assert compared["max_undercut"] < 0.01
    assert compared["cells"] == 200 * math.ceil(math.pi * 40 / 0.5)


def test_compare_stl_of_a_part_off_the_bar_is_an_error(tmp_path: Path) -> None:
    job = tmp_path / "job.nc"
    job.write_text("G0 X1\nM30\n")
    cylinder_stl(tmp_path / "far.stl", 20.0, 500.0, 600.0)
    result = invoke("sim", job, "--stock", "cylinder:40,100,20", "--compare-stl", tmp_path / "far.stl")
    assert result.exit_code == 2 and "does not lie along the bar" in result.stderr
