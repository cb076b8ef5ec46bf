"""``--samples FILE.npz`` streams (issue 28, item 4): the rows wait in temporary files, not in memory, and
the file is assembled at the end, swapped in whole; ``plot --joints`` reads it back thinned.  Memory is
measured with tracemalloc (numpy reports its arrays to it), never timed."""
from __future__ import annotations

import os
import threading
import tracemalloc
from collections.abc import Iterator
from pathlib import Path
from typing import IO

import numpy as np
import pytest

from edingcnc_lang import RunOptions, run_string
from edingcnc_lang.canon import Move
from edingcnc_lang.errors import EcncError
from edingcnc_lang.machine.observe import MachineView, Observer
from edingcnc_lang.motion import samples_file
from edingcnc_lang.motion.sinks import Timing
from edingcnc_lang.motion.sinks import SAMPLES_COLUMNS, SamplesWriter
from edingcnc_lang.motion.stage import Samples
from edingcnc_lang.syntax import nodes as n

MOVES = 50
ROWS = 8192  # rows per move: 50 * 8192 rows of 16 columns are 52 MB held whole
BOUND = 8 << 20  # what writing them all may add at its peak (one move's rows are 1 MB)
MOVE = Move("linear", "", 1, (0.0,) * 6, (1.0,) + (0.0,) * 5, feed=600.0)  # type: ignore[arg-type]


def _moves(count: int = MOVES, rows: int = ROWS) -> Iterator[Samples]:
    """Synthetic time-true samples, different in every column, times increasing across moves."""
    for index in range(count):
        t = (index * rows + np.arange(rows)) * 0.005
        pos = np.column_stack([np.sin(t * (axis + 1)) for axis in range(6)])
        yield Samples(t, pos, pos * 2.0 + index, speed=np.cos(t), accel=np.sin(t * 7.0))


def _write(path: Path, moves: Iterator[Samples]) -> None:
    writer = SamplesWriter(path)
    writer.open()
    try:
        for samples in moves:
            writer.move(MOVE, MOVE.end, samples, Timing(0.0, 0.0, 0.0))
    finally:
        writer.close()


def _expected(tmp_path: Path, count: int = MOVES, rows: int = ROWS) -> Path:
    """The file as the writer made it before: every row held, then numpy.savez."""
    data = np.concatenate([np.column_stack([s.t, s.pos, s.joints, np.zeros(len(s.t)), s.speed, s.accel])
                           for s in _moves(count, rows)])
    path = tmp_path / "expected.npz"
    np.savez(path, **{name: data[:, i] for i, name in enumerate(SAMPLES_COLUMNS)})
    return path


def _same_npz(a: Path, b: Path) -> None:
    with np.load(a) as left, np.load(b) as right:
        assert left.files == right.files == list(SAMPLES_COLUMNS)
        for name in left.files:
            assert left[name].dtype == right[name].dtype and left[name].shape == right[name].shape
            assert np.array_equal(left[name], right[name]), name


@pytest.mark.slow
def test_an_npz_of_many_rows_is_written_in_bounded_memory(tmp_path: Path) -> None:
    out = tmp_path / "s.npz"
    tracemalloc.start()
    try:
        start = tracemalloc.get_traced_memory()[0]
        tracemalloc.reset_peak()
        _write(out, _moves())
        peak = tracemalloc.get_traced_memory()[1] - start
    finally:
        tracemalloc.stop()
    assert peak < BOUND, f"writing {MOVES * ROWS} rows held {peak / 1e6:.1f} MB"
    _same_npz(out, _expected(tmp_path))
    assert sorted(p.name for p in tmp_path.iterdir()) == ["expected.npz", "s.npz"]  # no temporaries left


@pytest.mark.parametrize("rows", [0, 1, 3])
def test_small_and_empty_files_load_as_numpy_wrote_them(tmp_path: Path, rows: int) -> None:
    out = tmp_path / "s.npz"
    _write(out, _moves(1, rows) if rows else iter(()))
    _same_npz(out, _expected(tmp_path, 1, rows))


