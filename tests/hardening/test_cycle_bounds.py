"""Cycle expansion is bounded before anything is allocated (issue 28, item 1): every G76 pass,
spring passes included, counts against the pass cap and the step budget."""
from __future__ import annotations

import tracemalloc
from pathlib import Path

import pytest

from edingcnc_lang.errors import MachineError
from edingcnc_lang.syntax.input_limits import MAX_THREAD_PASSES
from edingcnc_lang.runner import RunOptions, run_string
from edingcnc_lang.machine.thread_passes import G76Words, ThreadError, g76

LATHE = "G18 G97 S100 M3\nG0 X20 Z0\n"


@pytest.fixture()
def lathe(tmp_path: Path) -> RunOptions:
    ini = tmp_path / "cnc.ini"
    ini.write_text("[SYSTEM]\nmachineType = 1\n")
    return RunOptions(ini=ini)


@pytest.mark.parametrize("h", ["1000000000", "1000000000000000000000", f"{MAX_THREAD_PASSES}"])
def test_spring_passes_count_against_the_pass_cap_before_allocating(h: str, lathe: RunOptions) -> None:
    tracemalloc.start()
    try:
        with pytest.raises(MachineError, match="passes"):
            run_string(LATHE + f"G76 P1 Z-10 I18 J0.1 K0.6 H{h}\n", lathe)
        peak = tracemalloc.get_traced_memory()[1]
    finally:
        tracemalloc.stop()
    assert peak < 50_000_000


def test_the_cap_counts_cut_and_spring_passes_together() -> None:
    cuts = len(g76(G76Words(p=1, z=-10, i=19, j=0.1, k=0.6), 20, 0)) // 4  # 4 moves a pass (+1 at the end)
    words = G76Words(p=1, z=-10, i=19, j=0.1, k=0.6, h=MAX_THREAD_PASSES - cuts + 1)
    with pytest.raises(ThreadError, match=f"more than {MAX_THREAD_PASSES:,} passes"):
        g76(words, 20, 0)
    assert len(g76(G76Words(p=1, z=-10, i=19, j=0.1, k=0.6, h=MAX_THREAD_PASSES - cuts), 20, 0)) > MAX_THREAD_PASSES


def test_spring_passes_spend_the_step_budget_before_they_move(lathe: RunOptions) -> None:
    moves: list[object] = []
    with pytest.raises(MachineError, match="step budget"):
        run_string(LATHE + "G76 P1 Z-10 I18 J0.1 K0.6 H5000\n",
                   RunOptions(ini=lathe.ini, max_steps=1000, on_move=lambda m, j: moves.append(m)))
    assert len(moves) <= 2  # only the set-up rapid ran


def test_a_few_spring_passes_still_run(lathe: RunOptions) -> None:
    result = run_string(LATHE + "G76 P1 Z-10 I18 J0.1 K0.6 H2\nM30\n", lathe)
    assert result.error is None
