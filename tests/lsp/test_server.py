"""The language server over stdio, driven by a real JSON-RPC client as an editor drives it.

One server for the module (starting it costs about half a second); each test opens its own
files in its own folder of the workspace.
"""
from __future__ import annotations

from collections.abc import Iterator
from pathlib import Path
from typing import Any

import pytest

from edingcnc_lang.lint import lint_paths
from tests.lsp.client import LspClient, at

pytestmark = pytest.mark.slow  # the whole module (pyproject's slow marker)

MACRO = """;@unit mm
Sub drill ; drill one hole at the current XY
; Z-5, retract to R2
  G81 Z-5 R2 F100
  G80
EndSub
Sub m100
  G0 X[#24]
EndSub
Sub change_tool
  M6 T[#5011]
EndSub
"""
JOB = """#27 = 12.5
GoSub drill
M100 X5
G38.2 Z-5 F100
GoSub nowhere
M6 T2
G0 X[#27] Y[#5221]
dlgmsg "Setup" "Width" 28
"""


@pytest.fixture(scope="module")
def root(tmp_path_factory: pytest.TempPathFactory) -> Path:
    return tmp_path_factory.mktemp("workspace")


@pytest.fixture(scope="module")
def client(root: Path) -> Iterator[LspClient]:
    lsp = LspClient()
    lsp.initialize(root)
    yield lsp
    assert lsp.close() == 0


@pytest.fixture
def folder(root: Path, request: pytest.FixtureRequest) -> Path:
    """A folder of the workspace with a macro.cnc and a job.nc, one per test."""
    path = root / request.node.name
    path.mkdir()
    (path / "macro.cnc").write_text(MACRO, encoding="utf-8")
    (path / "job.nc").write_text(JOB, encoding="utf-8")
    return path


def apply(text: str, edits: list[dict[str, Any]]) -> str:
    """Apply LSP text edits (ASCII text: UTF-16 units are characters), last first."""
    lines = text.split("\n")
    offsets = [0]
    for line in lines:
        offsets.append(offsets[-1] + len(line) + 1)

    def offset(pos: dict[str, int]) -> int:
        return offsets[pos["line"]] + pos["character"]

    for edit in sorted(edits, key=lambda e: offset(e["range"]["start"]), reverse=True):
        start, end = offset(edit["range"]["start"]), offset(edit["range"]["end"])
        text = text[:start] + edit["newText"] + text[end:]
    return text


def hover(client: LspClient, uri: str, line: int, character: int) -> str:
    result = client.request("textDocument/hover", at(uri, line, character))
    return result["contents"]["value"] if result else ""


def codes(diagnostics: list[dict[str, Any]]) -> list[tuple[int, str]]:
    return [(d["range"]["start"]["line"] + 1, d["code"]) for d in diagnostics]


# --------------------------------------------------------------------------- start-up


def test_initialize_announces_every_feature(root: Path) -> None:
    lsp = LspClient()
    capabilities = lsp.initialize(root)["capabilities"]
    assert lsp.close() == 0
    for name in ("hoverProvider", "definitionProvider", "referencesProvider", "documentSymbolProvider",
                 "workspaceSymbolProvider", "codeActionProvider", "documentFormattingProvider"):
        assert capabilities[name], name
    assert "#" in capabilities["completionProvider"]["triggerCharacters"]


# --------------------------------------------------------------------------- diagnostics


def test_diagnostics_on_open_are_what_ecnc_lint_reports(client: LspClient, folder: Path) -> None:
    job = folder / "job.nc"
    found = client.diagnostics(client.open(job))
    expected = lint_paths([job])
    assert [(d["range"]["start"]["line"] + 1, d["range"]["start"]["character"] + 1, d["code"], d["message"])
            for d in found] == [(d.line, d.col, d.code, d.message) for d in expected]
    assert codes(found) == [(4, "G504"), (5, "S208")]  # drill, m100, change_tool resolve
    assert {d["source"] for d in found} == {"ecnc"}
    assert [d["severity"] for d in found] == [2, 1]  # warning, error
    s208 = found[1]["range"]
    assert (s208["start"]["character"], s208["end"]["character"]) == (0, 5)  # the word, not the line


