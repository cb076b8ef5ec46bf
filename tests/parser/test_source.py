"""Reading files in blocks gives exactly the lines a line-by-line reader gives."""
from __future__ import annotations

from pathlib import Path

import pytest
from hypothesis import assume, given, settings
from hypothesis import strategies as st

from edingcnc_lang.syntax import parser, source


def _reference(path: Path) -> list[str]:
    lines = []
    with open(path, "rb") as handle:
        for number, raw in enumerate(handle):
            if number == 0 and raw.startswith(source.BOM):
                raw = raw[len(source.BOM):]
            lines.append(source.decode_line(raw.rstrip(b"\r\n")))
    return lines


@settings(max_examples=200, deadline=None)
@given(data=st.binary(max_size=40) |
       st.lists(st.sampled_from([b"G1 X1", b"\r\n", b"\n", b"\r", b"\xfc", "Grüße".encode(), b"\xef\xbb\xbf"]),
                max_size=12).map(b"".join),
       chunk=st.sampled_from([1, 2, 7, 1 << 20]))
def test_block_reading_matches_line_reading(tmp_path_factory: pytest.TempPathFactory, data: bytes, chunk: int) -> None:
    assume(not data.startswith(source.UTF16_BOMS))  # UTF-16 files: the test below
    path = tmp_path_factory.mktemp("src") / "f.nc"
    path.write_bytes(data)
    expected = _reference(path)
    if data == source.BOM:
        expected = []  # a file holding only a BOM has no lines
    with pytest.MonkeyPatch.context() as patch:
        patch.setattr(source, "CHUNK", chunk)
        assert list(source.iter_file_lines(path)) == expected


@settings(max_examples=100, deadline=None)
@given(lines=st.lists(st.text(st.characters(blacklist_characters="\r\n", blacklist_categories=("Cs",)), max_size=8),
                      max_size=6),
       codec=st.sampled_from(["utf-16-le", "utf-16-be"]), eol=st.sampled_from(["\n", "\r\n"]),
       chunk=st.sampled_from([1, 2, 3, 7, 1 << 20]))
def test_utf16_files_with_a_bom_are_decoded(tmp_path_factory: pytest.TempPathFactory, lines: list[str], codec: str,
                                            eol: str, chunk: int) -> None:
    """What Windows Notepad saves as "Unicode" (UTF-16 with a BOM) reads as the text it holds."""
    path = tmp_path_factory.mktemp("src") / "f.nc"
    path.write_bytes(("\ufeff" + "".join(line + eol for line in lines)).encode(codec))
    with pytest.MonkeyPatch.context() as patch:
        patch.setattr(source, "CHUNK", chunk)
        assert list(source.iter_file_lines(path)) == lines


def test_a_utf16_line_longer_than_the_limit_is_cut(tmp_path: Path) -> None:
    path = tmp_path / "long.nc"
    path.write_bytes(("G0 X1\r\n(" + "x" * (3 * source.MAX_LINE_LENGTH) + ")\r\nG0 X2").encode("utf-16"))
    with pytest.MonkeyPatch.context() as patch:
        patch.setattr(source, "CHUNK", 4096)
        lines = list(source.iter_file_lines(path))
    assert lines[0] == "G0 X1" and len(lines[1]) == source.MAX_LINE_LENGTH + 1 and lines[2:] == ["G0 X2"]


@settings(max_examples=60, deadline=None)
@given(lines=st.lists(st.sampled_from(["G1 X1 Y2", "G0 Z5", "If [#1 > 0]", "EndIf", "Sub a", "EndSub", "M30",
                                      "#1 = 2", "G1 X[#1]", "; note", "", "G2 X1 Y0 R5"]), max_size=40),
       eol=st.sampled_from(["\n", "\r\n"]), chunk=st.sampled_from([1, 5, 1 << 20]),
       chunk_lines=st.sampled_from([1, 3, 8192]), mode=st.sampled_from(["tree", "check", "run", "lint"]))
def test_a_file_read_in_blocks_gives_the_statements_of_its_lines(
        tmp_path_factory: pytest.TempPathFactory, lines: list[str], eol: str, chunk: int, chunk_lines: int,
        mode: str) -> None:
    """The reader of a file takes its lines in the lists they were read in (blocks of any size, cut
    into chunks): the statements, diagnostics and line count are those of the same lines one by one."""
    path = tmp_path_factory.mktemp("src") / "f.nc"
    path.write_bytes("".join(line + eol for line in lines).encode())
    with pytest.MonkeyPatch.context() as patch:
        patch.setattr(source, "CHUNK", chunk)
        patch.setattr(parser, "CHUNK_LINES", chunk_lines)
        blocks = parser.read_statements(path, mode=mode)
        one_by_one = parser.StatementReader(source.iter_file_lines(path), str(path), mode=mode)
        assert list(blocks) == list(one_by_one)
    assert blocks.diagnostics == one_by_one.diagnostics and blocks.lines == one_by_one.lines == len(lines)
