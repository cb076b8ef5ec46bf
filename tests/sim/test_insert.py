"""The lathe insert beyond its nose (``insert_angle``, ``insert_size``) and its holder
(``holder_width``): the shape each orientation gives, volumes against closed forms, the sweep
against point sampling, and a holder meeting the bar at its line."""
from __future__ import annotations

import math
import re
from pathlib import Path

import numpy as np
import pytest

from edingcnc_lang.pipeline.comp_geometry import TIP_X, TIP_Z
from edingcnc_lang.runner import RunOptions
from edingcnc_lang.sim.insert import Holder, holder_envelope, insert_shape, insert_spans
from edingcnc_lang.sim.lathe import BarResult, simulate_bar
from edingcnc_lang.sim.round_stock import RoundStock
from edingcnc_lang.sim.tools import Tool, load_tools
from edingcnc_lang.sim.turning import ranges_over

from .test_round_stock import LATHE_INI


def insert(nose: float = 0.0, orientation: int = 2, angle: float | None = 80.0, size: float | None = None,
           holder: float | None = None) -> Tool:
    return Tool(1, shape="insert", diameter=2 * nose, nose_radius=nose, orientation=orientation,
                insert_angle=angle, insert_size=size, holder_width=holder)


def turn(folder: Path, body: str, tool: Tool, bar: tuple[float, float, float] = (40, 50, 0),
         resolution: float = 0.1) -> BarResult:
    """``body`` on the example lathe (X a diameter) with ``tool`` as T1, the spindle turning."""
    job = folder / "job.nc"
    job.write_text("G18 G21 G90 G40\nG97 S1000 M3\n" + body.strip() + "\nM30\n")
    stock = RoundStock.bar(bar[0], bar[1], bar[2] - bar[1], resolution)
    return simulate_bar(job, stock, RunOptions(ini=str(LATHE_INI)), {1: tool}, 1)


def test_an_80_degree_insert_at_orientation_2_sits_as_an_sclcr_holds_it() -> None:
    """Its edges run 5° off the turned diameter (+Z) and 5° off the face (+X), 12 mm from the corner."""
    shape = insert_shape(insert(nose=0.4, size=12))
    assert shape is not None
    directions = {round(math.degrees(math.atan2(q[1] - p[1], q[0] - p[0])), 6) for p, q in shape.outline[:2]}
    assert directions == {5.0, 85.0}
    corner = -0.4 / math.sin(math.radians(40)) / math.sqrt(2)
    assert shape.outline[2, 0] == pytest.approx([corner + 12 * math.cos(math.radians(85)),
                                                 corner + 12 * math.sin(math.radians(85))])
    assert (shape.z_extent[0], shape.r_low) == pytest.approx((-0.4, -0.4))


def test_without_the_new_fields_the_insert_is_its_nose() -> None:
    assert insert_shape(insert(angle=None)) is None


def test_the_holder_points_out_of_the_bore_for_an_inside_tool() -> None:
    outside = insert_shape(insert(orientation=2, holder=20, size=12))
    inside = insert_shape(insert(orientation=3, holder=16, size=12))
    assert outside is not None and outside.holder is not None and not outside.holder.along_z
    assert outside.holder.side == pytest.approx((outside.z_extent[0], outside.z_extent[0] + 20))
    assert inside is not None and inside.holder is not None and inside.holder.along_z
    assert inside.holder.side[1] - inside.holder.side[0] == pytest.approx(16)


def test_a_facing_pass_takes_the_edge_s_width_off_the_end(tmp_path: Path) -> None:
    """A sharp 80° insert at orientation 2, its tip 0.5 below the face, across the axis: the edge
    trailing at 5° behind the tip takes the whole 0.5 mm (the nose alone took one slice)."""
    body = "G0 X42 Z1.5\nG1 X-1 F100\nG0 Z5"
    edged = turn(tmp_path, body, insert(), bar=(40, 50, 2))
    assert edged.stock.removed_volume == pytest.approx(math.pi * 20 ** 2 * 0.5, rel=1e-9)
    nose = turn(tmp_path, body, insert(angle=None), bar=(40, 50, 2))
    assert nose.stock.removed_volume == pytest.approx(math.pi * 20 ** 2 * 0.1, rel=1e-9)


def test_a_35_degree_insert_plunged_cuts_a_vee_groove(tmp_path: Path) -> None:
    """Orientation 6 (pointing at the axis), sharp, 5 mm deep: a groove of flanks 17.5° off X."""
    result = turn(tmp_path, "G0 X42 Z2\nG0 Z-10\nG1 X30 F50\nG0 X42", insert(orientation=6, angle=35), resolution=0.005)
    k = math.tan(math.radians(17.5))
    expected = 2 * math.pi * k * (400 * 5 - (20 ** 3 - 15 ** 3) / 3)
    assert result.stock.removed_volume == pytest.approx(expected, rel=2e-3)
    assert result.findings == []