def test_diagnostics_follow_every_change(client: LspClient, folder: Path) -> None:
    uri = client.open(folder / "job.nc")
    assert (5, "S208") in codes(client.diagnostics(uri))
    client.change(uri, "G0 X1\nIf [#1 == 1]\n", 2)
    client.change(uri, "G0 X1\nIf [#1 == 1]\nG0 X10+5\n", 3)
    found = client.diagnostics(uri)
    while codes(found) != [(2, "S204"), (3, "E105")]:  # changes typed quickly are linted once, after the last
        found = client.diagnostics(uri)
    assert "write X[10+5]" in found[1]["message"]


def test_unsaved_macro_file_resolves_the_jobs_calls(client: LspClient, folder: Path) -> None:
    job_uri = client.open(folder / "job.nc")
    assert (5, "S208") in codes(client.diagnostics(job_uri))
    client.open(folder / "macro.cnc", MACRO + "Sub nowhere\nEndSub\n")
    found = client.diagnostics(job_uri)  # the job is linted again against the editor's macro.cnc
    assert (5, "S208") not in codes(found)


def test_latin1_crlf_macro_file_is_read_like_the_linter_reads_it(client: LspClient, folder: Path) -> None:
    (folder / "macro.cnc").write_bytes(b";@unit mm\r\nSub messen ; Werkzeugl\xe4nge messen\r\n  G0 Z10\r\nEndSub\r\n")
    (folder / "job.nc").write_text("GoSub messen\n")
    uri = client.open(folder / "job.nc")
    assert client.diagnostics(uri) == []
    assert "Werkzeuglänge messen" in hover(client, uri, 0, 8)


# --------------------------------------------------------------------------- hover


@pytest.mark.parametrize(("line", "character", "wanted"), [
    (3, 2, ["**G38.2**: straight probe", "Words: `X Y Z F`", "Modal group: motion", "#5067"]),
    (6, 1, ["**G0**: rapid move", "Modal group: motion"]),
    (6, 13, ["**#5221**: G54 offset X", "Persistent"]),
    (7, 2, ["**dlgmsg**: dialog", "15 fields"]),
    (7, 24, ["**#28**: user variable"]),  # a dlgmsg field number is a parameter
    (1, 8, ["**Sub drill** (macro.cnc, line 2)", "drill one hole at the current XY", "Z-5, retract to R2"]),
    (2, 1, ["**Sub m100**"]),
    (5, 1, ["**M6**: tool change", "Modal group: tool change", "**Sub change_tool**"]),
    (6, 6, ["**#27**: user variable", "Always set to `12.5`"]),
])
def test_hover(client: LspClient, folder: Path, line: int, character: int, wanted: list[str]) -> None:
    text = hover(client, client.open(folder / "job.nc"), line, character)
    for part in wanted:
        assert part in text


def test_workspace_symbols_without_a_workspace_folder(tmp_path: Path) -> None:
    """An editor that opened one file (no root, no folders) still finds the subs of the macro files
    beside it."""
    (tmp_path / "macro.cnc").write_text(MACRO, encoding="utf-8")
    (tmp_path / "job.nc").write_text(JOB, encoding="utf-8")
    lsp = LspClient()
    lsp.request("initialize", {"processId": None, "rootUri": None, "capabilities": {}})
    lsp.notify("initialized", {})
    try:
        uri = lsp.open(tmp_path / "job.nc")
        lsp.diagnostics(uri)
        found = lsp.request("workspace/symbol", {"query": "dri"})
        assert [(s["name"], s["location"]["uri"].rsplit("/", 1)[1]) for s in found] == [("drill", "macro.cnc")]
    finally:
        assert lsp.close() == 0


def test_a_subs_comment_is_shown_as_written(client: LspClient, folder: Path) -> None:
    """Line by line, and ``<rpm>`` stays visible: the comment is a plain-text block, not markdown."""
    (folder / "macro.cnc").write_text(";@unit mm\nSub m101\n  ; Warm-up: M101 P<rpm>\n  ; ramp up _slowly_\n"
                                      "  M3 S#16\nEndSub\n")
    uri = client.open(folder / "job.nc", "M101 P8000\n")
    assert hover(client, uri, 0, 1).endswith("\n\n```text\nWarm-up: M101 P<rpm>\nramp up _slowly_\n```")


