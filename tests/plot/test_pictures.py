"""Picture tests that look at the PNG as a person would: is the path drawn where it should be?

Each test reads the written image back and finds the path's colour at the pixels where
``Picture.to_pixels`` says the contour lies, and nowhere outside the part's box.
"""
from __future__ import annotations

import re
import sys
from pathlib import Path

import click
import numpy as np
import pytest

pytest.importorskip("matplotlib")

from matplotlib.image import imread  # noqa: E402

from edingcnc_lang import RunOptions  # noqa: E402
from edingcnc_lang.errors import EcncError, MissingExtra  # noqa: E402
from edingcnc_lang.plot import views  # noqa: E402
from edingcnc_lang.plot.joints import plot_joints  # noqa: E402
from edingcnc_lang.picture_formats import require_matplotlib  # noqa: E402
from edingcnc_lang.plot.render import plot_toolpath  # noqa: E402
from edingcnc_lang.plot.toolpath import record_job  # noqa: E402
from tests.plot.jobs import CIRCLE, SQUARE, TWO_TOOLS, write  # noqa: E402

pytestmark = pytest.mark.slow  # the whole module (pyproject's slow marker)

ROOT = Path(__file__).resolve().parents[2]


def rgb(hex_color: str) -> np.ndarray:
    return np.array([int(hex_color[i:i + 2], 16) for i in (1, 3, 5)], dtype=float) / 255.0


def matches(image: np.ndarray, color: str, tolerance: float = 0.2) -> np.ndarray:
    """Pixels within ``tolerance`` (RGB distance, 0..1 scale) of ``color``."""
    return np.linalg.norm(image[:, :, :3] - rgb(color), axis=2) < tolerance


def near(mask: np.ndarray, pixel: np.ndarray, reach: int = 2) -> bool:
    col, row = (int(round(v)) for v in pixel)
    return bool(mask[max(row - reach, 0):row + reach + 1, max(col - reach, 0):col + reach + 1].any())


def contour(corners: list[tuple[float, float]], z: float, step: float = 1.0) -> np.ndarray:
    points = []
    for (x0, y0), (x1, y1) in zip(corners, corners[1:]):
        count = int(max(abs(x1 - x0), abs(y1 - y0)) / step)
        for k in range(count):
            points.append((x0 + (x1 - x0) * k / count, y0 + (y1 - y0) * k / count, z))
    return np.array(points)


@pytest.fixture
def square(tmp_path: Path):
    return record_job(write(tmp_path, "square.nc", SQUARE, newline="\r\n"))


def test_the_square_is_drawn_along_its_contour_and_nowhere_else(square, tmp_path: Path) -> None:
    picture = plot_toolpath(square, tmp_path / "square.png", view="top")
    image = imread(picture.path)
    assert image.shape[:2] == (picture.height, picture.width)
    feed = matches(image, views.tool_color(views.feed_tools(square), 1))
    pixels = picture.to_pixels(contour([(10, 10), (60, 10), (60, 60), (10, 60), (10, 10)], -1.0))
    missing = [tuple(p) for p in pixels if not near(feed, p)]
    assert not missing, f"{len(missing)} of {len(pixels)} contour points not drawn, first {missing[:3]}"
    (left, top), (right, bottom) = picture.to_pixels([[10, 60, 0], [60, 10, 0]])
    rows, cols = np.nonzero(feed)
    a_left, a_top, a_right, a_bottom = picture.axes
    inside_axes = (cols >= a_left) & (cols <= a_right) & (rows >= a_top) & (rows <= a_bottom)
    reach = 5  # half the line width and the ring that marks the plunge at the corner
    outside = inside_axes & ((cols < left - reach) | (cols > right + reach)
                             | (rows < top - reach) | (rows > bottom + reach))
    assert not outside.any(), f"{outside.sum()} path pixels outside the square's box"
    middle = picture.to_pixels([[35, 35, 0]])[0]
    assert not near(feed, middle, reach=5), "the inside of the square is empty"


