"""Output sinks behind the planner: the trace CSV, the samples file and the event recorder.

Each writes incrementally, so memory stays flat however long the job is (the .npz samples
file streams its columns to temporary files and is assembled from them at the end, see
``samples_file``).
Numbers are written with ``repr`` so they read back as the same double.  Only the samples
writer needs numpy, and imports it itself.
"""
from __future__ import annotations

import io
import math
from array import array
import os
import sys
from collections.abc import Callable, Sequence
from itertools import islice
from pathlib import Path
from typing import IO, TYPE_CHECKING

from edingcnc_lang import speedups
from edingcnc_lang.canon import Batch, Event, Move, Pose
from edingcnc_lang.errors import CallbackError, EcncError, Location, UsageFailure
from edingcnc_lang.records import record
from edingcnc_lang.motion.stage import Samples
from edingcnc_lang.outputs import STDOUT, open_replacing_text

if TYPE_CHECKING:
    import numpy as np

    from edingcnc_lang.motion.samples_file import ColumnFiles

SIX_REPR = ",".join(["%r"] * 6)


@record(frozen=True)
class Timing:
    """When one move runs (seconds from the start of the job) and the top speed the planner gave it
    (mm/s along XYZ, or deg/s for a move of the rotary axes only; 0 for a move of zero length): what the
    planner hands each sink with a move (the sinks are below the planner, which calls them)."""

    start: float
    end: float
    speed: float

TRACE_HEADER = "line,kind,x,y,z,a,b,c,jx,jy,jz,ja,jb,jc,file,t\n"
SAMPLES_FORMATS = (".csv", ".npz")  # by the file's extension; "-" is CSV on standard output


def samples_format_problem(path: Path) -> str | None:
    """Why ``path`` cannot take the samples (an extension that is neither .csv nor .npz), else None."""
    if str(path) == "-" or path.suffix.lower() in SAMPLES_FORMATS:
        return None
    return f"{path}: the samples file must end in .csv or .npz (or be - for CSV on standard output)"


CSV_ROWS_AT_ONCE = 8192  # samples turned into text in one go
SAMPLES_COLUMNS = ("t", "x", "y", "z", "a", "b", "c", "jx", "jy", "jz", "ja", "jb", "jc", "s", "v", "acc")




class _NotOpen(io.StringIO):
    """An output's stream before the run opens it (``open()``): closing it does nothing."""

    def write(self, text: str) -> int:
        raise ValueError("output written before it was opened")

    def close(self) -> None:
        pass


_NOT_OPEN = _NotOpen()


def _open_for_writing(path: Path, binary: bool = False) -> IO:
    """The file to write, locked against another run writing it at the same time; ``-`` is
    standard output (closing the returned stream leaves it open).

    The rows go to a file beside it that replaces it when the stream is closed (``outputs.
    ReplacingText``: a full disk leaves the old file whole); a file written in place is truncated
    only once it is locked, so a second run refused here leaves the first one's rows alone.
    ``binary`` (the .npz file, assembled and swapped in at the end) gives the file itself.
    Without fcntl (Windows) there is no lock.
    """
    try:
        if str(path) == STDOUT:
            sys.stdout.flush()  # anything printed before comes first
            return open(sys.stdout.fileno(), "w", encoding="utf-8", newline="", buffering=1 << 16, closefd=False)
        fd = os.open(path, os.O_WRONLY | os.O_CREAT | getattr(os, "O_CLOEXEC", 0), 0o666)
    except OSError as err:
        raise EcncError(f"cannot write {path}: {err.strerror}") from None
    try:
        _lock(fd, path)
    except BaseException:
        os.close(fd)
        raise
    if binary:
        return open(fd, "wb")
    return open_replacing_text(path, holder=fd)


def _lock(fd: int, path: Path) -> None:
    """An exclusive lock on an output for as long as it is open; EcncError if another run holds one."""
    try:
        import fcntl
    except ImportError:
        return
    try:
        fcntl.flock(fd, fcntl.LOCK_EX | fcntl.LOCK_NB)
    except BlockingIOError:
        raise EcncError(f"cannot write {path}: another run is writing it (two runs cannot share an output file)") \
            from None
    except OSError:  # a file system without locks (some network shares): write unlocked
        pass