def test_hover_on_commands_functions_and_system_variables(client: LspClient, folder: Path) -> None:
    job = folder / "job.nc"
    job.write_text("KIN ON\ntanknife on\nZHCINIT 1 2\n#30 = SQRT[#5067]\n#31 = #30 ; #99 is only in a comment\n")
    uri = client.open(job)
    assert "**KIN**: kinematics" in hover(client, uri, 0, 1)
    assert "**tanknife**: tangential knife" in hover(client, uri, 1, 3)
    assert "**ZHCINIT**" in hover(client, uri, 2, 2)
    assert "**SQRT**: square root" in hover(client, uri, 3, 7)
    assert "**#5067**: probe tripped" in hover(client, uri, 3, 14)
    assert "Read-only" in hover(client, uri, 3, 14)
    assert "Always set" not in hover(client, uri, 4, 7)  # #30 is set from a parameter: no constant
    assert hover(client, uri, 4, 16) == ""  # inside a comment


# --------------------------------------------------------------------------- navigation


def test_definition_of_gosub_m_code_and_m6(client: LspClient, folder: Path) -> None:
    uri = client.open(folder / "job.nc")
    macro = (folder / "macro.cnc").as_uri()
    for line, character, target_line, name in ((1, 7, 1, "drill"), (2, 1, 6, "m100"), (5, 1, 9, "change_tool")):
        result = client.request("textDocument/definition", at(uri, line, character))
        assert result["uri"] == macro
        assert result["range"]["start"] == {"line": target_line, "character": 4}
        assert result["range"]["end"]["character"] == 4 + len(name)


def test_references_across_the_folder(client: LspClient, folder: Path) -> None:
    (folder / "second.nc").write_text("G0 X0\ngosub DRILL\n")
    uri = client.open(folder / "macro.cnc")
    result = client.request("textDocument/references", {**at(uri, 1, 5), "context": {"includeDeclaration": True}})
    found = sorted((Path(r["uri"][len("file://"):]).name, r["range"]["start"]["line"]) for r in result)
    assert found == [("job.nc", 1), ("macro.cnc", 1), ("second.nc", 1)]
    result = client.request("textDocument/references", {**at(uri, 9, 6), "context": {"includeDeclaration": False}})
    assert [(Path(r["uri"]).name, r["range"]["start"]) for r in result] == [("job.nc", {"line": 5, "character": 0})]


def test_document_and_workspace_symbols(client: LspClient, folder: Path) -> None:
    uri = client.open(folder / "macro.cnc")
    symbols = client.request("textDocument/documentSymbol", {"textDocument": {"uri": uri}})
    assert [(s["name"], s["range"]["start"]["line"], s["range"]["end"]["line"]) for s in symbols] == [
        ("drill", 1, 5), ("m100", 6, 8), ("change_tool", 9, 11)]
    found = client.request("workspace/symbol", {"query": "CHANGE"})
    assert any(s["name"] == "change_tool" and s["location"]["uri"] == (folder / "macro.cnc").as_uri() for s in found)


# --------------------------------------------------------------------------- completion


def labels(client: LspClient, uri: str, line: int, character: int) -> list[str]:
    return [item["label"] for item in client.request("textDocument/completion", at(uri, line, character))["items"]]


def test_completion(client: LspClient, folder: Path) -> None:
    job = folder / "job.nc"
    job.write_text("GoSub \nG3\nM\n#27 = #\nX[SQ\ndlg\nG0 ; G\n")
    uri = client.open(job)
    assert labels(client, uri, 0, 6) == ["drill", "m100", "change_tool"]
    assert "G38.2" in labels(client, uri, 1, 2) and "G0" in labels(client, uri, 1, 2)
    found = labels(client, uri, 2, 1)
    assert "M6" in found and "M100" in found  # the built-ins and the file's M-code subs
    params = labels(client, uri, 3, 7)
    assert params[0] == "#27" and "#5067" in params  # the file's own parameters first
    item = next(i for i in client.request("textDocument/completion", at(uri, 3, 7))["items"] if i["label"] == "#5067")
    assert item["detail"] == "probe tripped"
    assert item["textEdit"]["range"]["start"] == {"line": 3, "character": 6}  # replaces the '#' typed
    assert "SQRT" in labels(client, uri, 4, 4)
    assert "dlgmsg" in labels(client, uri, 5, 3)
    assert labels(client, uri, 6, 6) == []  # in a comment


def test_the_number_being_typed_is_not_offered_as_used(client: LspClient, folder: Path) -> None:
    """``#50`` half typed is not "used in this file": only the numbers the file really uses come first."""
    job = folder / "job.nc"
    job.write_text("#27 = 1\nG0 X#50\n")
    uri = client.open(job)
    items = client.request("textDocument/completion", at(uri, 1, 7))["items"]
    used = [i["label"] for i in items if i["detail"].startswith("used in this file")]
    assert used == ["#27"]
    assert items[1]["label"] == "#5001"  # then the system variables


