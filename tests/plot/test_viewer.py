"""The HTML viewer's page: self-contained, small, its data faithful to the run, thinned past its budget."""
from __future__ import annotations

import base64
import json
import re
from pathlib import Path

import numpy as np
import pytest

from edingcnc_lang.plot.toolpath import KINDS, record_job
from edingcnc_lang.plot.viewer import decimate, page, view_data, write_view
from tests.plot.jobs import CIRCLE, TWO_TOOLS, write


def decode(text: str, dtype: str) -> np.ndarray:
    return np.frombuffer(base64.b64decode(text), dtype=np.dtype(dtype).newbyteorder("<"))


def zigzag(count: int, arcs_every: int = 0) -> str:
    """A job of ``count`` feed moves (every ``arcs_every``-th a half circle) between two tools."""
    lines = ["G21 G90 G17", "T1 M6", "G0 X0 Y0 Z1", "G1 Z-1 F600"]
    x = 0.0
    for k in range(count):
        y = 10.0 if k % 2 == 0 else 0.0
        if arcs_every and k % arcs_every == 0:
            lines.append(f"G2 X{x:.3f} Y{y:.3f} I0 J{(y - (10.0 - y)) / 2:.3f}" if y else f"G1 X{x:.3f} Y{y:.3f}")
        else:
            lines.append(f"G1 X{x:.3f} Y{y:.3f}")
        x += 0.1
    lines += ["G0 Z5", "M30"]
    return "\n".join(lines) + "\n"


def embedded(html: str) -> dict:
    match = re.search(r'<script type="application/json" id="job-data">(.*?)</script>', html, re.S)
    assert match
    return json.loads(match.group(1))


def test_points_and_columns_read_back_as_the_run_made_them(tmp_path: Path) -> None:
    path = record_job(write(tmp_path, "two.nc", TWO_TOOLS))
    data = view_data(path)
    points = decode(data["points"], "f4").reshape(-1, 3)
    last = decode(data["last"], "i4")
    assert np.allclose(points[last], path.ends[:, :3], atol=1e-4)
    assert decode(data["tool"], "i4").tolist() == path.tools.tolist()
    assert decode(data["line"], "i4").tolist() == path.lines.tolist()
    assert [data["kinds"][k] for k in decode(data["kind"], "u1")] == [KINDS[k] for k in path.kinds]
    assert data["moves"] == data["shown"] == len(path)
    source = data["source"]["two.nc"]  # a file outside the current folder: by its name alone
    assert source["9"] == "G1 Z-2 F100"


def test_an_arc_is_many_points_in_the_page(tmp_path: Path) -> None:
    path = record_job(write(tmp_path, "circle.nc", CIRCLE))
    data = view_data(path)
    first, last = decode(data["first"], "i4"), decode(data["last"], "i4")
    arc = next(iter(path.arcs))
    points = decode(data["points"], "f4").reshape(-1, 3)[first[arc]:last[arc] + 1]
    assert len(points) >= 60
    assert np.allclose(np.hypot(points[:, 0] - 40, points[:, 1] - 40), 30.0, atol=1e-4)


def test_the_page_fetches_nothing(tmp_path: Path) -> None:
    html = page(record_job(write(tmp_path, "two.nc", TWO_TOOLS)))
    assert not re.search(r"<(script|link|img|iframe)[^>]*\b(src|href)=", html)
    for word in ("fetch(", "XMLHttpRequest", "import(", "url(", "http://", "https://", "//cdn"):
        assert word not in html, word


def test_job_text_cannot_end_the_data_block(tmp_path: Path) -> None:
    job = write(tmp_path, "sneaky.nc", "G0 X1 ; </script><script>alert(1)</script>\nG1 X2 F100 (caf\xe9)\n")
    html = page(record_job(job))
    assert html.count("</script>") == 2  # the data block's and the viewer's
    data = embedded(html)
    lines = data["source"]["sneaky.nc"]
    assert lines["1"].endswith("</script><script>alert(1)</script>") and lines["2"].endswith("(caf\xe9)")


@pytest.mark.slow
def test_a_ten_thousand_move_job_is_a_small_page(tmp_path: Path) -> None:
    path = record_job(write(tmp_path, "big.nc", zigzag(10_000, arcs_every=50)))
    assert len(path) > 10_000
    out = write_view(path, tmp_path / "big.html")
    assert out.stat().st_size < 2_000_000
    assert embedded(out.read_text(encoding="utf-8"))["shown"] == len(path)  # nothing thinned


@pytest.mark.slow
def test_past_the_budget_moves_are_thinned_and_every_stretch_is_reachable(tmp_path: Path) -> None:
    path = record_job(write(tmp_path, "huge.nc", zigzag(30_000)))
    thinned = decimate(path, 5_000)
    assert len(thinned.keep) <= 5_100
    assert thinned.count.sum() == len(path) and thinned.keep[-1] == len(path) - 1
    rapids = np.flatnonzero(np.isin(path.kinds, [KINDS.index("rapid")]))
    assert set(rapids.tolist()) <= set(thinned.keep.tolist())  # rapids and the ends of runs stay
    html = page(path, max_moves=5_000)
    data = embedded(html)
    assert data["shown"] == len(thinned.keep) and data["moves"] == len(path)
    stretch = path.select_lines(1000, 1200)
    assert len(stretch) == 201 and embedded(page(stretch, max_moves=5_000))["shown"] == 201


@pytest.mark.parametrize("budget", [1, 2, 7])
def test_tiny_budgets_still_give_a_consistent_page(tmp_path: Path, budget: int) -> None:
    path = record_job(write(tmp_path, "two.nc", TWO_TOOLS))
    data = view_data(path, max_moves=budget)
    shown = data["shown"]
    assert len(decode(data["first"], "i4")) == len(decode(data["merged"], "i4")) == shown
    assert decode(data["merged"], "i4").sum() == len(path)