def csv_field(text: str) -> str:
    """A CSV field: quoted (quotes doubled) only when it holds a comma, quote or line end."""
    if any(ch in text for ch in ',"\r\n'):
        return '"' + text.replace('"', '""') + '"'
    return text


class TraceWriter:
    """One CSV row per executed move: source line, kind, machine end point, joints there, the file
    the line belongs to, and ``t``, the planned time (seconds from the job start) at which the move ends."""

    def __init__(self, path: Path) -> None:
        self.path = path
        self._file: IO = _NOT_OPEN

    def open(self) -> None:
        self._file = _open_for_writing(self.path)
        self._file.write(TRACE_HEADER)

    def move(self, move: Move, joints: Pose, samples: Samples | None, timing: Timing) -> None:
        self._file.write(f"{move.line},{move.kind},{SIX_REPR % move.end},{SIX_REPR % tuple(joints)},"
                         f"{csv_field(move.path)},{timing.end!r}\n")

    def write_batch(self, batch: Batch, times: Sequence[float], speeds: Sequence[float]) -> None:
        """Rows of straight moves whose joints equal their end points; ``times[i + 1]`` is when move i ends."""
        self._file.write(_TRACE_ROWS(batch.lines, batch.kinds, batch.ends, csv_field(batch.path), times))

    def event(self, event: Event) -> None:
        pass

    def close(self) -> None:
        self._file.close()


def trace_rows(lines: Sequence[int], kinds: Sequence[str], ends: Sequence[Pose], name: str,
               times: Sequence[float]) -> str:
    """The trace rows of straight moves whose joints are their end points (``times[i + 1]``: when move i ends).

    A coordinate that is the same in every row (A B C mostly, Z on a pass at one depth) is written
    once into the format instead of once a row, and one of few values (Z between cuts and lifts, a
    hole's X Y in its four moves) once a value (``_column_texts``): ``repr`` is most of the cost.
    The reference for ``_speedups.trace_rows``, which must give the same text byte for byte.
    """
    count = len(ends)
    if not count:
        return ""
    fields = []
    varying = []
    for column in zip(*ends):
        value = column[0]
        if column.count(value) == count and (value != 0.0 or _same_bits(column, value)):
            fields.append(repr(value))
        else:
            fields.append("%s")
            varying.append(_column_texts(column))
    coordinate = ",".join(fields)  # (a float's repr has no '%')
    # one format per row, applied in C, that takes the end point's texts twice (the joints are the end)
    row = "%s,%s," + coordinate + "," + coordinate + "," + name.replace("%", "%%") + ",%s\n"
    return "".join(map(row.__mod__, islice(zip(lines, kinds, *varying, *varying, map(repr, times[1:])), count)))


REPEATS_SAMPLE = 64  # a column's first values, looked at to tell whether its values repeat


def _column_texts(column: Sequence[float]) -> list[str]:
    """``repr`` of each value of ``column``, each distinct value's once when the column's first values
    repeat (each its own otherwise: the look costs less than a set of all of them).  Not with a zero
    among them: 0.0 and -0.0 are one key of a dict, but their reprs differ."""
    if len(set(column[:REPEATS_SAMPLE])) * 2 > min(len(column), REPEATS_SAMPLE):
        return list(map(repr, column))
    distinct = set(column)
    if 0.0 in distinct:
        return list(map(repr, column))
    return list(map(dict(zip(distinct, map(repr, distinct))).__getitem__, column))


def _same_bits(zeros: Sequence[float], value: float) -> bool:
    """Whether a column of zeros (0.0 == -0.0, but their reprs differ) are all ``value``'s zero: the same
    bytes as doubles (compared in C, no call a value)."""
    return array("d", zeros).tobytes() == array("d", (value,)).tobytes() * len(zeros)


_TRACE_ROWS = speedups.compiled("trace_rows") or trace_rows  # on the core that runs


