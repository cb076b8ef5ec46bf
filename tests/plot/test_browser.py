"""The viewer in a real browser: headless Chromium opens the page from a file, a screenshot is
taken, and the test checks that it is not blank, that the path is on it, and that the page logged
nothing (no error, no warning).  Skipped, saying why, when Chromium is not installed (``.ci/run``
installs Debian's ``chromium`` where it can)."""
from __future__ import annotations

import re
import shutil
import subprocess
from pathlib import Path

import numpy as np
import pytest

from edingcnc_lang import RunOptions
from edingcnc_lang.plot import views
from edingcnc_lang.plot.toolpath import record_job
from edingcnc_lang.plot.viewer import write_view

from tests.plot.cdp import Browser

ROOT = Path(__file__).resolve().parents[2]
CHROMIUM = next((found for name in ("chromium", "chromium-browser") if (found := shutil.which(name))), None)
pytestmark = [pytest.mark.skipif(CHROMIUM is None, reason="Chromium is not installed (Debian: apt-get install chromium)"), pytest.mark.slow]
WINDOW = (1280, 800)


def chromium(page: Path, profile: Path, *args: str, fragment: str = "") -> str:
    """Run headless Chromium on ``page``; returns what it logged (the page's console included)."""
    command = [CHROMIUM, "--headless", "--no-sandbox", "--disable-gpu", "--disable-background-networking",
               "--disable-component-update", "--no-first-run", f"--user-data-dir={profile}",
               "--enable-logging=stderr", "--v=0", f"--window-size={WINDOW[0]},{WINDOW[1]}", *args,
               page.resolve().as_uri() + fragment]
    done = subprocess.run(command, capture_output=True, text=True, timeout=120)
    return done.stdout + done.stderr


def console(log: str) -> list[str]:
    return [line for line in log.splitlines() if ":CONSOLE" in line]


@pytest.fixture(scope="module")
def pocket_page(tmp_path_factory: pytest.TempPathFactory) -> Path:
    folder = tmp_path_factory.mktemp("browser")
    path = record_job(ROOT / "examples/pocket.nc")
    return write_view(path, folder / "pocket.html")


def test_the_page_draws_the_job_and_logs_nothing(pocket_page: Path, tmp_path: Path) -> None:
    imread = pytest.importorskip("matplotlib.image").imread  # reads the screenshot back
    shot = tmp_path / "shot.png"
    log = chromium(pocket_page, tmp_path / "profile", f"--screenshot={shot}")
    assert console(log) == [], console(log)
    assert shot.exists(), log[-2000:]
    image = imread(shot)[:, :, :3]
    assert image.shape[:2] == (WINDOW[1], WINDOW[0])
    colours = np.unique((image * 255).astype(np.uint8).reshape(-1, 3), axis=0)
    assert len(colours) > 50, "the screenshot is blank"
    canvas = image[100:700, 50:900]  # left of the side panel, below the header
    t1 = np.linalg.norm(canvas - np.array([int(views.TOOL_COLORS[0][i:i + 2], 16) / 255 for i in (1, 3, 5)]),
                        axis=2) < 0.15
    assert t1.sum() > 500, "the T1 pocket contour is not on the screenshot"


def test_the_page_finishes_its_script_and_opens_at_a_move(pocket_page: Path, tmp_path: Path) -> None:
    log = chromium(pocket_page, tmp_path / "profile", "--dump-dom", fragment="#move=40&view=top")
    assert console(log) == [], console(log)
    status = re.search(r'<div id="status"[^>]*>', log)
    assert status, log[-2000:]
    assert 'data-errors="0"' in status.group(0) and 'data-ready="1"' in status.group(0)
    drawn = int(re.search(r'data-drawn="(\d+)"', status.group(0)).group(1))
    assert drawn > 100  # moves drawn: those done and those to come
    assert re.search(r'<span id="counter">move 40 of 168</span>', log)
    assert re.search(r'<li class="current"><span class="n">\d+</span>', log)  # the program listing follows
    assert "<th>planned speed</th>" in log and re.search(r"<th>time</th><td class=\"text\">\d+:\d\d\.\d of ", log)


def test_a_kinematic_job_shows_its_joints(tmp_path: Path) -> None:
    path = record_job(ROOT / "examples/delta/job.nc", RunOptions(ini=ROOT / "examples/delta/cnc.ini"))
    page = write_view(path, tmp_path / "delta.html")
    log = chromium(page, tmp_path / "profile", "--dump-dom")
    assert console(log) == [], console(log)
    assert "joint 2 (Z)" in log and 'data-errors="0"' in log
    assert "joint 3 (A)" not in log  # only the joints that move are read out


