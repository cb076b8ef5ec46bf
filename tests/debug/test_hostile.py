"""``ecnc debug`` against a hostile client (issue 43): every malformed message or argument is refused
with an output event or ``success: false`` and the session goes on; no traceback, no hang."""
from __future__ import annotations

import json
import os
from pathlib import Path

import pytest

from .dap_client import DapClient


@pytest.fixture
def client():
    dap = DapClient()
    yield dap
    assert dap.close() == 0


def send_bytes(dap: DapClient, data: bytes) -> None:
    assert dap.proc.stdin is not None
    dap.proc.stdin.write(data)
    dap.proc.stdin.flush()


def framed(message: object | str) -> bytes:
    body = (message if isinstance(message, str) else json.dumps(message)).encode()
    return b"Content-Length: %d\r\n\r\n" % len(body) + body


def still_answers(dap: DapClient) -> None:
    assert dap.request("threads")["threads"] == [{"id": 1, "name": "machine"}]


def refused_output(dap: DapClient) -> str:
    while True:
        body = dap.wait("output")
        if body["output"].startswith("ecnc debug:"):
            return body["output"]


@pytest.mark.parametrize(("data", "why"), [
    (b"Content-Length: -1\r\n\r\n{}", "negative"),
    (b"Content-Length: 100000000000\r\n\r\n{}", "more than the 16,777,216 bytes"),
    (b"Content-Length: 99999999999999999999999999\r\n\r\n{}", "more than the 16,777,216 bytes"),
    (b"Content-Length: abc\r\n\r\n{}", "not a number"),
    (b"Content-Length: 1e3\r\n\r\n{}", "not a number"),
    (b"Content-Type: x\r\n\r\n{}", "without a Content-Length"),
    (b"X-Junk: " + b"x" * 5000 + b"\r\nContent-Length: 2\r\n\r\n{}", "longer than 1024 bytes"),
    (framed("[" * 100_000 + "]" * 100_000), "nested too deeply"),
    (framed("{" + '"a":{' * 100_000 + "}" * 100_001), "nested too deeply"),
    (framed('{"seq": 1, "line": ' + "9" * 5000 + "}"), "not JSON"),
    (framed("[1, 2]"), "not a JSON object"),
    (b"Content-Length: 4\r\n\r\n\xff\xfe{}", "not UTF-8"),
])
def test_a_message_that_cannot_be_read_is_refused_and_the_next_one_answered(client, data: bytes, why: str) -> None:
    send_bytes(client, data)
    assert why in refused_output(client)
    still_answers(client)


@pytest.mark.parametrize(("message", "why"), [
    ({"seq": 1, "type": "request", "command": ["launch"]}, "needs a command"),
    ({"seq": 1, "type": "request", "command": {"a": 1}}, "needs a command"),
    ({"seq": "x", "type": "request", "command": "threads"}, "needs a seq"),
    ({"seq": 1, "type": "request", "command": "x" * 100_000}, "is not supported"),
    ({"seq": 1, "type": "request", "command": "__init__"}, "is not supported"),
    ({"seq": 1, "type": "request", "command": "launch", "arguments": "program=job.nc"}, "arguments must be an object"),
    ({"seq": 1, "type": "request", "command": "launch", "arguments": ["job.nc"]}, "arguments must be an object"),
    ({"seq": 1, "command": "threads"}, "type must be"),
])
def test_a_malformed_request_fails_with_a_message(client, message: dict, why: str) -> None:
    send_bytes(client, framed(message))
    while True:
        with client.cv:
            assert client.cv.wait_for(lambda: bool(client.responses), 30)
            response = client.responses.pop(next(iter(client.responses)))
        break
    assert not response["success"] and why in response["message"]
    assert isinstance(response["command"], str) and len(response["command"]) <= 100
    still_answers(client)


def launch_error(tmp_path: Path, dap: DapClient, **launch) -> str:
    job = tmp_path / "job.nc"
    job.write_text("#1 = 1\nM30\n")
    response = dap.raw("launch", **{"program": str(job), **launch})
    assert not response["success"]
    return response["message"]