def test_an_interrupted_assembly_leaves_the_old_file_and_no_temporaries(tmp_path: Path,
                                                                       monkeypatch: pytest.MonkeyPatch) -> None:
    out = tmp_path / "s.npz"
    out.write_bytes(b"the user's old file")
    copy = samples_file._copy

    def interrupted(source: IO[bytes], target: IO[bytes], count: int) -> None:
        copy(source, target, count)
        raise KeyboardInterrupt  # Ctrl-C after the first column went into the new file

    monkeypatch.setattr(samples_file, "_copy", interrupted)
    with pytest.raises(KeyboardInterrupt):
        _write(out, _moves(3, 100))
    assert out.read_bytes() == b"the user's old file"
    assert [p.name for p in tmp_path.iterdir()] == ["s.npz"]
    monkeypatch.undo()
    _write(out, _moves(3, 100))  # the lock was let go
    _same_npz(out, _expected(tmp_path, 3, 100))


def test_a_run_that_stops_writes_its_samples_so_far_and_no_temporaries(tmp_path: Path) -> None:
    out = tmp_path / "s.npz"
    with pytest.raises(EcncError, match="stop here"):
        run_string('G1 X10 F600\nerrmsg "stop here"\nG1 Y10\nM30\n', RunOptions(samples=out))
    with np.load(out) as data:
        assert data["x"][-1] == 10.0 and data["y"][-1] == 0.0 and len(data["t"]) > 100
    assert [p.name for p in tmp_path.iterdir()] == ["s.npz"]


class _CtrlC(Observer):
    """Ctrl-C while the job's line ``line`` runs."""

    def __init__(self, line: int) -> None:
        self.line = line

    def statement(self, machine: MachineView, stmt: n.Stmt) -> None:
        if machine.line == self.line:
            raise KeyboardInterrupt


def test_ctrl_c_in_a_run_writes_its_samples_so_far_and_no_temporaries(tmp_path: Path) -> None:
    out = tmp_path / "s.npz"
    with pytest.raises(EcncError, match="interrupted"):
        run_string("G1 X10 F600\nG1 Y10\nG1 Z10\nM30\n", RunOptions(samples=out, observer=_CtrlC(3)))
    with np.load(out) as data:
        assert data["x"][-1] == 10.0 and data["y"][-1] == 10.0 and data["z"][-1] == 0.0
    assert [p.name for p in tmp_path.iterdir()] == ["s.npz"]