# --------------------------------------------------------------------------- code actions


def quick_fixes(client: LspClient, uri: str, diagnostics: list[dict[str, Any]]) -> list[dict[str, Any]]:
    return client.request("textDocument/codeAction", {
        "textDocument": {"uri": uri}, "range": diagnostics[0]["range"], "context": {"diagnostics": diagnostics}})


@pytest.mark.parametrize(("text", "code", "fixed"), [
    (";@unit mm\nSub a\n  G0 X1\n", "S204", ";@unit mm\nSub a\n  G0 X1\nEndSub\n"),
    (";@unit mm\nSub a\n  If [#1 == 1]\n    G0 X1\nEndSub\n", "S204",
     ";@unit mm\nSub a\n  If [#1 == 1]\n    G0 X1\n  EndIf\nEndSub\n"),
    (";@unit mm\nSub a\nSub b\nEndSub\n", "S205", ";@unit mm\nSub a\nEndSub\nSub b\nEndSub\n"),
    (';@unit mm\ndlgmsg "Setup" "Width" #27\n', "D403", ';@unit mm\ndlgmsg "Setup" "Width" 27\n'),
    (";@unit mm\nG0 X10+5\n", "E105", ";@unit mm\nG0 X[10+5]\n"),
    (";@unit mm\nIf [#1 > 0] AND [#2 > 0] THEN ; both\nEndIf\n", "E106",
     ";@unit mm\nIf [[#1 > 0] AND [#2 > 0]] THEN ; both\nEndIf\n"),
    (";@unit mm\nIf [#1 > 0]] ; check\nEndIf\n", "V304", ";@unit mm\nIf [#1 > 0] ; check\nEndIf\n"),
    ("Sub a\nEndSub\n", "F600", ";@unit mm\nSub a\nEndSub\n"),
    (";@unit mm\nCheck the vise first\n", "F603", ";@unit mm\n; Check the vise first\n"),
])
def test_quick_fix_repairs_the_finding(client: LspClient, folder: Path, text: str, code: str, fixed: str) -> None:
    path = folder / "fix.cnc"
    path.write_text(text)
    uri = client.open(path)
    found = [d for d in client.diagnostics(uri) if d["code"] == code]
    assert found, code
    actions = quick_fixes(client, uri, found[:1])
    preferred = [a for a in actions if a.get("isPreferred")]
    assert preferred, actions
    assert apply(text, preferred[0]["edit"]["changes"][uri]) == fixed
    path.write_text(fixed)
    assert code not in {d.code for d in lint_paths([path])}


@pytest.mark.parametrize(("text", "code", "fixed"), [
    (";@unit mm\nSub a\n  G0 X1\n", "S204", ";@unit mm\nSub a\n  G0 X1\nEndSub\n"),
    (";@unit mm\nSub a\n  G0 X1\nSub b\nEndSub\n", "S205", ";@unit mm\nSub a\n  G0 X1\nEndSub\nSub b\nEndSub\n"),
    ("Sub a\nEndSub\n", "F600", ";@unit mm\nSub a\nEndSub\n"),
])
def test_a_fix_that_adds_a_line_keeps_the_files_crlf(client: LspClient, folder: Path, text: str, code: str,
                                                     fixed: str) -> None:
    """A Windows macro file (CRLF, as EdingCNC writes them) stays CRLF: no bare LF slips in."""
    text, fixed = text.replace("\n", "\r\n"), fixed.replace("\n", "\r\n")
    path = folder / "crlf.cnc"
    path.write_bytes(text.encode())
    uri = client.open(path, text)
    found = [d for d in client.diagnostics(uri) if d["code"] == code]
    preferred = [a for a in quick_fixes(client, uri, found[:1]) if a.get("isPreferred")]
    assert apply(text, preferred[0]["edit"]["changes"][uri]) == fixed


def test_noqa_action_silences_any_finding(client: LspClient, folder: Path) -> None:
    text = "G1 X5 F0 M3 M4 ; noqa: G500\n"
    path = folder / "probe.nc"
    path.write_text(text)
    uri = client.open(path)
    found = client.diagnostics(uri)
    assert codes(found) == [(1, "G503")]
    noqa = [a for a in quick_fixes(client, uri, found) if "noqa" in a["title"]]
    fixed = apply(text, noqa[0]["edit"]["changes"][uri])
    assert fixed == "G1 X5 F0 M3 M4 ; noqa: G500,G503\n"
    path.write_text(fixed)
    assert lint_paths([path]) == []


