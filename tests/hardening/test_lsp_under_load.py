"""The language server under load (issue 28, item 8): a request with a negative position or one
past 2**31 is answered (it used to get no response at all); formatting caps tabSize (2e9 took
1.9 GB); a document past MAX_LSP_DOCUMENT_CHARS is not analysed but told about."""
from __future__ import annotations

from collections.abc import Iterator
from pathlib import Path

import pytest

from edingcnc_lang.syntax.input_limits import MAX_LSP_DOCUMENT_CHARS, MAX_TAB_SIZE
from tests.lsp.client import LspClient, at

pytest.importorskip("pygls", reason="the language server needs the lsp extra")
pytest.importorskip("lsprotocol", reason="the language server needs the lsp extra")
from edingcnc_lang.lsp.server import _clamped_positions  # noqa: E402  (after the extra is known to be there)


@pytest.fixture(scope="module")
def client(tmp_path_factory: pytest.TempPathFactory) -> Iterator[LspClient]:
    lsp = LspClient()
    lsp.initialize(tmp_path_factory.mktemp("workspace"))
    yield lsp
    assert lsp.close() == 0


def test_positions_are_clamped_into_the_protocols_range() -> None:
    params = {"position": {"line": -1, "character": 2**40}, "range": [{"line": 3, "character": True}]}
    assert _clamped_positions(params) == {"position": {"line": 0, "character": 2**31 - 1},
                                          "range": [{"line": 3, "character": True}]}


@pytest.mark.slow
@pytest.mark.parametrize(("line", "character"), [(-1, 0), (0, -5), (0, 2**31), (2**40, 0), (-(2**40), -1)])
def test_every_position_gets_an_answer(client: LspClient, tmp_path: Path, line: int, character: int) -> None:
    job = tmp_path / "j.nc"
    job.write_text("G0 X1\nM30\n")
    uri = client.open(job)
    for method in ("textDocument/hover", "textDocument/definition", "textDocument/completion"):
        client.request(method, at(uri, line, character))  # a timeout here is the bug


def test_formatting_caps_the_tab_size(client: LspClient, tmp_path: Path) -> None:
    job = tmp_path / "f.nc"
    job.write_text("If [#1 == 1]\nG0 X1\nEndIf\n")
    uri = client.open(job)
    edits = client.request("textDocument/formatting", {"textDocument": {"uri": uri},
                                                        "options": {"tabSize": 2_000_000_000, "insertSpaces": True}})
    assert edits and max(len(e["newText"]) for e in edits) <= MAX_TAB_SIZE + len("G0 X1")


@pytest.mark.slow
def test_a_document_too_large_is_told_not_analysed(client: LspClient, tmp_path: Path) -> None:
    job = tmp_path / "big.nc"
    text = "G1 X1 Y2 F100\n" * (MAX_LSP_DOCUMENT_CHARS // 14 + 1)
    job.write_text("")
    uri = client.open(job, text)
    found = client.diagnostics(uri)
    assert len(found) == 1 and "more than the language server analyses" in found[0]["message"]
    assert client.request("textDocument/hover", at(uri, 5, 1)) is None