def test_a_full_disk_keeps_the_rows_every_column_has(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    """The disk fills up halfway through a move's columns: the file holds the moves before it, whole."""
    out = tmp_path / "s.npz"
    append = samples_file.ColumnFiles.append

    def full_on_the_third(self: samples_file.ColumnFiles, columns: list[np.ndarray]) -> None:
        if self.rows == 200:
            for handle, column in zip(self._files[:5], columns):
                handle.write(column.tobytes())
            raise OSError(28, "No space left on device")
        append(self, columns)

    monkeypatch.setattr(samples_file.ColumnFiles, "append", full_on_the_third)
    with pytest.raises(OSError, match="No space"):
        _write(out, _moves(4, 100))
    _same_npz(out, _expected(tmp_path, 2, 100))
    assert sorted(p.name for p in tmp_path.iterdir()) == ["expected.npz", "s.npz"]


def test_a_folder_that_takes_no_new_file_gets_the_samples_in_place(tmp_path: Path,
                                                                   monkeypatch: pytest.MonkeyPatch) -> None:
    out = tmp_path / "s.npz"
    out.write_bytes(b"old")
    make_folder = samples_file.tempfile.mkdtemp

    def refused_beside(*args: object, **kwargs: object) -> str:
        if kwargs.get("dir") == tmp_path:
            raise PermissionError(13, "Permission denied")
        return make_folder(*args, **kwargs)  # type: ignore[call-overload,no-any-return]

    monkeypatch.setattr(samples_file.tempfile, "mkdtemp", refused_beside)
    inode = out.stat().st_ino
    _write(out, _moves(2, 50))
    assert out.stat().st_ino == inode  # written in place, the temporaries elsewhere
    _same_npz(out, _expected(tmp_path, 2, 50))


def test_another_owners_file_is_written_in_place(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    out = tmp_path / "s.npz"
    out.write_bytes(b"old")
    inode = out.stat().st_ino
    monkeypatch.setattr(os, "getuid", lambda: out.stat().st_uid + 1)  # as if another user ran it
    _write(out, _moves(2, 50))
    assert out.stat().st_ino == inode
    _same_npz(out, _expected(tmp_path, 2, 50))


def test_a_new_file_replaces_the_old_one_with_its_mode(tmp_path: Path) -> None:
    out = tmp_path / "s.npz"
    out.write_bytes(b"old")
    out.chmod(0o640)
    inode = out.stat().st_ino
    _write(out, _moves(2, 50))
    assert out.stat().st_ino != inode and out.stat().st_mode & 0o777 == 0o640
    _same_npz(out, _expected(tmp_path, 2, 50))


def test_a_symbolic_link_keeps_pointing_at_the_new_file(tmp_path: Path) -> None:
    (tmp_path / "real").mkdir()
    target = tmp_path / "real" / "data.npz"
    target.write_bytes(b"old")
    link = tmp_path / "s.npz"
    link.symlink_to(target)
    _write(link, _moves(2, 50))
    assert link.is_symlink() and link.resolve() == target
    _same_npz(target, _expected(tmp_path, 2, 50))
    assert sorted(p.name for p in (tmp_path / "real").iterdir()) == ["data.npz"]


def test_a_fifo_gets_the_file_as_a_stream(tmp_path: Path) -> None:
    fifo = tmp_path / "s.npz"
    os.mkfifo(fifo)
    received: list[bytes] = []
    reader = threading.Thread(target=lambda: received.append(fifo.read_bytes()))
    reader.start()
    _write(fifo, _moves(2, 50))
    reader.join(10)
    (tmp_path / "got.npz").write_bytes(received[0])
    _same_npz(tmp_path / "got.npz", _expected(tmp_path, 2, 50))


@pytest.mark.slow
def test_the_samples_are_read_back_thinned_in_bounded_memory(tmp_path: Path) -> None:
    out = tmp_path / "s.npz"
    _write(out, _moves())
    tracemalloc.start()
    try:
        tracemalloc.reset_peak()
        thinned, spread, count = samples_file.read_thinned(out, 1000)
        peak = tracemalloc.get_traced_memory()[1]
    finally:
        tracemalloc.stop()
    assert peak < 4 << 20, f"reading back held {peak / 1e6:.1f} MB"
    step = -(-count // 1000)
    with np.load(out) as whole:
        assert count == len(whole["t"]) == MOVES * ROWS
        for name in SAMPLES_COLUMNS:
            assert np.array_equal(thinned[name], whole[name][::step]) and spread[name] == np.ptp(whole[name])


@pytest.mark.slow
def test_a_joint_plot_draws_what_it_drew_from_every_sample(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    """Thinned on reading to what the plot draws: the same points as thinning every sample at drawing."""
    pytest.importorskip("matplotlib")
    from matplotlib.axes import Axes

    from edingcnc_lang.plot import joints, toolpath

    monkeypatch.setattr(toolpath, "SAMPLE_ROWS", 500)
    monkeypatch.setattr(joints, "MAX_CURVE_POINTS", 500)
    job = tmp_path / "j.nc"
    job.write_text("G1 X10 F600\nG1 Y10 Z0.5\nG1 X0 Y0 Z0\nM30\n")
    drawn: list[tuple[np.ndarray, np.ndarray]] = []
    plot = Axes.plot
    monkeypatch.setattr(Axes, "plot", lambda self, x, y, *a, **k: (drawn.append((x, y)), plot(self, x, y, *a, **k))[1])
    path = toolpath.record_job(job, samples=True)
    joints.plot_joints(path, tmp_path / "j.png")
    run_string(job.read_text(), RunOptions(samples=tmp_path / "all.npz"))
    with np.load(tmp_path / "all.npz") as whole:
        step = -(-len(whole["t"]) // 500)
        assert step > 1
        expected = [(whole["t"][::step], whole[name][::step]) for name in ("jx", "jy", "jz")]
    assert len(drawn) == 3  # Z moves by 0.5 mm for a short while: still a moving joint
    for (x, y), (ex, ey) in zip(drawn, expected):
        assert np.array_equal(x, ex) and np.array_equal(y, ey)
