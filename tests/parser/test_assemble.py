"""The compiled reader's block assembler (``_lexer.assemble``) builds what ``StatementReader._fit`` builds
line by line, the reference (the pure-Python reader runs it for every line): the same statements,
spans included, the same diagnostics and warnings, on generated files with blocks nested, left open,
closed twice, a second Else, dialogs, Subs inside blocks and lines the compiled reader gives up on."""
from __future__ import annotations

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from edingcnc_lang.syntax import parser
from edingcnc_lang.syntax.fastparse import COMPILED_READER

pytestmark = [pytest.mark.skipif(not COMPILED_READER, reason="the compiled reader is not built"), pytest.mark.slow]

LINES = ["If [#1 > 0]", "  While [#2 < 3]", "Else", "EndIf", "  EndWhile", "Sub a", "EndSub", "G1 X1 Y[#3 * 2]",
         "#1 = [#1 + 1]", "", "; note", 'dlgmsg "t" "a" 1', "dlgmsg 5", 'msg "x "#1', "GoSub a", "home x",
         "(note) G1 X2", "G1 X]]", "If [#5380 == 1]", "M30", "errmsg \"stop\"", "If [#1 > 0]]", "Endif ; x",
         "G0 X" + "1" * 120]


def _read(lines: list[str], mode: str, tolerant: bool, assembled: bool) -> tuple[str, ...]:
    with pytest.MonkeyPatch.context() as patch:
        if not assembled:  # every line through _line and _fit
            patch.setattr(parser, "COMPILED_READER", False)
        reader = parser.StatementReader(list(lines), "f.cnc", mode=mode, tolerant=tolerant)
        found = repr(list(reader))
    return found, repr(reader.diagnostics), repr(reader.warnings), repr((reader.lines, reader.unit))


@settings(max_examples=300, deadline=None)
@given(st.lists(st.sampled_from(LINES), max_size=60), st.sampled_from(["tree", "lint"]), st.booleans(),
       st.sampled_from([3, 64]))
def test_the_assembler_builds_the_blocks_fit_builds(lines: list[str], mode: str, tolerant: bool, depth: int) -> None:
    with pytest.MonkeyPatch.context() as patch:
        patch.setattr(parser, "MAX_BLOCK_DEPTH", depth)
        patch.setattr(parser, "READ_AHEAD", 5)  # calls that end inside a run of lines, and at blocks' ends
        assert _read(lines, mode, tolerant, True) == _read(lines, mode, tolerant, False)


def test_the_assembler_takes_the_lines_inside_blocks() -> None:
    """It is what reads a block's lines: a sub of ordinary lines goes through it, not _line."""
    lines = ["Sub a", "  If [#1 > 0]", "    G1 X1", "  Else", "    #2 = 1", "  EndIf", "  While [#1 < 2]",
             "    #1 = [#1 + 1]", "  EndWhile", "EndSub"]
    calls = []
    with pytest.MonkeyPatch.context() as patch:
        original = parser.StatementReader._line
        patch.setattr(parser.StatementReader, "_line", lambda self, *a: calls.append(a[1]) or original(self, *a))
        (sub,) = parser.StatementReader(lines, "f.cnc", mode="tree")
    assert calls == ["Sub a"] and len(sub.body) == 2 and sub.body[0].has_else and sub.end_span.line == 10
