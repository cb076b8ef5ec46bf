"""G508 with the tool table of ``--ini``: ``G41/G42 D<n>`` takes tool n's diameter from cnc.ini."""
from __future__ import annotations

from pathlib import Path

from edingcnc_lang.lint.driver import LintOptions, lint_paths

JOB = ("G21 G17 G90\nG0 X-10 Y0\nG42 D2\nG1 X0 Y0 F500\nG2 X8 Y0 I4 J0\nG40\n"
       "G20\nG42 D2\nG1 X0 Y0\nG2 X0.5 Y0 I0.25 J0\nG2 X0.7 Y0 I0.1 J0\nG40\nM30\n")


def g508_lines(tmp_path: Path, ini_text: str | None) -> list[int]:
    job = tmp_path / "job.nc"
    job.write_text(JOB)
    options = LintOptions()
    if ini_text is not None:
        ini = tmp_path / "cnc.ini"
        ini.write_text(ini_text)
        options = LintOptions(ini=str(ini))
    return [d.line for d in lint_paths([job], options) if d.code == "G508"]


def test_the_ini_tool_table_gives_the_radius_in_the_programs_units(tmp_path: Path) -> None:
    # tool 2 is 10 mm: radius 5 mm > the 4 mm arc; under G20 0.1969 in: more than the 0.1 in arc, less than the 0.25 in one
    assert g508_lines(tmp_path, "[TOOL_2]\ndiameter = 10\n") == [5, 11]


def test_without_the_ini_the_radius_is_unknown(tmp_path: Path) -> None:
    assert g508_lines(tmp_path, None) == []


LATHE_JOB = "G21 G18\nG96 S200 D2000\nM3\nG1 X10 Z-5 F100\nG76 P1.5 Z-20 I9 J0.1 K1\nG97 S800\nM30\n"


def test_lathe_codes_are_g509_with_a_mills_ini_only(tmp_path: Path) -> None:
    job = tmp_path / "turn.nc"
    job.write_text(LATHE_JOB)
    ini = tmp_path / "cnc.ini"

    def g509(ini_text: str | None) -> list[tuple[int, str]]:
        options = LintOptions()
        if ini_text is not None:
            ini.write_text(ini_text)
            options = LintOptions(ini=str(ini))
        return [(d.line, d.message) for d in lint_paths([job], options) if d.code == "G509"]

    mill = g509("[SYSTEM]\nmachineType = 0\n")
    assert [line for line, _ in mill] == [2, 5]
    assert mill[0][1] == ("G96 is a lathe code and this machine is a mill: "
                          "a lathe's cnc.ini (--ini) sets [SYSTEM] machineType = 1")
    assert g509("[SYSTEM]\nmachineType = 1\n") == []
    assert g509(None) == []  # the machine is unknown without an ini
