"""``ecnc view --stock``: the page carries the stock's frames, and a browser draws them without a word."""
from __future__ import annotations

import base64
from pathlib import Path
from typing import Any

import numpy as np
import pytest

from tests.cli_runner import invoke

from .jobs import page_data, screenshot

ROOT = Path(__file__).resolve().parents[2]


def stock_data(page: Path) -> dict[str, Any]:
    return page_data(page, "stock-data")


@pytest.mark.slow
def test_the_page_has_frames_from_the_whole_stock_to_the_cut_part(tmp_path):
    page = tmp_path / "pocket.html"
    result = invoke("view", ROOT / "examples/pocket.nc", "--stock", "0,0,-20,100,60,0", "-o", page)
    assert result.exit_code == 0, result.output
    data = stock_data(page)
    frames = np.frombuffer(base64.b64decode(data["heights"]), "<u2").reshape(-1, data["ny"], data["nx"])
    assert data["moves"][0] == 0 and data["moves"][-1] == 168 and len(frames) == len(data["moves"])
    assert (frames[0] == 65535).all()          # nothing cut before the first move
    assert frames[-1].min() < frames[0].min()  # the pocket and holes at the end
    # the job's G54 is X100 Y50 Z-80 in machine coordinates: the stock is drawn where the path is
    assert (data["x0"], data["y0"], data["top"]) == (100.0, 50.0, -80.0)


@pytest.mark.slow
def test_a_browser_draws_the_stock(tmp_path):
    page = tmp_path / "pocket.html"
    invoke("view", ROOT / "examples/pocket.nc", "--stock", "0,0,-20,100,60,0", "-o", page)
    image = screenshot(page, tmp_path, "#move=40")[100:700, 50:900]
    yellow = np.all(np.abs(image - np.array([253, 231, 37]) / 255 * 0.9) < 0.25, axis=-1)
    assert yellow.mean() > 0.02, "the stock's top is not on the picture"


@pytest.mark.parametrize("args, message", [
    (("--stock", "0,0,-20,100,60,0", "--lines", "20:40"), "does not go with --lines"),
    (("--tools", "examples/pocket-tools.toml"), "give the stock too"),
])
def test_view_stock_usage_errors(tmp_path, args, message):
    result = invoke("view", ROOT / "examples/pocket.nc", "-o", tmp_path / "p.html",
                    *[str(ROOT / a) if a.endswith(".toml") else a for a in args])
    assert result.exit_code == 2 and message in result.stderr