def test_a_lathe_job_opens_in_the_lathe_view_with_z_across(tmp_path: Path) -> None:
    """Z to the right and X up: a long, thin turned part lies across the screen, not up it."""
    from edingcnc_lang.plot.actions import view_job

    job = tmp_path / "shaft.nc"
    job.write_text("G18 G90 G21\nG0 X12 Z2\nG1 X10 F200\nG1 Z-120\nG1 X14\nG0 Z2\nM30\n")
    page = view_job(job, RunOptions(), tmp_path / "shaft.html").out
    log = chromium(page, tmp_path / "profile", "--dump-dom")
    assert console(log) == [], console(log)
    assert re.search(r'<button type="button" data-view="lathe"[^>]*class="active"', log), log[-2000:]
    imread = pytest.importorskip("matplotlib.image").imread
    shots = {}
    for name in ("lathe", "front"):
        shot = tmp_path / f"{name}.png"
        chromium(page, tmp_path / f"profile-{name}", f"--screenshot={shot}", fragment=f"#view={name}")
        canvas = imread(shot)[100:700, 50:900, :3]
        colour = np.array([int(views.TOOL_COLORS[0][i:i + 2], 16) / 255 for i in (1, 3, 5)])
        rows, cols = np.nonzero(np.linalg.norm(canvas - colour, axis=2) < 0.15)
        assert len(rows) > 100, f"the cut is not on the {name} screenshot"
        shots[name] = (np.ptp(cols), np.ptp(rows))
    assert shots["lathe"][0] > 3 * shots["lathe"][1]  # Z across
    assert shots["front"][1] > 3 * shots["front"][0]  # the front view puts Z up


# ---------------------------------------------------------------- driven like a person, over DevTools
def _text(browser: Browser, element: str) -> str:
    return browser.evaluate(f"document.getElementById({element!r}).innerText")


def _readout(browser: Browser) -> dict[str, str]:
    rows = browser.evaluate("[...document.querySelectorAll('#readout tr')].map(r => [r.cells[0].innerText,"
                            " r.cells[1].innerText])")
    return dict(rows)


def _canvas(browser: Browser) -> str:
    return browser.evaluate("document.getElementById('view').toDataURL()")


def _centre(browser: Browser, element: str) -> tuple[float, float, float]:
    """The element's centre on the page and its width."""
    box = browser.evaluate(f"(() => {{ const r = document.getElementById({element!r}).getBoundingClientRect();"
                           " return [r.left + r.width / 2, r.top + r.height / 2, r.width]; })()")
    return box[0], box[1], box[2]


def _click(browser: Browser, x: float, y: float) -> None:
    browser.mouse("mousePressed", x, y, button="left", clickCount=1)
    browser.mouse("mouseReleased", x, y, button="left", clickCount=1)


def test_the_slider_keys_play_and_mouse_drive_the_page(pocket_page: Path, tmp_path: Path) -> None:
    """Real mouse and key events: the slider's readout is the run's move (line, tool, position),
    the arrow keys step, play advances, a drag turns the view and the wheel zooms; nothing is logged."""
    path = record_job(ROOT / "examples/pocket.nc")
    with Browser(CHROMIUM, pocket_page.resolve().as_uri(), tmp_path / "profile", WINDOW) as browser:
        assert browser.evaluate("document.getElementById('status').dataset.ready") == "1"
        x, y, width = _centre(browser, "slider")
        for fraction in (0.05, 0.5, 0.95):  # click on the slider's track, as a person does
            _click(browser, x - width / 2 + fraction * width, y)
            shown = _readout(browser)
            number = int(shown["move"].split()[0])
            assert abs(number - fraction * len(path)) < 0.05 * len(path), shown
            move = number - 1
            assert shown["source"] == f"pocket.nc:{path.lines[move]}"
            assert shown["tool"] == f"T{path.tools[move]}"
            for k, axis in enumerate("XYZ"):
                assert float(shown[axis]) == pytest.approx(path.ends[move, k], abs=1e-3), (axis, shown)
            assert _text(browser, "counter") == f"move {number} of {len(path)}"
            current = browser.evaluate("document.querySelector('#listing li.current .n').innerText")
            assert current == str(path.lines[move])  # the program listing highlights the move's line
        browser.key("ArrowLeft", "ArrowLeft", 37)
        assert int(_readout(browser)["move"].split()[0]) == number - 1
        browser.key("Home", "Home", 36)
        assert _text(browser, "counter") == f"move 1 of {len(path)}"

        play_x, play_y, _ = _centre(browser, "play")
        _click(browser, play_x, play_y)
        assert _text(browser, "play") == "pause"
        advanced = browser.evaluate("new Promise(done => { const start = document.getElementById('counter')"
                                    ".innerText; const look = () => document.getElementById('counter').innerText"
                                    " !== start ? done(true) : requestAnimationFrame(look); look(); })")
        assert advanced  # the player moved on (waits as long as the browser needs, no clock in the test)
        _click(browser, play_x, play_y)
        assert _text(browser, "play") == "play"

        cx, cy, _ = _centre(browser, "view")
        before = _canvas(browser)
        browser.mouse("mousePressed", cx, cy, button="left", clickCount=1)
        browser.mouse("mouseMoved", cx + 80, cy + 30, button="left", buttons=1)
        browser.mouse("mouseReleased", cx + 80, cy + 30, button="left", clickCount=1)
        turned = _canvas(browser)
        assert turned != before, "a drag did not turn the view"
        assert browser.evaluate("document.querySelectorAll('[data-view].active').length") == 0
        browser.mouse("mouseWheel", cx, cy, deltaX=0, deltaY=-300)
        assert browser.evaluate("new Promise(done => requestAnimationFrame(() => done(1)))") == 1
        assert _canvas(browser) != turned, "the wheel did not zoom"
        browser.key("t", "KeyT", 84)
        assert browser.evaluate("document.querySelector('[data-view].active').dataset.view") == "top"

        assert browser.logged() == []
        assert browser.evaluate("document.getElementById('status').dataset.errors") == "0"