def test_a_circle_is_drawn_as_a_circle_and_a_rapid_dashed(tmp_path: Path) -> None:
    path = record_job(write(tmp_path, "circle.nc", CIRCLE))
    picture = plot_toolpath(path, tmp_path / "circle.png", view="top")
    image = imread(picture.path)
    feed = matches(image, views.TOOL_COLORS[0])  # T3, the only tool that cuts: the first colour
    angles = np.linspace(0.0, 2 * np.pi, 90, endpoint=False)
    ring = np.column_stack((40 + 30 * np.cos(angles), 40 + 30 * np.sin(angles), np.zeros_like(angles)))
    assert all(near(feed, p) for p in picture.to_pixels(ring))
    # the polygon between the samples would cut corners; half way between two 3-degree chords it does not show
    chord_middles = np.column_stack((40 + 29.0 * np.cos(angles), 40 + 29.0 * np.sin(angles), np.zeros_like(angles)))
    assert sum(near(feed, p, reach=0) for p in picture.to_pixels(chord_middles)) < 10
    # the rapid from (70, 40) to the work zero: dashes, so some of its pixels are drawn and some are not
    inked = image[:, :, :3].mean(axis=2) < 0.8  # darker than the grid
    x = np.linspace(10, 30, 400)  # clear of the circle
    hits = [near(inked, p, reach=0) for p in picture.to_pixels(np.column_stack((x, x * 40 / 70, np.zeros_like(x))))]
    gaps = sum(1 for a, b in zip(hits, hits[1:]) if a and not b)
    assert 0.3 < sum(hits) / len(hits) < 0.95 and gaps >= 5, (sum(hits), gaps)


def test_each_view_puts_the_depth_where_it_belongs(square, tmp_path: Path) -> None:
    front = plot_toolpath(square, tmp_path / "front.png", view="front")
    (x0, z_top), (_x1, z_cut) = front.to_pixels([[10, 10, 5], [10, 10, -1]])
    assert z_top < z_cut  # Z up: the retract height is above the cut on the page
    side = plot_toolpath(square, tmp_path / "side.png", view="side")
    (y_low, _), (y_high, _) = side.to_pixels([[0, 10, 0], [0, 60, 0]])
    assert y_low < y_high  # seen from +X, Y grows to the right
    iso = plot_toolpath(square, tmp_path / "iso.png", view="iso")
    image = imread(iso.path)
    feed = matches(image, views.TOOL_COLORS[0])
    assert all(near(feed, p) for p in iso.to_pixels(contour([(10, 10), (60, 10), (60, 60)], -1.0, step=5.0)))


def test_colour_by_tool_gives_each_tool_its_colour(tmp_path: Path) -> None:
    path = record_job(write(tmp_path, "two.nc", TWO_TOOLS))
    picture = plot_toolpath(path, tmp_path / "two.png", view="top")
    image = imread(picture.path)
    assert views.feed_tools(path) == [1, 2]
    first, second = views.tool_color([1, 2], 1), views.tool_color([1, 2], 2)
    assert first != second
    assert near(matches(image, first), picture.to_pixels([[10, 0, 0]])[0])
    assert near(matches(image, second), picture.to_pixels([[40, 10, 0]])[0])
    assert not near(matches(image, first), picture.to_pixels([[40, 10, 0]])[0])


@pytest.mark.parametrize("mode", ["kind", "feed"])
def test_other_colour_modes_draw_the_same_contour(square, tmp_path: Path, mode: str) -> None:
    picture = plot_toolpath(square, tmp_path / f"{mode}.png", view="top", color=mode)
    image = imread(picture.path)
    background = np.all(image[:, :, :3] > 0.97, axis=2)
    pixels = picture.to_pixels(contour([(10, 10), (60, 10), (60, 60)], -1.0, step=5.0))
    assert all(near(~background, p, reach=1) for p in pixels)


