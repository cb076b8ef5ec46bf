"""The debugger's parts without a session: framing, expressions, breakpoints, the replay history."""
from __future__ import annotations

import io

import pytest

from edingcnc_lang.debug.breakpoints import Breakpoints, reached, sub_of
from edingcnc_lang.debug.expressions import (
    ExpressionError,
    dialog_answer,
    evaluate,
    interpolate,
    parse_assignment,
    parse_expression,
    probe_answer,
)
from edingcnc_lang.debug.history import History, Input
from edingcnc_lang.debug.protocol import Channel, ProtocolError, read_message
from edingcnc_lang.machine.evaluator import Evaluator
from edingcnc_lang.host import DialogAnswer


class Params:
    def __init__(self, **values: float) -> None:
        self.values = {int(k[1:]): v for k, v in values.items()}

    def read(self, index: int) -> float:
        return self.values.get(index, 0.0)


def test_framing_round_trip_and_bad_input() -> None:
    out = io.BytesIO()
    channel = Channel(out)
    channel.event("stopped", {"reason": "step", "text": "Tür"})
    channel.respond({"seq": 4, "command": "threads"}, {"threads": []})
    stream = io.BytesIO(out.getvalue())
    first, second = read_message(stream), read_message(stream)
    assert first == {"seq": 1, "type": "event", "event": "stopped", "body": {"reason": "step", "text": "Tür"}}
    assert second["request_seq"] == 4 and second["success"] and read_message(stream) is None
    with pytest.raises(ProtocolError, match="Content-Length"):
        read_message(io.BytesIO(b"Content-Length: x\r\n\r\n{}"))
    with pytest.raises(ProtocolError, match="not JSON"):
        read_message(io.BytesIO(b"Content-Length: 2\r\n\r\n{x"))


def test_expressions_are_the_dialects() -> None:
    ev = Evaluator(Params(p3=3, p5001=12, p5008=2))
    assert evaluate(ev, parse_expression("#3 == 3")) == 1.0
    assert evaluate(ev, parse_expression("[#5001 > 10] and [#5008 == 2]")) == 1.0
    assert evaluate(ev, parse_expression("[2 * SIN[30]]")) == pytest.approx(1.0)
    with pytest.raises(ExpressionError, match="division by zero"):
        evaluate(ev, parse_expression("[1 / 0]"))
    with pytest.raises(ExpressionError, match="unexpected 'G1'"):
        parse_expression("G1 X3")
    with pytest.raises(ExpressionError, match="not one expression"):
        parse_expression("1 G1 X3")
    with pytest.raises(ExpressionError):
        parse_expression("__import__('os')")
    target, value = parse_assignment("#4100 = [2 + 3]")
    assert evaluate(ev, value) == 5.0 and parse_assignment("#3 == 3") is None
    assert interpolate(ev, "T{#5008} at {[#5001 / 2]}, {[1 / 0]}") == "T2 at 6, <division by zero (1.0 / 0)>"


def test_console_answers() -> None:
    assert dialog_answer("ok #4100=5 #4101=2") == DialogAnswer(True, {4100: 5.0, 4101: 2.0})
    assert dialog_answer("OK:#4100=5") == DialogAnswer(True, {4100: 5.0})
    assert dialog_answer("cancel") == DialogAnswer(False) and dialog_answer("#4100") is None
    with pytest.raises(ExpressionError):
        dialog_answer("ok #4100=five")
    target = (1.0, 2.0, -10.0, 0.0, 0.0, 0.0)
    assert probe_answer("miss", target) == (True, None)
    assert probe_answer("ok", target) == (True, target)
    assert probe_answer("trip z-3.5", target) == (True, (1.0, 2.0, -3.5, 0.0, 0.0, 0.0))
    assert probe_answer("#5063", target) is None


def test_hit_conditions_count_only_hits_whose_condition_holds(tmp_path) -> None:
    job = tmp_path / "job.nc"
    job.write_text("#1 = 1\n")
    bps = Breakpoints()
    bp, = bps.set_source(str(job), [{"line": 1, "condition": "#1 > 0", "hitCondition": "% 2"}])
    holds, fails = Evaluator(Params(p1=1)), Evaluator(Params(p1=0))
    assert [reached(bp, e).stop for e in (holds, fails, holds, holds, holds)] == [False, False, True, False, True]
    bad, = bps.set_source(str(job), [{"line": 1, "hitCondition": "often"}])
    assert not bad.verified and "hit condition" in bad.message
    assert sub_of("M6") == "change_tool" and sub_of("m100") == "m100" and sub_of("Measure_Tool") == "measure_tool"


def test_history_keeps_what_came_before_the_target() -> None:
    history = History()
    for item in (Input(3, "dialog", DialogAnswer(), scripted=True), Input(5, "edit", (4100, 1.0)),
                 Input(5, "probe", None), Input(9, "edit", (4101, 2.0))):
        history.record(item)
    replay = history.until(5)
    assert replay.edits == {5: [(4100, 1.0)]} and replay.next("probe") is None
    assert replay.next("dialog") is not None and replay.next("dialog") is None
    history.truncate(5)
    assert [(i.step, i.kind) for i in history.inputs] == [(3, "dialog"), (5, "edit")]
    assert history.scripted_used() == 1
