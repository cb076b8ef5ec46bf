"""Reading files in blocks gives exactly the lines a line-by-line reader gives."""
from __future__ import annotations

from pathlib import Path

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from edingcnc_lang import source


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
    path = tmp_path_factory.mktemp("src") / "f.nc"
    path.write_bytes(data)
    expected = _reference(path)
    if data == source.BOM:
        expected = []  # a file holding only a BOM has no lines
    with pytest.MonkeyPatch.context() as patch:
        patch.setattr(source, "CHUNK", chunk)
        assert list(source.iter_file_lines(path)) == expected
