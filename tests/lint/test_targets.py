"""ecnc lint --target: which controller version the findings describe."""
from __future__ import annotations

from pathlib import Path

import pytest

from tests.cli_runner import invoke

NO_UNIT = "Sub x\nG0 X1\nEndSub\n"


@pytest.mark.parametrize("args, fires", [([], True), (["--target", "5"], True), (["--target", "4.03"], False)])
def test_f600_describes_edingcnc_5_only(tmp_path: Path, args: list[str], fires: bool) -> None:
    (tmp_path / "m.cnc").write_text(NO_UNIT)
    result = invoke("lint", "--no-source", *args, tmp_path / "m.cnc")
    assert ("F600" in result.stdout) is fires
    assert result.exit_code == (1 if fires else 0)


@pytest.mark.parametrize("name, text", [("ecnc.toml", '[tool.ecnc]\ntarget = "4.03"\n'),
                                        ("pyproject.toml", '[project]\nname = "x"\n[tool.ecnc]\ntarget = "4.03"\n')])
def test_the_target_from_a_config_file_above_the_path(tmp_path: Path, name: str, text: str) -> None:
    (tmp_path / name).write_text(text)
    (tmp_path / "macros").mkdir()
    (tmp_path / "macros" / "m.cnc").write_text(NO_UNIT)
    assert invoke("lint", tmp_path / "macros" / "m.cnc").exit_code == 0
    assert "F600" in invoke("lint", "--target", "5", tmp_path / "macros" / "m.cnc").stdout  # the option wins


def test_the_target_from_the_ini_version_line(tmp_path: Path) -> None:
    (tmp_path / "m.cnc").write_text(NO_UNIT)
    (tmp_path / "cnc.ini").write_text('[SYSTEM]\nversion = "V4.03.52"\n')
    assert invoke("lint", "--ini", tmp_path / "cnc.ini", tmp_path / "m.cnc").exit_code == 0
    (tmp_path / "cnc.ini").write_text('[SYSTEM]\nversion = "V5.1.0"\n')
    assert "F600" in invoke("lint", "--ini", tmp_path / "cnc.ini", tmp_path / "m.cnc").stdout


def test_a_bad_target_is_a_usage_error(tmp_path: Path) -> None:
    (tmp_path / "m.cnc").write_text(NO_UNIT)
    assert invoke("lint", "--target", "3", tmp_path / "m.cnc").exit_code == 2
    (tmp_path / "ecnc.toml").write_text('[tool.ecnc]\ntarget = "3.1"\n')
    result = invoke("lint", tmp_path / "m.cnc")
    assert result.exit_code == 2 and "unknown controller version '3.1'" in result.stderr
    (tmp_path / "ecnc.toml").unlink()
    (tmp_path / "cnc.ini").write_text('[SYSTEM]\nmachineType = 0\nversion = "garbage"\n')
    result = invoke("lint", "--ini", tmp_path / "cnc.ini", tmp_path / "m.cnc")
    assert result.exit_code == 2
    assert result.stderr.startswith(f"{tmp_path / 'cnc.ini'}:3: error: unknown controller version 'garbage'")


def test_unknown_g_codes_are_found_for_every_target(tmp_path: Path) -> None:
    (tmp_path / "job.nc").write_text("G7 X20\nG0 X1\n")
    for target in ("4.03", "5"):
        result = invoke("lint", "--target", target, tmp_path / "job.nc")
        assert "G509 unknown G code G7" in result.stdout and "diameterProgramming" in result.stdout
