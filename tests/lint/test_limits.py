"""Inputs past the nesting limits: reported, and everything else in the files still is."""
from __future__ import annotations

from pathlib import Path

from edingcnc_lang.lint import lint_paths


def _codes(found: list, path: Path) -> list[tuple[int, str]]:  # type: ignore[type-arg]
    return [(d.line, d.code) for d in found if d.path == str(path)]


def test_a_file_nested_too_deeply_is_reported_and_the_others_keep_their_findings(tmp_path: Path) -> None:
    deep = tmp_path / "deep.nc"
    deep.write_text("If [1]\n" * 3000 + "G0 G1 X1\n" + "EndIf\n" * 3000 + 'msg "' + "x" * 300 + '"\n')
    plain = tmp_path / "plain.nc"
    plain.write_text("G0 G1 X1\nM30\n")
    found = lint_paths([tmp_path])
    assert (51, "E112") in _codes(found, deep)
    assert (6002, "F601") in _codes(found, deep)
    assert _codes(found, plain) == [(1, "G500")]


def test_a_chain_of_operators_past_the_limit_is_an_error(tmp_path: Path) -> None:
    job = tmp_path / "chain.nc"
    job.write_text("G0 G1 X1\n#1 = #[" + "+".join(["1"] * 500) + "]\nM30\n")
    found = lint_paths([job])
    assert [(d.line, d.code) for d in found] == [(1, "G500"), (2, "E111"), (2, "F601")]
