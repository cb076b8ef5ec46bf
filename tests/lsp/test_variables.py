"""The variable map in the editor, through the server as an editor drives it: hover, inlay hints,
completion by name, workspace symbols, go to definition, rename of a name, the annotation quick fix."""
from __future__ import annotations

from collections.abc import Iterator
from pathlib import Path
from typing import Any

import pytest

from tests.lsp.client import LspClient, at

MACRO = """;@unit mm
;@var #1552 thread_major_diameter "diameter A of the thread"
Sub user_1
    dlgmsg "Thread" "diameter A" 1552 "pitch" 1554
    #1553 = [#1552 - #1554] ;; minor diameter
    G0 X[#1553] Z[#5071]
    #1560 = 0
EndSub
Sub user_2
    #5020 = #5071 ;x1
EndSub
Sub user_3
    #5020 = 12 ;sensor position
EndSub
"""


@pytest.fixture(scope="module")
def root(tmp_path_factory: pytest.TempPathFactory) -> Path:
    path = tmp_path_factory.mktemp("vars")
    (path / "macro.cnc").write_text(MACRO, encoding="utf-8")
    (path / "variables.toml").write_text('[1554]\nname = "thread_pitch"\n', encoding="utf-8")
    return path


@pytest.fixture(scope="module")
def client(root: Path) -> Iterator[LspClient]:
    lsp = LspClient()
    lsp.initialize(root)
    yield lsp
    assert lsp.close() == 0


@pytest.fixture(scope="module")
def uri(client: LspClient, root: Path) -> str:
    found = client.open(root / "macro.cnc")
    client.diagnostics(found)
    return found


def test_capabilities_advertise_inlay_hints(client: LspClient, root: Path) -> None:
    other = LspClient()
    try:
        capabilities = other.initialize(root)["capabilities"]
        assert capabilities["inlayHintProvider"] and "refactor.rewrite" in capabilities["codeActionProvider"]["codeActionKinds"]
    finally:
        assert other.close() == 0


def test_hover_shows_name_source_and_writers(client: LspClient, uri: str) -> None:
    text = client.request("textDocument/hover", at(uri, 4, 15))["contents"]["value"]  # the #1552 read
    assert text.startswith("**#1552 thread_major_diameter**: from the annotation at macro.cnc:2")
    assert "diameter A of the thread" in text and "Kind: user" in text
    assert "Written by: user_1 (macro.cnc:4)" in text
    pitch = client.request("textDocument/hover", at(uri, 4, 23))["contents"]["value"]
    assert pitch.startswith("**#1554 thread_pitch**: from the annotation at variables.toml:2")


def test_inlay_hints_beside_numbers(client: LspClient, uri: str) -> None:
    hints = client.request("textDocument/inlayHint", {"textDocument": {"uri": uri},
                                                      "range": {"start": {"line": 4, "character": 0},
                                                                "end": {"line": 6, "character": 0}}})
    shown = [(h["position"]["line"], h["position"]["character"], h["label"]) for h in hints]
    assert shown == [(4, 9, "minor diameter"), (4, 18, "thread_major_diameter"), (4, 26, "thread_pitch"),
                     (5, 14, "minor diameter"), (5, 23, "machine position X")]


def test_completion_by_name_inserts_the_number(client: LspClient, uri: str) -> None:
    client.change(uri, MACRO.replace("    #1560 = 0", "    #1560 = thread_"), 2)
    items = client.request("textDocument/completion", at(uri, 6, 22))["items"]
    found = [(i["label"], i["textEdit"]["newText"]) for i in items if i["kind"] == 6]
    assert found == [("thread_major_diameter", "#1552"), ("thread_pitch", "#1554")]
    assert items[0]["textEdit"]["range"]["start"] == {"line": 6, "character": 12}
    client.change(uri, MACRO, 3)


def test_workspace_symbols_find_variables(client: LspClient, uri: str) -> None:
    found = client.request("workspace/symbol", {"query": "diameter"})
    names = {(s["name"], s["kind"]) for s in found}
    assert ("#1552 thread_major_diameter", 13) in names and ("#1553 minor diameter", 13) in names


