"""``ecnc debug`` driven over stdio by a real DAP client, as an editor drives it."""
from __future__ import annotations

import shutil
import sys
from pathlib import Path

import pytest

from edingcnc_lang.runner import packaged_macro

from .dap_client import DapClient

pytestmark = pytest.mark.slow  # the whole module (pyproject's slow marker)

MACRO = str(packaged_macro())
CHANGE_TOOL_FIRST = 66  # "#5015 = 0", the first statement of Sub change_tool in the packaged macro
JOB = "G21 G90\r\n#1 = 5\r\nG1 X10 Y5 F500\r\nT2 M6\r\n#2 = [#1 * 2]\r\nG0 X0\r\nM30\r\n"  # CRLF, as on the machine


def write(tmp_path: Path, text: str, name: str = "job.nc") -> Path:
    job = tmp_path / name
    job.write_bytes(text.encode("latin-1"))
    return job


@pytest.fixture
def client():
    dap = DapClient()
    yield dap
    dap.close()


def everything(dap: DapClient) -> dict[str, dict[str, str]]:
    """Every scope's variables, name -> value (what "restored exactly" is measured on)."""
    scopes = dap.request("scopes", frameId=1)["scopes"]
    return {s["name"]: {v.get("evaluateName") or v["name"]: v["value"] for v in dap.request("variables", variablesReference=s["variablesReference"])["variables"]}
            for s in scopes}


def test_a_tool_change_sub_debugged_from_a_job(tmp_path, client) -> None:
    job = write(tmp_path, JOB)
    caps = client.start({MACRO: [{"line": 64}]}, program=job.name, cwd=str(tmp_path))
    assert caps["supportsStepBack"] and caps["supportsLogPoints"] and caps["supportsSetVariable"]
    assert client.placed[MACRO][0] == {"id": 1, "verified": True, "line": CHANGE_TOOL_FIRST,
                                       "source": {"path": MACRO}}  # the Sub line moves to its first statement
    assert client.wait("stopped")["reason"] == "breakpoint"
    assert client.stack() == [("change_tool", CHANGE_TOOL_FIRST), ("job", 4)]
    assert client.top()["source"]["path"] == MACRO

    # variables: what they are, where they were written; evaluate in the dialect
    system = client.scope("System")
    assert system["#5011"]["value"] == "2" and system["#5011"]["type"] == "new tool · written at job.nc:4"
    assert client.scope("User")["#1"]["type"].endswith("job.nc:2")
    assert client.value("#5011") == "2"
    assert client.value("[2 * SIN[30]]") == "1"
    assert client.value("[#5011 == 2] and [#5008 == 0]") == "1"
    assert client.request("evaluate", expression="#5071", context="hover")["result"] == "10"
    modal = client.scope("Modal")
    assert modal["units"]["value"] == "G21" and modal["motion"]["value"] == "G1"
    assert client.scope("Position")["work Y"]["value"] == "5"

    # set a persistent variable, from the Variables view and from the console
    assert client.request("setVariable", variablesReference=2, name="#4005", value="[10 + 5]")["value"] == "15"
    assert client.request("evaluate", expression="#4006 = 7", context="repl")["result"] == "#4006 = 7"
    assert client.scope("Persistent")["#4006"]["type"] == "persistent user variable · set in the debugger"
    refused = client.raw("setVariable", variablesReference=3, name="#5001", value="1")
    assert not refused["success"] and "read-only" in refused["message"]

    # step: next, in and out; then back, which restores everything as it was
    before = everything(client)
    client.step("next")
    assert client.stack()[0] == ("change_tool", 67)
    client.step("stepBack")
    assert client.stack() == [("change_tool", CHANGE_TOOL_FIRST), ("job", 4)]
    assert everything(client) == before  # the edits made at this stop are part of it
    assert client.scope("Persistent")["#4005"]["type"] == "persistent user variable · set in the debugger"

    client.step("stepOut")
    assert client.stack() == [("job", 5)]
    after_tool_change = everything(client)
    assert after_tool_change["System #5000.."]["#5008"] == "2"
    assert after_tool_change["Position"]["machine X"] == "15"  # G53 X[#4005] went where we said
    client.step("next")
    assert client.stack() == [("job", 6)]
    assert client.value("#2") == "10"
    client.step("stepBack")
    assert everything(client) == after_tool_change
    client.step("stepBack")  # back over the whole tool change, to the M6 line
    assert client.stack() == [("job", 4)]
    assert client.value("#5008") == "0" and client.value("#4005") == "0"  # before the edit, made in the sub
    client.step("stepIn")
    assert client.stack()[0] == ("change_tool", CHANGE_TOOL_FIRST)

    client.request("continue", threadId=1)
    assert client.wait("exited") == {"exitCode": 0}
    client.wait("terminated")
    assert "msg: Change tool: take out T0, put in T2" in client.outputs()


