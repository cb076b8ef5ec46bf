"""``ecnc view --bar``: the page carries the turned bar's profiles and findings, and a browser draws them."""
from __future__ import annotations

import base64
from pathlib import Path
from typing import Any

import numpy as np
import pytest

from tests.cli_runner import invoke

from .jobs import page_data, screenshot

ROOT = Path(__file__).resolve().parents[2]
LATHE_INI = ROOT / "examples" / "lathe" / "cnc.ini"
BAR = ROOT / "examples" / "round" / "bar.nc"


def bar_data(page: Path) -> dict[str, Any]:
    return page_data(page, "bar-data")


def profiles(data: dict) -> np.ndarray:  # type: ignore[type-arg]
    """(frames, outer/inner, slices) in mm."""
    radii = np.frombuffer(base64.b64decode(data["radii"]), "<u2").reshape(-1, 2, data["n"])
    return radii / 65535 * data["radius"]  # type: ignore[no-any-return]


def test_the_page_has_the_bar_from_whole_to_turned(tmp_path: Path) -> None:
    page = tmp_path / "bar.html"
    result = invoke("view", BAR, "--ini", LATHE_INI, "--bar", "40,80,1", "--chuck", "25",
                    "--tools", ROOT / "examples" / "round" / "bar-tools.toml", "-o", page)
    assert result.exit_code == 0, result.output
    data = bar_data(page)
    frames = profiles(data)
    assert len(frames) == len(data["moves"]) and data["moves"][0] == 0 and data["moves"] == sorted(data["moves"])
    assert (data["z0"], data["chuck"], data["radius"]) == (-79.0, -54.0, 20.0)
    z = data["z0"] + (np.arange(data["n"]) + 0.5) * data["slice"]
    assert frames[0, 0] == pytest.approx(20.0) and frames[0, 1] == pytest.approx(0.0)
    spigot, roughed = (z > -14) & (z < -2), (z > -34) & (z < -16)
    assert frames[-1, 0, spigot] == pytest.approx(12.5, abs=1e-3)   # the 25 mm spigot, X a radius
    assert frames[-1, 0, roughed].max() <= 15.0 + 1e-3
    assert frames[-1, 0, z < -36] == pytest.approx(20.0)
    assert data["findings"] == []


def test_a_holder_hit_is_on_the_page_at_its_line(tmp_path: Path) -> None:
    job, tools, page = tmp_path / "deep.nc", tmp_path / "t.toml", tmp_path / "deep.html"
    job.write_text("G18 G21 G90 G40\nM6 T1\nG97 S1000 M3\nG0 X42 Z2\nG1 X36 F100\nG1 Z-20\nG0 X42\nG0 Z2\n"
                   "G1 X8\nG1 Z-10\nG0 X42\nM30\n")
    tools.write_text('[tool.1]\nshape = "insert"\nnose_radius = 0.4\norientation = 2\ninsert_angle = 80\n'
                     'insert_size = 12\nholder_width = 20\n')
    result = invoke("view", job, "--ini", LATHE_INI, "--bar", "40,50", "--tools", tools, "-o", page)
    assert result.exit_code == 0, result.output
    found = bar_data(page)["findings"]
    assert [(f["kind"], f["line"]) for f in found] == [("holder", 10)]
    assert 4 < found[0]["x"] <= 18 and -10 <= found[0]["z"] <= 2  # X a radius, as the page's path


@pytest.mark.parametrize("args, message", [
    (("--bar", "40,80", "--stock", "0,0,-20,100,60,0"), "one of --stock (a box) and --bar"),
    (("--chuck", "20"), "--chuck LENGTH goes with --bar"),
    (("--bar", "40,80", "--chuck", "80"), "grips the whole bar"),
    (("--bar", "40,80", "--lines", "5:9"), "--bar shows the whole job being cut"),
    (("--stock", "cylinder:40,100"), "a bar on a rotary axis is a mill's"),
    (("--bar", "40"), "is not DIAMETER,LENGTH[,Z0]"),
])
def test_view_bar_usage_errors(tmp_path: Path, args: tuple[str, ...], message: str) -> None:
    result = invoke("view", BAR, "--ini", LATHE_INI, "-o", tmp_path / "p.html", *args)
    assert result.exit_code == 2 and message in result.stderr, result.output


def test_a_bar_on_a_mill_is_an_error_not_a_traceback(tmp_path: Path) -> None:
    result = invoke("view", ROOT / "examples" / "pocket.nc", "--bar", "40,80", "-o", tmp_path / "p.html")
    assert result.exit_code == 2 and "a bar turns on a lathe" in result.stderr


@pytest.mark.slow
def test_a_browser_draws_the_bar(tmp_path: Path) -> None:
    page = tmp_path / "bar.html"
    invoke("view", BAR, "--ini", LATHE_INI, "--bar", "40,80,1", "--chuck", "25", "-o", page)
    image = screenshot(page, tmp_path, "#move=38")
    part = np.all(np.abs(image - np.array([0x4c, 0x72, 0xb0]) / 255) < 0.05, axis=-1)
    assert part.mean() > 0.01, "the bar's half section is not on the picture"
