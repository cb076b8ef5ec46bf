"""Small jobs and helpers shared by the simulation tests."""
from __future__ import annotations

import json
import re
from pathlib import Path
from typing import Any

from edingcnc_lang.sim import Stock, Tool, simulate
from edingcnc_lang.sim.job import SimResult


def write_job(folder: Path, body: str, name: str = "job.nc") -> Path:
    """A job with the usual preamble, CRLF line ends as the controller's files have them."""
    path = folder / name
    path.write_bytes(("G21 G90 G17\r\nS10000 M3\r\n" + body.strip().replace("\n", "\r\n") + "\r\nM30\r\n").encode())
    return path


def cut(folder: Path, body: str, tool: Tool, box: tuple[float, ...] = (0, 0, -10, 40, 30, 0),
        resolution: float = 0.1) -> SimResult:
    """Simulate ``body`` with ``tool`` (tool 0, in the spindle from the start) on a box stock."""
    stock = Stock.box(box[:3], box[3:], resolution)  # type: ignore[arg-type]
    return simulate(write_job(folder, body), stock, tools={0: tool}, first_tool=0)


def page_data(page: Path, block: str) -> dict[str, Any]:
    """The JSON block ``block`` (``stock-data``, ``bar-data``, ``rotary-data``) of an ``ecnc view`` page."""
    found = re.search(rf'<script type="application/json" id="{block}">(.*?)</script>', page.read_text())
    assert found, f"no {block} block in the page"
    return json.loads(found[1])  # type: ignore[no-any-return]


def screenshot(page: Path, folder: Path, fragment: str) -> Any:
    """The page drawn by headless Chromium at ``fragment`` (``#move=N``) as an RGB array, with no
    message on the browser's console; the test skips where Chromium or matplotlib is missing."""
    import pytest

    from tests.plot.test_browser import CHROMIUM, chromium, console

    if CHROMIUM is None:
        pytest.skip("Chromium is not installed (Debian: apt-get install chromium)")
    imread = pytest.importorskip("matplotlib.image").imread
    shot = folder / "shot.png"
    log = chromium(page, folder / "profile", f"--screenshot={shot}", fragment=fragment)
    assert console(log) == [], console(log)
    return imread(shot)[..., :3]
