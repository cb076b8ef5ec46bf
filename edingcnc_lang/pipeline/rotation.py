"""G68 rotation as a pipeline stage: every move turned in the rotation's plane about the pivot.

The interpreter sends a ``RotationEvent`` when G68 takes effect (``on``, ``pivot`` machine
x y z, ``angle`` in degrees counter-clockwise, ``plane`` XY, YZ or XZ) and again when an offset
change moves the pivot on the machine; G69 ends it.  Arcs in the rotation's plane turn with the
rest; an arc in another plane would leave its plane and is refused, naming its line.
"""
from __future__ import annotations

from edingcnc_lang.canon import Arc, Canon, Event, Pose
from edingcnc_lang.config.machine_config import MachineConfig
from edingcnc_lang.errors import Location, MachineError
from edingcnc_lang.events import RotationEvent
from edingcnc_lang.machine.geometry import rotate_about
from edingcnc_lang.pipeline.transform import PoseTransform, map_center


PLANE_CODE = {"XY": "G17", "XZ": "G18", "YZ": "G19"}


class Rotation(PoseTransform):
    """Turns the two axes of its plane about the G68 pivot while G68 is on."""

    def __init__(self, next_canon: Canon, config: MachineConfig) -> None:
        super().__init__(next_canon, config)
        self.angle: float | None = None
        self.pivot: tuple[float, ...] = (0.0, 0.0, 0.0)
        self.plane = "XY"

    @property
    def on(self) -> bool:
        return self.angle is not None

    def event(self, event: Event) -> None:
        if isinstance(event, RotationEvent):
            self.angle = event.angle if event.on else None
            if event.on and event.pivot is not None:
                self.pivot = event.pivot
                self.plane = event.plane or "XY"
        self.next.event(event)

    def forward(self, pose: Pose) -> Pose:
        return rotate_about(pose, self.pivot, self.angle, self.plane) if self.angle else pose

    def inverse(self, pose: Pose) -> Pose:
        return rotate_about(pose, self.pivot, -self.angle, self.plane) if self.angle else pose

    def arc(self, arc: Arc, where: Location) -> Arc:
        if arc.plane != self.plane and self.angle and self.angle % 360.0:
            raise MachineError(f"an arc in the {arc.plane} plane cannot be turned by G68 (it turns the {self.plane} "
                               f"plane); use {PLANE_CODE[self.plane]} arcs or G69 first", where)
        return Arc(map_center(arc, self.forward), arc.plane, arc.turn, arc.full_turns)
