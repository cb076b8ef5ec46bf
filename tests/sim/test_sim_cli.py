"""``ecnc sim`` as a user runs it: exit codes, the JSON document, the files it writes, usage errors."""
from __future__ import annotations

import json

import pytest

from tests.cli_runner import invoke

from .jobs import write_job

TOOLS = '[tool.0]\nshape = "flat"\ndiameter = 6\nflute_length = 10\n'
STOCK = "0,0,-10,40,30,0"


@pytest.fixture
def files(tmp_path):  # type: ignore[no-untyped-def]
    (tmp_path / "tools.toml").write_text(TOOLS)
    good = write_job(tmp_path, "G0 X10 Y15\nG1 Z-1 F300\nG1 X30\nG0 Z5", "good.nc")
    bad = write_job(tmp_path, "G0 X-5 Y15\nG0 Z-1\nG0 X45\nG0 Z5", "bad.nc")
    return tmp_path, good, bad


def test_a_clean_job_exits_0_and_a_rapid_through_the_stock_1(files):
    folder, good, bad = files
    ok = invoke("sim", good, "--stock", STOCK, "--tools", folder / "tools.toml", "--tool", "0")
    assert ok.exit_code == 0, ok.output
    assert "0 collisions" in ok.stdout
    hit = invoke("sim", bad, "--stock", STOCK, "--tools", folder / "tools.toml", "--tool", "0")
    assert hit.exit_code == 1
    assert f"{bad}:5: error: a rapid move (G0) removes material [rapid_into_stock]" in hit.stdout


def test_json_has_the_issue_shape(files):
    folder, _good, bad = files
    result = invoke("sim", bad, "--stock", STOCK, "--resolution", "0.5", "--json", "--tool", "0")
    assert result.exit_code == 1
    doc = json.loads(result.stdout)
    assert doc["stock"]["box"] == [0, 0, -10, 40, 30, 0] and doc["stock"]["resolution"] == 0.5
    assert doc["stock"]["removed_volume"] + doc["stock"]["remaining_volume"] == pytest.approx(40 * 30 * 10)
    (hit,) = doc["collisions"]
    assert {k: hit[k] for k in ("kind", "file", "line", "depth")} == {
        "kind": "rapid_into_stock", "file": str(bad), "line": 5, "depth": 1.0}
    assert len(hit["position"]) == 3 and isinstance(doc["time"], float)
    # without --tools the report says the shank was not checked
    assert doc["shank_checked"] is False and any("shank" in note for note in doc["notes"])


@pytest.mark.slow
def test_picture_stl_and_compare(files):
    pytest.importorskip("matplotlib")
    from matplotlib.image import imread

    folder, good, _bad = files
    picture, mesh = folder / "part.png", folder / "part.stl"
    first = invoke("sim", good, "--stock", STOCK, "--tool", "0", "--tools", folder / "tools.toml",
                   "-o", picture, "--stl", mesh)
    assert first.exit_code == 0, first.output
    assert imread(picture).shape[2] in (3, 4)
    assert mesh.stat().st_size > 84
    again = invoke("sim", good, "--stock", STOCK, "--tool", "0", "--tools", folder / "tools.toml",
                   "--compare-stl", mesh, "--json", "-o", folder / "dev.svg")
    compared = json.loads(again.stdout)["compare"]
    assert compared["max_overcut"] == 0.0 and compared["mean_deviation"] < 0.01
    assert (folder / "dev.svg").read_text().startswith("<?xml")


@pytest.mark.slow
def test_stock_from_stl(files):
    folder, good, _bad = files
    invoke("sim", good, "--stock", STOCK, "--tool", "0", "--stl", folder / "cut.stl")
    again = invoke("sim", good, "--stock-stl", folder / "cut.stl", "--tool", "0", "--json")
    doc = json.loads(again.stdout)
    assert again.exit_code == 0
    assert doc["stock"]["removed_volume"] == pytest.approx(0.0, abs=1.0)  # the slot was already there


@pytest.mark.parametrize("args, message", [
    ((), "exactly one of --stock"),
    (("--stock", "0,0,0,1,1"), "is not six numbers"),
    (("--stock", "0,0,0,10,10,-1"), "each minimum must be below its maximum"),
    (("--stock", STOCK, "--resolution", "0"), "--resolution"),
    (("--stock", STOCK, "-o", "part.jpg"), "the extension names the picture format"),
])
def test_usage_errors_exit_2(files, args, message):
    _folder, good, _bad = files
    result = invoke("sim", good, *args)
    assert result.exit_code == 2
    assert message in result.stderr


@pytest.mark.parametrize("text, message", [
    ('[tool.1]\nshape = "square"\ndiameter = 6\n', "shape must be one of flat, ball, bull, vee"),
    ("[tool.1]\ndiameter = -6\n", "diameter must be a positive number"),
    ("[tool.1]\nlength = 6\n", "unknown key 'length'"),
    ("[tool.1\n", "not a TOML file"),
    ('[tool.1]\nshape = "bull"\ndiameter = 6\n', "corner_radius"),
])
def test_bad_tools_file_names_the_file(files, text, message):
    folder, good, _bad = files
    (folder / "t.toml").write_text(text)
    result = invoke("sim", good, "--stock", STOCK, "--tools", folder / "t.toml")
    assert result.exit_code == 2
    assert f"{folder / 't.toml'}: error:" in result.stderr and message in result.stderr


def test_a_runtime_error_keeps_the_cut_so_far_and_exits_70(files):
    folder, _good, _bad = files
    job = write_job(folder, "G0 X10 Y15\nG1 Z-1 F300\nG1 X30\nerrmsg \"stop here\"\nG1 Y5", "stops.nc")
    result = invoke("sim", job, "--stock", STOCK, "--tool", "0", "--json")
    assert result.exit_code == 70
    doc = json.loads(result.stdout)
    assert doc["stock"]["removed_volume"] > 0 and "error" in doc