@pytest.mark.parametrize(("launch", "why"), [
    ({"maxSteps": "abc"}, "maxSteps must be a whole number"),
    ({"maxSteps": 0}, "maxSteps must be a whole number"),
    ({"maxSteps": 1.5}, "maxSteps must be a whole number"),
    ({"maxSteps": True}, "maxSteps must be a whole number"),
    ({"program": "job\0.nc"}, "NUL"),
    ({"cwd": "/tmp\0"}, "NUL"),
    ({"logDir": "logs\0"}, "NUL"),
    ({"program": "x" * 100_000}, "more than the 4,096"),
    ({"program": "x" * 4000}, "cannot read"),
    ({"program": ["job.nc"]}, "program must be a string"),
    ({"answers": "ok"}, "answers must be a list"),
    ({"answers": [1]}, "answers[0] must be a string"),
    ({"stopOnEntry": "yes"}, "stopOnEntry must be true or false"),
    ({"logDir": "job.nc"}, "is not a folder"),
])
def test_launch_arguments_are_checked(tmp_path, client, launch: dict, why: str) -> None:
    client.request("initialize", adapterID="ecnc")
    launch.setdefault("cwd", str(tmp_path))
    assert why in launch_error(tmp_path, client, **launch)
    still_answers(client)


def test_infinity_as_max_steps_is_refused(tmp_path, client) -> None:
    job = tmp_path / "job.nc"
    job.write_text("M30\n")
    send_bytes(client, framed('{"seq": 7, "type": "request", "command": "launch", '
                              '"arguments": {"program": %s, "maxSteps": Infinity}}' % json.dumps(str(job))))
    with client.cv:
        assert client.cv.wait_for(lambda: 7 in client.responses, 30)
        response = client.responses.pop(7)
    assert not response["success"] and "maxSteps must be a whole number" in response["message"]


def started(tmp_path: Path, dap: DapClient, text: str, **launch) -> Path:
    job = tmp_path / "job.nc"
    job.write_text(text)
    dap.request("initialize", adapterID="ecnc")
    dap.request("launch", program=str(job), **launch)
    dap.wait("initialized")
    return job


def test_breakpoint_arguments_are_checked(tmp_path, client) -> None:
    job = started(tmp_path, client, "#1 = 1\n#2 = 2\nM30\n")
    for arguments, why in [({"source": {"path": str(job)}, "breakpoints": [{"line": "2"}]}, "line must be"),
                           ({"source": {"path": str(job)}, "breakpoints": [{"line": -1}]}, "line must be"),
                           ({"source": {"path": str(job)}, "breakpoints": [{}]}, "needs 'line'"),
                           ({"source": "job.nc"}, "source must be an object"),
                           ({"source": {"path": str(job)}, "breakpoints": {"line": 1}}, "must be a list"),
                           ({"source": {"path": str(job)}, "breakpoints": [{"line": 1, "condition": 5}]},
                            "condition must be a string"),
                           ({"source": {"path": str(job)}, "breakpoints": [{"line": 1}] * 10_001}, "more than")]:
        response = client.raw("setBreakpoints", **arguments)
        assert not response["success"] and why in response["message"], response
    huge = client.raw("setBreakpoints", source={"path": str(job)},
                      breakpoints=[{"line": 1, "hitCondition": "9" * 5000}])
    assert not huge["success"] and "hitCondition has 5,000 characters" in huge["message"]
    placed = client.request("setBreakpoints", source={"path": str(job)},
                            breakpoints=[{"line": 1, "hitCondition": "9" * 20}, {"line": 2, "hitCondition": "% 3"}])
    first, second = placed["breakpoints"]
    assert not first["verified"] and "N up to 999,999,999" in first["message"] and len(first["message"]) < 200
    assert second["verified"]
    assert not client.raw("setFunctionBreakpoints", breakpoints=[{"name": 5}])["success"]
    assert not client.raw("setExceptionBreakpoints", filters="runError")["success"]
    still_answers(client)


@pytest.mark.skipif(not hasattr(os, "mkfifo"), reason="FIFOs are POSIX")
def test_a_breakpoint_in_a_fifo_is_refused_without_blocking(tmp_path, client) -> None:
    started(tmp_path, client, "M30\n")
    fifo = tmp_path / "macro.cnc"
    os.mkfifo(fifo)
    placed = client.request("setBreakpoints", source={"path": str(fifo)}, breakpoints=[{"line": 1}])
    assert placed["breakpoints"][0]["message"].endswith("not a regular file")
    refused = client.raw("launch", program=str(fifo))
    assert not refused["success"] and "is not a file" in refused["message"]


def test_configuration_done_once(tmp_path, client) -> None:
    started(tmp_path, client, "#1 = 1\nM30\n", stopOnEntry=True)
    client.request("configurationDone")
    second = client.raw("configurationDone")
    assert not second["success"] and "sent already" in second["message"]
    assert client.wait("stopped")["reason"] == "entry"
    client.request("continue", threadId=1)
    assert client.wait("exited") == {"exitCode": 0}
    assert "threads can only be started once" not in client.outputs()


