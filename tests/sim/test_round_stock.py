"""Round stock (``ecnc sim --bar``): the model against closed forms, the nose's envelope, the
imaginary tip, each lathe finding and the revolved part's mesh."""
from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest

from edingcnc_lang.runner import RunOptions
from edingcnc_lang.sim.bar_output import bar_mesh
from edingcnc_lang.sim.lathe import BarResult, simulate_bar
from edingcnc_lang.sim.round_stock import RoundStock
from edingcnc_lang.sim.stl import read_stl, write_stl
from edingcnc_lang.sim.tools import Tool
from edingcnc_lang.sim.turning import envelope, ranges, spans

from .test_stl import mesh_volume
from .test_stl_manifold import check_closed

LATHE_INI = Path(__file__).parents[2] / "examples" / "lathe" / "cnc.ini"


def turn(folder: Path, body: str, nose: float = 0.0, orientation: int = 0, bar: tuple[float, float, float] = (40, 50, 0),
         resolution: float = 0.1, chuck: float | None = None) -> BarResult:
    """``body`` on the example lathe (X as a diameter) turning a bar; T1 an insert, in the turret."""
    job = folder / "job.nc"
    job.write_text("G18 G21 G90 G40\nG97 S1000 M3\n" + body.strip() + "\nM30\n")
    stock = RoundStock.bar(bar[0], bar[1], bar[2] - bar[1], resolution)
    tool = Tool(1, shape="insert", diameter=2 * nose, nose_radius=nose, orientation=orientation)
    return simulate_bar(job, stock, RunOptions(ini=str(LATHE_INI)), {1: tool}, 1,
                        chuck=None if chuck is None else bar[2] - bar[1] + chuck)


def test_a_bar_turned_from_one_diameter_to_another(tmp_path: Path) -> None:
    result = turn(tmp_path, "G0 X42 Z2\nG1 X30 F100\nG1 Z-20\nG1 X42\nG0 Z2")
    assert result.stock.removed_volume == pytest.approx(math.pi * (20 ** 2 - 15 ** 2) * 20, rel=1e-9)
    assert result.stock.remaining_volume == pytest.approx(math.pi * 400 * 50 - result.stock.removed_volume)
    assert result.findings == []


def test_the_imaginary_tip_is_what_touches_the_programmed_diameter(tmp_path: Path) -> None:
    """Orientation 2 (tip at X -r, Z -r of the nose's centre): the shoulder and diameter come out as programmed."""
    result = turn(tmp_path, "G0 X42 Z2\nG1 X30 F100\nG1 Z-20\nG1 X42\nG0 Z2", nose=0.4, orientation=2)
    z, outer, _ = result.stock.profile()
    assert outer[(z > -19.5) & (z < -0.5)] == pytest.approx(15.0, abs=1e-5)
    assert outer[z < -20.5] == pytest.approx(20.0)
    # the nose leaves its radius in the shoulder's corner: the slice at Z-19.95 is above 15
    assert 15.0 < outer[np.searchsorted(z, -19.95)] < 15.4


def test_a_face_cut_takes_the_nose_width_off_the_end(tmp_path: Path) -> None:
    """A radial pass past the axis with a 0.5 mm nose centred 0.5 below the face takes 1 mm off it."""
    result = turn(tmp_path, "G0 X42 Z1.5\nG1 X-1 F100\nG0 Z5", nose=0.5, bar=(40, 50, 2))
    assert result.stock.removed_volume == pytest.approx(math.pi * 20 ** 2 * 1.0, rel=1e-9)


def test_a_groove_is_the_nose_s_half_disc_deep(tmp_path: Path) -> None:
    result = turn(tmp_path, "G0 X42 Z2\nG0 Z-10\nG1 X30 F50\nG0 X42", nose=1.0, resolution=0.01)
    expected = math.pi * (175 * 2 + 30 * math.pi / 2 - 4 / 3)  # the solid of revolution of the stadium's cap
    assert result.stock.removed_volume == pytest.approx(expected, rel=1e-3)


def test_a_drill_on_the_axis_bores_the_bar(tmp_path: Path) -> None:
    """A nose on the axis (a drill's radius, orientation 0) raises the inner radius, leaving the outside."""
    result = turn(tmp_path, "G0 X0 Z5\nG1 Z-10 F50\nG0 Z5", nose=4.0)
    z, outer, inner = result.stock.profile()
    assert outer == pytest.approx(20.0)
    assert inner[z > -9.9] == pytest.approx(4.0)
    hemisphere = 2 / 3 * math.pi * 4 ** 3
    assert result.stock.removed_volume == pytest.approx(math.pi * 16 * 10 + hemisphere, rel=1e-3)


