"""Numbers that broke time, JSON and tables (issue 28, item 7): an ini's maxVelocity 1e-200 gave
0 s, maxAcceleration 1e-320 NaN (printed as bare NaN in --json) with numpy RuntimeWarnings on
stderr; ZHCcheck printed "range inf"; U+202E was accepted in a log file's name."""
from __future__ import annotations

import json
import math
import re
from pathlib import Path

import pytest

from edingcnc_lang.config.machine_config import load_config
from edingcnc_lang.errors import ConfigError, EcncError
from edingcnc_lang.config.heightmap import HeightMapError, ZhcTable
from edingcnc_lang.machine.job_files import job_file
from edingcnc_lang.syntax.input_limits import MAX_AXIS_RATE, MIN_AXIS_RATE
from edingcnc_lang.runner import run_string
from edingcnc_lang.syntax.serialize import json_text
from tests.cli_runner import invoke

JOB = "G0 X10\nG1 X20 F100\nG2 X30 Y0 R5\nM30\n"


@pytest.mark.parametrize("line", ["[JOINT_0]\nmaxVelocity = 1e-200", "[JOINT_0]\nmaxAcceleration = 1e-320",
                                  "[JOINT_1]\nmaxVelocity = 1e308\nmaxAcceleration = 1e308",
                                  "[KINEMATICS]\nmaxVelocityX = 1e-300"])
def test_axis_rates_beyond_the_planners_range_are_refused(tmp_path: Path, line: str) -> None:
    ini = tmp_path / "cnc.ini"
    ini.write_text(line + "\n")
    with pytest.raises(ConfigError, match=re.escape(f"must be {MIN_AXIS_RATE:g} to {MAX_AXIS_RATE:g}")):
        load_config(ini)


@pytest.mark.parametrize("rate", [MIN_AXIS_RATE, MAX_AXIS_RATE])
def test_the_ends_of_the_range_give_a_finite_time_and_valid_json(tmp_path: Path, rate: float) -> None:
    ini = tmp_path / "cnc.ini"
    ini.write_text("".join(f"[JOINT_{i}]\nmaxVelocity = {rate!r}\nmaxAcceleration = {rate!r}\n" for i in range(3)))
    job = tmp_path / "j.nc"
    job.write_text(JOB)
    result = invoke("run", job, "--ini", ini, "--json")
    assert "Warning" not in result.stderr
    seconds = json.loads(result.stdout)["estimate"]["seconds"]
    assert math.isfinite(seconds) and seconds > 0


def test_json_text_never_writes_a_bare_nan() -> None:
    text = json_text({"a": math.nan, "b": [math.inf, 1.5], "c": (-math.inf,)})
    assert json.loads(text) == {"a": None, "b": [None, 1.5], "c": [None]}


def test_zhc_tables_keep_their_statistics_finite(tmp_path: Path) -> None:
    text = ZhcTable.empty(2, 2, 0, 0, 10, 10).to_text().replace("nan nan\n", "1e300 -1e300\n", 1)
    with pytest.raises(HeightMapError, match="beyond"):
        ZhcTable.from_text(text, "t.txt")
    table = ZhcTable.empty(2, 2, 0, 0, 10, 10)
    table.add(0, 0, 1e9)
    table.add(10, 0, -1e9)
    assert "inf" not in table.statistics()


@pytest.mark.parametrize("name", ["log\u202etxt.exe", "a\u2066b.txt", "x\x85.txt", "a\x1b[2J.txt"])
def test_a_log_file_name_with_a_direction_override_or_control_is_refused(tmp_path: Path, name: str) -> None:
    with pytest.raises(ValueError, match="control characters or direction overrides"):
        job_file(tmp_path, name)
    with pytest.raises(EcncError):
        run_string(f'logfile "{name}" 0\n')