def test_turning_deeper_than_the_edge_brings_the_holder_into_the_bar(tmp_path: Path) -> None:
    """A 2 mm pass is clear; a 14 mm one (the edge is 11.5 mm high) meets the holder at its line."""
    body = "G0 X42 Z2\nG1 X36 F100\nG1 Z-20\nG0 X42\nG0 Z2\nG1 X8\nG1 Z-10\nG0 X42"
    result = turn(tmp_path, body, insert(nose=0.4, size=12, holder=20))
    assert [(f.kind, f.line) for f in result.findings] == [("holder", 9)]
    x, _, z = result.findings[0].position
    assert 2 * (4 + 11.5) <= x <= 36 and -10 <= z <= 2
    assert turn(tmp_path, body, insert(nose=0.4, size=20, holder=20)).findings == []


def test_a_boring_bar_s_shank_meets_the_bore_s_wall(tmp_path: Path) -> None:
    """Orientation 3 along a 20 mm bore (bored 30 deep beforehand), cutting it to 22: a 12 mm bar
    under the tip clears the wall; a 24 mm one reaches across the axis to the far side's wall."""
    job = tmp_path / "job.nc"
    job.write_text("G18 G21 G90 G40\nG97 S1000 M3\nG0 X42 Z5\nG0 X18\nG1 X22 Z2 F50\nG1 Z-20\nG0 Z5\nM30\n")
    for width, found in ((12, []), (24, [("holder", 6)])):
        stock = RoundStock.bar(60, 50, -50, 0.1)
        stock.inner[stock.centres() > -30] = 10.0
        bored = stock.remaining_volume
        result = simulate_bar(job, stock, RunOptions(ini=str(LATHE_INI)), {1: insert(orientation=3, size=6,
                                                                                      holder=width)}, 1)
        assert [(f.kind, f.line) for f in result.findings] == found, width
        if not found:  # the bore opened to 22 over 20 mm; the last slice is the shoulder the leading edge leaves
            assert math.pi * 21 * 19.9 <= bored - stock.remaining_volume <= math.pi * 21 * 20


def _cross(u: np.ndarray, v: np.ndarray) -> float:
    return float(u[0] * v[1] - u[1] * v[0])


def _chain(points: np.ndarray, lower: bool) -> np.ndarray:
    """The lower (or upper) convex hull of points (Z, r), by Z: Andrew's monotone chain."""
    ordered = points[np.lexsort((points[:, 1], points[:, 0]))]
    hull: list[np.ndarray] = []
    sign = 1 if lower else -1
    for p in ordered:
        while len(hull) >= 2 and sign * _cross(hull[-1] - hull[-2], p - hull[-2]) <= 0:
            hull.pop()
        hull.append(p)
    return np.array(hull)


def test_the_insert_sweep_agrees_with_point_sampling() -> None:
    """Random strokes, orientations, angles and noses: each slice's low/high radius against the
    hull of the nose's circle and the edges' ends, built here on its own, moved along the stroke."""
    rng = np.random.default_rng(11)
    stock = RoundStock.bar(60, 30, -30, 0.5)
    t = np.linspace(0.0, 1.0, 20001)
    for _ in range(40):
        orientation = int(rng.integers(1, 9))
        angle = float(rng.choice([35.0, 55.0, 60.0, 80.0]))
        nose, size = float(rng.uniform(0.0, 1.2)), float(rng.uniform(5.5, 9.0))  # the back clears the nose
        shape = insert_shape(insert(nose, orientation, angle, size))
        assert shape is not None
        tip = math.atan2(TIP_X[orientation] if orientation in TIP_X else 0, TIP_Z.get(orientation, 0))
        half = math.radians(angle) / 2
        corner = np.array([math.cos(tip), math.sin(tip)]) * nose / math.sin(half)
        ends = [corner + size * np.array([math.cos(tip + math.pi + s * half), math.sin(tip + math.pi + s * half)])
                for s in (1, -1)]
        arc = np.linspace(0, 2 * math.pi, 3600, endpoint=False)
        cloud = np.vstack([nose * np.column_stack((np.cos(arc), np.sin(arc))), *ends])
        lower, upper = _chain(cloud, True), _chain(cloud, False)
        a, b = rng.uniform((-25, 0), (-5, 30), size=(2, 2))
        first, last = ranges_over(stock, np.array([min(a[0], b[0]) + shape.z_extent[0]]),
                                  np.array([max(a[0], b[0]) + shape.z_extent[1]]))
        seg, cell, low, high = insert_spans(stock, a[None], b[None], shape, first, last)
        for z, lo, hi in zip(stock.centres()[cell], low, high):
            u = z - (a[0] + t * (b[0] - a[0]))
            r = a[1] + t * (b[1] - a[1])
            inside = (u >= lower[0, 0]) & (u <= lower[-1, 0])
            if not inside.any():  # a stroke narrower than a slice: cut at its nearest end, not sampled here
                continue
            assert lo == pytest.approx(np.min(np.interp(u[inside], lower[:, 0], lower[:, 1]) + r[inside]), abs=2e-3)
            assert hi == pytest.approx(np.max(np.interp(u[inside], upper[:, 0], upper[:, 1]) + r[inside]), abs=2e-3)


