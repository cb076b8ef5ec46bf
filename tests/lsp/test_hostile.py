"""The language server against a hostile client (issue 43): every request is answered (an error
for params that do not fit), no file but a regular one is ever opened, rename and references
take time linear in the document and let other requests through meanwhile."""
from __future__ import annotations

import os
import time
from collections.abc import Iterator
from pathlib import Path

import pytest

from edingcnc_lang.gcpause import whole_trees
from edingcnc_lang.lsp import navigation, rename
from edingcnc_lang.lsp.model import LanguageModel
from tests.lsp.client import LspClient, at

pytest.importorskip("pygls")
INVALID_PARAMS = -32602


@pytest.fixture(scope="module")
def client(tmp_path_factory: pytest.TempPathFactory) -> Iterator[LspClient]:
    lsp = LspClient()
    lsp.initialize(tmp_path_factory.mktemp("workspace"))
    yield lsp
    assert lsp.close() == 0


def formatting(uri: str, tab_size: object) -> dict[str, object]:
    return {"textDocument": {"uri": uri}, "options": {"tabSize": tab_size, "insertSpaces": True}}


@pytest.mark.parametrize("tab_size", [-5, 2**31, 2**64, "x", None, [4]])
def test_formatting_with_a_bad_tab_size_is_answered_with_an_error(client: LspClient, tmp_path: Path,
                                                                   tab_size: object) -> None:
    job = tmp_path / "f.nc"
    job.write_text("If [#1 == 1]\nG0 X1\nEndIf\n")
    uri = client.open(job)
    error = client.request_error("textDocument/formatting", formatting(uri, tab_size))
    assert error["code"] == INVALID_PARAMS and "tab_size" in error["message"] or "options" in error["message"]
    assert client.request("textDocument/formatting", formatting(uri, 2))  # and the server goes on


@pytest.mark.parametrize(("method", "params"), [
    ("textDocument/hover", None),
    ("textDocument/hover", "abc"),
    ("textDocument/hover", {"textDocument": 5}),
    ("textDocument/hover", {"textDocument": {"uri": "file:///x.nc"}, "position": {"line": "a", "character": 0}}),
    ("textDocument/definition", {"textDocument": {"uri": "file:///x.nc"}, "position": {"line": 0}}),
    ("textDocument/references", {"textDocument": {"uri": "file:///x.nc"}, "position": {"line": 0, "character": 0}}),
    ("textDocument/rename", {"textDocument": {"uri": "file:///x.nc"}, "position": {"line": 0, "character": 0}}),
    ("textDocument/completion", {"textDocument": {"uri": "file:///x.nc"}, "position": [0, 0]}),
    ("workspace/symbol", {}),
    ("textDocument/codeAction", {"textDocument": {"uri": "file:///x.nc"}}),
])
def test_a_request_with_bad_params_is_answered_with_an_error(client: LspClient, method: str, params: object) -> None:
    error = client.request_error(method, params)
    assert error["code"] == INVALID_PARAMS and method in error["message"]
    assert client.request("workspace/symbol", {"query": "zzz"}) == []


def test_params_nested_past_pythons_recursion_are_refused(client: LspClient) -> None:
    """900 levels: JSON reads them, clamping positions recursed past Python's limit (no answer)."""
    body = ('{"jsonrpc": "2.0", "id": 900, "method": "textDocument/hover", "params": ' + "[" * 900 + "]" * 900
            + "}").encode()
    assert client.proc.stdin is not None
    client.proc.stdin.write(b"Content-Length: %d\r\n\r\n" % len(body) + body)
    client.proc.stdin.flush()
    while True:
        message = client._take()
        if message.get("id") == 900:
            break
        client._keep(message)
    assert message["error"] == {"code": INVALID_PARAMS,
                                "message": "textDocument/hover: invalid params: nested too deeply"}


def test_an_unknown_method_is_answered_method_not_found(client: LspClient) -> None:
    assert client._reply("ecnc/nothing", {"a": 1})["error"]["code"] == -32601
    client._next += 1
    client._send({"id": client._next, "method": "ecnc/nothing"})  # no params at all: pygls could not read it
    while True:
        message = client._take()
        if message.get("id") == client._next:
            break
        client._keep(message)
    assert message["error"]["code"] == -32601 and "not a method" in message["error"]["message"]