LOOP = """#1 = 0
While [#1 < 5]
    #1 = [#1 + 1]
    GoSub count
EndWhile
M30
Sub count
    ; add up
    #2 = [#2 + #1]
EndSub
"""


def test_conditions_hit_counts_log_points_and_reverse_continue(tmp_path, client) -> None:
    job = write(tmp_path, LOOP)
    client.start({str(job): [{"line": 3, "condition": "#1 == 3"},
                             {"line": 8, "hitCondition": ">= 4"},
                             {"line": 4, "logMessage": "sum so far {#2} at #1 = {#1}"},
                             {"line": 40}]},
                 program=str(job))
    placed = client.placed[str(job)]
    assert [b["line"] for b in placed[:3]] == [3, 9, 4]  # the comment line moves to the next statement
    assert not placed[3]["verified"] and "no statement on or after line 40" in placed[3]["message"]
    client.wait("stopped")
    assert client.stack()[0] == ("job", 3) and client.value("#1") == "3"
    client.request("continue", threadId=1)
    client.wait("stopped")
    assert client.stack() == [("count", 9), ("job", 4)]
    assert client.value("#1") == "4" and client.value("#2") == "6"  # 4th hit: #1 is 4, the sum 1+2+3
    logs = [e["body"]["output"] for e in client.seen if e.get("event") == "output"]
    assert logs[:4] == [f"sum so far {s} at #1 = {i}\n" for i, s in ((1, 0), (2, 1), (3, 3), (4, 6))]

    client.step("reverseContinue")  # back to the last breakpoint that held: #1 == 3 on line 3
    assert client.stack() == [("job", 3)] and client.value("#1") == "3" and client.value("#2") == "6"
    client.request("continue", threadId=1)
    client.wait("stopped")
    assert client.stack()[0] == ("count", 9) and client.value("#1") == "4"


def test_stepping_back_retraces_every_step(tmp_path, client) -> None:
    """next through a job (plain lines, a While, GoSubs), then stepBack all the way to its start."""
    job = write(tmp_path, "G0 X1\nG1 X2 F100\n" + LOOP.replace("M30", "G0 X3\nG0 X4\nM30"))
    client.start({str(job): [{"line": 1}]}, program=str(job))
    client.wait("stopped")
    seen = [(client.stack()[0], client.value("#1"), client.value("#2"), client.value("#5001"))]
    while seen[-1][0] != ("job", 10):  # M30
        client.step("next")
        seen.append((client.stack()[0], client.value("#1"), client.value("#2"), client.value("#5001")))
    assert [place[1] for place, *_ in seen[:9]] == [1, 2, 3, 4, 5, 6, 4, 5, 6]  # the While line at every turn
    back = [seen[-1]]
    while len(back) < len(seen):
        client.step("stepBack")
        back.append((client.stack()[0], client.value("#1"), client.value("#2"), client.value("#5001")))
    assert back == seen[::-1]


