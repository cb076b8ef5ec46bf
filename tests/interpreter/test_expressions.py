"""Expressions as a macro writer uses them: operators, functions, logic, and the runtime errors.

Every case runs a one-line job through the API and reads the result back from a
parameter, so precedence, degrees and rounding are checked end to end.
"""
from __future__ import annotations

from pathlib import Path

import pytest

from edingcnc_lang.errors import EcncError, MachineError
from edingcnc_lang.runner import RunOptions, RunResult, run_string

EMPTY_MACRO = Path(__file__).parent / "data" / "empty_macro.cnc"


def run(source: str) -> RunResult:
    return run_string(source, RunOptions(macro=EMPTY_MACRO), path="job.nc")


def value_of(expression: str) -> float:
    """The value the dialect gives ``expression`` (stored in #100 and read back)."""
    return run(f"#100 = {expression}\n").variables[100]


EXACT = [
    # arithmetic and precedence (manual example: 0.5)
    ("[2.0/3*1.5-5.5/11.0]", 0.5),
    ("[1 + 2 * 3]", 7.0),
    ("[10 - 2 - 3]", 5.0),
    ("[12 / 4 / 3]", 1.0),
    ("[[1 + 2] * 3]", 9.0),
    ("[-3 + +5]", 2.0),
    ("[2 ** 10]", 1024.0),
    ("[2 ** 3 ** 2]", 64.0),        # left-associative: [2**3]**2
    ("[3 * 2 ** 2]", 12.0),         # ** binds tighter than *
    ("[4 ** 0.5]", 2.0),
    ("[2 ** -1]", 0.5),
    # MOD: result in [0, |b|), binds like * and /
    ("[7 MOD 3]", 1.0),
    ("[-7 MOD 3]", 2.0),
    ("[7 MOD -3]", 1.0),
    ("[-7 MOD -3]", 2.0),
    ("[-5.5 MOD 2]", 0.5),
    ("[6 MOD 3]", 0.0),
    ("[5 MOD 3 * 2]", 4.0),
    ("[7 / 2 MOD 2]", 1.5),
    # logic on reals gives 1/0
    ("[1 AND 0]", 0.0), ("[0.5 AND -1]", 1.0), ("[0 OR 0]", 0.0), ("[0 OR 3]", 1.0),
    ("[2 XOR 3]", 0.0), ("[0 XOR 3]", 1.0), ("[0 XOR 0]", 0.0),
    # comparisons give 1/0 and bind loosest (project decision)
    ("[1 == 1]", 1.0), ("[1 == 2]", 0.0), ("[1 <> 2]", 1.0), ("[2 <> 2]", 0.0),
    ("[1 < 2]", 1.0), ("[2 < 2]", 0.0), ("[2 > 1]", 1.0), ("[1 > 1]", 0.0),
    ("[2 <= 2]", 1.0), ("[3 <= 2]", 0.0), ("[2 >= 2]", 1.0), ("[1 >= 2]", 0.0),
    ("[1 != 2]", 1.0), ("[2 EQ 2]", 1.0), ("[2 NE 2]", 0.0), ("[3 GT 2]", 1.0),
    ("[3 GE 4]", 0.0), ("[1 LT 2]", 1.0), ("[2 LE 1]", 0.0),
    ("[1 + 2 == 3]", 1.0), ("[3 > 2 + 2]", 0.0), ("[[1 < 2] AND [3 < 4]]", 1.0),
    # functions (angles in degrees)
    ("ABS[-2.5]", 2.5), ("ABS[3]", 3.0),
    ("SQRT[16]", 4.0), ("SQRT[0]", 0.0),
    ("ASIN[1]", 90.0), ("ASIN[-1]", -90.0), ("ACOS[-1]", 180.0), ("ACOS[1]", 0.0),
    ("ATAN[1]/[1]", 45.0), ("ATAN[1]/[-1]", 135.0), ("ATAN[-1]/[-1]", -135.0),
    ("ATAN[0]/[-1]", 180.0), ("ATAN[-0.0]/[-1]", 180.0),   # (-180, 180]: never -180
    ("ATAN[-1]/[0]", -90.0), ("ATAN[0]/[1]", 0.0),
    ("EXP[0]", 1.0), ("LN[1]", 0.0), ("SIN[0]", 0.0), ("COS[0]", 1.0), ("TAN[0]", 0.0),
    # FIX toward minus infinity, FUP toward plus infinity, ROUND half away from zero
    ("FIX[2.7]", 2.0), ("FIX[-2.5]", -3.0), ("FIX[-0.1]", -1.0), ("FIX[3]", 3.0),
    ("FUP[2.1]", 3.0), ("FUP[-2.5]", -2.0), ("FUP[-0.9]", 0.0), ("FUP[3]", 3.0),
    ("ROUND[2.5]", 3.0), ("ROUND[-2.5]", -3.0), ("ROUND[0.5]", 1.0), ("ROUND[-0.5]", -1.0),
    ("ROUND[1.49999]", 1.0), ("ROUND[-1.5]", -2.0),
    ("[ABS[-2] + SQRT[16]]", 6.0),
]


