"""G51 scaling as a pipeline stage: X and Y of every move scaled about a centre; Z never.

The interpreter sends a ``scaling`` event when G51 takes effect (data: ``on``, ``factors`` x y z,
``center`` machine x y) and when G50 or M2/M30 end it.  Arcs keep their shape only when both of
their plane's factors have the same size (a negative factor mirrors, which reverses an arc made
by mirroring one axis); any other arc is refused, naming its line.  Each scaled move starts where
the previous move really ended, so switching scaling on or off never jumps.
"""
from __future__ import annotations

from edingcnc_lang.canon import PLANES, Arc, Canon, Event, Pose
from edingcnc_lang.config.machine_config import MachineConfig
from edingcnc_lang.events import EndEvent, ScalingEvent
from edingcnc_lang.errors import Location, MachineError
from edingcnc_lang.machine.geometry import scale_about
from edingcnc_lang.pipeline.transform import PoseTransform, map_center


class Scaling(PoseTransform):
    """Scales X and Y about the G51 centre while G51 is on."""

    def __init__(self, next_canon: Canon, config: MachineConfig) -> None:
        super().__init__(next_canon, config)
        self.factors: tuple[float, float, float] | None = None
        self.center = (0.0, 0.0, 0.0)

    @property
    def on(self) -> bool:
        return self.factors is not None

    def event(self, event: Event) -> None:
        if isinstance(event, ScalingEvent):
            if event.on and event.factors is not None and event.center is not None:
                self.factors = event.factors
                cx, cy = event.center
                self.center = (cx, cy, 0.0)
            else:
                self.factors = None
        elif isinstance(event, EndEvent):
            self.factors = None
        self.next.event(event)

    def forward(self, pose: Pose) -> Pose:
        return scale_about(pose, self.center, self.factors) if self.factors else pose

    def inverse(self, pose: Pose) -> Pose:
        if not self.factors:
            return pose
        return scale_about(pose, self.center, [1.0 / f for f in self.factors])

    def arc(self, arc: Arc, where: Location) -> Arc:
        assert self.factors is not None
        first, second, _ = PLANES[arc.plane]
        f1, f2 = self.factors[first], self.factors[second]
        if abs(f1) != abs(f2):
            raise MachineError(f"an arc cannot be scaled by different factors in the {arc.plane} plane "
                               f"({f1:g} and {f2:g}); use G51 P or break the arc into lines", where)
        turn = arc.turn if f1 * f2 > 0 else -arc.turn
        return Arc(map_center(arc, self.forward), arc.plane, turn, arc.full_turns)
