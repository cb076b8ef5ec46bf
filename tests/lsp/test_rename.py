"""Issue 21 item 8: the language server renames subs and variables across the macro files."""
from __future__ import annotations

from collections.abc import Iterator
from pathlib import Path
from typing import Any

import pytest

from tests.lsp.client import LspClient, at
from tests.lsp.test_server import apply

MACRO = """;@unit mm
Sub drill
  G81 Z-5 R2 F#1001
  G80
EndSub
Sub m100
  GoSub drill
EndSub
Sub change_tool
  dlgmsg "Tool length" "Length" 1001
  GetToolInfo 1 1001
EndSub
"""
USER = """Sub user_1
  GoSub drill ; drill here
  #1001 = 2   ; (#1001 in a comment stays)
  modbus s1 f3 a100 n1 u1001
  msg "#1001 in a string stays"
EndSub
Sub spot
EndSub
"""
JOB = "#1001 = 5\nGoSub drill\nG0 X#1001\n"


@pytest.fixture(scope="module")
def client(tmp_path_factory: pytest.TempPathFactory) -> Iterator[LspClient]:
    lsp = LspClient()
    lsp.initialize(tmp_path_factory.mktemp("workspace"))
    yield lsp
    assert lsp.close() == 0


@pytest.fixture
def folder(tmp_path: Path) -> Path:
    for name, text in (("macro.cnc", MACRO), ("user_macro.cnc", USER), ("job.nc", JOB)):
        (tmp_path / name).write_text(text)
    return tmp_path


def rename(client: LspClient, uri: str, line: int, col: int, new: str) -> dict[str, Any]:
    return client.request("textDocument/rename", {**at(uri, line, col), "newName": new})


def applied(folder: Path, edit: dict[str, Any]) -> dict[str, str]:
    return {Path(uri.removeprefix("file://")).name: apply((folder / Path(uri).name).read_text(), edits)
            for uri, edits in edit["changes"].items()}


@pytest.mark.slow
def test_the_server_offers_rename_with_prepare(client: LspClient, folder: Path) -> None:
    uri = client.open(folder / "job.nc")
    assert client.request("textDocument/prepareRename", at(uri, 1, 8)) == {
        "range": {"start": {"line": 1, "character": 6}, "end": {"line": 1, "character": 11}}, "placeholder": "drill"}
    assert client.request("textDocument/prepareRename", at(uri, 2, 5))["placeholder"] == "1001"
    assert client.request("textDocument/prepareRename", at(uri, 2, 0)) is None  # G0: nothing to rename


def test_a_sub_is_renamed_where_defined_and_wherever_called(client: LspClient, folder: Path) -> None:
    uri = client.open(folder / "job.nc")
    texts = applied(folder, rename(client, uri, 1, 8, "drill_hole"))
    assert texts["job.nc"] == JOB.replace("GoSub drill", "GoSub drill_hole")
    assert texts["macro.cnc"] == MACRO.replace("drill", "drill_hole")
    assert texts["user_macro.cnc"] == USER.replace("GoSub drill", "GoSub drill_hole")


def test_a_variable_is_renumbered_in_every_file_and_every_kind_of_use(client: LspClient, folder: Path) -> None:
    uri = client.open(folder / "user_macro.cnc")
    texts = applied(folder, rename(client, uri, 2, 3, "#1050"))
    assert texts["job.nc"] == JOB.replace("1001", "1050")
    assert texts["macro.cnc"] == MACRO.replace("1001", "1050")  # F#1001, the dlgmsg field, GetToolInfo's target
    assert texts["user_macro.cnc"] == USER.replace("#1001 = 2", "#1050 = 2").replace("u1001", "u1050")


@pytest.mark.slow
@pytest.mark.parametrize("line, col, new, reason", [
    (5, 5, "m101", "Sub m100 is called by its name"),            # an M-code sub
    (8, 5, "swap", "Sub change_tool is called by its name"),     # the controller's
    (1, 5, "spot", "a Sub spot exists already"),
    (1, 5, "m100", "Sub m100 would be called by the controller or an M code"),
    (1, 5, "two words", "is not a sub name"),
    (2, 14, "#5001", "#5001 is not a user variable"),
    (2, 14, "#100", "#100 is used already"),                    # in other.nc
])
def test_a_rename_that_would_change_the_program_is_refused(client: LspClient, folder: Path, line: int, col: int,
                                                          new: str, reason: str) -> None:
    (folder / "other.nc").write_text("#100 = 1\n")
    uri = client.open(folder / "macro.cnc")
    error = client.request_error("textDocument/rename", {**at(uri, line, col), "newName": new})
    assert reason in error["message"] and error["code"] == -32803
