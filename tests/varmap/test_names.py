"""Names found where authors write them, strongest source first; the explicit convention."""
from __future__ import annotations

from pathlib import Path

import pytest

from edingcnc_lang.syntax.parser import parse_text
from edingcnc_lang.varmap import convention
from edingcnc_lang.varmap.kinds import (
    ARGUMENT, KINDS, PERSISTENT_USER, READ_ONLY, RESERVED, SCRATCH, TOOL_TABLE, USER, WRITABLE, kind_of, manual_name,
)
from edingcnc_lang.varmap.names import Names, source_of


def names_of(text: str, sidecars: tuple[str, ...] = ()) -> Names:
    return Names([source_of("m.cnc", text.splitlines(), parse_text(text, "m.cnc").body)], sidecars)


def test_precedence_annotation_dlgmsg_comment_header_manual() -> None:
    text = "\n".join([
        ";; #1500 = 1 ;; Z1 from the header",
        ";; #1501 = 0 ;; header only",
        "Sub user_1",
        '    dlgmsg "Facing" "Z start" 1500 "pitch" 1502',
        "    #1500 = 3 ;; commented Z",
        "    #1502 = 1 ;; commented pitch",
        "    #1503 = 2 ;; only a comment",
        "EndSub",
        ';@var #1502 thread_pitch "mm per turn"',
    ])
    found = names_of(text)
    assert [(found.best(i).name, found.best(i).source) for i in (1500, 1501, 1502, 1503)] == [  # type: ignore[union-attr]
        ("Z start", "dlgmsg"), ("header only", "header"), ("thread_pitch", "annotation"),
        ("only a comment", "comment")]
    assert found.best(1502).description == "mm per turn"  # type: ignore[union-attr]
    assert found.best(1500).sub == "user_1"  # type: ignore[union-attr]
    manual = found.best(5067)
    assert manual is not None and (manual.name, manual.source) == ("probe tripped", "manual")
    assert found.best(1600) is None


@pytest.mark.parametrize("line, number, name", [
    (";; #2001 = cutting speed in [m/s]", 2001, "cutting speed in [m/s]"),
    (";;[5012] actual tool X offset", 5012, "actual tool X offset"),
    (";   #4507 ;Position of the X axis", 4507, "Position of the X axis"),
    (";   #4561 - 3D finder offset X", 4561, "3D finder offset X"),
    ("; #3500         INIT flag", 3500, "INIT flag"),
])
def test_header_comment_forms(line: str, number: int, name: str) -> None:
    found = names_of(line).best(number)
    assert found is not None and (found.name, found.source) == (name, "header")


def test_a_header_range_names_each_number() -> None:
    found = names_of("; #5061-#5066   probe position, work")
    assert {n for n in found.candidates} == set(range(5061, 5067))


@pytest.mark.parametrize("text", [
    ";         - initialisation of #4548 and #4549 added",  # prose that mentions numbers
    ";#5017 = #[5400 + #5016]",  # commented-out code
    ";; #1500 = 1",  # a value, no name
    "#5026 = [#5026 + 1] ; next",  # an update says what the line does
    "#1659 = 1; ",  # an empty comment
    "#27 = 1 ; 12345",  # no letter
])
def test_no_name(text: str) -> None:
    assert names_of(text).candidates == {}


def test_assignment_comment_forms() -> None:
    found = names_of("#1653 = 2.5 ;; tool width\n#5016 = [#5008]\t; current tool\n#30 = 1 (paren note)")
    assert [found.name(i) for i in (1653, 5016, 30)] == ["tool width", "current tool", "paren note"]


def test_annotation_problems_have_a_position() -> None:
    found = names_of(";@var #27 1bad\n;@var #6000 too_big\n;@var 28 no_hash\n;@var #29 a\n;@var #29 b")
    assert [(p.line, p.col) for p in found.problems] == [(1, 11), (2, 13), (3, 2), (5, 11)]
    assert "already named a" in found.problems[-1].message


def test_sidecar_tables_and_strings(tmp_path: Path) -> None:
    sidecar = tmp_path / "variables.toml"
    sidecar.write_text('# names\n1600 = "depth"\n\n[1554]\nname = "thread_pitch"\ndescription = "mm per turn"\n',
                       encoding="utf-8")
    found = names_of('dlgmsg "T" "pitch" 1554 "depth" 1600', (str(sidecar),))
    pitch, depth = found.best(1554), found.best(1600)
    assert pitch is not None and (pitch.name, pitch.source, pitch.line, pitch.col) == ("thread_pitch", "annotation", 5, 9)
    assert depth is not None and (depth.name, depth.line, depth.col) == ("depth", 2, 9)


@pytest.mark.parametrize("text, line, col, words", [
    ("[1554\nname = 1", 1, 6, "Expected ']'"),
    ('[1554]\ntitle = "x"', 1, 1, "needs a name"),
    ('[speed]\nname = "x"', 1, 1, "not a variable number"),
    ('[1554]\nname = "9lives"', 2, 9, "not a name"),
])
def test_sidecar_problems(tmp_path: Path, text: str, line: int, col: int, words: str) -> None:
    sidecar = tmp_path / "variables.toml"
    sidecar.write_text(text, encoding="utf-8")
    problems = convention.sidecar(str(sidecar))
    assert len(problems) == 1 and isinstance(problems[0], convention.Problem)
    assert (problems[0].line, problems[0].col) == (line, col) and words in problems[0].message


def test_no_sidecar_is_no_names(tmp_path: Path) -> None:
    assert convention.sidecar(str(tmp_path / "variables.toml")) == []


@pytest.mark.parametrize("number, kind", [
    (1, ARGUMENT), (27, USER), (3999, USER), (4000, PERSISTENT_USER), (5001, READ_ONLY), (5020, SCRATCH),
    (5398, WRITABLE), (5401, TOOL_TABLE), (5999, TOOL_TABLE), (5230, RESERVED), (5231, RESERVED), (5500, RESERVED),
])
def test_kinds(number: int, kind: str) -> None:
    assert kind_of(number) == kind and kind in KINDS


def test_manual_names_only_for_system_numbers() -> None:
    assert manual_name(5011) == "new tool" and manual_name(5012) == "tool X offset"
    assert manual_name(27) is None and manual_name(5020) is None and manual_name(5230) is None


def test_identifier_of_a_label() -> None:
    assert convention.identifier("diameter A [mm]") == "diameter_a_mm"
    assert convention.identifier("1st pass") == "v_1st_pass"
    assert convention.annotation_line(1552, "d", "x y") == ';@var #1552 d "x y"'
