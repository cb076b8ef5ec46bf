"""An ``ecnc view`` page gets shared: it holds no absolute path of the computer that wrote it and not
the text of ecnc's own macro.cnc, unless ``--embed-sources`` asks for them."""
from __future__ import annotations

import json
import re
from pathlib import Path

import pytest

from edingcnc_lang.plot.viewer import _shown_names
from tests.cli_runner import invoke

ROOT = Path(__file__).resolve().parents[2]
JOB = "G21 G90\nT1 M6\nG0 X10 Y10 Z5\nG1 Z-1 F300\nG1 X40\nG1 X[1/0]\nM30\n"


def embedded(html: str) -> dict:
    block = re.search(r'<script type="application/json" id="job-data">(.*?)</script>', html, re.DOTALL)
    assert block
    return dict(json.loads(block.group(1)))


@pytest.fixture
def shop(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> Path:
    (tmp_path / "jobs").mkdir()
    (tmp_path / "jobs" / "part 1.nc").write_text(JOB)
    monkeypatch.chdir(tmp_path / "jobs")
    return tmp_path


def test_the_page_holds_no_absolute_path_nor_the_packaged_macro(shop: Path) -> None:
    result = invoke("view", str(shop / "jobs" / "part 1.nc"), "-o", "page.html")
    assert result.exit_code != 0  # the division by zero: the page shows the path up to it
    html = (shop / "jobs" / "page.html").read_text(encoding="utf-8")
    assert str(shop) not in html and str(ROOT) not in html and "/tmp/" not in html
    data = embedded(html)
    assert data["job"] == "part 1.nc" and data["files"] == ["ecnc/stdlib/macro.cnc", "part 1.nc"]
    assert list(data["source"]) == ["part 1.nc"]  # the job's own lines; not ecnc's macro.cnc
    assert data["error"].startswith("part 1.nc:6:") and "part 1.nc:6:" in data["title"]


def test_embed_sources_keeps_them(shop: Path) -> None:
    invoke("view", str(shop / "jobs" / "part 1.nc"), "-o", "page.html", "--embed-sources")
    data = embedded((shop / "jobs" / "page.html").read_text(encoding="utf-8"))
    macro = str(ROOT / "edingcnc_lang" / "stdlib" / "macro.cnc")
    assert data["files"] == [macro, str(shop / "jobs" / "part 1.nc")]
    assert macro in data["source"] and data["error"].startswith(str(shop))


def test_names_below_the_folder_stay_relative_and_equal_names_apart(shop: Path, tmp_path_factory: pytest.TempPathFactory) -> None:
    other = tmp_path_factory.mktemp("elsewhere") / "macro.cnc"
    names = _shown_names([str(shop / "jobs" / "sub" / "macro.cnc"), str(shop / "jobs" / "job.nc"), str(other),
                          "<string>", str(ROOT / "edingcnc_lang" / "stdlib" / "macro.cnc")])
    assert list(names.values()) == ["sub/macro.cnc", "job.nc", "macro.cnc", "<string>", "ecnc/stdlib/macro.cnc"]
    assert _shown_names([str(other), str(shop / "macro.cnc")])[str(shop / "macro.cnc")] == "macro.cnc (2)"