def test_the_devtools_client_does_see_what_a_page_logs(tmp_path: Path) -> None:
    """The check above can fail: a page that logs and throws is caught."""
    page = tmp_path / "noisy.html"
    page.write_text("<html><body><script>console.error('boom'); missing();</script></body></html>")
    with Browser(CHROMIUM, page.resolve().as_uri(), tmp_path / "profile") as browser:
        logged = browser.logged()
    assert any("boom" in line for line in logged) and any("missing" in line for line in logged), logged


def test_the_iso_view_shows_the_whole_part_box(tmp_path: Path) -> None:
    """The page fits the part's box too: an L cut's box corner at X0 Y100, left of the path when
    seen iso, is on the screen (the box's grey does not run into the canvas' left edge; rows above the
    axis triad and the hint)."""
    imread = pytest.importorskip("matplotlib.image").imread
    job = tmp_path / "ell.nc"
    job.write_text("G21 G90\nG0 X0 Y0 Z5\nG1 Z-1 F300\nG1 X100\nY100\nG0 Z5\nM30\n")
    page = write_view(record_job(job), tmp_path / "ell.html")
    shot = tmp_path / "ell.png"
    chromium(page, tmp_path / "profile", f"--screenshot={shot}", fragment="#view=iso")
    image = imread(shot)[:, :, :3]
    canvas = image[100:650, :900, :]
    grey = (np.ptp(canvas, axis=2) < 0.06) & (canvas.mean(axis=2) < 0.85)  # grey ink: the box's dots
    cols = np.nonzero(grey.any(axis=0))[0]
    assert len(cols) > 0, "the part box is not drawn"
    assert cols.min() > 20, f"the part box runs off the left of the canvas (grey from column {cols.min()})"


def _ink(browser: Browser, colour: str) -> tuple[int, float, float]:
    """How many canvas pixels have ``colour`` (#rrggbb), and their centroid."""
    import base64
    import io

    imread = pytest.importorskip("matplotlib.image").imread
    url = _canvas(browser)
    image = imread(io.BytesIO(base64.b64decode(url.split(",", 1)[1])), format="png")[:, :, :3]
    target = np.array([int(colour[i:i + 2], 16) / 255 for i in (1, 3, 5)])
    rows, cols = np.nonzero(np.linalg.norm(image - target, axis=2) < 0.15)
    return len(rows), float(cols.mean()) if len(cols) else -1.0, float(rows.mean()) if len(rows) else -1.0


def test_a_drag_turns_the_view_about_the_parts_centre(tmp_path: Path) -> None:
    """A part far from zero (X500..600, Y400..480) stays where it is on the canvas while a drag turns
    the view: the turn is about the part's centre, not about X0 Y0 Z0."""
    job = tmp_path / "far.nc"
    job.write_text("G21 G90\nT1 M6\nG0 X500 Y400 Z5\nG1 Z-2 F500\nG1 X600\nY480\nX500\nY400\nG0 Z5\nM30\n")
    page = write_view(record_job(job), tmp_path / "far.html")
    colour = views.TOOL_COLORS[0]
    with Browser(CHROMIUM, page.resolve().as_uri() + "#view=top", tmp_path / "profile", WINDOW) as browser:
        assert browser.evaluate("document.getElementById('status').dataset.ready") == "1"
        count, x, y = _ink(browser, colour)
        assert count > 200, "the part is not drawn"
        cx, cy, _ = _centre(browser, "view")
        for step in range(1, 6):  # a long drag: about 1.5 radians of turn and some tilt
            browser.mouse("mouseMoved" if step > 1 else "mousePressed", cx + 30 * step, cy + 8 * step,
                          button="left", buttons=1, clickCount=1)
        browser.mouse("mouseReleased", cx + 150, cy + 40, button="left", clickCount=1)
        turned, tx, ty = _ink(browser, colour)
        assert turned > 100, "the part left the canvas when the view turned"
        width = browser.evaluate("document.getElementById('view').width")
        assert abs(tx - x) < 0.05 * width and abs(ty - y) < 0.05 * width, ((x, y), (tx, ty))
        assert browser.logged() == []