@pytest.mark.parametrize(("expression", "expected"), EXACT, ids=[e for e, _ in EXACT])
def test_exact_value(expression: str, expected: float) -> None:
    assert value_of(expression) == expected


TRIG = [
    ("SIN[30]", 0.5), ("SIN[90]", 1.0), ("COS[60]", 0.5), ("COS[180]", -1.0), ("TAN[45]", 1.0),
    ("TAN[-45]", -1.0), ("EXP[1]", 2.718281828459045), ("LN[EXP[2]]", 2.0), ("ACOS[0.5]", 60.0),
    ("ASIN[0.5]", 30.0), ("ATAN[SQRT[3]]/[1]", 60.0),
]


@pytest.mark.parametrize(("expression", "expected"), TRIG, ids=[e for e, _ in TRIG])
def test_trigonometry_in_degrees(expression: str, expected: float) -> None:
    assert value_of(expression) == pytest.approx(expected, abs=1e-12)


def test_parameter_reads_direct_indirect_and_double() -> None:
    result = run("#2 = 5\n#5 = 9\n#101 = ##2\n#102 = #[1 + 1]\n#103 = #[#2 * 2 - 5]\n")
    assert (result.variables[101], result.variables[102], result.variables[103]) == (9.0, 5.0, 9.0)


def test_an_unset_parameter_reads_zero() -> None:
    assert value_of("[#3999 + 1]") == 1.0


def test_expression_as_a_word_value_and_a_g_number() -> None:
    result = run("#1 = 4\nG[2 * 0 + 1] X[#1 * 2.5] Y-[#1 / 2] F[100]\n")
    assert result.position[:2] == (10.0, -2.0)
    assert "G1" in result.modal


def test_runtime_error_inside_a_sub_names_the_sub_line_and_the_caller() -> None:
    source = "G0 X1\nGoSub calc\nM30\nSub calc\n  #100 = SQRT[-4]\nEndSub\n"
    with pytest.raises(MachineError) as info:
        run(source)
    assert str(info.value.location) == "job.nc:5:10"
    assert info.value.notes == ("in Sub calc, called from job.nc:2",)


def test_runtime_error_stops_the_job_where_it_happened() -> None:
    with pytest.raises(EcncError) as info:
        run("G0 X5\n#100 = [1/0]\nG0 X9\n")
    partial: RunResult = info.value.result  # type: ignore[attr-defined]
    assert partial.position[0] == 5.0
    assert partial.moves == 1


def test_tangent_of_90_degrees_is_an_error() -> None:
    with pytest.raises(MachineError, match="TAN"):
        run("#100 = TAN[90]\n")
