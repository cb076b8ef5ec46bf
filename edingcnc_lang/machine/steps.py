"""The steps of a G-code line in the controller's order of execution (tables.ORDER_OF_EXECUTION)."""
from __future__ import annotations

from collections.abc import Mapping

from edingcnc_lang.syntax import nodes as n
from edingcnc_lang.machine import devices, tables as t
from edingcnc_lang.events import (CoolantEvent, DwellEvent, EndEvent, MCodeEvent, OperatorWaitEvent, OutputEvent,
                                  OverrideEvent, PathControlEvent, PauseEvent, ToolChangeEvent)
from edingcnc_lang.host import checked_level
from edingcnc_lang.machine.offsets import NON_MODAL
from edingcnc_lang.machine.state import (
    G_1,
    G_17,
    G_18,
    G_4,
    G_40,
    G_43,
    G_43_1,
    G_49,
    G_90,
    G_93,
    G_94,
    MachineState,
    PAUSE_CODES,
    ProgramEnd,
    SPINDLE_SELECT,
    format_value,
    StepTable,
)


M_60 = t.code_key(60)
MAX_OVERRIDE = 1000.0  # percent: M50/M51 P above it is a typo (the --feed-override knob's range)


class LineSteps(MachineState):
    """Each ``_step_<name>`` takes the value that triggered it (a G/M key or a word's value), the line's words,
    its G codes by group and its span.  Add a step by adding a row to ``tables.ORDER_OF_EXECUTION`` and a
    ``_step_<name>`` method here (or in a module of its own mixed into ``Interpreter``)."""

    def _step_feed_mode(self, code: int, words: Mapping[str, float], g: Mapping[str, int], span: n.Span) -> None:
        if code != self.modal["feed_mode"]:
            self.modal["feed_mode"] = code
            self.feed = 0.0  # an F of the old mode means something else: the next feed move needs a new F

    def _step_feed(self, value: float, words: Mapping[str, float], g: Mapping[str, int], span: n.Span) -> None:
        if value < 0:
            raise self.fail("negative feed rate", span)
        self.feed = value * (1.0 if self.modal["feed_mode"] == G_93 else self.scale)

    def _step_tool_select(self, value: float, words: Mapping[str, float], g: Mapping[str, int],
                          span: n.Span) -> None:
        if value != int(value) or not 0 <= value <= t.MAX_TOOL:
            raise self.fail(f"tool T{format_value(value)} does not exist (tools are T0..T{t.MAX_TOOL})", span)
        self.offsets.selected_tool = int(value)

    def _step_tool_change(self, code: int, words: Mapping[str, float], g: Mapping[str, int], span: n.Span) -> None:
        """M6 (manual 3.7.3): the change (the change_tool sub, or the built-in), then the spindle is
        stopped, and a plain G43 in force compensates the new tool (3.6.12: G43 H and G43.1 do not)."""
        self.refuse_with_comp("a tool change (M6)", span)
        self._tool_change(span)
        if self.spindle.direction != 5:
            self._spindle_stop()
        if self.modal["length_offset"] == G_43 and self.offsets.length_follows_tool:
            self._apply_length(G_43, {})

    def _step_coolant(self, code: int, words: Mapping[str, float], g: Mapping[str, int], span: n.Span) -> None:
        self.devices.coolant = set() if code == 90 else self.devices.coolant | {code // 10}
        self.canon.event(CoolantEvent(self.path, self.line, code // 10))

    def _step_overrides(self, code: int, words: Mapping[str, float], g: Mapping[str, int], span: n.Span) -> None:
        """M48..M53 (manual 3.7.5, p. 61): the planner follows the feed override (M48..M50), the spindle's
        (M51) changes the speed the spindle turns at; ``M50 P0``/``M51 P0`` wait for the operator's knob."""
        m = code // 10
        p = words.get("P")
        if m in (50, 51) and p is not None and p > MAX_OVERRIDE:
            raise self.fail(f"M{m} P{format_value(p)}: an override is at most {MAX_OVERRIDE:g} percent", span)
        if m in (48, 49) or (m == 51 and (p is None or p >= 0)):
            self.spindle.set_override(m, p)
        if m in (50, 51) and p == 0:
            self.canon.event(OperatorWaitEvent(self.path, self.line, m, "feed" if m == 50 else "spindle"))
        elif m == 51 and p is not None and p < 0:
            self.spindle.override_on = False  # off; the value stays (p. 61)
        self.canon.event(OverrideEvent(self.path, self.line, m, p))

    def _step_path_control(self, code: int, words: Mapping[str, float], g: Mapping[str, int],
                           span: n.Span) -> None:
        """G61/G61.1/G64: the planner stops at every corner or blends within P (mm).

        ``words`` are G64's own (manual 3.6.16: P Q R S D F, never the speed or the feed); the
        planner uses P, the others are recorded in the event (lengths in mm, angles in degrees).
        """
        self.modal["path_control"] = code
        tolerance = words["P"] * self.scale if "P" in words else self.config.g64_p
        if tolerance < 0:
            raise self.fail("G64 P: the path tolerance must be 0 or more", span)
        extra: dict[str, float] = {}
        for letter in "QRSDF":
            if letter in words:
                value = words[letter] * (self.scale if letter in t.G64_LENGTHS else 1.0)
                if value < 0:
                    raise self.fail(f"G64 {letter}{format_value(words[letter])}: must be 0 or more", span)
                extra[letter.lower()] = value
        self.canon.event(PathControlEvent(self.path, self.line, t.code_name("G", code), tolerance, extra.get("q"),
                                          extra.get("r"), extra.get("s"), extra.get("d"), extra.get("f")))

    def _step_io(self, code: int, words: Mapping[str, float], g: Mapping[str, int], span: n.Span) -> None:
        self._io(code // 10, words, span)

    def _step_m_state(self, code: int, words: Mapping[str, float], g: Mapping[str, int], span: n.Span) -> None:
        m = code // 10
        if m in (26, 27):  # clamp / release the rotary axes: a move that turns one while clamped is refused
            self.guards.clamped = m == 26
            if "P" in words:  # manual 3.7.9 (p. 65): "P1 bedeutet AUX 1": the output that drives the brake
                port = int(words["P"])
                self.devices.outputs[port] = m == 26
                self.canon.event(OutputEvent(self.path, self.line, port, m == 26, None))
        elif m == 100:  # manual 3.7.12: the axis resolution by a factor ("1,01 ist 1% mehr")
            factor = words.get("P", 1.0)
            if factor <= 0:
                raise self.fail(f"M100 P{format_value(factor)}: the resolution factor must be more than 0 (1 is "
                                "the standard)", span)
            self.devices.resolution_factor = factor
        elif m in SPINDLE_SELECT:  # M90 standard spindle, M91..M97 the alternate spindles, probe, camera
            devices.select_spindle(self, m)
        self.canon.event(MCodeEvent(self.path, self.line, m, words.get("P")))  # M100 P: the axis resolution factor

    def _step_dwell(self, code: int, words: Mapping[str, float], g: Mapping[str, int], span: n.Span) -> None:
        if code == G_4:
            self._dwell(words, span)

    def _step_modal(self, code: int, words: Mapping[str, float], g: Mapping[str, int], span: n.Span) -> None:
        """Units, path control, distance and return mode: state only."""
        self.modal[t.G_GROUPS[code]] = code

    def _step_length_offset(self, code: int, words: Mapping[str, float], g: Mapping[str, int],
                            span: n.Span) -> None:
        self._length_offset(code, words, span)

    def _step_coord_system(self, code: int, words: Mapping[str, float], g: Mapping[str, int],
                           span: n.Span) -> None:
        if code != self.modal["coord_system"]:
            self.refuse_with_comp(f"changing the coordinate system ({t.code_name('G', code)})", span)
        self._select_coord_system(code)

    def _step_rotation(self, code: int, words: Mapping[str, float], g: Mapping[str, int], span: n.Span) -> None:
        self._rotation(code, words, span)

    def _step_non_modal(self, code: int, words: Mapping[str, float], g: Mapping[str, int], span: n.Span) -> None:
        handler = NON_MODAL.get(code)
        if handler is not None:
            handler(self, code, words, span)

    def _step_motion(self, code: int | None, words: Mapping[str, float], g: Mapping[str, int],
                     span: n.Span) -> None:
        self._motion(words, g, g.get("non_modal"), span)

    def _step_stopping(self, code: int, words: Mapping[str, float], g: Mapping[str, int], span: n.Span) -> None:
        self._stop(code, span)

    def _tool_change(self, span: n.Span) -> None:
        if t.TOOL_CHANGE_SUB in self.flow.subs and all(f.name != t.TOOL_CHANGE_SUB for f in self.flow.stack):
            self.params.set(t.TOOL_NEW, float(self.offsets.selected_tool))
            self.params.set(t.TOOL_CHANGED, 0.0)
            self.call_sub(t.TOOL_CHANGE_SUB, span)
            return
        old = int(self.params.read(t.TOOL_CURRENT))
        self.params.set(t.TOOL_CURRENT, float(self.offsets.selected_tool))
        tool = self.offsets.selected_tool
        self.params.set(t.TOOL_RADIUS, self.params.read(t.TOOL_DIAMETER + tool) / 2.0 if tool else 0.0)
        self._tool_offsets_read()
        self.canon.event(ToolChangeEvent(self.path, self.line, tool, old))

    def _io(self, code: int, words: Mapping[str, float], span: n.Span) -> None:
        port = int(words.get("P", words.get("E", 0)))
        if "E" in words and code in (54, 55, 57):  # a PWM output: M54 E<n> Q<0..1000>, M55 E<n>, M57 E<n>
            self._pwm(code, port, words, span)
            return
        if code in (54, 55):
            self.devices.outputs[port] = code == 54
            self.canon.event(OutputEvent(self.path, self.line, port, code == 54, words.get("Q")))
        elif code == 56:
            try:
                level = checked_level(self.host.read_input(port)) if self.host.read_input else 0.0
            except ValueError as err:
                raise self.fail(str(err), span) from None
            wait = int(words.get("L", 0))
            if wait in (1, 2) and (level != 0.0) != (wait == 1):
                level = -1.0  # the wait for high (L1) / low (L2) timed out
            self.params.set(t.IO_RESULT, level)
        else:
            self.params.set(t.IO_RESULT, 1.0 if self.devices.output_on(port, self.spindle.direction) else 0.0)

    def _pwm(self, code: int, port: int, words: Mapping[str, float], span: n.Span) -> None:
        """PWM outputs: M54 E Q sets the duty (0..1000 per mille), M55 E sets 0, M57 E reads it into #5399."""
        if code == 57:
            self.params.set(t.IO_RESULT, self.devices.pwm.get(port, 0.0))
            return
        duty = words.get("Q", 0.0) if code == 54 else 0.0
        if not 0.0 <= duty <= 1000.0:
            raise self.fail(f"M54 E{port} Q{format_value(duty)}: the PWM value Q must lie in 0..1000", span)
        self.devices.pwm[port] = duty
        self.canon.event(OutputEvent(self.path, self.line, port, duty > 0, duty))

    def _dwell(self, words: Mapping[str, float], span: n.Span) -> None:
        if "P" not in words or words["P"] < 0:
            raise self.fail("G4 needs a dwell time P (seconds) of 0 or more", span)
        seconds = words["P"] / 1000.0 if self.config.g4_in_milliseconds else words["P"]
        self.canon.event(DwellEvent(self.path, self.line, seconds))

    def _length_offset(self, code: int, words: Mapping[str, float], span: n.Span) -> None:
        """G43/G43.1/G49; on a lathe G43 applies the tool's X offset (a radius) as well as Z."""
        self.refuse_with_comp(f"changing the tool length offset ({t.code_name('G', code)})", span)
        self.offsets.length_follows_tool = code == G_43 and "H" not in words
        self._apply_length(code, words, span)

    def _tool_offsets_read(self) -> None:
        """#5010 and #5012 (manual p. 2): the current tool's Z offset (length + zDelta) and X offset
        (width + xDelta) as the tool table stores them, so a diameter value on a diameter lathe;
        set at M6 and at G43, so a macro that wrote #54xx/#56xx reads its new value after G43."""
        tool = int(self.params.read(t.TOOL_CURRENT))
        read = self.params.read
        valid = 1 <= tool <= t.MAX_TOOL
        self.params.set(t.TOOL_Z_OFFSET, read(t.TOOL_LENGTH + tool) + read(t.TOOL_Z_WEAR + tool) if valid else 0.0)
        if self.config.lathe:
            self.params.set(t.TOOL_X_TOTAL, read(t.TOOL_X_OFFSET + tool) + read(t.TOOL_X_WEAR + tool) if valid else 0.0)

    def _apply_length(self, code: int, words: Mapping[str, float], span: n.Span | None = None) -> None:
        """Set the length offset of G43 [H]/G43.1/G49 (a plain G43: the tool in the spindle, #5008).

        On a lathe the X offset too: the tool table's width + xDelta (G43.1: I) is a diameter
        value on a diameter lathe, so X moves by half of it (the real lathe's saved state: width
        -35.248, #5014 = -17.624)."""
        self.offsets.tool_x = 0.0
        if code == G_49:
            self.offsets.tool_z = 0.0
        else:
            tool = int(words.get("H", self.params.read(t.TOOL_CURRENT)))
            if not 0 <= tool <= t.MAX_TOOL:
                raise self.fail(f"G43 H{tool}: no such tool", span)
            lathe = self.config.lathe
            x_part = 0.5 if self.diameter_mode else 1.0
            if code == G_43_1:  # dynamic offset: K is the tool length, I the X offset on a lathe
                self.offsets.tool_z = words.get("K", 0.0) * self.scale
                self.offsets.tool_x = words.get("I", 0.0) * self.scale * x_part if lathe else 0.0
            elif tool:
                read = self.params.read
                # zDelta: the wear, on a mill and a lathe
                self.offsets.tool_z = read(t.TOOL_LENGTH + tool) + read(t.TOOL_Z_WEAR + tool)
                if lathe:
                    self.offsets.tool_x = (read(t.TOOL_X_OFFSET + tool) + read(t.TOOL_X_WEAR + tool)) * x_part
            else:
                self.offsets.tool_z = 0.0
            if code == G_43 and "H" not in words:
                self._tool_offsets_read()
        self.modal["length_offset"] = code
        self.params.set(t.TOOL_G43_OFFSET, self.offsets.tool_z)
        if self.config.lathe:
            self.params.set(t.TOOL_G43_X_OFFSET, self.offsets.tool_x)
        self._offsets_changed()

    def _stop(self, code: int, span: n.Span) -> None:
        if code in PAUSE_CODES:
            self.canon.event(PauseEvent(self.path, self.line, code // 10))
            return
        # Manual 3.7.1: G17 (G18 on a lathe), G90, G94, M48, G40, M5, G1, M9; the coordinate system is
        # kept; M60 keeps the spindle and the coolant on (nesting).  M2 ends as M30 does.
        for group, reset in (("plane", G_18 if self.config.lathe else G_17), ("distance", G_90), ("feed_mode", G_94),
                             ("cutter_comp", G_40), ("motion", G_1)):
            self.modal[group] = reset
        self.canon.event(OverrideEvent(self.path, self.line, 48))
        self.spindle.set_override(48, None)
        if code != M_60:
            self.spindle.direction = 5
            if self.devices.coolant:  # M9 (3.7.1), as an event like the program's own M9
                self.canon.event(CoolantEvent(self.path, self.line, 9))
            self.devices.coolant = set()
            self.params.set(t.SPINDLE_ON, 0.0)
        self.scaling_off()
        devices.heaters_off(self)
        self.flow.ended_by = f"M{code // 10}"
        self.canon.event(EndEvent(self.path, self.line, code // 10))
        raise ProgramEnd()


# The order-of-execution steps this part performs, by tables.ORDER_OF_EXECUTION name (interpreter.py merges them).
STEPS: StepTable = {"feed_mode": LineSteps._step_feed_mode, "feed": LineSteps._step_feed, "tool_select": LineSteps._step_tool_select, "tool_change": LineSteps._step_tool_change, "coolant": LineSteps._step_coolant, "overrides": LineSteps._step_overrides, "path_control": LineSteps._step_path_control, "io": LineSteps._step_io, "m_state": LineSteps._step_m_state, "dwell": LineSteps._step_dwell, "length_offset": LineSteps._step_length_offset, "coord_system": LineSteps._step_coord_system, "rotation": LineSteps._step_rotation, "non_modal": LineSteps._step_non_modal, "motion": LineSteps._step_motion, "stopping": LineSteps._step_stopping, "units": LineSteps._step_modal, "distance": LineSteps._step_modal, "return_mode": LineSteps._step_modal}