class SamplesWriter:
    """The time-true trajectory: CSV rows as moves arrive, or an .npz file assembled at the end.

    Rows are strictly increasing in time, one every ``interpolationTime`` along the planned
    profile, with the path speed ``v`` and acceleration ``acc``.  The .npz file holds one 1-D
    array per column name; its rows wait in temporary files beside it (``ColumnFiles``), and the
    whole file replaces the old one when the run ends (also one ended by an error or Ctrl-C, with
    the rows so far), so a run that cannot finish it leaves the old file as it was.
    """

    def __init__(self, path: Path) -> None:
        problem = samples_format_problem(path)
        if problem:
            raise UsageFailure(problem)
        self.path = path
        self._npz = path.suffix.lower() == ".npz"
        self._columns: ColumnFiles | None = None
        self._last_time = -math.inf
        self._file: IO = _NOT_OPEN

    def open(self) -> None:
        self._file = _open_for_writing(self.path, binary=self._npz)
        if not self._npz:
            self._file.write(",".join(SAMPLES_COLUMNS) + "\n")
            return
        from edingcnc_lang.motion.samples_file import ColumnFiles

        try:
            self._columns = ColumnFiles(SAMPLES_COLUMNS, Path(os.path.realpath(self.path)))
        except BaseException:
            self._file.close()
            raise

    def move(self, move: Move, joints: Pose, samples: Samples | None, timing: Timing) -> None:
        if samples is None:
            return
        import numpy as np

        spindle = _spindle_column(move, samples.pos[:, 0])
        assert samples.speed is not None and samples.accel is not None  # the planner's time-true samples
        # as columns (views), never one table of a long move's rows: that would be 128 bytes a sample more
        columns = [samples.t, *samples.pos.T, *samples.joints.T, spindle, samples.speed, samples.accel]
        keep = samples.t > self._last_time
        if not keep.all():
            columns = [column[keep] for column in columns]
        if not len(columns[0]):
            return
        self._last_time = float(columns[0][-1])
        if self._columns is not None:
            self._columns.append(columns)
        else:  # a slice at a time: a long move's rows as text would be hundreds of megabytes at once
            for first in range(0, len(columns[0]), CSV_ROWS_AT_ONCE):
                chunk = np.column_stack([column[first:first + CSV_ROWS_AT_ONCE] for column in columns]).tolist()
                self._file.write("".join(",".join(map(repr, row)) + "\n" for row in chunk))

    def write_batch(self, batch: Batch, times: Sequence[float], speeds: Sequence[float]) -> None:
        pass  # batches come only when no samples are written

    def event(self, event: Event) -> None:
        pass

    def close(self) -> None:
        columns, self._columns = self._columns, None
        try:
            if columns is not None:
                self._write_npz(columns)
        finally:
            if columns is not None:
                columns.remove()
            self._file.close()

    def _write_npz(self, columns: ColumnFiles) -> None:
        """Assemble the .npz beside the old file (a symbolic link's target) and swap it in; in place (the
        old file cut first) only when a new file would lose a hard link or the owner (decided first:
        the columns are used up as they are assembled), when the folder takes no new file or when
        the output is no plain file (a FIFO)."""
        import stat

        from edingcnc_lang.config.ini import write_atomic
        from edingcnc_lang.outputs import owned_by_us

        info = os.fstat(self._file.fileno())
        if columns.beside and owned_by_us(info) and stat.S_ISREG(info.st_mode) and info.st_nlink == 1:
            write_atomic(Path(os.path.realpath(self.path)), columns.write_npz, info)  # our file: never False
            return
        if self._file.seekable():
            self._file.seek(0)
            self._file.truncate()
        columns.write_npz(self._file)


def _spindle_column(move: Move, xs: np.ndarray) -> np.ndarray:
    """The spindle speed (rpm) at every sample: constant, or following X under constant surface speed."""
    import numpy as np

    css = move.css
    if css is None:
        return np.full(len(xs), move.spindle)
    radius = np.abs(xs - css.axis_x)
    with np.errstate(divide="ignore"):
        rpm = css.surface / (2.0 * np.pi * radius)
    if css.max_rpm > 0.0:
        rpm = np.minimum(rpm, css.max_rpm)
    return np.maximum(rpm, css.min_rpm)


