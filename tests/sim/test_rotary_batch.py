"""The rotary simulator's batch form (``CylinderSimulator.on_batch``) against its moves one at a time
(``SimulatorBase.on_batch``): the same bar, bit for bit, the same findings and volumes, with a queue
so small that its cuts start and end in the middle of batches."""
from __future__ import annotations

from collections.abc import Callable
from pathlib import Path

import numpy as np
import pytest

from edingcnc_lang.canon import Batch
from edingcnc_lang.sim import queue
from edingcnc_lang.sim.rotary import CylinderResult, CylinderSimulator, simulate_cylinder
from edingcnc_lang.sim.round_stock import RoundStock
from edingcnc_lang.sim.simulator import SimulatorBase
from edingcnc_lang.sim.tools import Tool

WRAP = "\n".join(f"G1 X{30 + 0.3 * k:.3f} A{1.7 * k:.3f} Y{0.05 * (k % 9):.3f}" for k in range(120))


def run_of(x: float, a: float, count: int = 12) -> str:
    """``count`` short moves of X and A together from X``x`` A``a``."""
    return "\n".join(f"G1 X{x + 0.4 * k:.3f} A{a + 2.5 * k:.3f}" for k in range(count))


JOBS = {
    # (small steps whose end is not start + (end - start) exactly: Y0.05 to Y0.21, A0.04 to A0.11)
    "wrap": f"G0 X30 Y0 A0\nG1 Z18.5 F800\n{WRAP}\nG1 Z17.2\n{WRAP}\nG1 Y0.05 A0.04\nG1 Y0.21 A0.11\nG1 Y0.04 A0.01",
    "arcs": "G0 X40 Y-4 A10\nG1 Z18 F500\nG1 X45 A20\nG2 X50 Y-4 I2.5 J0\nG1 X52 A35\nG1 X54 A50\n"
            "G3 X60 Y-4 I3 J0\nG1 X61 A70\nG2 X66 Y-2 I2.5 J1\nG1 X70 A90\nG1 X72",
    "rapids": "G0 X30 Y0 A0\nG0 Z18\nG0 X40 A30\nG0 X45\nG1 X50 A60 F500\nG0 X60 A0\nG0 Z25",
    "spindle off": f"G0 X30 Y0 A0\nG1 Z18 F500\nG1 X40 A40\nM5\nG1 X50 A80\n{run_of(52, 80)}\nM3\nG1 X60 A120",
    "tool change": "G0 X30 Y0 A0\nG1 Z18.5 F500\nG1 X40 A40\nG1 X42 A45\nG0 Z25\nT1 M6\nS9000 M3\nG0 X50 Y0\n"
                   f"G1 Z16 F500\n{run_of(55, 60)}\nG1 X61 A95\nG0 Z25\nT0 M6\nM3\nG0 X70\nG1 Z18 F500\nG1 X80 A200",
    "shank": "G0 X30 Y0 A0\nG1 Z16.5 F500\nG1 X40 A100\nG1 X41 A110\nG1 X42 A120\nG0 X43 A125\nG1 X60 A300",
}
TOOLS = {0: Tool(0, diameter=3.0, flute_length=2.0), 1: Tool(1, shape="ball", diameter=4.0, flute_length=5.0)}


def simulate(folder: Path, body: str, cuts: list[tuple[bytes, bytes, bytes]] | None = None) -> CylinderResult:
    job = folder / "job.nc"
    job.write_text("G21 G90 G17\nS10000 M3\nG0 Z25\n" + body.strip() + "\nG0 Z25\nM30\n")
    stock = RoundStock.cylinder(40, 100, 20, 0.25)
    result = simulate_cylinder(job, stock, tools=TOOLS, first_tool=0)
    if cuts is not None:
        cuts.extend(CUTS)
        CUTS.clear()
    assert result.error is None
    return result


CUTS: list[tuple[bytes, bytes, bytes]] = []  # what each cut took from the queue, as it was queued


def noting(flush: Callable[[CylinderSimulator], None]) -> Callable[[CylinderSimulator], None]:
    """``flush`` noting the queue's rows (the sampled poses), moves and codes first."""
    def noted(self: CylinderSimulator) -> None:
        if len(self.queue):
            CUTS.append((self.queue.rows.tobytes(), self.queue.moves.tobytes(), self.queue.codes.tobytes()))
        flush(self)
    return noted


@pytest.mark.parametrize("rows", [7, 20_000])
@pytest.mark.parametrize("name", sorted(JOBS))
def test_the_batch_form_cuts_as_the_moves_one_by_one(tmp_path: Path, monkeypatch: pytest.MonkeyPatch, name: str,
                                                     rows: int) -> None:
    monkeypatch.setattr(queue, "BATCH", rows)
    heard: list[Batch] = []
    batch_form = CylinderSimulator.on_batch

    def spy(self: CylinderSimulator, batch: Batch) -> None:
        heard.append(batch)
        batch_form(self, batch)

    monkeypatch.setattr(CylinderSimulator, "on_batch", spy)
    monkeypatch.setattr(CylinderSimulator, "flush", noting(CylinderSimulator.flush))
    CUTS.clear()
    fast_cuts: list[tuple[bytes, bytes, bytes]] = []
    slow_cuts: list[tuple[bytes, bytes, bytes]] = []
    fast = simulate(tmp_path, JOBS[name], fast_cuts)
    assert heard  # the job's moves did come as batches
    monkeypatch.setattr(CylinderSimulator, "on_batch", SimulatorBase.on_batch)
    slow = simulate(tmp_path, JOBS[name], slow_cuts)
    assert fast_cuts == slow_cuts  # the same poses, moves and codes, cut in the same pieces
    assert np.array_equal(fast.stock.outer, slow.stock.outer)
    assert np.array_equal(fast.stock.inner, slow.stock.inner)
    assert fast.stock.removed_volume == slow.stock.removed_volume > 0
    assert fast.findings == slow.findings
    assert fast.moves == slow.moves and fast.tools == slow.tools and fast.notes == slow.notes
    if name == "arcs":
        assert any(b.arcs is not None and any(b.arcs) and len(b) > 2 for b in heard)
    if name in ("rapids", "spindle off", "shank", "tool change"):
        assert fast.findings
    if rows == 7:
        assert max(len(b) for b in heard) > rows