def test_colour_by_planned_speed_shows_slow_corners_and_fast_runs(tmp_path: Path) -> None:
    """A long run reaches the programmed feed; a zigzag of 1 mm steps on a machine accelerating at
    1500 mm/s^2 never does: they get the two ends of the scale."""
    job = write(tmp_path, "speeds.nc", "G21 G90 G61\nT1 M6\nG0 X10 Y10 Z-5\nG1 Z-10 F300\nG1 X200 F6000\n"
                                       + "".join(f"G1 X{200 + k + 1} Y{10 + (k + 1) % 2}\n" for k in range(10))
                                       + "G0 Z-5\nM30\n")
    path = record_job(job, RunOptions(ini=ROOT / "examples/estimate/cnc.ini"))
    long_run = int(np.flatnonzero(path.lines == 5)[0])
    zigzag = np.flatnonzero((path.lines > 5) & (path.lines < 16))
    assert path.speeds[long_run] > 1.5 * path.speeds[zigzag].max()
    assert path.speeds[long_run] <= 6000.0 + 1e-6
    picture = plot_toolpath(path, tmp_path / "speed.png", view="top", color="speed")
    image = imread(picture.path)
    fast, slow = image_colour(image, picture, [100, 10, -1]), image_colour(image, picture, [205.5, 10.5, -1])
    assert np.linalg.norm(fast - slow) > 0.3  # far apart on the colour scale


def image_colour(image: np.ndarray, picture, point: list[float]) -> np.ndarray:
    """The most saturated pixel near where ``point`` lands (the line's own colour, not its antialiased edge)."""
    col, row = (int(round(v)) for v in picture.to_pixels([point])[0])
    patch = image[row - 2:row + 3, col - 2:col + 3, :3].reshape(-1, 3)
    return patch[np.argmax(patch.max(axis=1) - patch.min(axis=1))]


@pytest.mark.parametrize("suffix, magic", [(".svg", b"<?xml"), (".pdf", b"%PDF"), (".PNG", b"\x89PNG")])
def test_the_format_follows_the_extension(square, tmp_path: Path, suffix: str, magic: bytes) -> None:
    out = plot_toolpath(square, tmp_path / f"square{suffix}").path
    assert out.read_bytes().startswith(magic)


def test_an_unknown_extension_is_a_plain_error(square, tmp_path: Path) -> None:
    with pytest.raises(EcncError, match=r"one of \.png, \.svg, \.pdf \(not \.jpg\)"):
        plot_toolpath(square, tmp_path / "square.jpg")


