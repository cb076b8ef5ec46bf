"""The compiled look at a block (``_lexer.block_facts``, ``_lexer.expr_reads``) gives exactly what the
Python functions of ``lint/facts.py`` give (the reference): the same G and M numbers with the same word
nodes, the same parameters in the same order with the same literal indices."""
from __future__ import annotations

from pathlib import Path

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from edingcnc_lang.lint import facts
from edingcnc_lang.lint.walk import Scope, literal_index
from edingcnc_lang.machine.tables import code_key
from edingcnc_lang.syntax import blocks, fastparse
from edingcnc_lang.syntax import nodes as n
from edingcnc_lang.syntax.parser import parse_text
from edingcnc_lang.syntax.source import iter_file_lines

from tests.parser.test_properties import blocks as block_nodes, exprs, programs
from edingcnc_lang.lint.model import load_source

lexer = pytest.importorskip("edingcnc_lang._lexer", reason="the compiled reader is not built")
lexer.setup(n, blocks, fastparse.GIVE_UP, fastparse._KEYWORDS - fastparse._HANDLED)  # also under ECNC_PURE_PYTHON=1


def _same_block(block: n.Block) -> None:
    scope = Scope(None, True)
    uses: list[facts.Use] = [(n.Param(n.Number(1.0)), 1, scope)]  # appended to, as the walk's lists are
    targets: list[facts.Use] = []
    g, m, coded, reads = lexer.block_facts(code_key, literal_index, block, scope, uses, targets)
    want_uses, want_targets = [uses[0]], []
    want = facts.block_facts(block, scope, want_uses, want_targets)
    assert (g, m, coded, reads) == want and type(g) is type(m) is type(reads) is tuple
    assert [id(w) for _k, w in g + m] == [id(w) for _k, w in want[0] + want[1]]  # the very word nodes
    assert [(id(p), type(i)) for p, i in reads] == [(id(p), type(i)) for p, i in want[3]]
    assert uses == want_uses and targets == want_targets
    assert [(id(p), type(i), s) for p, i, s in uses + targets] == [(id(p), type(i), s) for p, i, s in
                                                                   want_uses + want_targets]


computed = st.builds(lambda e: n.Param(e), exprs)  # #[expr]: a literal index only when it folds
odd_numbers = st.sampled_from([0.05, 0.15, 2.5, 38.25, -1.05, 1e300, 5380.0, 1.5, 27.0])


@pytest.mark.slow
@settings(max_examples=200, deadline=None)
@given(block_nodes)
def test_the_compiled_block_facts_are_the_python_ones(block: n.Block) -> None:
    _same_block(block)


@pytest.mark.slow
@settings(max_examples=100, deadline=None)
@given(st.lists(st.tuples(st.sampled_from("GMTXF"), st.one_of(odd_numbers.map(n.Number), computed, exprs)),
                max_size=6),
       st.lists(st.tuples(st.one_of(computed, st.integers(1, 6000).map(lambda i: n.Param(n.Number(float(i))))),
                          exprs), max_size=3))
def test_codes_that_round_half_to_even_and_computed_indices(words: list[tuple[str, n.Expr]],
                                                            assigns: list[tuple[n.Param, n.Expr]]) -> None:
    _same_block(n.Block(tuple(n.Word(letter, value) for letter, value in words),
                        tuple(n.Assign(target, value) for target, value in assigns)))


@pytest.mark.slow
@settings(max_examples=200, deadline=None)
@given(exprs)
def test_the_compiled_expression_reads_are_the_python_ones(expr: n.Expr) -> None:
    got = lexer.expr_reads(literal_index, expr)
    assert got == facts.expr_reads(expr)
    assert [id(p) for p, _ in got] == [id(p) for p, _ in facts.expr_reads(expr)]


def test_the_shipped_files() -> None:
    """Every block and If/While condition of the examples, packaged macros and test files."""
    root = Path(__file__).resolve().parent.parent.parent
    count = 0
    for folder in ("examples", "stdlib", "tests/lint/cases", "tests/corpus"):
        for path in sorted((root / folder).rglob("*")):
            if path.suffix.lower() not in (".cnc", ".nc", ".ngc", ".tap"):
                continue
            try:
                program = parse_text("\n".join(iter_file_lines(path)), str(path))
            except Exception:  # files with syntax errors: other tests read them
                continue
            for stmt, _scope in facts.survey(program.body).walked:
                if isinstance(stmt, n.Block):
                    _same_block(stmt)
                    count += 1
                elif isinstance(stmt, (n.If, n.While)):
                    assert lexer.expr_reads(literal_index, stmt.cond) == facts.expr_reads(stmt.cond)
    assert count > 100


# ------------------------------------------------------------------ the compiled walk

def _python_survey(body: tuple[n.Stmt, ...]) -> facts.FileFacts:
    found = facts._Survey()
    found.visit(body, Scope())
    return found.facts()


def _compiled_survey(body: tuple[n.Stmt, ...]) -> facts.FileFacts:
    found = facts._Survey()
    lexer.survey(code_key, literal_index, Scope, facts.simulation_branches, facts._other_reads, facts.BlockCodes,
                 facts.END_OF_PROGRAM, facts.GUARD_PARAMS, found, body, Scope())
    return found.facts()


def _ids(value: object) -> object:
    """Nodes by identity, scopes and numbers by value, through tuples, lists and dicts."""
    if isinstance(value, (tuple, list)):
        return [type(value).__name__, *(_ids(v) for v in value)]
    if isinstance(value, dict):
        return {k: _ids(v) for k, v in value.items()}
    if isinstance(value, (frozenset, set)):
        return sorted(value)
    if value is None or isinstance(value, (int, float, str, bool, Scope)):
        return (type(value).__name__, value)
    return id(value)


def _same_survey(body: tuple[n.Stmt, ...]) -> None:
    compiled, python = _compiled_survey(body), _python_survey(body)
    for field in ("walked", "coded", "reads", "targets", "dialogs", "commands", "callers", "heads", "reads_of",
                  "codes_of", "ending", "unreachable"):
        assert _ids(getattr(compiled, field)) == _ids(getattr(python, field)), field
    assert all(type(c) is facts.BlockCodes for c in compiled.coded)


@pytest.mark.slow
@settings(max_examples=100, deadline=None)
@given(programs)
def test_the_compiled_walk_is_the_python_walk(program: n.Program) -> None:
    _same_survey(program.body)


def test_the_compiled_walk_of_the_shipped_files_and_the_guards() -> None:
    root = Path(__file__).resolve().parent.parent.parent
    count = 0
    for folder in ("examples", "stdlib", "tests/lint/cases", "tests/corpus"):
        for path in sorted((root / folder).rglob("*")):
            if path.suffix.lower() in (".cnc", ".nc", ".ngc", ".tap"):
                _same_survey(load_source(path, is_macro=True).body)
                count += 1
    guards = """\
If [[#5380 == 0] and [#5397 == 0]]
  G38.2 Z-1 F10
EndIf
If [#5380 == 1]
  M30
EndIf
G1 X1
If [#5380 <> #1]
  msg "x" %d #2
Else
  errmsg "y"
EndIf
logfile "a" [#3]
M2
Sub m3
  M3
EndSub
GoSub m3
"""
    _same_survey(parse_text(guards, "g.nc").body)
    assert count > 20