def test_a_continue_before_the_entry_stop_is_not_dropped(tmp_path, client) -> None:
    started(tmp_path, client, "#1 = 1\nM30\n", stopOnEntry=True)
    client.request("continue", threadId=1)  # before configurationDone: the machine has not stopped yet
    client.request("configurationDone")
    assert client.wait("stopped")["reason"] == "entry"
    client.wait("continued")
    assert client.wait("exited") == {"exitCode": 0}
    late = client.raw("next", threadId=1)
    assert not late["success"] and "not stopped" in late["message"]


@pytest.mark.parametrize(("name", "why"), [
    ("#-620", "is not a parameter"), ("#[0 - 620]", "does not exist"), ("#0", "does not exist"),
    ("#6000", "does not exist"), ("#5380", "read-only"), ("#5001", "read-only"),
    ("#" + "9" * 1000, "more than 400 digits"),
    ("#" + "9" * 5000, "more than the 1,024"),
    ("5380", "is not a parameter"), ("#1 = 2", "is not a parameter"), ("G0", "is not a parameter"),
])
def test_set_variable_reads_names_by_the_dialects_rules(tmp_path, client, name: str, why: str) -> None:
    started(tmp_path, client, "#1 = 1\n#2 = 2\nM30\n", stopOnEntry=True)
    client.request("configurationDone")
    client.wait("stopped")
    response = client.raw("setVariable", variablesReference=3, name=name, value="0")
    assert not response["success"] and why in response["message"], response
    assert client.value("#5380") == "1"  # still in simulation
    assert client.request("setVariable", variablesReference=1, name="#[2 + 1]", value="7")["value"] == "7"
    assert client.value("#3") == "7"
    client.request("continue", threadId=1)
    assert client.wait("exited") == {"exitCode": 0}


def test_function_breakpoints_report_the_subs_line(tmp_path, client) -> None:
    started(tmp_path, client, "GoSub here\nM30\n\nSub here\n    #1 = 1\nEndSub\n")
    placed = client.request("setFunctionBreakpoints", breakpoints=[{"name": "here"}, {"name": "M6"},
                                                                    {"name": "nowhere"}])["breakpoints"]
    assert placed[0]["line"] == 4 and placed[0]["source"]["path"].endswith("job.nc")
    assert placed[1]["line"] > 0 and placed[1]["source"]["path"].endswith("macro.cnc")
    assert not placed[2]["verified"] and placed[2]["line"] == 0


def test_step_back_over_a_logmsg_writes_its_line_once(tmp_path, client) -> None:
    logs = tmp_path / "logs"
    logs.mkdir()
    job = started(tmp_path, client, 'logmsg "first"\n#1 = 1\nlogmsg "second"\n#2 = 2\nlogmsg "third"\nM30\n',
                  logDir=str(logs))
    client.request("setBreakpoints", source={"path": str(job)}, breakpoints=[{"line": 4}])
    client.request("configurationDone")
    assert client.wait("stopped")["reason"] == "breakpoint"
    client.step("stepBack")
    client.step("stepBack")
    assert client.top()["line"] == 2
    client.request("continue", threadId=1)
    assert client.wait("stopped")["reason"] == "breakpoint"  # line 4 again
    assert (logs / "log.txt").read_text() == "first\nsecond\n"
    client.request("continue", threadId=1)
    assert client.wait("exited") == {"exitCode": 0}
    assert (logs / "log.txt").read_text() == "first\nsecond\nthird\n"


def _testsupport() -> str | None:
    """node, when it finds @vscode/debugadapter-testsupport (npm install it, or set NODE_PATH)."""
    import shutil
    import subprocess

    node = shutil.which("node")
    if node is None:
        return None
    found = subprocess.run([node, "-e", "require.resolve('@vscode/debugadapter-testsupport')"],
                           cwd=Path(__file__).parent, capture_output=True)
    return node if found.returncode == 0 else None


@pytest.mark.skipif(_testsupport() is None, reason="needs node and @vscode/debugadapter-testsupport")
def test_vscodes_own_debug_client_drives_a_session(tmp_path) -> None:
    import subprocess
    import sys

    node = _testsupport()
    assert node is not None
    script = Path(__file__).with_name("vscode_client.js")
    done = subprocess.run([node, str(script), sys.executable, str(tmp_path)], capture_output=True, text=True,
                          timeout=300)
    assert done.returncode == 0 and done.stdout.strip() == "ok", done.stderr
