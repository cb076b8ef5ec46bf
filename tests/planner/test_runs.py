"""The run-length columns the planner keeps per move: the same values as a plain list would hold."""
from __future__ import annotations

import numpy as np
from hypothesis import given
from hypothesis import strategies as st

from edingcnc_lang.motion.planner.runs import Runs

ops = st.lists(st.one_of(st.tuples(st.just("add"), st.sampled_from([0.0, 1.5, float("inf")]), st.integers(0, 5)),
                         st.tuples(st.just("drop"), st.just(0.0), st.integers(0, 7))), max_size=30)


@given(ops)
def test_runs_hold_what_a_list_would(steps: list[tuple[str, float, int]]) -> None:
    runs, plain = Runs(), []
    for op, value, count in steps:
        if op == "add":
            runs.add(value, count)
            plain += [value] * count
        else:
            count = min(count, len(plain))
            runs.drop(count)
            del plain[:count]
        assert runs.array(float).tolist() == plain
    assert all(c > 0 for c in runs.counts)


def test_equal_neighbours_share_one_run() -> None:
    runs = Runs()
    runs.add(3, 1000)
    runs.add(3)
    runs.add(4, 2)
    assert (runs.values, runs.counts) == ([3, 4], [1001, 2])
    runs.drop(1001)
    assert runs.array(np.int64).tolist() == [4, 4]
