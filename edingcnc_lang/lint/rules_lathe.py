"""Lathe rules: G76 in LinuxCNC's words (G520) and spindle speeds the ini's limits change (G521).

Only constant words are checked (``I[#1]`` and ``S#1556`` are decided at run time, where the run
reports the same).  G521 follows G96/G97 in source order through each file, since an S after a G96
is a surface speed; a mode set in a sub another file calls is not seen.
"""
from __future__ import annotations

from collections.abc import Iterator

from edingcnc_lang.diagnostics import Diagnostic
from edingcnc_lang.machine.spindle import clamp_rpm, speed_clamp_message
from edingcnc_lang.machine.tables import code_key
from edingcnc_lang.syntax import nodes as n
from edingcnc_lang.lint.evaluate import evaluate
from edingcnc_lang.lint.model import SourceFile
from edingcnc_lang.lint.project import Project
from edingcnc_lang.lint.registry import at, rule

G76, G96, G97 = code_key(76), code_key(96), code_key(97)


def _last(block: n.Block, letter: str) -> n.Word | None:
    """The line's last word of a letter (the one the controller uses)."""
    return next((w for w in reversed(block.words) if w.letter == letter), None)


@rule("G520")
def g76_linuxcnc_crest(file: SourceFile, project: Project) -> Iterator[Diagnostic]:
    """A constant I of 0 or below on a G76 line: LinuxCNC's offset, which stops the run."""
    for codes in project.facts(file).coded:
        if not any(key == G76 for key, _ in codes.g):
            continue
        word = _last(codes.block, "I")
        value = evaluate(word.value) if word is not None else None
        if word is not None and value is not None and value <= 0:
            yield at("G520", f"G76 I{value:g}: EdingCNC reads I as the thread's crest diameter (an X position, "
                     "always positive, manual 3.6.18), not as LinuxCNC's offset from the drive line; J and K "
                     "are radial depths beyond the crest", word.span)


@rule("G521")
def spindle_speed_outside_the_range(file: SourceFile, project: Project) -> Iterator[Diagnostic]:
    """A constant S (under G97) or G96 D the ini's spindleNmin/spindleNmax change."""
    low, high = project.spindle_range
    if not (low or high):
        return
    css = False
    for stmt, _scope in project.walked(file):
        if not isinstance(stmt, n.Block):
            continue
        g = {key for key, _ in project.codes(file, stmt, "G")}
        css = G96 in g or (css and G97 not in g)
        speed, d_word = _last(stmt, "S"), _last(stmt, "D") if G96 in g else None
        if d_word is not None and (value := evaluate(d_word.value)) is not None and value > high > 0:
            yield at("G521", f"G96 D{value:g}: the spindle turns at most {high:g} rpm, the machine's "
                     "spindleNmax (cnc.ini)", d_word.span)
        if speed is None or css or (asked := evaluate(speed.value)) is None or asked <= 0:
            continue
        rpm = clamp_rpm(asked, high, low)
        if rpm != asked:
            yield at("G521", speed_clamp_message(asked, rpm, high), speed.span)
