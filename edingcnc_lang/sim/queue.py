"""Moves waiting to be cut, as flat arrays of numbers: one queue for every simulator.

A simulator hears moves one at a time (``on_move``) or a batch at a time (``on_batch``) but cuts them in
batches with numpy, so each
queues the rows of numbers its cut reads (the box sim a segment's two ends, the lathe the
controlled point's two (z, r), the rotary axis the tool's sampled poses), each row with the index
of the move it belongs to and its finding code, and takes them as arrays once ``full``.
"""
from __future__ import annotations

from array import array
from collections.abc import Iterable

import numpy as np

BATCH = 20_000  # rows cut at once


class MoveQueue:
    """Rows of ``width`` numbers, each with its move's index and finding code."""

    def __init__(self, width: int) -> None:
        self.width = width
        self._clear()

    def _clear(self) -> None:
        self.rows, self.moves, self.codes = array("d"), array("q"), array("b")

    def add(self, numbers: Iterable[float], move: int, code: int) -> None:
        """Queue whole rows (``numbers`` flat, a multiple of ``width``) of move ``move``."""
        before = len(self.rows)
        self.rows.extend(numbers)
        count = (len(self.rows) - before) // self.width
        self.moves.extend([move] * count)
        self.codes.extend([code] * count)

    def add_rows(self, rows: np.ndarray, moves: np.ndarray, codes: np.ndarray) -> None:
        """Queue ``rows`` (N x ``width``), each of the move ``moves[i]`` with the code ``codes[i]``: what N calls
        of ``add`` queue, for the moves of a batch at once."""
        self.rows.frombytes(np.ascontiguousarray(rows, dtype=float).tobytes())
        self.moves.frombytes(np.ascontiguousarray(moves, dtype=np.int64).tobytes())
        self.codes.frombytes(np.ascontiguousarray(codes, dtype=np.int8).tobytes())

    @property
    def room(self) -> int:
        """Rows still to queue before the queue is ``full``."""
        return max(BATCH - len(self.moves), 0)

    def __len__(self) -> int:
        return len(self.moves)

    @property
    def full(self) -> bool:
        """Enough rows for a batch: time to cut them."""
        return len(self.moves) >= BATCH

    def take(self) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """The rows (N x ``width``), their moves and codes, as arrays of their own; the queue is empty after."""
        rows = np.frombuffer(self.rows, dtype=float).reshape(-1, self.width).copy()
        moves = np.frombuffer(self.moves, dtype=np.int64).copy()
        codes = np.frombuffer(self.codes, dtype=np.int8).copy()
        self._clear()
        return rows, moves, codes