def test_definition_jumps_to_the_annotation_or_the_first_writer(client: LspClient, uri: str) -> None:
    annotated = client.request("textDocument/definition", at(uri, 4, 15))
    assert annotated["uri"] == uri and annotated["range"]["start"] == {"line": 1, "character": 12}
    written = client.request("textDocument/definition", at(uri, 5, 10))  # #1553
    assert written["range"]["start"] == {"line": 4, "character": 4}
    sidecar = client.request("textDocument/definition", at(uri, 4, 23))
    assert sidecar["uri"].endswith("/variables.toml") and sidecar["range"]["start"]["line"] == 1


def test_rename_of_a_name_edits_the_annotation(client: LspClient, uri: str) -> None:
    prepared = client.request("textDocument/prepareRename", at(uri, 1, 15))
    assert prepared["placeholder"] == "thread_major_diameter"
    edit = client.request("textDocument/rename", {**at(uri, 1, 15), "newName": "major_d"})
    (edits,) = edit["changes"].values()
    assert edits == [{"range": {"start": {"line": 1, "character": 12}, "end": {"line": 1, "character": 33}},
                      "newText": "major_d"}]
    error = client.request_error("textDocument/rename", {**at(uri, 1, 15), "newName": "9 lives"})
    assert "not a name" in error["message"]


def _actions(client: LspClient, uri: str, line: int, col: int, diagnostics: list[Any]) -> list[Any]:
    where = {"start": {"line": line, "character": col}, "end": {"line": line, "character": col}}
    return client.request("textDocument/codeAction", {"textDocument": {"uri": uri}, "range": where,
                                                      "context": {"diagnostics": diagnostics}})


def test_quick_fix_names_a_number_with_an_annotation(client: LspClient, uri: str, root: Path) -> None:
    client.change(uri, MACRO + " ", 4)
    v305 = [d for d in client.diagnostics(uri) if d["code"] == "V305"]
    assert len(v305) == 1 and v305[0]["range"]["start"]["line"] == 12
    fixes = [a for a in _actions(client, uri, 12, 20, v305) if a["kind"] == "quickfix" and "@var" in a["title"]]
    assert [f["title"] for f in fixes] == ["Name #5020: add ;@var #5020 x1"]
    (edits,) = fixes[0]["edit"]["changes"].values()
    assert edits == [{"range": {"start": {"line": 2, "character": 0}, "end": {"line": 2, "character": 0}},
                      "newText": ";@var #5020 x1\n"}]
    refactor = [a["title"] for a in _actions(client, uri, 5, 10, []) if a["kind"] == "refactor.rewrite"]
    assert refactor == ["Name #1553: add ;@var #1553 minor_diameter"]
    assert [a for a in _actions(client, uri, 4, 15, []) if a["kind"] == "refactor.rewrite"] == []  # named already
    client.change(uri, MACRO, 5)


ROOT = Path(__file__).resolve().parents[2]


@pytest.mark.parametrize("name", ["stdlib/macro.cnc", "examples/variables/macro.cnc", "examples/lathe/user_macro.cnc"])
def test_every_token_of_a_real_file(name: str) -> None:
    """Each variable feature at every token, in process: no exceptions, a hint for every named #n."""
    from edingcnc_lang.lsp import variables
    from edingcnc_lang.lsp.lexer import tokens
    from edingcnc_lang.lsp.model import LanguageModel

    model = LanguageModel()
    path = str(ROOT / name)
    file = model.source(path)
    assert file is not None
    hinted = {(h.line, h.col) for h in variables.inlay_hints(model, path, 0, len(file.lines))}
    for number, line in enumerate(file.lines):
        for token in tokens(line):
            text = variables.hover_text(model, path, number, token.start)
            variables.definition(model, path, number, token.start)
            variables.complete_names(model, path, number, token.end)
            variables.annotation_fixes(model, path, file.lines, number, token.start)
            if token.kind == "param":
                assert text and "Kind:" in text, (number + 1, token)
                if (number, token.end) not in hinted:
                    assert "(no name" in text or "**" not in text.split("\n")[0], (number + 1, token)
    assert variables.workspace_symbols(model, "") == []  # nothing open, no workspace folder
