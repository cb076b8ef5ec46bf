"""Names in the variables view, and data breakpoints: stop when a parameter is written."""
from __future__ import annotations

from pathlib import Path

import pytest

from edingcnc_lang.debug.data_breakpoints import DataBreakpoints, number_of
from edingcnc_lang.varmap.names import label

from .dap_client import DapClient

MACRO = """;@unit mm
;@var #1552 thread_major_diameter "diameter A"
Sub user_1
    #1552 = 12
EndSub
"""
JOB = """#1552 = 10 ; overwritten below
#100 = 1 ;; pass counter
While [#100 < 3]
    #100 = [#100 + 1]
EndWhile
GoSub user_1
G0 X[#1552]
M30
"""


@pytest.fixture
def client():
    dap = DapClient()
    yield dap
    dap.close()


def _launch(client: DapClient, tmp_path: Path) -> dict:
    (tmp_path / "macro.cnc").write_text(MACRO, encoding="utf-8")
    (tmp_path / "job.nc").write_text(JOB, encoding="utf-8")
    caps = client.request("initialize", adapterID="ecnc", linesStartAt1=True, columnsStartAt1=True)
    client.request("launch", program="job.nc", cwd=str(tmp_path), macro=str(tmp_path / "macro.cnc"))
    client.wait("initialized")
    return caps


def test_stop_when_a_variable_is_written(tmp_path: Path, client: DapClient) -> None:
    caps = _launch(client, tmp_path)
    assert caps["supportsDataBreakpoints"]
    info = client.request("dataBreakpointInfo", name="thread_major_diameter")
    assert info == {"dataId": "1552", "description": "when #1552 thread_major_diameter is written",
                    "accessTypes": ["write"], "canPersist": True}
    assert client.request("dataBreakpointInfo", name="#100")["dataId"] == "100"
    assert client.request("dataBreakpointInfo", name="nothing")["dataId"] is None
    placed = client.request("setDataBreakpoints", breakpoints=[{"dataId": "1552", "accessType": "write"}])
    assert placed["breakpoints"][0]["verified"]
    client.request("configurationDone")
    first = client.wait("stopped")
    assert first["reason"] == "data breakpoint" and first["hitBreakpointIds"] == [placed["breakpoints"][0]["id"]]
    assert first["description"] == "#1552 thread_major_diameter = 10 (written at job.nc:1)"
    assert client.stack() == [("job", 2)]  # stopped before the statement after the write
    user = client.scope("User")
    assert user["#1552"]["name"] == "#1552 thread_major_diameter" and user["#1552"]["value"] == "10"
    client.request("continue", threadId=1)
    second = client.wait("stopped")
    assert second["description"] == "#1552 thread_major_diameter = 12 (written at macro.cnc:4)"
    assert client.stack()[0] == ("job", 7)  # the return from user_1: the next statement runs
    assert client.scope("User")["#100"]["name"] == "#100 pass counter"
    client.request("continue", threadId=1)
    client.wait("terminated")


def test_a_watch_set_at_a_stop_counts_every_write(tmp_path: Path, client: DapClient) -> None:
    _launch(client, tmp_path)
    client.request("setBreakpoints", source={"path": str(tmp_path / "job.nc")}, breakpoints=[{"line": 3}])
    client.request("configurationDone")
    assert client.wait("stopped")["reason"] == "breakpoint"
    client.request("setDataBreakpoints", breakpoints=[{"dataId": "100"}])
    client.request("continue", threadId=1)
    hits = []
    for _ in range(2):
        event = client.wait("stopped")
        hits.append(event["description"])
        client.request("continue", threadId=1)
    assert hits == ["#100 pass counter = 2 (written at job.nc:4)", "#100 pass counter = 3 (written at job.nc:4)"]
    client.wait("terminated")


def test_set_variable_takes_a_named_variable(tmp_path: Path, client: DapClient) -> None:
    _launch(client, tmp_path)
    client.request("setDataBreakpoints", breakpoints=[{"dataId": "100"}])
    client.request("configurationDone")
    client.wait("stopped")
    assert client.request("setVariable", variablesReference=1, name="#100 pass counter", value="7")["value"] == "7"
    assert client.scope("User")["#100"]["value"] == "7"


def test_the_watch_set() -> None:
    data = DataBreakpoints()
    answers = data.set([{"dataId": "5011"}, {"dataId": "x"}, {"dataId": "27", "accessType": "read"}, {"dataId": "6000"}])
    assert [a["verified"] for a in answers] == [True, False, False, False]
    data.written(27)
    assert data.take() is None
    data.written(5011)
    data.written(5011)
    assert data.take() == 5011 and data.take() is None
    assert number_of("#1552 thread_major_diameter", {}) == 1552 and number_of("Pitch", {1554: "pitch"}) == 1554
    assert label(5, {}) == "#5" and label(5, {5: "five"}) == "#5 five"
