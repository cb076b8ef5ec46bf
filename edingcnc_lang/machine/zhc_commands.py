"""Z height compensation commands: ZHCINIT, ZHCINITEX, ZHCADDPOINT, ZHC on/off, ZHCS, ZHCL, ZHCcheck.

The grid lies in machine X/Y, from the work zero at ``ZHCINIT`` (the stock ``zhcmgrid`` sub
probes ``x[i * gridSize] y[j * gridSize]`` in work coordinates).  ``ZHCADDPOINT`` stores the
last probe's work Z at the grid point nearest its XY, so the table holds surface heights
relative to the work Z zero and a job's ``Z-0.1`` means 0.1 below the surface while ZHC is on.
Applying the table to the moves is the ``HeightCompensation`` stage's job (``pipeline/``).

A composed part, not a mixin: each command is a function of the machine as ``ZhcMachine``, the
few things it uses (its own state ``machine.zhc``, the parameters, the files, the canon, errors
naming the line), so mypy refuses a use of anything else.
"""
from __future__ import annotations

from pathlib import Path
from typing import Protocol, TextIO

from edingcnc_lang.syntax import nodes as n
from edingcnc_lang.machine import tables as t
from edingcnc_lang.events import ZhcEvent, ZhcSaveEvent
from edingcnc_lang.errors import EcncError
from edingcnc_lang.config.heightmap import ZhcTable
from edingcnc_lang.machine.evaluator import Evaluator
from edingcnc_lang.machine.job_files import OpenMode
from edingcnc_lang.machine.parts import JobFiles, PartMachine, ZhcState
from edingcnc_lang.syntax.input_limits import MAX_HEIGHT_MAP_VALUE
from edingcnc_lang.machine.state import CommandTable, MessageKind


class ZhcMachine(PartMachine, Protocol):
    """What the ZHC commands use of the machine, read-only (the table changes inside ``zhc``)."""

    @property
    def zhc(self) -> ZhcState: ...
    @property
    def evaluator(self) -> Evaluator: ...
    @property
    def files(self) -> JobFiles: ...
    def offset(self) -> list[float]: ...
    def message(self, kind: MessageKind, text: str) -> None: ...


def _values(machine: ZhcMachine, stmt: n.Command, count: int, usage: str) -> list[float]:
    """The ``count`` numeric arguments of a command (``ZHCINIT [#4104] 10 [#4101]``), evaluated
    (the parser read them as expressions; ``ZHCINIT 10 5 nan`` has none)."""
    if stmt.values is None or len(stmt.values) != count:
        raise machine.fail(f"{usage} (got {stmt.args or 'nothing'!r})", stmt.span)
    return [machine.evaluator.value(item) for item in stmt.values]


def init(machine: ZhcMachine, stmt: n.Command) -> None:
    if stmt.name == "zhcinit":
        size, nx, ny = _values(machine, stmt, 3, "ZHCINIT expects gridSize nX nY, e.g. ZHCINIT 10 5 4")
        dx = dy = size
    else:
        dx, dy, nx, ny = _values(machine, stmt, 4, "ZHCINITEX expects gridSizeX gridSizeY nX nY")
    problem = ZhcTable.grid_problem(dx, dy, nx, ny)
    if problem:
        raise machine.fail(f"{stmt.name.upper()}: {problem}", stmt.span)
    origin = machine.offset()
    machine.zhc.table = ZhcTable.empty(int(nx), int(ny), origin[0], origin[1], dx, dy)


def add_point(machine: ZhcMachine, stmt: n.Command) -> None:
    if machine.zhc.table is None:
        raise machine.fail("ZHCADDPOINT before ZHCINIT: there is no grid to add the point to", stmt.span)
    if machine.params.read(t.PROBE_TRIPPED) != 1.0:
        raise machine.fail("ZHCADDPOINT: the last G38.2 did not touch (#5067 is not 1)", stmt.span)
    x, y = machine.params.read(t.PROBE_MACHINE), machine.params.read(t.PROBE_MACHINE + 1)
    z = machine.params.read(t.PROBE_WORK + 2)
    if not abs(z) <= MAX_HEIGHT_MAP_VALUE:  # a host's probe answer: the table's statistics stay finite
        raise machine.fail(f"ZHCADDPOINT: the probed height {z:g} is beyond {MAX_HEIGHT_MAP_VALUE:g} mm", stmt.span)
    if machine.zhc.table.add(x, y, z) is None:
        raise machine.fail(f"ZHCADDPOINT: the probe point X{x:g} Y{y:g} (machine) is not on the ZHC grid",
                           stmt.span)


def switch(machine: ZhcMachine, on: bool, span: n.Span) -> None:
    table = machine.zhc.table
    if on and (table is None or not table.complete()):
        measured = f"{len(table.measured())} of {table.nx * table.ny} points are measured" if table else \
            "there is no height table (probe one with ZHCINIT and ZHCADDPOINT, or load one with ZHCL)"
        raise machine.fail(f"ZHC on: {measured}", span)
    machine.params.set(t.ZHC_ACTIVE, 1.0 if on else 0.0)
    heights = table.height_map() if on and table is not None else None
    machine.canon.event(ZhcEvent(machine.path, machine.line, on, heights))


def _file(machine: ZhcMachine, stmt: n.Command) -> Path:
    """The file ZHCS/ZHCL name, in the log folder under logfile's rules (job_files.py)."""
    try:
        return machine.files.named(stmt.args.strip().strip('"'), machine.path)
    except ValueError as exc:
        raise machine.fail(f"{stmt.name.upper()} {exc}", stmt.span) from None


def _open(machine: ZhcMachine, path: Path, mode: OpenMode, span: n.Span) -> TextIO:
    try:
        return machine.files.open(path, mode)
    except OSError as exc:
        verb = "read" if mode == "read" else "write"
        raise machine.fail(f"cannot {verb} the height table {path}: {exc.strerror or exc}", span) from None


def save(machine: ZhcMachine, stmt: n.Command) -> None:
    if machine.zhc.table is None:
        raise machine.fail("ZHCS before ZHCINIT: there is no height table to save", stmt.span)
    path = _file(machine, stmt)
    path.parent.mkdir(parents=True, exist_ok=True)
    with _open(machine, path, "write", stmt.span) as handle:
        handle.write(machine.zhc.table.to_text())
    machine.canon.event(ZhcSaveEvent(machine.path, machine.line, str(path)))


def load(machine: ZhcMachine, stmt: n.Command) -> None:
    path = _file(machine, stmt)
    with _open(machine, path, "read", stmt.span) as handle:
        text = handle.read()
    try:
        machine.zhc.table = ZhcTable.from_text(text, str(path))
    except EcncError as err:
        loc = err.location
        where = f"{loc.path}, line {loc.line}" if loc is not None and loc.line else str(path)
        raise machine.fail(f"ZHCL: the height table {where} does not load: {err.message}", stmt.span) from None


def check(machine: ZhcMachine, stmt: n.Command) -> None:
    if machine.zhc.table is None:
        raise machine.fail("ZHCcheck before ZHCINIT or ZHCL: there is no height table", stmt.span)
    machine.message("msg", machine.zhc.table.statistics())


# Named commands of this part, by lower-case name (named_commands.py dispatches them).
COMMANDS: CommandTable = {"zhcinit": init, "zhcinitex": init,
                          "zhcaddpoint": add_point, "zhcs": save,
                          "zhcl": load, "zhccheck": check}
