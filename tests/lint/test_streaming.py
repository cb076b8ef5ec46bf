"""ecnc lint streams plain CAM lines (issue 17): the findings are those of the whole tree."""
from __future__ import annotations

from pathlib import Path

import pytest

from edingcnc_lang.lint import lint_paths
from edingcnc_lang.lint.model import load_source, stream_source

ROOT = Path(__file__).resolve().parents[2]
JOB = """G21 G90
G0 Z5
G0 G1 X1 Y1
G1 X2 Y2 F0
G1 X3 Y3 F100
G1 X4 Y4
G2 X5 Y5
T120
G53 X0
G38.2 Z-10 F50
G1 X5 Y6
M3 M4 S100
M30
G1 X7 Y7
G1 X8 Y8
"""


def _both(paths: list[Path]) -> tuple[list[object], list[object]]:
    return lint_paths(paths, reader=stream_source), lint_paths(paths, reader=load_source)


def test_streaming_finds_what_the_whole_tree_finds(tmp_path: Path) -> None:
    job = tmp_path / "job.nc"
    job.write_text(JOB)
    streamed, whole = _both([job])
    assert streamed == whole
    assert [(d.line, d.code) for d in streamed] == [  # type: ignore[attr-defined]
        (3, "G500"), (4, "G503"), (7, "G502"), (8, "G506"), (9, "G501"), (10, "G504"),
        (12, "G500"), (14, "S209")]


@pytest.mark.parametrize("folder", ["examples", "stdlib", "tests/lint/cases"])
def test_streaming_agrees_on_the_shipped_files(folder: str) -> None:
    streamed, whole = _both([ROOT / folder])
    assert streamed == whole


def test_plain_motion_lines_are_not_kept(tmp_path: Path) -> None:
    job = tmp_path / "job.nc"
    job.write_text("G0 Z5\n" + "G1 X1 Y2 F100\n" * 1000 + "M30\n")
    assert [s.span.line for s in stream_source(job, False).body] == [1002]  # type: ignore[attr-defined]
