"""The spindle: S, M3/M4/M5 and the speed modes G96 (constant surface speed) and G97 (rpm).

What a speed means lives here; the arithmetic (the speed at a radius, the mean speed along a
move) is ``spindle.py``.  Every change of the speed in force is an ``spindle_speed`` event, and
every move carries the speed along it (``state._move``).
"""
from __future__ import annotations

from collections.abc import Mapping

from edingcnc_lang.syntax import nodes as n
from edingcnc_lang.machine import tables as t
from edingcnc_lang.events import SpindleEvent, SpindleSpeedEvent
from edingcnc_lang.machine.spindle import (FT_PER_MIN, M_PER_MIN, SpindleError, clamp_rpm, css_limits,
                                          speed_clamp_message)
from edingcnc_lang.machine.state import G_96, MachineState, format_value, StepTable


class SpindleModes(MachineState):
    """G96/G97 run before S on a line (the order of execution), so ``G96 S150 D2500`` reads S as m/min."""

    def _step_spindle_mode(self, code: int, words: Mapping[str, float], g: Mapping[str, int],
                           span: n.Span) -> None:
        spindle = self.spindle
        if code == G_96:
            if "D" in words:
                if words["D"] < 0:
                    raise self.fail(f"G96 D{format_value(words['D'])}: the maximum spindle speed must not be "
                                    "negative", span)
                spindle.css_max = words["D"]
                if spindle.css_max > self.config.spindle_max_rpm > 0:
                    self.warn("G521", f"G96 D{format_value(spindle.css_max)}: the spindle turns at most "
                              f"{format_value(self.config.spindle_max_rpm)} rpm, the machine's spindleNmax "
                              "(cnc.ini)", span)
            spindle.css = spindle.css or (0.0, 0.0, 0.0)
        else:
            if spindle.css is not None:  # keep turning at the speed CSS asked for here
                spindle.rpm = self.rpm_at(self.pos[0], overridden=False)
                spindle.speed = spindle.rpm
            spindle.css = None
        if "S" not in words:
            self._apply_speed(span)

    def _step_spindle_speed(self, value: float, words: Mapping[str, float], g: Mapping[str, int],
                            span: n.Span) -> None:
        if value < 0:
            raise self.fail(f"spindle speed S{format_value(value)} is negative", span)
        self.spindle.speed = value
        self._apply_speed(span)

    def _apply_speed(self, span: n.Span) -> None:
        """Turn the S in force into the speed the spindle runs at, and report it."""
        config, spindle = self.config, self.spindle
        if spindle.css is not None:
            try:
                max_rpm, min_rpm = css_limits(spindle.css_max or None, config.spindle_max_rpm, config.spindle_min_rpm)
            except SpindleError as err:
                raise self.fail(str(err), span) from None
            per_unit = FT_PER_MIN if self.inch else M_PER_MIN
            spindle.css = (spindle.speed * per_unit, max_rpm, min_rpm)
            mode, top = "css", max_rpm
        else:
            spindle.rpm = clamp_rpm(spindle.speed, config.spindle_max_rpm, config.spindle_min_rpm)
            if spindle.rpm != spindle.speed and spindle.speed > 0:
                self.warn("G521", speed_clamp_message(spindle.speed, spindle.rpm, config.spindle_max_rpm), span)
            mode, top = "rpm", config.spindle_max_rpm
        rpm = self.rpm_at(self.pos[0])
        self.canon.event(SpindleSpeedEvent(self.path, self.line, mode, spindle.speed, top, rpm))

    def _step_spindle(self, code: int, words: Mapping[str, float], g: Mapping[str, int], span: n.Span) -> None:
        self._spindle_turn(code // 10)

    def _spindle_stop(self) -> None:
        """The spindle stops without an M5 of the program (after M6, manual 3.7.3)."""
        self._spindle_turn(5)

    def _spindle_turn(self, direction: int) -> None:
        self.spindle.direction = direction
        on = direction != 5
        rpm = self.rpm_at(self.pos[0])
        self.params.set(t.SPINDLE_ON, 1.0 if on else 0.0)
        self.canon.event(SpindleEvent(self.path, self.line, direction, self.spindle.speed, rpm if on else 0.0))

    def spindle_state(self) -> dict[str, object]:
        """The spindle at the end of a run, for ``--json``: direction, mode and speed."""
        spindle = self.spindle
        css = spindle.css
        return {"m": spindle.direction, "mode": "G96" if css is not None else "G97", "s": spindle.speed,
                "rpm": self.rpm_at(self.pos[0]) if spindle.direction != 5 else 0.0,
                "max_rpm": css[1] if css is not None else self.config.spindle_max_rpm}


# The order-of-execution steps this part performs, by tables.ORDER_OF_EXECUTION name (interpreter.py merges them).
STEPS: StepTable = {"spindle_mode": SpindleModes._step_spindle_mode, "spindle_speed": SpindleModes._step_spindle_speed, "spindle": SpindleModes._step_spindle}
