"""Issue 21 item 7: real 4.03 cnc.ini files load unchanged and behave (lathe mode, spindle limits, lint target).

The two files in tests/data/config/{lathe,mill}-4.03 have the layout EdingCNC 4.03 writes: CRLF,
Latin-1 tool descriptions, ``machineType`` and ``lastKnownServerVersion`` in [SYSTEM], the spindle
limits in [SPINDLE_0]..[SPINDLE_2], probe and camera offsets in [SPINDLE_3]/[SPINDLE_4], Windows
macro paths, no ``version`` key.
"""
from __future__ import annotations

import json
from pathlib import Path

import pytest

from edingcnc_lang import RunOptions, run_string
from edingcnc_lang.config.machine_config import LATHES, MACHINE_TYPES, load_config
from tests.cli_runner import invoke

DATA = Path(__file__).resolve().parents[1] / "data" / "config"
LATHE = DATA / "lathe-4.03" / "cnc.ini"
MILL = DATA / "mill-4.03" / "cnc.ini"
NO_UNIT = "Sub x\nG0 X1\nEndSub\n"


def test_the_files_are_what_the_controller_writes() -> None:
    for path in (LATHE, MILL):
        raw = path.read_bytes()
        assert raw.count(b"\r\n") == raw.count(b"\n")  # CRLF throughout
        assert b"\xb0" in raw  # a Latin-1 degree sign in a tool description
        assert b"[SPINDLE_0]" in raw and b"[SPINDLE]" not in raw and b"\nversion =" not in raw.lower()


def test_the_lathe_loads_as_a_back_tool_lathe() -> None:
    config = load_config(LATHE)
    assert config.machine_type == 2 and config.lathe and config.diameter_mode
    assert (config.spindle_max_rpm, config.spindle_min_rpm) == (3000.0, 50.0)
    assert config.warnings == ()
    assert config.tools[1].description == "Schruppstahl 80° r0,8"


def test_the_mill_loads_with_its_spindle_limits() -> None:
    config = load_config(MILL)
    assert config.machine_type == 0 and not config.lathe
    assert (config.spindle_max_rpm, config.spindle_min_rpm) == (24000.0, 6000.0)


@pytest.mark.parametrize("value", sorted(MACHINE_TYPES))
def test_every_machine_type_the_controller_writes_loads(tmp_path: Path, value: int) -> None:
    (tmp_path / "cnc.ini").write_bytes(f"[SYSTEM]\r\nmachineType = {value}\r\n".encode())
    config = load_config(tmp_path / "cnc.ini")
    assert config.lathe is (value in LATHES) and config.warnings == ()


def test_an_unknown_machine_type_is_a_warning_not_a_refusal(tmp_path: Path) -> None:
    ini = tmp_path / "cnc.ini"
    ini.write_text("[SYSTEM]\nmachineType = 9\n")
    config = load_config(ini)
    assert not config.lathe
    (warning,) = config.warnings
    assert (warning.code, warning.line) == ("C702", 2) and "machineType = 9" in warning.message
    (tmp_path / "job.nc").write_text("G0 X1\n")
    result = invoke("run", "--ini", ini, tmp_path / "job.nc")
    assert result.exit_code == 0
    assert f"{ini}:2:1: warning: machineType = 9" in result.stderr
    linted = invoke("lint", "--no-source", ini)
    assert "C702" in linted.stdout and "error" not in linted.stdout


def test_the_old_spindle_section_still_counts(tmp_path: Path) -> None:
    (tmp_path / "cnc.ini").write_text("[SPINDLE]\nspindleNmax = 1200\n")
    assert load_config(tmp_path / "cnc.ini").spindle_max_rpm == 1200.0


def test_a_bad_spindle_value_is_reported_in_spindle_0(tmp_path: Path) -> None:
    (tmp_path / "cnc.ini").write_text("[SPINDLE_0]\nspindleNmax = 1000\nspindleNmin = 2000\n")
    (tmp_path / "job.nc").write_text("G0 X1\n")
    result = invoke("run", "--ini", tmp_path / "cnc.ini", tmp_path / "job.nc")
    assert result.exit_code != 0
    assert "cnc.ini:3: error: spindleNmin = 2000 in [SPINDLE_0]" in result.stderr


def events(ini: Path, source: str) -> list[dict[str, object]]:
    found: list[dict[str, object]] = []
    run_string(source, RunOptions(ini=ini, on_event=lambda e: found.append({"kind": e.kind, **e.data})))
    return found


def test_s_is_clamped_to_the_spindle_0_limits() -> None:
    speeds = [e for e in events(MILL, "S30000 M3\nS100\n") if e["kind"] == "spindle_speed"]
    assert [e["rpm"] for e in speeds][-2:] == [24000.0, 6000.0]


def test_constant_surface_speed_is_clamped_on_the_lathe() -> None:
    css = [e for e in events(LATHE, "G0 X4 Z-5\nG96 S200 M3\n") if e["kind"] == "spindle_speed"][-1]
    assert css["mode"] == "css" and css["rpm"] == 3000.0  # 200 m/min at 4 mm would be 15,900 rpm


def test_the_lathe_runs_in_lathe_mode(tmp_path: Path) -> None:
    (tmp_path / "job.nc").write_text("G0 X20 Z-5\nG95 S500 M3\nG1 X10 F0.1\n")
    result = invoke("run", "--ini", LATHE, "--json", tmp_path / "job.nc")
    state = json.loads(result.stdout[: result.stdout.rindex("}") + 1])
    assert result.exit_code == 0, result.stderr
    assert "G18" in state["modal"]
    assert state["machine"]["x"] == 5.0  # X is a diameter (diameterProgramming = 1)


@pytest.mark.parametrize("ini", [LATHE, MILL], ids=["lathe", "mill"])
def test_lint_takes_the_target_from_last_known_server_version(tmp_path: Path, ini: Path) -> None:
    (tmp_path / "m.cnc").write_text(NO_UNIT)
    result = invoke("lint", "--no-source", "--ini", ini, tmp_path / "m.cnc")
    assert "F600" not in result.stdout
    assert "F600" in invoke("lint", "--no-source", tmp_path / "m.cnc").stdout


def test_the_version_key_may_stand_in_another_section(tmp_path: Path) -> None:
    (tmp_path / "m.cnc").write_text(NO_UNIT)
    (tmp_path / "cnc.ini").write_text('[USERINTERFACE]\nlastKnownServerVersion = "CNC V5.1.2"\n')
    assert "F600" in invoke("lint", "--no-source", "--ini", tmp_path / "cnc.ini", tmp_path / "m.cnc").stdout
    (tmp_path / "cnc.ini").write_text('[USERINTERFACE]\nlastKnownServerVersion = "CNC V4.03.50"\n')
    assert "F600" not in invoke("lint", "--no-source", "--ini", tmp_path / "cnc.ini", tmp_path / "m.cnc").stdout


def test_the_lathe_starts_in_the_feed_mode_of_its_initial_string() -> None:
    """The lathe's initialString says G95: the packaged macro's start sub must not turn it back to G94."""
    result = run_string("M3 S500\nG1 X10 Z-1 F0.1\n", RunOptions(ini=LATHE))
    assert "G95" in result.modal and "G94" not in result.modal
