"""``RoundStock.cut`` takes a batch of entries as it would take them one at a time: a cell's result
does not depend on which other cells share the batch, nor on where a simulator's batch ends (the
viewer's snapshots flush the queue every few moves)."""
from __future__ import annotations

import numpy as np
import pytest

from edingcnc_lang.sim.round_stock import RoundStock


def entries(seed: int, count: int = 400) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    rng = np.random.default_rng(seed)
    cells = rng.integers(0, 12, count)
    low = rng.uniform(0.5, 19.5, count)
    high = low + rng.exponential(1.5, count)  # many stop short of the surface: a tool's side on the ray
    return cells, low, high


@pytest.mark.parametrize("open_top", [False, True])
@pytest.mark.parametrize("seed", range(8))
def test_a_batch_cuts_as_its_entries_one_by_one(seed: int, open_top: bool) -> None:
    cells, low, high = entries(seed)
    batch, single = RoundStock.bar(40, 6, 0, 0.5, angles=1), RoundStock.bar(40, 6, 0, 0.5, angles=1)
    depth = batch.cut(cells, low, high, open_top=open_top)
    one = np.array([single.cut(cells[k:k + 1], low[k:k + 1], high[k:k + 1], open_top=open_top)[0]
                    for k in range(len(cells))])
    assert np.array_equal(batch.outer, single.outer)
    assert depth == pytest.approx(one, abs=1e-6)


def test_a_cell_alone_or_beside_others_is_cut_alike() -> None:
    """An entry short of the surface is no cut, whatever an earlier cell of the batch left (a cell
    with no cut of its own before it once saw that cell's minimum, shifted, as its surface)."""
    alone, shared = RoundStock.bar(40, 2, 0, 0.5, angles=1), RoundStock.bar(40, 2, 0, 0.5, angles=1)
    alone.cut(np.array([1, 1]), np.array([17.0, 17.0]), np.array([18.2, 19.8]), open_top=False)
    shared.cut(np.array([0, 1, 1]), np.array([17.0, 17.0, 17.0]), np.array([25.0, 18.2, 19.8]), open_top=False)
    assert alone.outer[1, 0] == shared.outer[1, 0] == 20.0 and shared.outer[0, 0] == 17.0