class EventsWriter:
    """JSON Lines (``ecnc run --events``): one object per move and per event, in the order they happen.

    A move: ``{"type": "move", "file", "line", "kind", "end", "feed", "spindle", "synchronised", "t"}``
    (``t``: when the move ends, as the planner timed it)
    plus ``"pitch"`` (mm per revolution) for a spindle-synchronised move and ``"spindle_start"``
    when constant surface speed changes the speed along it.  An event: ``{"type": "event",
    "file", "line", "kind", "data"}``.
    """

    def __init__(self, path: Path) -> None:
        from edingcnc_lang.syntax.serialize import json_text  # only when writing events

        self._dumps = json_text
        self.path = path
        self._file: IO = _NOT_OPEN

    def open(self) -> None:
        self._file = _open_for_writing(self.path)

    def _write(self, record: dict[str, object]) -> None:
        self._file.write(self._dumps(record, default=str) + "\n")

    def move(self, move: Move, joints: Pose, samples: Samples | None, timing: Timing) -> None:
        record: dict[str, object] = {"type": "move", "file": move.path, "line": move.line, "kind": move.kind,
                                     "end": list(move.end), "feed": move.feed, "spindle": move.spindle,
                                     "synchronised": move.sync > 0.0, "t": timing.end}
        if move.sync > 0.0:
            record["pitch"] = move.sync
        if move.css is not None:
            record["spindle_start"] = move.css.rpm(move.start[0])
        self._write(record)

    def write_batch(self, batch: Batch, times: Sequence[float], speeds: Sequence[float]) -> None:
        for move, t0, t1, speed in zip(batch.moves(), times, times[1:], speeds):
            self.move(move, move.end, None, Timing(t0, t1, speed))

    def event(self, event: Event) -> None:
        self._write({"type": "event", "file": event.path, "line": event.line, "kind": event.kind,
                     "data": event.data})

    def close(self) -> None:
        self._file.close()


class CallbackSink:
    """The embedding program's callbacks when it asks for planned times (``on_timed_move``): every
    move with its ``Timing`` (planned start and end times, top speed), and with it ``on_move`` and
    ``on_event``, all in program order, a look-ahead window after the machine made the move.  (Without
    ``on_timed_move``, ``on_move``/``on_event`` come at once from motion/callback_tap.py.)  A callback
    that raises ends the run with a ``CallbackError`` at its line; the callbacks hear nothing after it.
    """

    def __init__(self, on_move: Callable[[Move, Pose], None] | None = None,
                 on_event: Callable[[Event], None] | None = None,
                 on_timed_move: Callable[[Move, Pose, Timing], None] | None = None) -> None:
        self.on_move = on_move
        self.on_event = on_event
        self.on_timed_move = on_timed_move
        self.failed = False

    def move(self, move: Move, joints: Pose, samples: Samples | None, timing: Timing) -> None:
        if self.on_move:
            self._call(self.on_move, "on_move", move, move, joints)
        if self.on_timed_move:
            self._call(self.on_timed_move, "on_timed_move", move, move, joints, timing)

    def write_batch(self, batch: Batch, times: Sequence[float], speeds: Sequence[float]) -> None:
        """Straight moves in bulk, each a ``Move`` again for the callables."""
        if not (self.on_move or self.on_timed_move):
            return
        for move, t0, t1, speed in zip(batch.moves(), times, times[1:], speeds):
            self.move(move, move.end, None, Timing(t0, t1, speed))

    def event(self, event: Event) -> None:
        if self.on_event:
            self._call(self.on_event, "on_event", event, event)

    def close(self) -> None:
        pass

    def _call(self, callback: Callable[..., None], name: str, at: Move | Event, *args: object) -> None:
        if self.failed:
            return
        try:
            callback(*args)
        except EcncError:  # the embedding program's own error, raised on purpose: as it is
            self.failed = True
            raise
        except Exception as exc:
            self.failed = True
            raise CallbackError.of(name, exc, Location(at.path, at.line)) from exc