@pytest.mark.parametrize(("body", "found"), [
    ("G0 X42 Z2\nG0 X30\nG0 Z-5\nG0 X42", [("rapid_into_stock", 5)]),
    ("M5\nG0 X42 Z2\nG1 X30 F100\nG1 Z-5\nG0 X42", [("spindle_off", 6)]),
    ("G0 X42 Z2\nG0 Z-45\nG0 X50", [("chuck", 4), ("chuck", 5)]),
])
def test_each_finding_at_its_line(tmp_path: Path, body: str, found: list[tuple[str, int]]) -> None:
    result = turn(tmp_path, body, chuck=10.0)
    assert [(f.kind, f.line) for f in result.findings] == found


def test_a_retract_through_what_was_just_cut_is_no_rapid_into_stock(tmp_path: Path) -> None:
    """Within one batch the cuts are taken in order: a rapid back along the cut pass finds air."""
    result = turn(tmp_path, "G0 X42 Z2\nG1 X30 F100\nG1 Z-20\nG0 Z2\nG0 X42")
    assert result.findings == []


def test_the_envelope_of_a_slanted_stroke_is_its_offset_line() -> None:
    a, b = np.array([[0.0, 10.0]]), np.array([[10.0, 0.0]])
    low, high = envelope(a, b, 1.0, np.array([5.0]))
    assert (low[0], high[0]) == pytest.approx((5 - math.sqrt(2), 5 + math.sqrt(2)))


def test_the_fast_path_agrees_with_point_sampling_of_the_stadium() -> None:
    """Random strokes: every slice's low/high radius against a dense sampling of the swept disc."""
    rng = np.random.default_rng(7)
    stock = RoundStock.bar(40, 20, -20, 0.5)
    for _ in range(30):
        a, b = rng.uniform((-20, 0), (0, 25), size=(2, 2))
        nose = float(rng.uniform(0.2, 2.0))
        seg, cell, low, high = spans(stock, a[None], b[None], nose, *ranges(stock, a[None], b[None], nose))
        z = stock.centres()[cell][:, None]
        t = np.linspace(0, 1, 20001)[None, :]
        zc, rc = a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1])
        half = np.sqrt(np.where(np.abs(z - zc) <= nose, nose ** 2 - (z - zc) ** 2, np.nan))
        assert low == pytest.approx(np.nanmin(rc - half, axis=1), abs=1e-3)
        assert high == pytest.approx(np.nanmax(rc + half, axis=1), abs=1e-3)


def test_the_revolved_part_is_a_closed_mesh_of_the_part_s_volume(tmp_path: Path) -> None:
    result = turn(tmp_path, "G0 X42 Z2\nG1 X30 F100\nG1 Z-20\nG1 X42\nG0 X42 Z-30\nG1 X0\nG0 X42\n"
                            "G0 X0 Z5\nG1 Z-8\nG0 Z5", nose=0.5, resolution=0.25)
    path = tmp_path / "part.stl"
    write_stl(path, bar_mesh(result.stock))
    triangles = read_stl(path)
    check_closed(triangles)
    facets = 128 * math.sin(2 * math.pi / 128) / (2 * math.pi)  # a 128-gon's area against the circle's
    assert mesh_volume(triangles) == pytest.approx(result.stock.remaining_volume * facets, rel=1e-4)
    z, outer, _ = result.stock.profile()
    assert (outer[np.abs(z + 30) < 0.4] == 0).all()  # parted off: two pieces


def test_memory_of_a_100_by_300_bar_at_0_1_mm() -> None:
    stock = RoundStock.bar(100, 300, -300, 0.1)
    assert stock.shape == (3000, 1) and stock.outer.nbytes + stock.inner.nbytes == 24_000


def test_an_arc_turns_a_dome(tmp_path: Path) -> None:
    """G3 in G18 from the axis to the bar's surface: a hemisphere's end; chords a quarter slice inside
    the circle remove a little more (their sagitta over the dome's surface)."""
    result = turn(tmp_path, "G0 X0 Z2\nG1 Z0 F100\nG3 X20 Z-10 R10\nG0 X30\nG0 Z2", bar=(20, 50, 0), resolution=0.05)
    removed = math.pi * 100 * 10 - 2 / 3 * math.pi * 1000
    sagitta = 2 * math.pi * 100 * 0.05 / 4 * 2 / 3
    assert removed <= result.stock.removed_volume <= removed + 1.5 * sagitta


def test_a_drill_pecking_back_into_its_hole_finds_air(tmp_path: Path) -> None:
    """Within one batch a later cut sees the bore the earlier ones opened: the rapids of a peck
    cycle in and out of the hole are no rapid into the stock."""
    result = turn(tmp_path, "G0 X0 Z5\nG1 Z-10 F50\nG0 Z5\nG0 Z-9\nG1 Z-15\nG0 Z5", nose=4.0)
    assert result.findings == []
    hemisphere = 2 / 3 * math.pi * 4 ** 3
    assert result.stock.removed_volume == pytest.approx(math.pi * 16 * 15 + hemisphere, rel=1e-3)
