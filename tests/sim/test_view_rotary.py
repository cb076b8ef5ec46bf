"""``ecnc view --stock cylinder:``: the page carries the bar's unrolled depth maps, the tool's place on
the bar and the findings, the same cut as ``ecnc sim``'s; a browser draws them."""
from __future__ import annotations

import base64
from pathlib import Path
from typing import Any

import numpy as np
import pytest

from edingcnc_lang.runner import RunOptions
from edingcnc_lang.sim.rotary import simulate_cylinder
from edingcnc_lang.sim.rotary_frames import CELLS, coarse_depth
from edingcnc_lang.sim.round_stock import RoundStock
from edingcnc_lang.sim.tools import load_tools
from tests.cli_runner import invoke

from .jobs import page_data, screenshot

ROOT = Path(__file__).resolve().parents[2]
MILL_INI = ROOT / "examples" / "cylinder" / "cnc.ini"
LATHE_INI = ROOT / "examples" / "lathe" / "cnc.ini"
ROTARY = ROOT / "examples" / "round" / "rotary.nc"
TOOLS = ROOT / "examples" / "round" / "rotary-tools.toml"


def rotary_data(page: Path) -> dict[str, Any]:
    return page_data(page, "rotary-data")


def depth_maps(data: dict) -> np.ndarray:  # type: ignore[type-arg]
    """(frames, angle blocks, axial blocks) of depth in mm."""
    raw = np.frombuffer(base64.b64decode(data["depths"]), np.uint8).reshape(-1, data["m"], data["n"])
    return raw / 255 * data["deepest"]  # type: ignore[no-any-return]


def view(tmp_path: Path, *args: object, job: Path = ROTARY) -> dict:  # type: ignore[type-arg]
    page = tmp_path / "rotary.html"
    result = invoke("view", job, "--ini", MILL_INI, "-o", page, *args)
    assert result.exit_code == 0, result.output
    return rotary_data(page)


def test_the_last_frame_is_the_sims_cut(tmp_path: Path) -> None:
    data = view(tmp_path, "--stock", "cylinder:40,100,20", "--tools", TOOLS, "--resolution", "0.4")
    maps = depth_maps(data)
    assert len(maps) == len(data["moves"]) and data["moves"][0] == 0 and data["moves"] == sorted(data["moves"])
    assert data["moves"][-1] == 20 and (data["axis"], data["start"], data["radius"]) == ("A", 20.0, 20.0)
    assert maps.shape[1] * maps.shape[2] <= CELLS and maps[0].max() == 0.0
    stock = RoundStock.cylinder(40, 100, 20, 0.4)  # what ecnc sim cuts at the same resolution
    simulate_cylinder(ROTARY, stock, RunOptions(ini=str(MILL_INI)), load_tools(str(TOOLS)))
    final, step = coarse_depth(stock)
    assert data["block"] == pytest.approx(step * stock.resolution)
    assert maps[-1] == pytest.approx(final, abs=data["deepest"] / 510 + 1e-9)  # within the 8-bit quantisation
    assert data["deepest"] == pytest.approx(final.max())
    # the slot 3 mm deep at the bar's 90° from X20 to X75, the far one 2 mm deep at 270°
    along = data["start"] + (np.arange(data["n"]) + 0.5) * data["block"]
    angle = (np.arange(data["m"]) + 0.5) * data["blockAngle"]
    middle = (along > 30) & (along < 60)
    assert maps[-1][:, middle].max(axis=1)[np.abs(angle - 90).argmin()] > 2.0
    assert maps[-1][:, middle].max(axis=1)[np.abs(angle - 270).argmin()] > 1.3
    assert maps[-1][np.abs(angle - 180) < 20][:, middle].max() == 0.0


def test_snapshots_leave_the_cut_as_it_is() -> None:
    """The view's hook cuts the moves queued before each snapshot: the bar is cut the same (a cell's
    cuts do not depend on which other cells share their batch: ``RoundStock.cut``)."""
    plain, watched = RoundStock.cylinder(40, 100, 20, 0.5), RoundStock.cylinder(40, 100, 20, 0.5)
    options = RunOptions(ini=str(MILL_INI))
    simulate_cylinder(ROTARY, plain, options)
    seen: list[int] = []
    result = simulate_cylinder(ROTARY, watched, options, every=1, on_snapshot=lambda move, _: seen.append(move),
                               tips=True)
    assert np.array_equal(plain.outer, watched.outer) and seen == list(range(20))
    assert result.tips is not None and result.tips.shape == (20, 2)
    assert result.tips[-1] == pytest.approx((110.0, 90.0), abs=1e-3)  # X110 at A360: above the bar's 90°


