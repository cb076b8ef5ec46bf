"""Command arguments are checked, and a number is ASCII digits everywhere (issue 28, items 3, 7
and 9): '²' after GetJobDistance was a ValueError traceback in run and an int() traceback in lint;
'١٠', '𝟏', '１' and '1_0' were read as numbers by Python's float() in jobs, the ini, --answer and
options; --box took only one quoted value and accepted nan; --probe-surface accepted nan."""
from __future__ import annotations

from pathlib import Path

import pytest

from edingcnc_lang.config.machine_config import load_config
from edingcnc_lang.errors import ConfigError, EcncError
from edingcnc_lang.host import DialogAnswer
from edingcnc_lang.lint import lint_paths
from edingcnc_lang.mdi import MdiSession
from edingcnc_lang.runner import RunOptions, run_string
from edingcnc_lang.syntax.source import plain_float, plain_int
from tests.cli_runner import invoke

NOT_ASCII = ["١٠", "𝟏", "１", "²", "⁵", "1_0", "٣.٥"]


@pytest.mark.parametrize("line", ["GetJobDistance ²", "GetToolInfo num ²", "GetHeightControlVact ⁵",
                                  "GetHeightControlVset １", "GetToolInfo first ١"])
def test_a_command_argument_that_is_no_ascii_number_is_an_error_at_its_line(tmp_path: Path, line: str) -> None:
    with pytest.raises(EcncError) as err:
        run_string(line + "\n")
    assert err.value.location is not None and err.value.location.line == 1
    with pytest.raises(EcncError):
        MdiSession().execute(line)
    job = tmp_path / "j.nc"
    job.write_text(f"{line}\nM30\n")
    assert isinstance(lint_paths([job]), list)  # the language server publishes what lint finds
    result = invoke("run", job)
    assert result.exit_code == 70 and "Traceback" not in result.output


def test_exec_without_a_program_is_an_error_not_an_index_error() -> None:
    with pytest.raises(EcncError, match="Exec needs the program"):
        run_string("Exec\n", RunOptions(allow_exec=True))


@pytest.mark.parametrize("digits", NOT_ASCII)
def test_a_word_or_expression_with_other_digits_does_not_parse(digits: str) -> None:
    for text in (f"G1 X{digits} F100\n", f"#1 = [{digits} + 1]\n", f"T{digits} M6\n"):
        with pytest.raises(EcncError):
            run_string(text)


@pytest.mark.parametrize("digits", NOT_ASCII)
def test_the_ini_reads_only_ascii_numbers(tmp_path: Path, digits: str) -> None:
    ini = tmp_path / "cnc.ini"
    ini.write_text(f"[INTERPRETER]\nfullCircleThetaEpsilon = {digits}\n", encoding="utf-8")
    with pytest.raises(ConfigError, match="expected a number"):
        load_config(ini)


@pytest.mark.parametrize("digits", NOT_ASCII)
def test_answers_and_number_options_take_only_ascii_digits(tmp_path: Path, digits: str) -> None:
    with pytest.raises(ValueError):
        DialogAnswer.parse(f"ok:#1={digits}")
    with pytest.raises(ValueError):
        DialogAnswer.parse(f"ok:#{digits}=1")
    job = tmp_path / "j.nc"
    job.write_text("M30\n")
    for args in (["run", job, "--feed-override", digits], ["run", job, "--max-steps", digits],
                 ["kins", "inverse", "trivial", "1", "2", digits], ["lint", job, "-j", digits]):
        result = invoke(*args)
        assert result.exit_code == 2, (args, result.output)


def test_plain_numbers() -> None:
    assert plain_float(" -1.5e3 ") == -1500.0 and plain_float(".5") == 0.5 and plain_int("+7") == 7
    assert plain_float("nan", special=True) != plain_float("nan", special=True)
    for bad in ["nan", "inf", "1_0", "١", "0x10", "", "1e"]:
        with pytest.raises(ValueError):
            plain_float(bad)
    with pytest.raises(ValueError):
        plain_int("1.0")


# --------------------------------------------------------------------------- kins check --box

@pytest.mark.slow
@pytest.mark.parametrize("box", [["10", "100", "-50", "50", "-5", "5"], ["10,", "100,", "-50,", "50,", "-5,", "5"],
                                 ["10 100 -50 50 -5 5"], ["10,100,-50,50,-5,5"]])
def test_box_as_separate_numbers_or_one_value(box: list[str]) -> None:
    result = invoke("kins", "check", "trivial", "--box", *box, "--samples", "5", "--no-speed", "--json")
    assert result.exit_code == 0, result.output
    result = invoke("kins", "check", "--box", *box, "trivial", "--samples", "5", "--no-speed", "--json")
    assert result.exit_code == 0, result.output


@pytest.mark.parametrize("box", ["--box=nan,1,2,3,4,5", "--box=1,inf,2,3,4,5", "--box=１,2,3,4,5,6"])
def test_box_refuses_what_is_no_finite_number(box: str) -> None:
    result = invoke("kins", "check", "trivial", box, "--samples", "5")
    assert result.exit_code == 2 and "Traceback" not in result.output


# --------------------------------------------------------------------------- --probe-surface

@pytest.mark.parametrize("z", ["nan", "NaN", "inf", "１", "1_0"])
def test_a_probe_surface_takes_finite_ascii_heights(tmp_path: Path, z: str) -> None:
    surface = tmp_path / "s.csv"
    surface.write_text(f"x,y,z\n0,0,0\n10,0,0\n0,10,{z}\n10,10,0\n")
    job = tmp_path / "j.nc"
    job.write_text("M30\n")
    result = invoke("run", job, "--probe-surface", surface)
    assert result.exit_code == 70 and "number" in result.stderr, result.output
