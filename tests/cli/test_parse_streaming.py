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


def _whole_text_refused(*args: object, **kwargs: object) -> None:
    raise AssertionError("standard input was read whole instead of streamed")


@pytest.mark.parametrize("command", [["parse", "-"], ["parse", "-", "--json"], ["run", "-", "--json"], ["lint", "-"]])
def test_standard_input_streams_like_a_file(tmp_path: Path, monkeypatch: pytest.MonkeyPatch,
                                            command: list[str]) -> None:
    """A million-line job on stdin took 2 GB when read whole; copied to a temporary file it streams."""
    import tempfile

    import edingcnc_lang.parser
    import edingcnc_lang.runner

    job = ROOT / "examples/pocket.nc"
    from_file = invoke(*[job if arg == "-" else arg for arg in command])
    monkeypatch.setattr(edingcnc_lang.parser, "parse_text", _whole_text_refused)
    monkeypatch.setattr(edingcnc_lang.runner.Run, "execute_text", _whole_text_refused)
    monkeypatch.setattr(tempfile, "tempdir", str(tmp_path))
    from_stdin = invoke(*command, input=job.read_bytes())
    assert from_stdin.exit_code == from_file.exit_code == 0, from_stdin.stderr
    assert from_stdin.stdout == from_file.stdout.replace(json.dumps(str(job)), json.dumps("<stdin>"))
    assert list(tmp_path.iterdir()) == []  # the copy is gone
