"""Formatting keeps the tree, comments and line count, and is stable when run twice."""
from __future__ import annotations

from pathlib import Path

import pytest

from edingcnc_lang.lsp.formatting import format_lines, format_text, split_comment
from edingcnc_lang.syntax.source import iter_file_lines

ROOT = Path(__file__).resolve().parents[2]
FILES = sorted([ROOT / "stdlib" / "macro.cnc", *ROOT.glob("examples/**/*.nc")])


@pytest.mark.parametrize("path", FILES, ids=lambda p: str(p.relative_to(ROOT)))
def test_real_files_format_safely_and_stably(path: Path) -> None:
    lines = list(iter_file_lines(path))
    once = format_lines(lines, "    ")
    assert once is not None and len(once) == len(lines)
    assert format_lines(once, "    ") == once
    comments = [split_comment(line)[1].strip() for line in lines]
    assert [split_comment(line)[1].strip() for line in once] == comments


def test_comments_keep_their_column_and_strings_keep_semicolons() -> None:
    assert format_text('g0 x1      ; here\nmsg "a;b" ; c\n') == 'G0 X1      ; here\nmsg "a;b" ; c\n'


def test_paren_comments_keep_the_code_as_written() -> None:
    assert format_text("If [#1==1]\ng01 x1 (MSG cut)\nEndIf\n") == "If [#1 == 1]\n  g01 x1 (MSG cut)\nEndIf\n"


def test_extra_brackets_and_errors_are_not_formatted() -> None:
    assert format_text("If [#1 > 0]]\nG0 X1\nEndIf\n") == "If [#1 > 0]]\n  G0 X1\nEndIf\n"
    assert format_text("G0 X10+5\n") is None
    assert format_text("Sub a\n") is None