def test_the_tool_is_marked_where_each_move_leaves_it(tmp_path: Path) -> None:
    data = view(tmp_path, "--stock", "cylinder:40,100,20")
    tips = np.frombuffer(base64.b64decode(data["tips"]), "<f4").reshape(-1, 2)
    assert len(tips) == 20  # one per move the page shows
    assert tips[10] == pytest.approx((75.0, 270.0), abs=1e-3)  # line 18: along the far slot, indexed A180
    assert tips[14] == pytest.approx((90.0, 90.0), abs=1e-3)  # line 22: the ring groove back at A360


def test_findings_are_on_the_page_at_their_line(tmp_path: Path) -> None:
    job = tmp_path / "crash.nc"
    job.write_text("G17 G21 G90\nG10 L2 P1 X0 Y200 Z-60 A0\nG54\nM6 T1\nS8000 M3\nG0 Z30\nG0 X30 Y0 A90\n"
                   "G0 Z18\nG0 Z30\nM5\nG1 X60 Z19 F500\nG0 Z30\nM30\n")
    data = view(tmp_path, "--stock", "cylinder:40,100,20", job=job)
    found = [(f["kind"], f["line"]) for f in data["findings"]]
    assert found == [("rapid_into_stock", 8), ("spindle_off", 11)]
    rapid = data["findings"][0]
    assert rapid["along"] == pytest.approx(30.0) and rapid["angle"] == pytest.approx(0.0, abs=1e-3)  # 90° less A90
    assert all(f["move"] < data["moves"][-1] for f in data["findings"])


@pytest.mark.parametrize("args, ini, message", [
    (("--stock", "cylinder:40,100", "--bar", "40,80"), MILL_INI, "one of --stock (a bar on the rotary axis) and --bar"),
    (("--stock", "cylinder:40,100", "--lines", "5:9"), MILL_INI, "--stock shows the whole job being cut"),
    (("--resolution", "0.2",), MILL_INI, "--resolution is the cell of the stock's simulation"),
    (("--stock", "cylinder:40,100,20"), LATHE_INI, "a bar on a rotary axis is a mill's"),
    (("--stock", "cylinder:40"), MILL_INI, "is not cylinder:DIAMETER,LENGTH[,X0]"),
])
def test_view_cylinder_usage_errors(tmp_path: Path, args: tuple[str, ...], ini: Path, message: str) -> None:
    page = tmp_path / "p.html"
    result = invoke("view", ROTARY, "--ini", ini, "-o", page, *args)
    assert result.exit_code == 2 and message in result.stderr, result.output
    assert "Traceback" not in result.output and not page.exists()


@pytest.mark.slow
def test_a_browser_draws_the_unrolled_bar(tmp_path: Path) -> None:
    page = tmp_path / "rotary.html"
    invoke("view", ROTARY, "--ini", MILL_INI, "--stock", "cylinder:40,100,20", "--tools", TOOLS, "-o", page)
    image = screenshot(page, tmp_path, "#move=20")
    lower = image[image.shape[0] // 2:]
    uncut = np.all(np.abs(lower - np.array([252, 253, 191]) / 255) < 0.03, axis=-1)  # the bar's surface
    deep = np.all(lower < 0.25, axis=-1) & (np.abs(lower[..., 2] - lower[..., 0]) < 0.2)  # near black: deep
    assert uncut.mean() > 0.05, "the unrolled bar is not on the picture"
    assert deep.mean() > 0.0005, "the cuts are not on the picture"
    marker = np.all(np.abs(lower - np.array([0xe0, 0x20, 0x20]) / 255) < 0.06, axis=-1)
    assert marker.sum() > 10, "the tool's marker is not on the picture"


def test_on_b_the_map_runs_along_y(tmp_path: Path) -> None:
    from tests.sim.test_rotary_kinematics import B_INI, ini, job

    page = tmp_path / "b.html"
    crash = job(tmp_path, "G0 X0 Y50 B30\nG0 Z15")  # a rapid straight down onto the bar at Y50, turned by B30
    result = invoke("view", crash, "--ini", ini(tmp_path, extra=B_INI), "--stock", "cylinder:40,100,20", "-o", page)
    assert result.exit_code == 0, result.output
    data = rotary_data(page)
    assert data["axis"] == "B" and data["start"] == 20.0
    (found,) = data["findings"]
    assert (found["kind"], found["line"]) == ("rapid_into_stock", 7)
    assert found["along"] == pytest.approx(50.0) and found["angle"] == pytest.approx(60.0, abs=1e-3)  # 90° less B30
    tips = np.frombuffer(base64.b64decode(data["tips"]), "<f4").reshape(-1, 2)
    assert tips[found["move"]] == pytest.approx((50.0, 60.0), abs=1e-3)
    assert depth_maps(data)[-1].max() > 4.0  # the rapid went 5 mm into the bar