def test_without_matplotlib_the_message_says_how_to_install_it(monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setitem(sys.modules, "matplotlib", None)  # what an import finds when it is not installed
    with pytest.raises(MissingExtra, match=r"pip install 'edingcnc-lang\[plot\]'") as caught:
        require_matplotlib()
    assert caught.value.exit_code == 2


def test_title_names_the_job_its_tools_and_a_stop(tmp_path: Path) -> None:
    path = record_job(write(tmp_path, "two.nc", TWO_TOOLS + "errmsg \"late\"\n"))
    assert views.title_text(path).startswith("two.nc")
    assert "T1, T2" in views.title_text(path)
    assert "about " in views.title_text(path) and path.seconds > 0  # the planner's estimate
    path.seconds = 4325.0
    assert "1 h 12 min 5 s" in views.title_text(path)


def test_joint_plot_of_a_delta_shows_curved_carriage_paths(tmp_path: Path) -> None:
    """The delta's straight moves are curves for the carriages: the plotted joint 0 is not
    piecewise linear in time while the effector draws its circle."""
    path = record_job(ROOT / "examples/delta/job.nc", RunOptions(ini=ROOT / "examples/delta/cnc.ini"), samples=True)
    out = plot_joints(path, tmp_path / "joints.png")
    image = imread(out)
    assert image.shape[0] > 300 and (image[:, :, :3] < 0.9).any()
    jx = path.samples["jx"]
    assert np.ptp(jx) > 100 and np.abs(np.diff(jx, 2)).max() > 1e-3


def test_a_lathe_job_is_seen_in_its_turning_plane(tmp_path: Path) -> None:
    job = write(tmp_path, "turn.nc", "G18 G21 G90\nT1 M6\nG0 X20 Z2\nG1 Z-30 F150\nG1 X25\nG0 Z2\nM30\n")
    path = record_job(job)
    assert views.auto_view(path) == "lathe"
    picture = plot_toolpath(path, tmp_path / "turn.png")
    assert picture.view == "lathe"
    (z_right, x_low), (z_left, x_high) = picture.to_pixels([[20, 0, 2], [25, 0, -30]])
    assert z_left < z_right and x_high < x_low  # Z runs across (towards the chuck on the left), X up
    image = imread(picture.path)
    feed = matches(image, views.TOOL_COLORS[0])
    assert all(near(feed, p) for p in picture.to_pixels([[20, 0, z] for z in range(-29, 1, 3)]))


def test_fit_machine_shows_the_travel_from_the_ini(tmp_path: Path) -> None:
    path = record_job(ROOT / "examples/delta/job.nc", RunOptions(ini=ROOT / "examples/delta/cnc.ini"))
    picture = plot_toolpath(path, tmp_path / "travel.png", view="top", fit="machine")
    image = imread(picture.path)
    limit = matches(image, "#b22222")
    left, top, right, bottom = picture.axes
    for corner in picture.to_pixels([[-400, -400, 0], [400, 400, 0], [-400, 400, 0], [400, -400, 0]]):
        assert left <= corner[0] <= right and top <= corner[1] <= bottom  # the whole box is in view
    edge = picture.to_pixels([[x, -400, 0] for x in range(-350, 351, 10)])
    assert sum(near(limit, p, reach=1) for p in edge) > len(edge) // 2  # dash-dotted: mostly drawn
    job_only = plot_toolpath(path, tmp_path / "job.png", view="top")
    assert job_only.to_pixels([[-400, -400, 0]])[0][0] < job_only.axes[0]  # fitted to the job, the box is outside


def test_fit_part_cuts_off_far_rapids(tmp_path: Path) -> None:
    job = write(tmp_path, "far.nc", "G21 G90\nG0 X500 Y500 Z100\nT1 M6\nG0 X10 Y10 Z2\nG1 Z-1 F100\n"
                                    "G1 X30\nY30\nG0 Z100\nG0 X500 Y500\nM30\n")
    path = record_job(job)
    whole = plot_toolpath(path, tmp_path / "whole.png", view="top")
    part = plot_toolpath(path, tmp_path / "part.png", view="top", fit="part")
    (x0, _), (x1, _) = part.to_pixels([[10, 10, 0], [30, 10, 0]])
    (w0, _), (w1, _) = whole.to_pixels([[10, 10, 0], [30, 10, 0]])
    assert (x1 - x0) > 10 * (w1 - w0)  # the 20 mm cut fills the picture instead of a corner of it
    assert part.to_pixels([[500, 500, 0]])[0][0] > part.axes[2]  # the tool change position is off the picture


def test_the_title_gives_the_estimate_as_the_run_summary_does(square) -> None:
    from edingcnc_lang.motion.planner.estimate import format_duration

    assert 0 < square.seconds < 59.0
    title = views.title_text(square)
    assert f"about {format_duration(square.seconds)}" in title and re.search(r"about \d+\.\d s", title)


def test_the_commands_offer_exactly_the_views_and_colours_there_are() -> None:
    from edingcnc_lang.cli.plot_cmd import plot
    from edingcnc_lang.cli.view_cmd import view
    from edingcnc_lang.plot.names import COLOR_MODES, VIEW_NAMES

    choices = {(command.name, p.name): tuple(p.type.choices) for command in (plot, view) for p in command.params
               if isinstance(p.type, click.Choice) and p.name in ("view", "color")}
    assert choices[("plot", "view")] == choices[("view", "view")] == ("auto", *views.VIEWS) == ("auto", *VIEW_NAMES)
    assert choices[("plot", "color")] == COLOR_MODES


@pytest.mark.parametrize("corner", ["right top", "left bottom"])
def test_the_part_size_is_written_inside_the_drawing(tmp_path: Path, corner: str) -> None:
    """The size label stays in the drawing area, off the legend, wherever the part sits: a square
    at the top right of the job (right of the legend's side) or at its bottom left."""
    x, y = (300, 200) if corner == "right top" else (-300, -200)
    job = write(tmp_path, "far.nc", f"G21 G90\nG0 X0 Y0 Z5\nG0 X{x} Y{y}\nG1 Z-1 F300\n"
                                    f"G1 X{x + 40}\nY{y + 40}\nX{x}\nY{y}\nG0 Z5\nM30\n")
    picture = plot_toolpath(record_job(job), tmp_path / "far.png", view="top")
    assert picture.part_label is not None
    left, top, right, bottom = picture.part_label
    a_left, a_top, a_right, a_bottom = picture.axes
    assert a_left <= left < right <= a_right and a_top <= top < bottom <= a_bottom, (picture.part_label, picture.axes)


def test_a_lathe_part_is_sized_in_its_turning_plane() -> None:
    """A lathe has no Y: the label gives Z across, then X, as the lathe view shows them."""
    lower, upper = np.array([0.0, 0.0, -120.0]), np.array([7.0, 0.0, 2.0])
    assert views.size_text(lower, upper, view="lathe") == "Z 122.00 x X 7.00 mm"
    assert views.size_text(lower, upper) == "X 7.00 x Y 0.00 x Z 122.00 mm"


def test_a_picture_that_cannot_be_written_is_a_plain_error(square, tmp_path: Path,
                                                           monkeypatch: pytest.MonkeyPatch) -> None:
    """A full disk or a denied folder: the message names the file, no traceback."""
    import errno

    from matplotlib.figure import Figure

    def full(*args: object, **kwargs: object) -> None:
        raise OSError(errno.ENOSPC, "No space left on device")

    monkeypatch.setattr(Figure, "savefig", full)
    with pytest.raises(EcncError, match="cannot write .*square.png: No space left on device"):
        plot_toolpath(square, tmp_path / "square.png")


def test_the_iso_view_writes_the_part_size_at_the_box_top_corner(square, tmp_path: Path) -> None:
    """In the iso view the box's top-left corner on paper is no corner of the box: the size is
    written at the box's top vertex (its X, Y and Z maxima), not out in the empty page."""
    picture = plot_toolpath(square, tmp_path / "iso.png", view="iso")
    lower, upper = square.bounds()
    col, row = picture.to_pixels([upper])[0]
    left, top, right, bottom = picture.part_label
    assert abs(left - col) <= 3 and 0 <= row - bottom <= 10, (picture.part_label, (col, row))


def test_the_iso_view_fits_the_part_box_whose_corner_lies_beside_the_path(tmp_path: Path) -> None:
    """An L cut (along X, then along Y): the box's corner at X0 Y100 is no point of the path and,
    seen iso, lies far left of it; the picture still shows the whole box."""
    job = write(tmp_path, "ell.nc", "G21 G90\nG0 X0 Y0 Z5\nG1 Z-1 F300\nG1 X100\nY100\nG0 Z5\nM30\n")
    path = record_job(job)
    picture = plot_toolpath(path, tmp_path / "ell.png", view="iso")
    lower, upper = path.bounds()
    corners = [[(lower, upper)[(k >> a) & 1][a] for a in range(3)] for k in range(8)]
    a_left, a_top, a_right, a_bottom = picture.axes
    for col, row in picture.to_pixels(corners):
        assert a_left < col < a_right and a_top < row < a_bottom, (col, row, picture.axes)
