"""Cutter radius compensation, the interpreter's part: G40/G41/G42/G41.1/G42.1 and the plane step.

The interpreter only decides what is programmed: which side, which radius (from the tool table,
``G10 L1 P R`` or ``#5500 + n``, or a D diameter with G41.1/G42.1) and in which plane.  It tells
the pipeline with a ``cutter_comp`` event; the ``pipeline.cutter_comp`` stage moves the path.
"""
from __future__ import annotations

from collections.abc import Mapping

from edingcnc_lang.syntax import nodes as n
from edingcnc_lang.machine import tables as t
from edingcnc_lang.events import CutterCompEvent
from edingcnc_lang.machine.state import (
    G_40,
    G_41,
    G_41_1,
    G_42_1,
    PLANE_OF,
    MachineState,
    format_value,
    StepTable,
)

DIAMETER_CODES = frozenset({G_41_1, G_42_1})  # D is the diameter itself, not a tool number


class CompensationSteps(MachineState):
    """G41/G42 switch compensation on with a radius, G40 off; the plane cannot change meanwhile."""

    def _step_plane(self, code: int, words: Mapping[str, float], g: Mapping[str, int], span: n.Span) -> None:
        if code != self.modal["plane"]:
            self.refuse_with_comp("changing the plane (G17/G18/G19)", span)
        self.modal["plane"] = code

    def _step_cutter_comp(self, code: int, words: Mapping[str, float], g: Mapping[str, int],
                          span: n.Span) -> None:
        if code == G_40:
            if self.modal["cutter_comp"] != G_40:
                self.canon.event(CutterCompEvent(self.path, self.line, "off"))
            self.modal["cutter_comp"] = code
            return
        if self.modal["cutter_comp"] != G_40:
            raise self.fail(f"{t.code_name('G', code)}: cutter compensation is already on; turn it off with G40 "
                            "first", span)
        plane = PLANE_OF[self.modal["plane"]]
        allowed = "XZ" if self.config.lathe else "XY"
        if plane != allowed:  # manual 3.6.13 (p. 27): "die XY-Ebene ist nicht aktiv oder zum Drehen ist die ZX-Ebene
            #                   nicht aktiv" is an error
            raise self.fail(f"{t.code_name('G', code)}: cutter compensation works in the "
                            f"{'ZX plane (G18) on a lathe' if self.config.lathe else 'XY plane (G17) on a mill'}, "
                            f"not in {plane}", span)
        radius = self._comp_radius(code, words, span)
        self.modal["cutter_comp"] = code
        side = "left" if code in (G_41, G_41_1) else "right"
        orientation = self._comp_orientation(code, words) if self.config.lathe and plane == "XZ" else None
        self.canon.event(CutterCompEvent(self.path, self.line, side, radius, plane, self.inch, orientation))

    def _comp_orientation(self, code: int, words: Mapping[str, float]) -> int:
        """The lathe tool's orientation (#5700 + n): of tool D for G41/G42 (default the tool in the
        turret), of the tool in the turret for G41.1/G42.1 (whose D is a diameter).  It places the
        nose's controlled point (manual pp. 5-6)."""
        tool = int(self.params.read(t.TOOL_CURRENT)) if code in DIAMETER_CODES else \
            int(words.get("D", self.params.read(t.TOOL_CURRENT)))
        return int(self.params.read(t.TOOL_ORIENTATION + tool)) if tool else 0

    def _comp_radius(self, code: int, words: Mapping[str, float], span: n.Span) -> float:
        """The tool radius in mm; negative swaps the side (a tool smaller than the nominal one)."""
        name = t.code_name("G", code)
        if code in DIAMETER_CODES:
            if "D" not in words:
                raise self.fail(f"{name} needs D, the tool diameter", span)
            return words["D"] * self.scale / 2.0
        tool = words.get("D", self.params.read(t.TOOL_CURRENT))
        if tool != int(tool) or not 0 <= tool <= t.MAX_TOOL:
            raise self.fail(f"{name} D{format_value(tool)}: D is a tool number, T0..T{t.MAX_TOOL} "
                            f"(G41.1/G42.1 take a diameter)", span)
        return self.params.read(t.TOOL_DIAMETER + int(tool)) / 2.0 if tool else 0.0


# The order-of-execution steps this part performs, by tables.ORDER_OF_EXECUTION name (interpreter.py merges them).
STEPS: StepTable = {"plane": CompensationSteps._step_plane, "cutter_comp": CompensationSteps._step_cutter_comp}
