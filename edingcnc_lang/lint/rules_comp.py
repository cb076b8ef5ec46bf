"""Cutter compensation rules: what the run would refuse, found without running.

The lint follows a file's lines in order (not its control flow) and knows a tool radius when the
file states it with literals (``G41.1/G42.1 D<diameter>``, ``G10 L1 P<n> R<radius>`` before
``G41/G42 D<n>``) or when ``--ini`` gives the tool table (``[TOOL_n] diameter``, mm; divided by
25.4 after a literal G20).  Radius and arc sizes are both in the program's units.
"""
from __future__ import annotations

import math
from collections.abc import Iterator

from edingcnc_lang.diagnostics import Diagnostic
from edingcnc_lang.machine.tables import MM_PER_INCH, code_key, code_name
from edingcnc_lang.lint.evaluate import evaluate
from edingcnc_lang.lint.facts import BlockCodes
from edingcnc_lang.lint.model import SourceFile
from edingcnc_lang.lint.project import Project
from edingcnc_lang.lint.registry import at, rule

G10 = code_key(10)
OFF = code_key(40)
LEFT = frozenset(code_key(c) for c in (41, 41.1))
DIAMETER = frozenset(code_key(c) for c in (41.1, 42.1))
COMP = LEFT | frozenset(code_key(c) for c in (42, 42.1))
PLANES = {code_key(17): ("I", "J"), code_key(18): ("I", "K"), code_key(19): ("J", "K")}
G2, G3 = code_key(2), code_key(3)
G20, G21 = code_key(20), code_key(21)
_READ_WORDS = COMP | {G10}  # the codes whose line's word values update() reads
_UPDATING = _READ_WORDS | {OFF, G20, G21} | PLANES.keys()  # the codes update() follows


class _Comp:
    """Compensation as the lines so far leave it: side (+1 left, -1 right, 0 off), radius, plane."""

    def __init__(self, tool_diameters: dict[int, float]) -> None:
        self.side = 0
        self.radius: float | None = None
        self.centre_words = PLANES[code_key(17)]
        self.tool_radius: dict[int, float] = {}  # from G10 L1 P R
        self.table = tool_diameters              # the ini's diameters, mm
        self.inch = False

    def words(self, codes: BlockCodes) -> dict[str, float | None]:
        return {w.letter: evaluate(w.value) for w in codes.block.words if w.letter not in "GM"}

    def update(self, keys: set[int], words: dict[str, float | None]) -> None:
        """Follow one line: its G codes (integer tenths) and its words' values (needed on G10, G41/G42 lines)."""
        self.inch = True if G20 in keys else False if G21 in keys else self.inch
        self.centre_words = next((PLANES[k] for k in keys if k in PLANES), self.centre_words)
        if G10 in keys and words.get("L") == 1 and words.get("P") is not None and words.get("R") is not None:
            self.tool_radius[int(words["P"])] = abs(words["R"])  # type: ignore[arg-type]
        if OFF in keys:
            self.side, self.radius = 0, None
        code = next((k for k in keys if k in COMP), None)
        if code is None:
            return
        self.side = 1 if code in LEFT else -1
        d = words.get("D")
        if code in DIAMETER:
            self.radius = abs(d) / 2.0 if d is not None else None
        else:
            self.radius = self._tool_radius(int(d)) if d is not None and d == int(d) else None

    def _tool_radius(self, tool: int) -> float | None:
        if tool in self.tool_radius:
            return self.tool_radius[tool]
        diameter = self.table.get(tool)
        return None if diameter is None else abs(diameter) / 2.0 / (MM_PER_INCH if self.inch else 1.0)


@rule("G508")
def arc_too_small_for_the_tool(file: SourceFile, project: Project) -> Iterator[Diagnostic]:
    comp = _Comp(project.tool_diameters)
    for codes in project.facts(file).coded:  # a block without G codes changes nothing here
        if not codes.g:
            continue
        if not (comp.side and comp.radius):  # off: only a code update() follows can matter (most lines)
            for key, _word in codes.g:
                if key in _UPDATING:
                    break
            else:
                continue
        keys = {key for key, _ in codes.g}
        # the words' values matter to a G10 or a G41/G42 line, and to an arc under compensation
        words = comp.words(codes) if keys & _READ_WORDS else {}
        if keys & _UPDATING:  # a line without these leaves the compensation as it is
            comp.update(keys, words)
        if not comp.side or not comp.radius:
            continue
        arc = next(((k, w) for k, w in codes.g if k in (G2, G3)), None)
        if arc is None or (comp.side > 0) != (arc[0] == G3):  # the tool runs outside this arc
            continue
        radius = _arc_radius(words or comp.words(codes), comp.centre_words)
        if radius is not None and radius <= comp.radius:
            side = "G41" if comp.side > 0 else "G42"
            yield at("G508", f"{code_name('G', arc[0])} arc of radius {radius:g} with the tool inside it ({side}) "
                     f"and a tool radius of {comp.radius:g}: the tool does not fit, the run stops here; use a "
                     "smaller tool or a larger arc", arc[1].span)


def _arc_radius(words: dict[str, float | None], centre: tuple[str, str]) -> float | None:
    if "R" in words:
        r = words["R"]
        return abs(r) if r is not None else None
    first, second = (words.get(letter, 0.0) if letter in words else 0.0 for letter in centre)
    if first is None or second is None or not (centre[0] in words or centre[1] in words):
        return None
    return math.hypot(first, second)
