"""What a lathe user sees is in the coordinates they program (issue 36, item 4): MDI, the
debugger's variables, and the picture and viewer of a turning job (a half section in work
coordinates, X read as a diameter); ``plot --joints`` keeps the machine's view."""
from __future__ import annotations

import json
from pathlib import Path

import numpy as np
import pytest

from edingcnc_lang import RunOptions
from edingcnc_lang.mdi import MdiSession
from edingcnc_lang.plot.lathe import in_work
from edingcnc_lang.plot.toolpath import record_job
from edingcnc_lang.plot.views import auto_view, size_text
from tests.cli_runner import invoke

EXAMPLE = Path(__file__).resolve().parents[2] / "examples" / "lathe"
INI = EXAMPLE / "cnc.ini"
TWO_TOOLS = "T1 M6\nG0 X60 Z2\nG1 Z-10 F100\nG0 X70 Z5\nT2 M6\nG0 X50 Z2\nG1 Z-20\nG0 X70\nM30\n"


def test_mdi_shows_work_x_as_a_diameter() -> None:
    session = MdiSession(RunOptions(ini=INI, macro=EXAMPLE / "macro.cnc"))
    outcome = session.execute("G0 X20 Z2")
    assert outcome.position[0] == pytest.approx(20.0) and session.execute("#5001").value == pytest.approx(20.0)
    assert outcome.machine[0] == pytest.approx(24.0 + 10.0)  # G54 X 24 (radius), no tool offset in force
    session.close()


def test_the_part_view_puts_every_tool_on_the_diameters_programmed(tmp_path: Path) -> None:
    """T1 and T2 have other X and Z offsets: in machine coordinates their cuts lie apart, in the part
    view each at the radius of its diameter, Z from the work zero."""
    job = tmp_path / "job.nc"
    job.write_text(TWO_TOOLS)
    path = record_job(job, RunOptions(ini=INI, macro=EXAMPLE / "macro.cnc"))
    part = in_work(path)
    cuts = np.flatnonzero(part.kinds == 1)
    assert [tuple(np.round(part.ends[i, [0, 2]], 6)) for i in cuts] == [(30.0, -10.0), (25.0, -20.0)]
    machine_x = {round(float(path.ends[i, 0]), 6) for i in cuts}
    assert machine_x == {24 + 30 + 0.03 / 2, 24 + 25 - 21.44 / 2}  # each tool's own offset: a diameter value
    assert part.part and part.x_diameter and part.work_zero == (0.0, 0.0, 0.0) and auto_view(part) == "lathe"
    bounds = part.bounds()
    assert bounds is not None and size_text(*bounds, view="lathe", diameter=True) == "Z 22.00 x diameter 60.00 mm"


def test_plot_and_view_of_a_turning_job(tmp_path: Path) -> None:
    job = tmp_path / "job.nc"
    job.write_text(TWO_TOOLS)
    for args in ([], ["--joints"]):
        result = invoke("plot", "--ini", INI, "--macro", EXAMPLE / "macro.cnc", job, "-o", tmp_path / "p.png", *args)
        assert result.exit_code == 0, result.stderr
    result = invoke("view", "--ini", INI, "--macro", EXAMPLE / "macro.cnc", job, "-o", tmp_path / "v.html")
    assert result.exit_code == 0, result.stderr
    page = (tmp_path / "v.html").read_text()
    data = json.loads(page.split('id="job-data">', 1)[1].split("</script>", 1)[0])
    assert data["xDiameter"] is True and data["view"] == "lathe"


def test_a_mills_path_keeps_machine_coordinates(tmp_path: Path) -> None:
    job = tmp_path / "job.nc"
    job.write_text("G0 X10 Y5\nG1 Z-1 F100\n")
    path = record_job(job, RunOptions())
    assert path.offsets is None and in_work(path) is path


def test_the_debugger_shows_work_x_as_a_diameter_and_the_g43_x_offset(tmp_path: Path) -> None:
    from edingcnc_lang.debug.variables import _modal, _position
    from edingcnc_lang.runner import Run

    job = tmp_path / "job.nc"
    job.write_text("T2 M6\nG0 X30 Z5\n")
    run = Run(RunOptions(ini=INI, macro=EXAMPLE / "macro.cnc"))
    run.execute_file(job)
    position = {v["name"]: v["value"] for v in _position(run)}
    modal = {v["name"]: v["value"] for v in _modal(run)}
    assert position["work X"] == "30" and modal["G43 X offset (radius)"] == "-10.72"


def test_the_picture_knows_the_tool_the_ini_left_in_the_turret(tmp_path: Path) -> None:
    job = tmp_path / "job.nc"
    job.write_text("G0 X20 Z2\nG1 Z-5 F100\n")
    path = record_job(job, RunOptions(ini=INI, macro=EXAMPLE / "macro.cnc"))
    assert set(path.tools.tolist()) == {3}   # [VARIABLES] #5008 = 3


def test_ecnc_test_boxes_read_x_as_the_program_does(tmp_path: Path) -> None:
    """A turning test's forbid.outside box is written in the program's coordinates: X a diameter."""
    from edingcnc_lang.testing.checks import failures
    from edingcnc_lang.testing.execute import run_case
    from edingcnc_lang.testing.spec import from_mapping

    keys = {"ini": str(INI), "macro": str(EXAMPLE / "macro.cnc"), "job": "G0 X40 Z2\nG0 X64 Z2\nM30\n",
            "forbid": {"outside": [0, -1, -50, 62, 1, 5]}}
    assert failures(run_case(from_mapping(keys, tmp_path))) == [
        "forbid.outside: the rapid move at <job>:2 reaches work X64 Y0 Z2, outside the box"]
