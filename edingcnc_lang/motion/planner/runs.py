"""Per-move columns kept as runs of equal values.

The fast path hands the planner thousands of moves that share their kind, speed caps and machine
state; a column stored as (value, count) runs turns them into an array with one ``numpy.repeat``
instead of converting a Python list of equal numbers per window.
"""
from __future__ import annotations

from typing import TYPE_CHECKING, Any

if TYPE_CHECKING:
    import numpy as np


class Runs:
    """A column of per-move values: ``add`` at the end, ``drop`` from the front, ``array`` of all."""

    __slots__ = ("values", "counts")

    def __init__(self) -> None:
        self.values: list[Any] = []
        self.counts: list[int] = []

    def add(self, value: Any, count: int = 1) -> None:
        """``count`` more moves with ``value``."""
        if count <= 0:
            return
        if self.values and self.values[-1] == value:
            self.counts[-1] += count
        else:
            self.values.append(value)
            self.counts.append(count)

    def drop(self, count: int) -> None:
        """Forget the first ``count`` moves."""
        whole = 0
        while whole < len(self.counts) and self.counts[whole] <= count:
            count -= self.counts[whole]
            whole += 1
        del self.values[:whole], self.counts[:whole]
        if count and self.counts:
            self.counts[0] -= count

    def array(self, dtype: Any) -> np.ndarray:
        """Every move's value, in order."""
        import numpy as np

        return np.repeat(np.array(self.values, dtype=dtype), self.counts)