@pytest.mark.skipif(not hasattr(os, "mkfifo"), reason="FIFOs are POSIX")
def test_a_fifo_or_device_not_open_in_the_editor_is_never_opened(client: LspClient, tmp_path: Path) -> None:
    fifo = tmp_path / "macro.cnc"
    os.mkfifo(fifo)  # opening it would block the server until something writes to it
    job = tmp_path / "job.nc"
    job.write_text("GoSub drill\nM30\n")
    uri = client.open(job)  # its macro.cnc beside it is the FIFO
    assert client.request("textDocument/definition", at(uri, 0, 7)) is None
    for path in (fifo, Path("/dev/zero"), tmp_path):
        other = at(path.as_uri(), 0, 1)
        assert client.request("textDocument/hover", other) is None
        assert client.request("textDocument/definition", other) is None
        assert client.request("textDocument/references", {**other, "context": {"includeDeclaration": True}}) == []
        assert client.request("textDocument/documentSymbol", {"textDocument": {"uri": path.as_uri()}}) == []
        assert client.request("textDocument/formatting", formatting(path.as_uri(), 2)) is None
    assert isinstance(client.request("workspace/symbol", {"query": ""}), list)


@pytest.mark.parametrize(("line", "hovered"), [
    ("G" + "9" * 310 + " X1", ""), ("M" + "9" * 400, ""), ("#" + "9" * 5000 + " = 1", "not a valid parameter"),
    ("G0 X#" + "0" * 30 + "5008", "current tool"),
])
def test_hover_over_numbers_past_every_table(client: LspClient, tmp_path: Path, line: str, hovered: str) -> None:
    job = tmp_path / "n.nc"
    uri = client.open(job, line + "\nM30\n")
    column = 4 if line.startswith("G0") else 2
    result = client.request("textDocument/hover", at(uri, 0, column))
    assert (result["contents"]["value"] if result else "").find(hovered) >= 0
    client.request("textDocument/definition", at(uri, 0, column))
    client.request("textDocument/completion", at(uri, 0, column))
    refused = client.request_error("textDocument/rename", {**at(uri, 0, column), "newName": "#" + "9" * 5000})
    assert len(refused["message"]) < 300


def calls(count: int) -> str:
    return "Sub foo\n#1 = 1\nEndSub\n" + "GoSub foo\n" * count


@pytest.mark.slow
def test_other_requests_are_answered_while_a_rename_is_worked_out(client: LspClient, tmp_path: Path) -> None:
    job = tmp_path / "macro.cnc"
    uri = client.open(job, calls(100_000))
    assert client.request("textDocument/hover", at(uri, 0, 5))  # parsed
    client._next += 1
    rename_id = client._next
    client._send({"id": rename_id, "method": "textDocument/rename", "params": {**at(uri, 0, 5), "newName": "bar"}})
    client._next += 1
    hover_id = client._next
    client._send({"id": hover_id, "method": "textDocument/hover", "params": at(uri, 1, 1)})
    order = []
    while len(order) < 2:
        message = client._take()
        if message.get("id") in (rename_id, hover_id):
            order.append(message["id"])
            if message["id"] == rename_id:
                assert len(message["result"]["changes"][uri]) == 100_001
        else:
            client._keep(message)
    assert order == [hover_id, rename_id]


def _cpu_seconds(count: int) -> float:
    path = "/nowhere/macro.cnc"
    model = LanguageModel()
    model.set_text(path, calls(count))
    model.source(path)
    start = time.process_time()
    with whole_trees():  # as the server works them out (server.in_worker)
        assert len(rename.rename(model, path, 0, 5, "bar")[path]) == count + 1
        assert len(navigation.references(model, path, 0, 5, True)) == count + 1
    return time.process_time() - start


@pytest.mark.slow
def test_rename_and_references_take_time_linear_in_the_calls() -> None:
    small, large = _cpu_seconds(20_000), _cpu_seconds(80_000)
    assert large < 8 * max(small, 0.05)  # 4x the calls: about 4x the time (quadratic would be 16x)
