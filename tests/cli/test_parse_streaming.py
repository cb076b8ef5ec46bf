"""ecnc parse --json writes the tree statement by statement (issue 17), byte for byte what json.dumps gives."""
from __future__ import annotations

import json
from pathlib import Path

import pytest

from edingcnc_lang.parser import parse_file
from edingcnc_lang.serialize import to_data
from tests.cli_runner import invoke

ROOT = Path(__file__).resolve().parents[2]


@pytest.mark.parametrize("name", ["examples/pocket.nc", "stdlib/macro.cnc", "examples/delta/job.nc", "empty"])
@pytest.mark.parametrize("spans", [True, False])
def test_streamed_json_is_the_whole_trees_json(tmp_path: Path, name: str, spans: bool) -> None:
    path = ROOT / name if name != "empty" else tmp_path / "empty.nc"
    if name == "empty":
        path.write_text(";@unit mm\n")
    result = invoke("parse", "--json", path, *([] if spans else ["--no-spans"]))
    assert result.exit_code == 0, result.stderr
    assert result.stdout == json.dumps(to_data(parse_file(path), with_spans=spans), indent=1) + "\n"


def test_a_syntax_error_anywhere_prints_only_the_error_record(tmp_path: Path) -> None:
    job = tmp_path / "job.nc"
    job.write_text("G0 X1\n" * 100 + "G1 X[\n")
    result = invoke("parse", "--json", job)
    assert result.exit_code == 65
    assert list(json.loads(result.stdout)) == ["error"]  # no half-written tree before it
