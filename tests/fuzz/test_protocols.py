"""Fuzzing the two protocols (issue 43): the debug adapter's byte stream (framing and request
arguments) and the language server's requests.  Whatever comes in, every request is answered,
no internal error shows, and the session goes on.

CI runs the derandomized ``ci`` profile; hunt with ``--hypothesis-profile=fuzz``.
"""
from __future__ import annotations

import io
import json
import tempfile
import threading
from collections.abc import Iterator
from pathlib import Path
from typing import Any

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from edingcnc_lang.debug import serve
from edingcnc_lang.debug.arguments import REQUESTS

EMPTY_MACRO = Path(__file__).resolve().parents[1] / "interpreter" / "data" / "empty_macro.cnc"
RELAXED = settings(deadline=None, suppress_health_check=[HealthCheck.too_slow, HealthCheck.data_too_large,
                                                         HealthCheck.function_scoped_fixture])

# JSON values, with the ones that broke the adapter before: huge numbers, NaN, NUL, long text, nesting
_SCALARS = st.one_of(st.none(), st.booleans(), st.integers(-2**63, 2**64), st.floats(allow_nan=True),
                     st.text(max_size=20), st.sampled_from(["#-620", "#0", "#6000", "#5380", "9" * 5000, "a\0b",
                                                            "x" * 5000, "job.nc", "M6", "% 3", "#1 == 1"]))
_JSON = st.recursive(_SCALARS, lambda inner: st.one_of(st.lists(inner, max_size=3),
                                                       st.dictionaries(st.text(max_size=8), inner, max_size=3)),
                     max_leaves=8)
_FIELDS = sorted({"program", "cwd", "logDir", "maxSteps", "stopOnEntry", "noDebug", "answers", "source",
                  "breakpoints", "lines", "name", "value", "variablesReference", "expression", "context", "frameId",
                  "threadId", "filters", "line", "hitCondition", "condition", "logMessage", "path", "macro"})
_ARGUMENTS = st.one_of(_JSON, st.dictionaries(st.sampled_from(_FIELDS), _JSON, max_size=5))
_COMMANDS = st.one_of(st.sampled_from(sorted(REQUESTS) + ["configurationDone", "threads"]), _JSON)


def _frame(body: bytes, how: str) -> bytes:
    length = {"ok": b"%d" % len(body), "negative": b"-1", "huge": b"100000000000", "word": b"abc",
              "float": b"%d.0" % len(body)}[how]
    return b"Content-Length: " + length + b"\r\n\r\n" + body


_MESSAGES = st.tuples(_COMMANDS, _ARGUMENTS, st.sampled_from(["ok"] * 6 + ["negative", "huge", "word", "float"]),
                      st.sampled_from(["request"] * 8 + ["event", "x"]))


def _messages(data: bytes) -> Iterator[dict[str, Any]]:
    stream = io.BytesIO(data)
    while True:
        header = stream.readline()
        if not header:
            return
        length = int(header.split(b":")[1])
        stream.readline()
        yield json.loads(stream.read(length))


@settings(RELAXED, max_examples=60)
@given(st.lists(_MESSAGES, max_size=8), st.binary(max_size=30))
def test_the_debug_adapter_answers_every_request_of_any_stream(messages: list[tuple[Any, Any, str, str]],
                                                                 noise: bytes) -> None:
    with tempfile.TemporaryDirectory() as folder:
        root = Path(folder)
        (root / "job.nc").write_text("#1 = 1\nlogmsg \"x\"\nM30\n")
        start = [("initialize", {"adapterID": "fuzz"}, "ok", "request"),
                 ("launch", {"program": "job.nc", "cwd": folder, "macro": str(EMPTY_MACRO), "logDir": folder,
                             "stopOnEntry": True}, "ok", "request")]
        sequence = [*start, *messages]
        data = b"".join(_frame(json.dumps({"seq": seq, "type": kind, "command": command, "arguments": arguments})
                               .encode(), how) for seq, (command, arguments, how, kind) in enumerate(sequence, 1))
        out = io.BytesIO()
        assert serve(io.BytesIO(data + noise), out) == 0
        sent = list(_messages(out.getvalue()))
        responses = [m for m in sent if m["type"] == "response"]
        ended = min((r["request_seq"] for r in responses if r["command"] == "disconnect" and r["success"]),
                    default=len(sequence))  # a disconnect ends the session: what follows is not read
        framed = {seq for seq, (_c, _a, how, kind) in enumerate(sequence, 1)
                  if how == "ok" and kind != "event" and seq <= ended}
        assert framed <= {r["request_seq"] for r in responses}  # every request read is answered
        assert all(isinstance(r["success"], bool) and isinstance(r["command"], str) for r in responses)
        assert all(isinstance(r["message"], str) for r in responses if not r["success"])
        assert not any("internal error" in json.dumps(m) for m in sent)
        assert sorted(p.name for p in root.iterdir()) in (["job.nc"], ["job.nc", "log.txt"])


# ----------------------------------------------------------------------------- the language server

_POSITION = st.fixed_dictionaries({"line": st.one_of(st.integers(-5, 10), _JSON),
                                   "character": st.one_of(st.integers(-5, 400), _JSON)})
_METHODS = st.sampled_from(["textDocument/hover", "textDocument/definition", "textDocument/references",
                            "textDocument/completion", "textDocument/rename", "textDocument/prepareRename",
                            "textDocument/formatting", "textDocument/documentSymbol", "textDocument/foldingRange",
                            "textDocument/codeAction", "workspace/symbol"])


def _drain(stream: Any) -> None:
    """Read the server's stderr as an editor does: each refused request logs a line there, and a
    full pipe would block the server (a long hunt refuses thousands)."""
    try:
        while stream.read(65536):
            pass
    except (OSError, ValueError):  # closed when the test ends
        pass


@pytest.fixture(scope="module")
def lsp(tmp_path_factory: pytest.TempPathFactory) -> Iterator[tuple[Any, str]]:
    pytest.importorskip("pygls")
    from tests.lsp.client import LspClient

    root = tmp_path_factory.mktemp("fuzz")
    (root / "macro.cnc").write_text("Sub drill\n  G81 Z-5 R2 F100\nEndSub\n")
    client = LspClient()
    threading.Thread(target=_drain, args=(client.proc.stderr,), daemon=True).start()
    client.initialize(root)
    uri = client.open(root / "job.nc", "GoSub drill\n#27 = [#27 + 1]\nG" + "9" * 310 + " M100\n"
                      'dlgmsg "w" 28\nM30\n')
    yield client, uri
    assert client.close() == 0


@settings(RELAXED, max_examples=80)
@given(_METHODS, st.one_of(_JSON, st.fixed_dictionaries(
    {"textDocument": st.one_of(st.just("<uri>"), _JSON), "position": st.one_of(_POSITION, _JSON)},
    optional={"newName": st.one_of(st.sampled_from(["bar", "#30", "#" + "9" * 5000, "a b"]), _JSON),
              "options": st.one_of(st.fixed_dictionaries({"tabSize": _JSON, "insertSpaces": _JSON}), _JSON),
              "context": _JSON, "query": _JSON})))
def test_the_language_server_answers_every_request(lsp: tuple[Any, str], method: str, params: Any) -> None:
    client, uri = lsp
    if isinstance(params, dict) and params.get("textDocument") == "<uri>":
        params = {**params, "textDocument": {"uri": uri}}
    answer = client._reply(method, params)  # a queue.Empty here is a request left unanswered
    assert "result" in answer or answer["error"]["code"] in (-32602, -32803, -32801)