def test_function_breakpoints(tmp_path, client) -> None:
    job = write(tmp_path, "T3 M6\nM100\nM30\nSub m100\n    #3 = 1\nEndSub\n")
    client.start({}, functions=["M6", "m100", "no_such_sub"], program=str(job))
    assert [b["verified"] for b in client.functions] == [True, True, False]
    assert "no Sub no_such_sub" in client.functions[2]["message"]
    assert client.wait("stopped")["reason"] == "function breakpoint"
    assert client.stack() == [("change_tool", CHANGE_TOOL_FIRST), ("job", 1)]
    client.request("continue", threadId=1)
    client.wait("stopped")
    assert client.stack() == [("m100", 5), ("job", 2)]
    client.request("continue", threadId=1)
    assert client.wait("exited") == {"exitCode": 0}


def test_the_operator_answers_dialog_and_probe_from_the_console(tmp_path, client) -> None:
    job = write(tmp_path, 'dlgmsg "Setup" "Depth" 4100 "Passes" 4101\nmsg "depth "#4100" passes "#4101\n'
                          'G38.2 Z-10 F100\nmsg "probe "#5067" at "#5063\nM30\n')
    client.start({}, program=str(job), answers=[])
    stop = client.wait("stopped")
    assert stop["reason"] == "dialog" and "Setup" in stop["text"]
    bad = client.raw("evaluate", expression="ok #9999=1", context="repl")
    assert not bad["success"] and bad["message"] == "#9999 is not a field of this dialog (its fields: #4100, #4101)"
    answered = client.request("evaluate", expression="ok #4100=5, #4101=3", context="repl")
    assert answered["result"] == "answered: ok #4100=5, #4101=3"
    client.wait("continued")
    stop = client.wait("stopped")
    assert stop["reason"] == "probe"
    assert client.request("evaluate", expression="trip Z-3", context="repl")["result"] == "answered: trip Z-3"
    assert client.wait("exited") == {"exitCode": 0}
    out = client.outputs()
    assert "msg: depth 5 passes 3" in out and "msg: probe 1 at -3" in out


def test_a_probe_trips_on_the_probe_surface(tmp_path, client) -> None:
    write(tmp_path, "x,y,z\n0,0,-2\n10,0,-2\n0,10,-2.5\n10,10,-2.5\n", "surface.csv")
    write(tmp_path, 'G0 X0 Y0\nG38.2 Z-10 F100\nmsg "probe "#5067" at "#5063\nM30\n')
    client.start({}, program="job.nc", probeSurface="surface.csv", cwd=str(tmp_path))
    assert client.wait("exited") == {"exitCode": 0}
    assert "msg: probe 1 at -2" in client.outputs()
    bad = write(tmp_path, "x,y,z\n0,0\n", "bad.csv")
    refused = client.raw("launch", program="job.nc", probeSurface=bad.name, cwd=str(tmp_path))
    assert not refused["success"] and "bad.csv" in refused["message"]


def test_a_run_error_stops_with_its_text_and_can_be_stepped_back_from(tmp_path, client) -> None:
    job = write(tmp_path, "#1 = 2\n#2 = [#1 / [#1 - 2]]\nM30\n")
    client.start({}, program=str(job))
    stop = client.wait("stopped")
    assert stop["reason"] == "exception" and "division by zero" in stop["text"]
    info = client.request("exceptionInfo", threadId=1)
    assert info["exceptionId"] == "R813" == info["details"]["code"] and f"{job}:2:" in info["details"]["message"]
    assert client.stack()[0] == ("job", 2)
    client.step("stepBack")  # to the failing statement, before it ran: fix #1 and go on
    assert client.stack() == [("job", 2)]
    client.request("evaluate", expression="#1 = 4", context="repl")
    client.request("continue", threadId=1)
    assert client.wait("exited") == {"exitCode": 0}


def test_a_run_error_without_the_filter_ends_the_run(tmp_path) -> None:
    job = write(tmp_path, "#2 = [1 / 0]\n")
    dap = DapClient()
    try:
        dap.request("initialize", adapterID="ecnc")
        dap.request("launch", program=str(job))
        dap.request("setExceptionBreakpoints", filters=[])
        dap.request("configurationDone")
        assert dap.wait("exited") == {"exitCode": 70}
        assert "division by zero" in dap.outputs()
    finally:
        dap.close()


