"""Z height compensation (``ZHC on``) as a pipeline stage: every move's Z follows a height map.

The interpreter sends a ``ZhcEvent`` when compensation turns on (``on``, ``map`` the
``HeightMap`` in machine X/Y) or off.  While on, a straight move is split where its XY path
crosses a grid line of the map, and each piece ends at its programmed Z plus the surface height
there: between grid lines the bilinear surface is smooth along the line, so the compensated
path follows it.  An XY arc keeps its circle and gets the height of its end (a helix); an arc in
the XZ or YZ plane cannot follow the surface and is refused.  Probe and home moves are not
compensated (a probe measures the real surface, homing goes to the switches).  Each move starts
where the previous one really ended, so switching on or off never jumps: the first move after it
ramps to the new height.
"""
from __future__ import annotations

from dataclasses import replace

from edingcnc_lang.canon import Batch, Canon, Event, Move, Pose
from edingcnc_lang.config.machine_config import MachineConfig
from edingcnc_lang.errors import Location, MachineError
from edingcnc_lang.events import HeightSurface, ZhcEvent
from edingcnc_lang.pipeline.base import Stage

UNCOMPENSATED = frozenset({"probe", "home"})


class HeightCompensation(Stage):
    """Adds the height map's Z to every move while ZHC is on."""

    def __init__(self, next_canon: Canon, config: MachineConfig) -> None:
        super().__init__(next_canon, config)
        self.surface: HeightSurface | None = None
        self.applied = 0.0  # the Z added at the end of the last move handed on

    def event(self, event: Event) -> None:
        if isinstance(event, ZhcEvent):
            self.surface = event.map if event.on else None
            event = replace(event, map=None)  # the map is for this stage only
        self.next.event(event)

    def _lift(self, pose: Pose) -> Pose:
        assert self.surface is not None
        return (*pose[:2], pose[2] + self.surface.height(pose[0], pose[1]), *pose[3:])

    def move(self, move: Move) -> None:
        start = (*move.start[:2], move.start[2] + self.applied, *move.start[3:])
        if self.surface is None or move.kind in UNCOMPENSATED:
            self.applied = 0.0
            self.next.move(move if start == move.start else replace(move, start=start))
            return
        if move.arc is not None:
            if move.arc.plane != "XY":
                raise MachineError(f"Z height compensation cannot follow an arc in the {move.arc.plane} plane; "
                                   "use G17 arcs or ZHC off", Location(move.path, move.line))
            self._hand_on(replace(move, start=start, end=self._lift(move.end)))
            return
        a, b = move.start, move.end
        for t in (*self.surface.crossings(a, b), 1.0):
            end = self._lift(tuple(p + (q - p) * t for p, q in zip(a, b)) if t < 1.0 else b)
            self._hand_on(replace(move, start=start, end=end))
            start = end

    def _hand_on(self, move: Move) -> None:
        assert self.surface is not None
        self.applied = self.surface.height(move.end[0], move.end[1])
        self.next.move(move)

    def move_batch(self, batch: Batch) -> None:
        if self.surface is None and self.applied == 0.0:
            self.next.move_batch(batch)
            return
        batch.each(self.move)
