"""Z height compensation commands: ZHCINIT, ZHCINITEX, ZHCADDPOINT, ZHC on/off, ZHCS, ZHCL, ZHCcheck.

The grid lies in machine X/Y, from the work zero at ``ZHCINIT`` (the stock ``zhcmgrid`` sub
probes ``x[i * gridSize] y[j * gridSize]`` in work coordinates).  ``ZHCADDPOINT`` stores the
last probe's work Z at the grid point nearest its XY, so the table holds surface heights
relative to the work Z zero and a job's ``Z-0.1`` means 0.1 below the surface while ZHC is on.
Applying the table to the moves is the ``HeightCompensation`` stage's job (``pipeline/``).
"""
from __future__ import annotations

from pathlib import Path
from typing import TextIO

from edingcnc_lang.syntax import nodes as n
from edingcnc_lang.machine import tables as t
from edingcnc_lang.events import ZhcEvent, ZhcSaveEvent
from edingcnc_lang.errors import EcncError
from edingcnc_lang.config.heightmap import ZhcTable
from edingcnc_lang.machine.job_files import OpenMode
from edingcnc_lang.syntax.input_limits import MAX_HEIGHT_MAP_VALUE
from edingcnc_lang.machine.state import CommandTable, MachineState


class HeightComp(MachineState):
    """The ZHC table of one machine (``MachineState.zhc``) and the commands that build, save and switch it."""

    def _command_values(self, stmt: n.Command, count: int, usage: str) -> list[float]:
        """The ``count`` numeric arguments of a command (``ZHCINIT [#4104] 10 [#4101]``), evaluated
        (the parser read them as expressions; ``ZHCINIT 10 5 nan`` has none)."""
        if stmt.values is None or len(stmt.values) != count:
            raise self.fail(f"{usage} (got {stmt.args or 'nothing'!r})", stmt.span)
        return [self.evaluator.value(item) for item in stmt.values]

    def _zhc_init(self, stmt: n.Command) -> None:
        if stmt.name == "zhcinit":
            size, nx, ny = self._command_values(stmt, 3, "ZHCINIT expects gridSize nX nY, e.g. ZHCINIT 10 5 4")
            dx = dy = size
        else:
            dx, dy, nx, ny = self._command_values(stmt, 4, "ZHCINITEX expects gridSizeX gridSizeY nX nY")
        problem = ZhcTable.grid_problem(dx, dy, nx, ny)
        if problem:
            raise self.fail(f"{stmt.name.upper()}: {problem}", stmt.span)
        origin = self.offset()
        self.zhc.table = ZhcTable.empty(int(nx), int(ny), origin[0], origin[1], dx, dy)

    def _zhc_add_point(self, stmt: n.Command) -> None:
        if self.zhc.table is None:
            raise self.fail("ZHCADDPOINT before ZHCINIT: there is no grid to add the point to", stmt.span)
        if self.params.read(t.PROBE_TRIPPED) != 1.0:
            raise self.fail("ZHCADDPOINT: the last G38.2 did not touch (#5067 is not 1)", stmt.span)
        x, y = self.params.read(t.PROBE_MACHINE), self.params.read(t.PROBE_MACHINE + 1)
        z = self.params.read(t.PROBE_WORK + 2)
        if not abs(z) <= MAX_HEIGHT_MAP_VALUE:  # a host's probe answer: the table's statistics stay finite
            raise self.fail(f"ZHCADDPOINT: the probed height {z:g} is beyond {MAX_HEIGHT_MAP_VALUE:g} mm", stmt.span)
        if self.zhc.table.add(x, y, z) is None:
            raise self.fail(f"ZHCADDPOINT: the probe point X{x:g} Y{y:g} (machine) is not on the ZHC grid",
                            stmt.span)

    def _zhc_switch(self, on: bool, span: n.Span) -> None:
        table = self.zhc.table
        if on and (table is None or not table.complete()):
            measured = f"{len(table.measured())} of {table.nx * table.ny} points are measured" if table else \
                "there is no height table (probe one with ZHCINIT and ZHCADDPOINT, or load one with ZHCL)"
            raise self.fail(f"ZHC on: {measured}", span)
        self.params.set(t.ZHC_ACTIVE, 1.0 if on else 0.0)
        self.canon.event(ZhcEvent(self.path, self.line, on, table.height_map() if on and table is not None else None))

    def _zhc_file(self, stmt: n.Command) -> Path:
        """The file ZHCS/ZHCL name, in the log folder under logfile's rules (job_files.py)."""
        try:
            return self.files.named(stmt.args.strip().strip('"'), self.path)
        except ValueError as exc:
            raise self.fail(f"{stmt.name.upper()} {exc}", stmt.span) from None

    def _zhc_open(self, path: Path, mode: OpenMode, span: n.Span) -> TextIO:
        try:
            return self.files.open(path, mode)
        except OSError as exc:
            verb = "read" if mode == "read" else "write"
            raise self.fail(f"cannot {verb} the height table {path}: {exc.strerror or exc}", span) from None

    def _zhc_save(self, stmt: n.Command) -> None:
        if self.zhc.table is None:
            raise self.fail("ZHCS before ZHCINIT: there is no height table to save", stmt.span)
        path = self._zhc_file(stmt)
        path.parent.mkdir(parents=True, exist_ok=True)
        with self._zhc_open(path, "write", stmt.span) as handle:
            handle.write(self.zhc.table.to_text())
        self.canon.event(ZhcSaveEvent(self.path, self.line, str(path)))

    def _zhc_load(self, stmt: n.Command) -> None:
        path = self._zhc_file(stmt)
        with self._zhc_open(path, "read", stmt.span) as handle:
            text = handle.read()
        try:
            self.zhc.table = ZhcTable.from_text(text, str(path))
        except EcncError as err:
            loc = err.location
            where = f"{loc.path}, line {loc.line}" if loc is not None and loc.line else str(path)
            raise self.fail(f"ZHCL: the height table {where} does not load: {err.message}", stmt.span) from None

    def _zhc_check(self, stmt: n.Command) -> None:
        if self.zhc.table is None:
            raise self.fail("ZHCcheck before ZHCINIT or ZHCL: there is no height table", stmt.span)
        self.message("msg", self.zhc.table.statistics())


# Named commands of this part, by lower-case name (named_commands.py dispatches them).
COMMANDS: CommandTable = {"zhcinit": HeightComp._zhc_init, "zhcinitex": HeightComp._zhc_init,
                          "zhcaddpoint": HeightComp._zhc_add_point, "zhcs": HeightComp._zhc_save,
                          "zhcl": HeightComp._zhc_load, "zhccheck": HeightComp._zhc_check}
