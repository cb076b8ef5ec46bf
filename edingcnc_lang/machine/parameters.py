"""The parameter store #1..#5999, with the live system variables.

Positions (#5001.., #5071..) and the spindle speed (#5070, which follows X under G96) are computed when read instead of being copied
after every move; writes to the offset parameters tell the owner to refresh its
cached offsets.  Which parameters were written is remembered for reports and
for writing the persistent ones back to cnc.ini.
"""
from __future__ import annotations

from collections.abc import Callable, Iterator, Mapping

from edingcnc_lang.machine import tables as t
from edingcnc_lang.errors import Location, MachineError

LIVE_RANGES = (range(t.POS_WORK, t.POS_WORK + 6), range(t.SPINDLE_SPEED, t.POS_MACHINE + 6))
OFFSET_RANGES = (range(t.G92_OFFSET, t.G92_OFFSET + 6), range(t.COORD_SYSTEM, t.COORD_OFFSETS + 9 * t.COORD_STRIDE),
                 range(t.ALT_SPINDLE_OFFSET, t.ALT_SPINDLE_OFFSET + 3))


class Parameters:
    """Doubles #1..#5999; ``live`` answers the position parameters, ``on_offsets`` hears offset writes."""

    def __init__(self, live: Callable[[int], float], on_offsets: Callable[[], None]) -> None:
        self.values = [0.0] * (t.LAST_PARAM + 1)
        self.written: set[int] = set()
        self._start: dict[int, float] = {}  # loaded values: what "changed" is measured against
        self._live = live
        self._on_offsets = on_offsets
        self._live_set = frozenset(i for r in LIVE_RANGES for i in r)
        self._offset_set = frozenset(i for r in OFFSET_RANGES for i in r)
        # told of every write (the debugger's "last written at"); None in a plain run
        self.on_write: Callable[[int], None] | None = None

    def read(self, index: int) -> float:
        if index in self._live_set:
            return self._live(index)
        return self.values[index]

    def write(self, index: int, value: float, where: Location | None = None) -> None:
        """A program's assignment: read-only system variables are refused."""
        if t.is_read_only(index):
            raise MachineError(f"#{index} is a read-only system variable (the machine sets it)", where)
        if index == t.COORD_SYSTEM and value not in range(1, 10):  # manual 3.3 (p. 7): anything else is an error
            raise MachineError(f"#5220 = {value:g}: the coordinate system is a whole number 1..9 (1 = G54 .. "
                               "9 = G59.3)", where)
        self.set(index, value)

    def set(self, index: int, value: float) -> None:
        """The machine's own write (no read-only check)."""
        self.values[index] = value
        self.written.add(index)
        if self.on_write is not None:
            self.on_write(index)
        if index in self._offset_set:
            self._on_offsets()

    def load(self, values: Mapping[int, float]) -> None:
        """Initial values (persisted variables, tool table) that do not count as written."""
        for index, value in values.items():
            self.values[index] = value
        self._start.update(values)
        self._on_offsets()

    def snapshot_written(self) -> dict[int, float]:
        return {i: self.read(i) for i in sorted(self.written)}

    def snapshot_changed(self) -> dict[int, float]:
        """Written parameters whose value is not the one the run started with (what --save-vars stores)."""
        return {i: v for i, v in self.snapshot_written().items() if v != self._start.get(i, 0.0)}

    def frozen(self) -> ParameterView:
        """Every parameter as it is now, written or not, as a read-only mapping (``RunResult.parameters``)."""
        values = list(self.values)
        for index in self._live_set:
            values[index] = self._live(index)
        return ParameterView(values)


class ParameterView(Mapping[int, float]):
    """Parameters #1..#5999 at one moment, read-only: ``view[4050]``; a number outside raises KeyError."""

    __slots__ = ("_values",)

    def __init__(self, values: list[float]) -> None:
        self._values = values

    def __getitem__(self, index: int) -> float:
        if not isinstance(index, int) or not t.FIRST_PARAM <= index <= t.LAST_PARAM:
            raise KeyError(index)
        return self._values[index]

    def __iter__(self) -> Iterator[int]:
        return iter(range(t.FIRST_PARAM, t.LAST_PARAM + 1))

    def __len__(self) -> int:
        return t.LAST_PARAM - t.FIRST_PARAM + 1

    def __repr__(self) -> str:
        nonzero = {i: v for i, v in enumerate(self._values) if v and i}
        return f"ParameterView({len(self)} parameters, non-zero: {nonzero})"
