"""The one-walk gathering of what the lint rules look at (``lint/facts.py``)."""
from __future__ import annotations

from edingcnc_lang.syntax import nodes as n
from edingcnc_lang.lint.facts import gather
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
    return gather(walk(program.body))


def test_blocks_carry_their_g_and_m_numbers_in_line_order() -> None:
    facts = _facts()
    codes = [([k for k, _ in b.g], [k for k, _ in b.m]) for b in facts.blocks]
    assert codes == [([382, 910], []), ([], []), ([0, 900], [30, 80]), ([], [])]
    probe = facts.blocks[0]
    assert probe.scope.guarded and probe.scope.sub is not None and probe.scope.sub.name == "probe_z"
    assert facts.blocks[2].scope.sub is None


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
    every = [stmt for stmt, _ in walk(parse_text(SOURCE, "job.nc").body)]
    assert len(facts.reads_of) == len(every)  # every statement has its reads, most of them none


def test_rules_name_the_first_matching_code_of_a_line(tmp_path) -> None:  # type: ignore[no-untyped-def]
    """With two motion codes on a line (a G500 of its own) G502/G503 speak of the first one."""
    from edingcnc_lang.lint import lint_paths

    job = tmp_path / "t.nc"
    job.write_text("G3 G2 X1 Y1\nG2 G1 X1 F0\n")
    found = {(d.line, d.col, d.code): d.message for d in lint_paths([job])}
    assert found[(1, 1, "G502")].startswith("G3 arc needs")
    assert found[(2, 10, "G503")].startswith("F0 on a G2 move")