# --------------------------------------------------------------------------- formatting


def format_request(client: LspClient, uri: str, tab_size: int = 2) -> list[dict[str, Any]] | None:
    return client.request("textDocument/formatting", {
        "textDocument": {"uri": uri}, "options": {"tabSize": tab_size, "insertSpaces": True}})


def test_formatting_prints_each_statement_canonically(client: LspClient, folder: Path) -> None:
    text = ";@unit mm\nsub Drill   ; one hole\ng01 x.5 f100\nif [#1==2] then\n#27=3\nendif\nendsub\n"
    path = folder / "style.cnc"
    path.write_text(text)
    uri = client.open(path)
    formatted = apply(text, format_request(client, uri, 4))
    assert formatted == (";@unit mm\nSub Drill   ; one hole\n    G1 X0.5 F100\n    If [#1 == 2]\n"
                         "        #27 = 3\n    EndIf\nEndSub\n")


def test_formatting_keeps_the_lines_with_errors_and_formats_the_rest(client: LspClient, folder: Path) -> None:
    """Issue 21: a file being written has errors; the lines that parse are formatted all the same."""
    text = "g01 x1\nIf [#1 == 1]\ng0 x10+5\ng0   y2 ; here\n"
    path = folder / "broken.nc"
    path.write_text(text)
    formatted = apply(text, format_request(client, client.open(path)))
    assert formatted == "G1 X1\nIf [#1 == 1]\ng0 x10+5\nG0 Y2   ; here\n"  # the unclosed If, X10+5 as written


# --------------------------------------------------------------------------- what editors really send


def test_untitled_document_is_checked_and_navigated(client: LspClient) -> None:
    uri = "untitled:Untitled-1"
    client.notify("textDocument/didOpen", {"textDocument": {
        "uri": uri, "languageId": "edingcnc", "version": 1, "text": "G0 X1+2\nGoSub a\nSub a\nEndSub\n"}})
    assert codes(client.diagnostics(uri)) == [(1, "E105")]
    assert client.request("textDocument/definition", at(uri, 1, 7)) == {
        "uri": uri, "range": {"start": {"line": 2, "character": 4}, "end": {"line": 2, "character": 5}}}
    assert client.request("textDocument/hover", at(uri, 40, 1)) is None  # past the end


def test_incremental_changes_and_utf16_columns(client: LspClient, folder: Path) -> None:
    uri = client.open(folder / "job.nc", "G0 X1\n")
    assert client.diagnostics(uri) == []
    client.notify("textDocument/didChange", {"textDocument": {"uri": uri, "version": 2}, "contentChanges": [
        {"range": {"start": {"line": 0, "character": 5}, "end": {"line": 0, "character": 5}}, "text": "+5"}]})
    assert codes(client.diagnostics(uri)) == [(1, "E105")]
    client.change(uri, "(MSG Maß 😀) G0 X1+5\n", 3)  # the emoji is two UTF-16 units
    found = client.diagnostics(uri)
    assert found[0]["range"]["start"] == {"line": 0, "character": 16}  # X is code point 15
    assert "**G0**" in hover(client, uri, 0, 14)


def test_folding_ranges_cover_subs_ifs_and_whiles(client: LspClient, folder: Path) -> None:
    text = ";@unit mm\nSub a\n  If [#1 == 1]\n    G0 X1\n  Else\n    G0 X2\n  EndIf\n  While [0]\n  EndWhile\nEndSub\n"
    uri = client.open(folder / "fold.cnc", text)
    found = client.request("textDocument/foldingRange", {"textDocument": {"uri": uri}})
    assert sorted((r["startLine"], r["endLine"]) for r in found) == [(1, 8), (2, 5)]  # an empty While folds nothing


def test_macro_file_changed_on_disk_rechecks_the_open_job(client: LspClient, folder: Path) -> None:
    uri = client.open(folder / "job.nc")
    assert (5, "S208") in codes(client.diagnostics(uri))
    macro = folder / "macro.cnc"
    macro.write_text(MACRO + "Sub nowhere\nEndSub\n")
    client.notify("workspace/didChangeWatchedFiles", {"changes": [{"uri": macro.as_uri(), "type": 2}]})
    assert (5, "S208") not in codes(client.diagnostics(uri))
