"""The ``.npz`` samples file, streamed both ways, so a long job's samples never sit in memory.

Written: each column's rows are appended to a temporary file as the run makes them, and at the end
the zip is assembled from those files a megabyte at a time, member by member as ``numpy.savez``
writes it (one ``NAME.npy`` per column, stored, zip64, a version 1.0 header written once the row
count is known), so ``numpy.load`` reads the same names, dtypes and values.  Read back: a column
at a time, thinned to a bounded number of rows, with its spread over every row (pictures).
"""
from __future__ import annotations

import contextlib
import os
import shutil
import tempfile
import zipfile
from collections.abc import Sequence
from pathlib import Path
from typing import IO

import numpy as np

COPY_BYTES = 1 << 20  # bytes moved in one go, assembling or reading a column
DTYPE = np.dtype(float)  # every column is float64, as numpy.savez wrote the rows it was given


class ColumnFiles:
    """One temporary file per column in a folder of its own, beside the output when its folder can take
    it (the output's file system must hold the file anyway), else in the system's temporary folder."""

    def __init__(self, names: Sequence[str], beside: Path) -> None:
        self.names = tuple(names)
        try:
            self.folder = Path(tempfile.mkdtemp(prefix=f".{beside.name}.", suffix=".tmp", dir=beside.parent))
            self.beside = True
        except OSError:  # a folder we may not create in (the output itself may be writable)
            self.folder = Path(tempfile.mkdtemp(prefix="ecnc-samples-"))
            self.beside = False
        self.rows = 0
        self._files: list[IO[bytes]] = []
        try:
            for index in range(len(self.names)):
                self._files.append(open(self.folder / f"{index}.bin", "wb"))
        except BaseException:
            self.remove()
            raise

    def append(self, columns: Sequence[np.ndarray]) -> None:
        """The next rows of every column, one array (of the same length) per name."""
        for handle, column in zip(self._files, columns, strict=True):
            handle.write(np.ascontiguousarray(column, dtype=DTYPE).data)
        self.rows += len(columns[0])

    def write_npz(self, out: IO[bytes]) -> None:
        """The zip of every column into ``out``; each column's file is removed once it is copied."""
        header = np.lib.format.header_data_from_array_1_0(np.empty(0, dtype=DTYPE))
        header["shape"] = (self.rows,)
        for handle in self._files:
            handle.close()
        with zipfile.ZipFile(out, mode="w", compression=zipfile.ZIP_STORED, allowZip64=True) as archive:
            for index, name in enumerate(self.names):
                column = self.folder / f"{index}.bin"
                with archive.open(f"{name}.npy", "w", force_zip64=True) as member, open(column, "rb") as rows:
                    np.lib.format.write_array_header_1_0(member, header)
                    _copy(rows, member, self.rows * DTYPE.itemsize)
                column.unlink()

    def remove(self) -> None:
        """Close and delete the temporary files (after success, an error or Ctrl-C alike)."""
        for handle in self._files:
            with contextlib.suppress(OSError):
                handle.close()
        shutil.rmtree(self.folder, ignore_errors=True)


def _copy(source: IO[bytes], target: IO[bytes], count: int) -> None:
    """The first ``count`` bytes of ``source`` (a column file may hold part of a row that failed, a full
    disk, beyond the rows every column has), a megabyte at a time."""
    while count > 0:
        chunk = source.read(min(COPY_BYTES, count))
        if not chunk:
            raise OSError(f"a temporary samples column ended {count} bytes early")
        target.write(chunk)
        count -= len(chunk)


def read_thinned(path: str | os.PathLike[str], max_rows: int) -> tuple[dict[str, np.ndarray], dict[str, float], int]:
    """The columns of an ``.npz`` file of 1-D arrays, each as every ``step``-th row (``step`` the
    least that leaves at most ``max_rows``), their spread (max - min over every row) and the row count.

    Holds one megabyte of a column at a time besides the thinned rows.
    """
    thinned: dict[str, np.ndarray] = {}
    spread: dict[str, float] = {}
    count = 0
    with zipfile.ZipFile(path) as archive:
        for info in archive.infolist():
            name = info.filename.removesuffix(".npy")
            with archive.open(info) as member:
                version = np.lib.format.read_magic(member)
                shape, _fortran, dtype = (np.lib.format.read_array_header_1_0(member) if version == (1, 0)
                                          else np.lib.format.read_array_header_2_0(member))
                count = int(np.prod(shape))
                step = max(1, -(-count // max_rows))
                thinned[name], spread[name] = _thin(member, dtype, count, step)
    return thinned, spread, count


def _thin(member: IO[bytes], dtype: np.dtype, count: int, step: int) -> tuple[np.ndarray, float]:
    """Every ``step``-th of ``count`` values read from ``member``, and max - min of them all."""
    per_read = max(1, COPY_BYTES // dtype.itemsize // step) * step  # whole steps, so the pattern repeats
    kept: list[np.ndarray] = []
    low, high = np.inf, -np.inf
    for first in range(0, count, per_read):
        take = min(per_read, count - first)
        values = np.frombuffer(member.read(take * dtype.itemsize), dtype=dtype)
        kept.append(values[::step].copy())
        if take:
            low, high = np.minimum(low, values.min()), np.maximum(high, values.max())
    return (np.concatenate(kept) if kept else np.empty(0, dtype=dtype)), float(high - low) if count else 0.0
