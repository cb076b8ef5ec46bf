"""The box simulator's batch form (``Simulator.on_batch``: a batch's straight moves queued as arrays) cuts what
its moves one by one cut (``SimulatorBase.on_batch``, a move at a time): the same field to the bit, the same
findings, whatever the queue's size (the pieces must fill it where the moves one by one would)."""
from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from edingcnc_lang.sim import Stock, Tool, simulate
from edingcnc_lang.sim import queue
from edingcnc_lang.sim.job import SimResult, Simulator
from edingcnc_lang.sim.simulator import SimulatorBase
from tests.sim.jobs import write_job

FLAT = Tool(0, "flat", 6.0, flute_length=8.0)
BALL = Tool(1, "ball", 4.0, flute_length=3.0)
# a pocket of feed moves, arcs among them, a rapid through the stock, plunges, a cut with the spindle
# stopped, a tool change, a canned cycle's holes, a zig-zag below the bottom
BODY = ("G0 X35 Y3 Z2\nG1 Z-5 F200\nG0 Z2\nG0 X5 Y5 Z2\nG1 Z-1 F500\n" + "".join(f"G1 X{5 + (k % 2) * 25} Y{5 + k * 0.5:.1f}\n" for k in range(30))
        + "G2 X30 Y29.5 I0 J5\nG3 X20 Y29.5 R5\nG1 Z-3\nG0 X10 Y10\nG0 Z2\nG1 X12 Y12 Z-4\nM5\n"
        + "".join(f"G1 X{10 + k} Y{12 + (k % 3)} Z-2\n" for k in range(12)) + "M3\nT1 M6\nG0 Z2\n"
        + "G81 X5 Y20 Z-5 R1\nX10\nX15 Y22\nG80\n"
        + "".join(f"G1 X{2 + k} Y{28 - (k % 2)} Z-{11 if k % 4 == 0 else 2}\n" for k in range(20)) + "G0 Z5\n")


def _simulate(folder: Path, one_by_one: bool, monkeypatch: pytest.MonkeyPatch) -> SimResult:
    if one_by_one:
        monkeypatch.setattr(Simulator, "on_batch", SimulatorBase.on_batch)
    result = simulate(write_job(folder, BODY), Stock.box((0, 0, -10), (40, 30, 0), 0.1), tools={0: FLAT, 1: BALL},
                      first_tool=0)
    monkeypatch.undo()
    return result


@pytest.mark.parametrize("batch", [7, 64, queue.BATCH])
def test_the_batch_form_cuts_what_the_moves_one_by_one_cut(tmp_path: Path, monkeypatch: pytest.MonkeyPatch,
                                                           batch: int) -> None:
    monkeypatch.setattr(queue, "BATCH", batch)
    fast = _simulate(tmp_path, False, monkeypatch)
    monkeypatch.setattr(queue, "BATCH", batch)
    slow = _simulate(tmp_path, True, monkeypatch)
    assert np.array_equal(fast.stock.top, slow.stock.top)
    assert fast.findings == slow.findings and fast.moves == slow.moves
    kinds = {finding.kind for finding in fast.findings}
    assert fast.error is None and {"rapid_into_stock", "spindle_off", "plunge"} <= kinds, kinds  # the job makes the findings it is meant to


def test_the_batch_form_is_what_runs(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    """(The test above compares something: a run of the job takes batches.)"""
    taken: list[int] = []
    original = Simulator.on_batch

    def counting(self: Simulator, batch: object) -> None:
        taken.append(len(batch))  # type: ignore[arg-type]
        original(self, batch)  # type: ignore[arg-type]
    monkeypatch.setattr(Simulator, "on_batch", counting)
    simulate(write_job(tmp_path, BODY), Stock.box((0, 0, -10), (40, 30, 0), 0.1), tools={0: FLAT, 1: BALL},
             first_tool=0)
    assert max(taken) >= 30