def test_the_holder_sweep_agrees_with_point_sampling() -> None:
    rng = np.random.default_rng(5)
    t = np.linspace(0.0, 1.0, 20001)
    for along_z in (False, True):
        holder = Holder(along_z, float(rng.uniform(2, 10)), (-3.0, 12.0))
        for _ in range(20):
            a, b = rng.uniform((-25, 0), (-5, 30), size=(2, 2))
            z = rng.uniform(-30, 0, size=8)
            low, high = holder_envelope(np.repeat(a[None], 8, 0), np.repeat(b[None], 8, 0), holder, z, 99.0)
            zc, rc = a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1])
            for k in range(8):
                if along_z:  # a bar across the axis reaches as far on the other side
                    there = zc <= z[k] - holder.start
                else:
                    there = (z[k] - zc >= holder.side[0]) & (z[k] - zc <= holder.side[1])
                if not there.any():
                    assert not np.isfinite(low[k])
                    continue
                if along_z:
                    lowest, highest = rc[there].min() + holder.side[0], rc[there].max() + holder.side[1]
                    want = (lowest, max(highest, -lowest))
                else:
                    want = (rc[there].min() + holder.start, 99.0)
                assert (low[k], high[k]) == pytest.approx(want, abs=1e-2)


def test_the_tools_file_takes_the_insert_s_fields(tmp_path: Path) -> None:
    path = tmp_path / "t.toml"
    path.write_text('[tool.1]\nshape = "insert"\nnose_radius = 0.4\norientation = 2\ninsert_angle = 55\n'
                    'insert_size = 15\nholder_width = 25\n')
    tool = load_tools(path)[1]
    assert (tool.insert_angle, tool.insert_size, tool.holder_width) == (55, 15, 25)


def test_the_example_finds_its_holder_at_line_19() -> None:
    """examples/round/deep.nc as docs/simulation.md runs it: one holder finding, at the deep pass."""
    import json

    from tests.cli_runner import invoke

    root = LATHE_INI.parents[1]
    result = invoke("sim", root / "round" / "deep.nc", "--ini", LATHE_INI, "--bar", "40,60,1", "--chuck", "20",
                    "--tools", root / "round" / "insert-tools.toml", "--json")
    assert result.exit_code == 1, result.output
    doc = json.loads(result.stdout)
    assert [(c["kind"], c["line"]) for c in doc["collisions"]] == [("holder", 19)]
    assert doc["tools"]["1"]["insert_angle"] == 80 and doc["tools"]["1"]["holder_width"] == 20


@pytest.mark.parametrize(("text", "message"), [
    ('[tool.1]\nshape = "insert"\ninsert_angle = 200\n', "insert_angle must be from 1 to below 180"),
    ('[tool.1]\nshape = "insert"\nholder_width = -3\n', "holder_width must be a positive number"),
    ('[tool.1]\nshape = "flat"\ndiameter = 6\ninsert_size = 12\n', 'are for shape = "insert"'),
])
def test_bad_insert_fields_name_the_file_and_tool(tmp_path: Path, text: str, message: str) -> None:
    from edingcnc_lang.sim.tools import ToolFileError

    path = tmp_path / "t.toml"
    path.write_text(text)
    with pytest.raises(ToolFileError, match=re.escape(message)):
        load_tools(path)


def test_an_insert_angle_without_a_direction_is_its_nose_and_said_so(tmp_path: Path) -> None:
    result = turn(tmp_path, "G0 X42 Z2\nG1 X30 F100\nG1 Z-20\nG1 X42\nG0 Z2", insert(nose=0.4, orientation=9))
    assert result.stock.removed_volume == pytest.approx(
        turn(tmp_path, "G0 X42 Z2\nG1 X30 F100\nG1 Z-20\nG1 X42\nG0 Z2", insert(nose=0.4, orientation=9,
                                                                            angle=None)).stock.removed_volume)
    assert any("orientation from 1 to 8" in note for note in result.notes)
