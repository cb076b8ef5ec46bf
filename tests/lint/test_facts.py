"""The one-walk gathering of what the lint rules look at (``lint/facts.py``)."""
from __future__ import annotations

from edingcnc_lang.syntax import nodes as n
from edingcnc_lang.lint.facts import indexed_reads, survey
from edingcnc_lang.lint.walk import walk
from edingcnc_lang.syntax.parser import parse_text

SOURCE = """\
Sub probe_z
    If [[#5380 == 0] and [#5397 == 0]]
        G38.2 G91 Z-[#4013 + 2] F[#4001]
        If [#5067 <> 1]
            errmsg "no touch"
        EndIf
    EndIf
    #1000 = [#1000 + #[5400 + 5]]
    dlgmsg "Setup" "Depth" 1001
    GetToolInfo 1 1002
EndSub
G0 G90 X1 M3 M8
GoSub probe_z
#[#1] = 2
"""


def _facts():  # type: ignore[no-untyped-def]
    program = parse_text(SOURCE, "job.nc")
    return survey(program.body)


def test_blocks_carry_their_g_and_m_numbers_in_line_order() -> None:
    facts = _facts()
    codes = [([k for k, _ in b.g], [k for k, _ in b.m]) for b in facts.coded]
    assert codes == [([382, 910], []), ([0, 900], [30, 80])]  # the blocks with a G, M or T word
    probe = facts.coded[0]
    assert probe.scope.guarded and probe.scope.sub is not None and probe.scope.sub.name == "probe_z"
    assert facts.coded[1].scope.sub is None


def test_reads_and_targets_in_source_order_with_literal_indices() -> None:
    facts = _facts()
    assert [index for _, index, _ in facts.reads] == [5380, 5397, 4013, 4001, 5067, 1000, 5405, 1]
    assert isinstance(facts.reads[6][0].index, n.Binary)  # #[5400 + 5]: a constant, folded
    assert [index for _, index, _ in facts.targets] == [1000, None]  # #[#1]: known only when run


def test_statements_of_each_kind_and_the_possible_callers() -> None:
    facts = _facts()
    assert [d.items[0] for d, _ in facts.dialogs] == ["Setup"]
    assert [c.name for c in facts.commands] == ["gettoolinfo"]
    callers = [type(stmt).__name__ for stmt, _ in facts.callers]
    assert callers == ["Block", "GoSub"]  # the block with M3 M8 may run Sub m3 / m8
    every = [stmt for stmt, _ in facts.walked]
    assert len(every) == len(walk(parse_text(SOURCE, "job.nc").body))
    for stmt in every:  # the statements that read parameters have their reads; the others read none
        assert facts.reads_of.get(id(stmt), ()) == indexed_reads(stmt), stmt
    assert [type(b.block.words[0].value).__name__ for b in facts.coded] == ["Number", "Number"]  # G38.2.., G0..


def test_rules_name_the_first_matching_code_of_a_line(tmp_path) -> None:  # type: ignore[no-untyped-def]
    """With two motion codes on a line (a G500 of its own) G502/G503 speak of the first one."""
    from edingcnc_lang.lint import lint_paths

    job = tmp_path / "t.nc"
    job.write_text("G3 G2 X1 Y1\nG2 G1 X1 F0\n")
    found = {(d.line, d.col, d.code): d.message for d in lint_paths([job])}
    assert found[(1, 1, "G502")].startswith("G3 arc needs")
    assert found[(2, 10, "G503")].startswith("F0 on a G2 move")


ENDS = """\
G0 X1 M30
/M30
M2 M8
errmsg "stop"
msg "go on"
If [#1 == 1]
    M30
EndIf
#1 = [#2 + #[#3]] X[#4] Y2 M5
"""


def test_the_ending_statements_are_those_ends_program_names() -> None:
    from edingcnc_lang.lint.walk import ends_program

    facts = survey(parse_text(ENDS, "job.nc").body)
    walked, ending = facts.walked, facts.ending
    assert [id(stmt) in ending for stmt, _ in walked] == [ends_program(stmt) for stmt, _ in walked]
    assert sum(id(stmt) in ending for stmt, _ in walked) == 4  # M30, M2, errmsg, the M30 in the If


def test_each_list_with_an_end_names_its_first_end_and_the_first_statement_after_it() -> None:
    """The first end of a list and what follows it (not a Sub), as S209 reports them."""
    text = "M30\nSub a\nEndSub\nG0 X1\nM2\nIf [#1 == 1]\n    errmsg \"x\"\n    M30\nEndIf\nWhile [1]\n    M2\nEndWhile\n"
    found = [(end.span.line, dead.span.line) for end, dead in survey(parse_text(text, "job.nc").body).unreachable]
    assert sorted(found) == [(1, 4), (7, 8)]


def test_the_reads_of_a_block_follow_its_expressions_in_order() -> None:
    """``reads`` unrolls ``expressions`` for blocks; both give the same parameters in the same order."""
    from edingcnc_lang.lint.evaluate import params_in
    from edingcnc_lang.lint.walk import expressions, reads

    for stmt, _ in walk(parse_text(SOURCE + ENDS, "job.nc").body):
        assert reads(stmt) == [p for e in expressions(stmt) for p in params_in(e)], stmt


def test_linting_leaves_no_reference_cycles(tmp_path) -> None:  # type: ignore[no-untyped-def]
    """The CLI pauses the cyclic collector while it lints: a cycle holding a tree (a recursive closure
    in the walk did) would keep the whole tree alive until the collector walked it at the end."""
    import gc

    from edingcnc_lang.lint import lint_paths

    job = tmp_path / "macro.cnc"
    job.write_text(";@unit mm\n" + SOURCE + ENDS)
    lint_paths([job])  # everything imported and cached first
    gc.collect()
    gc.disable()
    try:
        assert lint_paths([job])
        assert gc.collect() == 0
    finally:
        gc.enable()
