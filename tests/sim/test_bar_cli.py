"""``ecnc sim --bar`` as a lathe owner runs it: the JSON's keys, the picture and STL, the findings'
exit code, usage errors (exit 2) for bad values and combinations, a tools file's insert."""
from __future__ import annotations

import json
import math
from pathlib import Path

import pytest

from tests.cli_runner import invoke

from .test_round_stock import LATHE_INI

TOOLS = '[tool.3]\nshape = "insert"\nnose_radius = 0\norientation = 0\n'
TURN = "G18 G21 G90 G40\nG97 S1000 M3\nG0 X42 Z2\nG1 X30 F100\nG1 Z-20\nG1 X42\nG0 Z2\nM30\n"


@pytest.fixture
def job(tmp_path: Path) -> Path:
    (tmp_path / "tools.toml").write_text(TOOLS)
    path = tmp_path / "turn.nc"
    path.write_text(TURN)
    return path


def test_json_has_the_box_sim_s_keys(job: Path) -> None:
    result = invoke("sim", job, "--ini", LATHE_INI, "--bar", "40,50", "--chuck", "10", "--resolution", "0.1",
                    "--tools", job.parent / "tools.toml", "--json")
    assert result.exit_code == 0, result.output
    doc = json.loads(result.stdout)
    assert doc["stock"]["bar"] == [40, 50, 0] and doc["stock"]["chuck"] == -40
    assert doc["stock"]["removed_volume"] == pytest.approx(math.pi * 175 * 20, rel=1e-6)
    assert doc["stock"]["removed_volume"] + doc["stock"]["remaining_volume"] == pytest.approx(math.pi * 400 * 50)
    assert doc["collisions"] == [] and doc["tools"]["3"]["shape"] == "insert"


def test_a_rapid_into_the_bar_exits_1_at_its_line(job: Path) -> None:
    job.write_text(TURN.replace("G1 Z-20", "G0 Z-20"))
    result = invoke("sim", job, "--ini", LATHE_INI, "--bar", "40,50", "--json")
    assert result.exit_code == 1
    (hit,) = json.loads(result.stdout)["collisions"]
    assert (hit["kind"], hit["line"]) == ("rapid_into_stock", 5)


@pytest.mark.slow
def test_picture_and_stl(job: Path) -> None:
    pytest.importorskip("matplotlib")
    from matplotlib.image import imread

    picture, mesh = job.parent / "bar.png", job.parent / "bar.stl"
    result = invoke("sim", job, "--ini", LATHE_INI, "--bar", "40,50", "-o", picture, "--stl", mesh)
    assert result.exit_code == 0, result.output
    assert imread(picture).shape[2] in (3, 4) and mesh.stat().st_size > 84


