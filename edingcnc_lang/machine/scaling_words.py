"""G51/G50 scaling, the interpreter's part: factors, centre, parameters; the stage scales the moves.

``G51 P2 I10 J5`` scales X and Y by 2 about the work point (10, 5) (default: the work zero);
``G51 X2 Y0.5`` scales each axis by its own factor (a missing one is 1).  Z is never scaled.  Under G68
the centre is the rotation's pivot (manual p. 33); #5191/#5192 hold the centre as G68's pivot does.
"""
from __future__ import annotations

from collections.abc import Mapping

from edingcnc_lang.syntax import nodes as n
from edingcnc_lang.machine import tables as t
from edingcnc_lang.events import ScalingEvent
from edingcnc_lang.machine.state import G_51, MachineState, format_value, StepTable


class ScalingWords(MachineState):
    """G51 switches scaling on (or changes it), G50 and M2/M30 switch it off."""

    def _step_scaling(self, code: int, words: Mapping[str, float], g: Mapping[str, int], span: n.Span) -> None:
        if code != G_51:
            self.scaling_off()
            return
        uniform = "P" in words
        if uniform and ("X" in words or "Y" in words):
            raise self.fail("G51 takes either P (one factor for X and Y) or X/Y (a factor per axis), not both", span)
        if not uniform and "X" not in words and "Y" not in words:
            raise self.fail("G51 needs a factor: P for X and Y alike, or X and/or Y", span)
        factors = (words["P"], words["P"]) if uniform else (words.get("X", 1.0), words.get("Y", 1.0))
        for factor in factors:
            if factor == 0:
                raise self.fail(f"G51 factor {format_value(factor)}: a factor of 0 would flatten the job", span)
        work = (words.get("I", 0.0) * self.scale, words.get("J", 0.0) * self.scale)
        turn = self.rotation.turn
        if turn is not None:  # manual 3.6.13 (p. 33): "In Kombination mit G68 sind der Drehpunkt und
            work = turn.pivot[:2]  # der Skalierungspunkt die gleich"
        offset = self.offset()
        with self.machine_kept():
            scaling = self.scaling
            scaling.factors = (*factors, 1.0)
            scaling.center = (work[0] + offset[0], work[1] + offset[1])
        for index, value in enumerate((1.0, work[0], work[1], 0.0, *scaling.factors)):
            self.params.set(t.SCALING_ACTIVE + index, value)
        self.params.set(t.G68_ACTIVE + 1, work[0])  # #5191/#5192: the G68/G51 point (manual 3.1, p. 3)
        self.params.set(t.G68_ACTIVE + 2, work[1])
        self.canon.event(ScalingEvent(self.path, self.line, True, scaling.factors, scaling.center))

    def scaling_off(self) -> None:
        if self.scaling.factors is not None:
            with self.machine_kept():
                self.scaling.factors = None
            self.params.set(t.SCALING_ACTIVE, 0.0)
            self.canon.event(ScalingEvent(self.path, self.line, False))


# The order-of-execution steps this part performs, by tables.ORDER_OF_EXECUTION name (interpreter.py merges them).
STEPS: StepTable = {"scaling": ScalingWords._step_scaling}
