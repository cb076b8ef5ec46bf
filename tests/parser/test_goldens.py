"""Golden tests for the parser: good inputs dump their AST, bad inputs their diagnostics.

Data lives in tests/parser/good, tests/parser/bad (inputs) and tests/parser/expected
(outputs); the stdlib macro file and every example are good inputs too.
Run ``pytest --regen-goldens`` to rewrite the expected files after a deliberate change.
"""
from __future__ import annotations

import json
from pathlib import Path

import pytest

from edingcnc_lang.diagnostics import SyntaxErrors
from edingcnc_lang.syntax.parser import parse_file
from edingcnc_lang.syntax.serialize import to_data

HERE = Path(__file__).parent
ROOT = HERE.parent.parent
EXPECTED = HERE / "expected"
SUFFIXES = {".nc", ".cnc", ".ngc"}


def _inputs(folder: Path) -> list[Path]:
    return sorted(p for p in folder.rglob("*") if p.suffix in SUFFIXES)


GOOD = _inputs(HERE / "good") + [ROOT / "stdlib" / "macro.cnc"] + _inputs(ROOT / "examples")
BAD = _inputs(HERE / "bad")


def _name(path: Path) -> str:
    return str(path.relative_to(ROOT)).replace("/", "__")


@pytest.mark.parametrize("path", GOOD, ids=_name)
def test_good_input_parses_to_golden_ast(path: Path, golden, monkeypatch) -> None:
    monkeypatch.chdir(path.parent)
    program = parse_file(path.name)
    golden(EXPECTED / f"{_name(path)}.ast.json", json.dumps(to_data(program), indent=1) + "\n")


@pytest.mark.parametrize("path", BAD, ids=_name)
def test_bad_input_reports_golden_errors(path: Path, golden, monkeypatch) -> None:
    monkeypatch.chdir(path.parent)
    with pytest.raises(SyntaxErrors) as info:
        parse_file(path.name)
    golden(EXPECTED / f"{_name(path)}.errors.txt", info.value.format() + "\n")


def test_every_bad_input_has_an_error_on_a_real_line() -> None:
    for path in BAD:
        try:
            parse_file(path)
        except SyntaxErrors as err:
            lines = path.read_text(encoding="latin-1").splitlines()
            assert all(1 <= d.line <= len(lines) for d in err.diagnostics), path
        else:
            pytest.fail(f"{path} parsed without errors")