def test_pause_stops_a_long_job(tmp_path, client) -> None:
    lines = "".join(f"G1 X{i % 100} Y{i % 7} F1000\n" for i in range(20000))
    job = write(tmp_path, "While [#1 < 100000000]\n#1 = [#1 + 1]\nEndWhile\n" + lines + "M30\n")
    client.start({}, program=str(job))
    client.request("pause", threadId=1)
    assert client.wait("stopped")["reason"] == "pause"
    client.request("continue", threadId=1)
    client.request("pause", threadId=1)
    assert client.wait("stopped")["reason"] == "pause"
    assert client.stack()[-1][0] == "job"


def test_stop_on_entry_and_no_debug(tmp_path) -> None:
    job = write(tmp_path, JOB)
    command = [shutil.which("ecnc")] if shutil.which("ecnc") else [sys.executable, "-m", "edingcnc_lang"]
    dap = DapClient(*command, "debug")
    try:
        dap.start({str(job): [{"line": 5}]}, program=str(job), stopOnEntry=True)
        assert dap.wait("stopped")["reason"] == "entry"
        dap.request("continue", threadId=1)
        assert dap.wait("stopped")["reason"] == "breakpoint"
    finally:
        dap.close()
    dap = DapClient()
    try:
        dap.start({str(job): [{"line": 5}]}, program=str(job), noDebug=True)
        assert dap.wait("exited") == {"exitCode": 0}
    finally:
        dap.close()


def test_launch_errors_are_failed_responses(tmp_path, client) -> None:
    client.request("initialize", adapterID="ecnc")
    missing = client.raw("launch", program="nope.nc", cwd=str(tmp_path))
    assert not missing["success"] and "nope.nc is not a file" in missing["message"]
    bad = write(tmp_path, "If [1]\nG0 X1\n")
    broken = client.raw("launch", program=str(bad))
    assert not broken["success"] and f"{bad}:" in broken["message"]


def test_stepping_back_from_an_error_in_a_plain_line_of_the_bulk_path(tmp_path, client) -> None:
    """The motion stage refuses a CAM line the bulk path ran unseen: back to it, and before it."""
    lines = "".join(f"G1 X{i % 50} Y{i % 7} F800\n" for i in range(3000))
    job = write(tmp_path, lines + "G0 X99999\n" + "G1 X1\n" * 600 + "M30\n")
    (tmp_path / "cnc.ini").write_bytes(b"[JOINT_0]\r\nname = X\r\npositiveLimit = 600\r\nnegativeLimit = 0\r\n")
    client.start({}, program=job.name, ini="cnc.ini", cwd=str(tmp_path))
    stop = client.wait("stopped")
    assert stop["reason"] == "exception" and "outside its limits [0, 600]" in stop["text"]
    assert client.stack() == [("job", 3001)]
    client.step("stepBack")
    assert client.stack() == [("job", 3001)] and client.value("#5001") == "49"
    client.step("stepBack")
    assert client.stack() == [("job", 3000)] and client.value("#5001") == "48"
    client.step("next")
    assert client.stack() == [("job", 3001)] and client.value("#5001") == "49"


def test_launch_sets_up_the_machine_as_the_command_line_does(tmp_path, client) -> None:
    job = write(tmp_path, 'G38.2 Z-50 F100\nmsg "at "#5063" v "#4520" g54 "#5221" t3 "#5403","#5503" in "#5008\nM30\n')
    client.start({}, program=str(job), vars={"4520": 7}, offsets={"G54": [10, 0, 0]}, tools={"3": [42.5, 6]},
                 probeAt=-12.5)
    assert client.wait("exited") == {"exitCode": 0}
    assert "at -12.5 v 7 g54 10 t3 42.5,6 in 0" in client.outputs()
    refused = client.raw("launch", program=str(job), vars={"5001": 3})
    assert not refused["success"] and "#5001 is a read-only system variable" in refused["message"]
    refused = client.raw("launch", program=str(job), probeAt="high")
    assert not refused["success"] and "probeAt must be a finite number" in refused["message"]
