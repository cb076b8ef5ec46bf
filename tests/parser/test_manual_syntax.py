"""Line syntax as the manual says (issue 38; manual 3.4, p. 7, and 3.4.4).

p. 7: "Leerzeichen und Tabulatoren sind an einer beliebigen Stelle in einer Codezeile zulässig ...
Die Zeile "g0x + 0. 12 34y 7" entspricht beispielsweise "g0 x + 0.1234 y7"" (rs274 agrees);
"die Anzahl der Zeichen in einer Zeile maximal (derzeit 256)"; 3.4.1: a line number is "eine Ganzzahl
... zwischen 0 und 99999, die mit nicht mehr als fünf Ziffern geschrieben ist (000009 ist
beispielsweise nicht in Ordnung)".  3.4.4: comments do not nest.
"""
from __future__ import annotations

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from edingcnc_lang import RunOptions, run_string
from edingcnc_lang.diagnostics import SyntaxErrors
from edingcnc_lang.syntax.fastparse import GIVE_UP, compiled_statement, parse_fast
from edingcnc_lang.syntax.parser import _LineError, parse_line, parse_line_grammar
from edingcnc_lang.syntax.serialize import to_data


def values(line: str) -> list[tuple[str, float]]:
    block = parse_line(line, "f", 1)
    return [(w.letter, w.value.value) for w in block.words]  # type: ignore[union-attr]


def test_the_manuals_example_reads_as_x0_1234_y7() -> None:
    assert values("g0x + 0. 12 34y 7") == [("G", 0.0), ("X", 0.1234), ("Y", 7.0)]
    assert values("G1 X1 2.5 F1 000") == [("G", 1.0), ("X", 12.5), ("F", 1000.0)]


def test_the_run_moves_where_the_manual_says() -> None:
    moves: list[tuple[float, ...]] = []
    run_string("g0x + 0. 12 34y 7\n", RunOptions(on_move=lambda m, _j: moves.append(m.end[:2])))
    assert moves == [(0.1234, 7.0)]


def test_numbers_with_blanks_in_expressions_and_conditions() -> None:
    block = parse_line("#1 = 1 2 + 3", "f", 1)
    assert block.assigns[0].value.left.value == 12.0  # type: ignore[union-attr]
    head = parse_line("If [#1 == 1 2]", "f", 1)
    assert head.cond.right.value == 12.0  # type: ignore[union-attr]


def test_lists_of_values_keep_blanks_as_separators() -> None:
    # dlgmsg and KIN take lists of values: there a blank separates two numbers
    dialog = parse_line('dlgmsg "a" 1400 1401', "f", 1)
    assert [item.value for item in dialog.items[1:]] == [1400.0, 1401.0]  # type: ignore[union-attr]


SPACED = st.from_regex(r"[GXYZF] ?[+-]? ?[0-9]{1,3}( [0-9]{1,3}){0,2}( ?\. ?[0-9]{1,2}( [0-9])?)?", fullmatch=True)


@pytest.mark.slow
@settings(max_examples=200, deadline=None)
@given(st.lists(SPACED, min_size=1, max_size=4).map(" ".join))
def test_every_parse_path_agrees_on_numbers_with_blanks(line: str) -> None:
    """The fast readers (Python and C) give such lines to the grammar or read them as it does."""
    grammar = to_data(parse_line_grammar(line, "f", 1))
    assert to_data(parse_line(line, "f", 1)) == grammar
    for fast in (parse_fast(line, "f", 1), compiled_statement(line, "f", 1)):
        assert fast is GIVE_UP or to_data(fast) == grammar, line


def test_a_nested_comment_says_so_at_the_inner_paren() -> None:
    with pytest.raises(_LineError) as err:
        parse_line("G0 X1 ( T1: End Mill (6 mm) )", "f", 1)
    assert err.value.code == "E116" and "nested comment" in str(err.value) and err.value.col == 22


@pytest.mark.parametrize("line", ["N123456 G1 X1", "N000009 G1 X1", "N1 2 3 4 5 6 G1 X1", "N123456 #1 = 2"])
def test_a_line_number_has_at_most_five_digits(line: str) -> None:
    with pytest.raises(_LineError) as err:
        parse_line(line, "f", 1)
    assert err.value.code == "E115"
    assert parse_line("N12345 G1 X1", "f", 1).line_number == 12345  # type: ignore[union-attr]


def test_a_gcode_line_holds_at_most_256_characters_and_a_run_refuses_it_before_moving() -> None:
    line = "G1 X1 ; " + "x" * 249
    assert len(line) == 257
    with pytest.raises(SyntaxErrors) as err:
        run_string("G0 X5\n" + line + "\n", RunOptions())
    assert "at most 256 characters" in str(err.value) and ":2:257:" in err.value.format()
    parse_line(line[:-1], "f", 1)  # 256 are fine
    # a macro statement may be longer: real 4.03 dialogs are (docs/dialect.md)
    parse_line('dlgmsg "' + "d" * 300 + '"', "f", 1)
