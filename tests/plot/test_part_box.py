"""Issue 21 item 8: the part box (``--fit part``, the size label, the viewer) leaves out measuring moves."""
from __future__ import annotations

from pathlib import Path

import numpy as np

from edingcnc_lang import RunOptions
from edingcnc_lang.plot.toolpath import record_job
from tests.plot.jobs import write

# A tool change that measures the tool on a setter at X470 Y160 (the shape of Eding's own
# change_tool), and a probing sub that touches off the stock's corner.
MACRO = """\
Sub change_tool
    G53 G0 Z0
    G53 G0 X470 Y160
    G38.2 G91 Z-80 F200
    G90 G1 Z-2 F50
    G38.2 G91 Z-5 F20
    G90 G53 G0 Z0
EndSub
"""
JOB = """\
G21 G90 G17
T1 M6
GoSub touch_corner
G0 X0 Y0 Z5
G1 Z-1 F300
G1 X80 F1000
Y50
X0
Y0
G0 Z5
M30
Sub touch_corner
    G0 X-20 Y-20 Z5
    G38.2 Z-30 F100
    G1 Z5 F500
    G1 X-40
EndSub
"""


def test_the_part_is_the_80_by_50_cut_not_the_tool_setter(tmp_path: Path) -> None:
    macro = write(tmp_path, "macro.cnc", MACRO)
    path = record_job(write(tmp_path, "job.nc", JOB), RunOptions(macro=macro))
    lower, upper = path.bounds()
    assert np.allclose((upper - lower)[:2], [80.0, 50.0]), (lower, upper)
    whole_lower, whole_upper = path.bounds(feed_only=False)
    assert whole_upper[0] == 470.0 and whole_lower[0] == -40.0  # the whole path still has them


def test_the_size_label_says_80_by_50(tmp_path: Path) -> None:
    from edingcnc_lang.plot.render import plot_toolpath

    macro = write(tmp_path, "macro.cnc", MACRO)
    path = record_job(write(tmp_path, "job.nc", JOB), RunOptions(macro=macro))
    picture = plot_toolpath(path, tmp_path / "part.svg", view="top", fit="part")
    assert "X 80.00 x Y 50.00 x Z 6.00 mm" in (tmp_path / "part.svg").read_text()
    assert picture.to_pixels([[470, 160, 0]])[0][0] > picture.axes[2]  # the setter is off the fitted picture


def test_a_job_of_probing_only_still_has_a_box(tmp_path: Path) -> None:
    path = record_job(write(tmp_path, "probe.nc", "G0 X5 Y5 Z5\nG38.2 Z-10 F100\nG0 Z5\n"))
    lower, upper = path.bounds()
    assert lower[2] < 5.0 and upper[2] == 5.0