@pytest.mark.parametrize(("args", "message"), [
    (["--bar", "40"], "is not DIAMETER,LENGTH[,Z0]"),
    (["--bar", "40,-5"], "must be above 0"),
    (["--bar", "40,x"], "is not DIAMETER,LENGTH[,Z0]"),
    (["--bar", "40,50", "--chuck", "0"], "--chuck"),
    (["--bar", "40,50", "--chuck", "60"], "grips the whole bar"),
    (["--chuck", "5"], "--chuck LENGTH goes with --bar"),
    (["--bar", "40,50", "--stock", "0,0,-1,1,1,0"], "exactly one of --stock, --stock-stl and --bar"),
    (["--bar", "40,50", "--stl", "turn.nc"], "turn.nc"),
])
def test_usage_errors_exit_2(job: Path, args: list[str], message: str, monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.chdir(job.parent)
    result = invoke("sim", job, "--ini", LATHE_INI, *args)
    assert result.exit_code == 2, result.output
    assert message in result.stderr


def test_a_mill_ini_is_told_to_use_a_lathe(job: Path) -> None:
    result = invoke("sim", job, "--bar", "40,50")
    assert result.exit_code == 2 and "a bar turns on a lathe" in result.stderr


@pytest.mark.parametrize(("text", "message"), [
    ('[tool.1]\nshape = "insert"\nnose_radius = -1\n', "nose_radius must be 0"),
    ('[tool.1]\nshape = "insert"\norientation = 12\n', "orientation must be a whole number from 0 to 9"),
    ('[tool.1]\nshape = "flat"\ndiameter = 6\norientation = 2\n', "are for shape = \"insert\""),
])
def test_bad_insert_names_the_file(job: Path, text: str, message: str) -> None:
    bad = job.parent / "t.toml"
    bad.write_text(text)
    result = invoke("sim", job, "--ini", LATHE_INI, "--bar", "40,50", "--tools", bad)
    assert result.exit_code == 2 and f"{bad}: error:" in result.stderr and message in result.stderr


def test_the_examples_simulate_clean() -> None:
    """examples/round as docs/simulation.md runs them: no finding, material removed."""
    root = LATHE_INI.parents[1]
    bar = invoke("sim", root / "round" / "bar.nc", "--ini", LATHE_INI, "--bar", "40,80,1", "--chuck", "25",
                 "--tools", root / "round" / "bar-tools.toml", "--json")
    rotary = invoke("sim", root / "round" / "rotary.nc", "--ini", root / "cylinder" / "cnc.ini",
                    "--stock", "cylinder:40,100,20", "--json")
    for result in (bar, rotary):
        assert result.exit_code == 0, result.output
        doc = json.loads(result.stdout)
        assert doc["collisions"] == [] and doc["stock"]["removed_volume"] > 1000


def _pin(path: Path, diameter: float, length: float, low: float) -> None:
    """An intended part: a plain pin of ``diameter`` from Z ``low`` for ``length``, revolved about Z."""
    from edingcnc_lang.sim.bar_output import bar_mesh
    from edingcnc_lang.sim.round_stock import RoundStock
    from edingcnc_lang.sim.stl import write_stl

    write_stl(path, bar_mesh(RoundStock.bar(diameter, length, low, 0.1)))


def test_compare_stl_against_the_part_it_wrote_is_exact(job: Path) -> None:
    mesh = job.parent / "turned.stl"
    args = ["sim", job, "--ini", LATHE_INI, "--bar", "40,50", "--resolution", "0.1",
            "--tools", job.parent / "tools.toml"]
    assert invoke(*args, "--stl", mesh).exit_code == 0
    result = invoke(*args, "--compare-stl", mesh, "--json")
    assert result.exit_code == 0, result.output
    compared = json.loads(result.stdout)["compare"]
    assert compared["cells"] == 500 and compared["max_overcut"] == 0 and compared["max_undercut"] == 0


def test_compare_stl_tells_material_left_and_a_gouge(job: Path) -> None:
    """The job turns X30 (radius 15) over Z0..-20 of a 40 mm bar: against a 32 mm pin over Z0..-30
    it leaves 4 mm on Z-20..-30 and gouges 1 mm into Z0..-20."""
    pin = job.parent / "pin.stl"
    _pin(pin, 32, 30, -30)
    result = invoke("sim", job, "--ini", LATHE_INI, "--bar", "40,50", "--resolution", "0.1",
                    "--tools", job.parent / "tools.toml", "--compare-stl", pin, "--json")
    assert result.exit_code == 0, result.output
    compared = json.loads(result.stdout)["compare"]
    assert compared["cells"] == 300
    assert compared["max_overcut"] == pytest.approx(1.0, abs=1e-3)
    assert compared["max_undercut"] == pytest.approx(4.0, abs=1e-3)
    report = invoke("sim", job, "--ini", LATHE_INI, "--bar", "40,50", "--tools", job.parent / "tools.toml",
                    "--compare-stl", pin, "-o", job.parent / "cmp.svg")
    assert f"against {pin}: over-cut 1.000 mm, under-cut 4.000 mm" in report.stdout
    assert "pin.stl (max over-cut 1.000 mm)" in (job.parent / "cmp.svg").read_text()
