"""Walking a file's statements in source order with what the rules need to know about each.

``walk`` yields every statement with its ``Scope``: the sub it is in and
whether it is under the simulation guard.  The helpers below say which
parameters a statement reads and writes and whether it ends the program.
"""
from __future__ import annotations

from collections.abc import Iterator, Sequence

from edingcnc_lang.syntax import nodes as n
from edingcnc_lang.records import record
from edingcnc_lang.machine.tables import RENDERING, SIMULATION, code_key
from edingcnc_lang.lint.evaluate import constant_index, evaluate, params_in

END_OF_PROGRAM = frozenset(code_key(c) for c in (2, 30))
Code = tuple[int, n.Word]  # a literal G or M number as integer tenths (G38.2 -> 382) and its word


@record(frozen=True)
class Scope:
    """Where a statement sits: its sub (None at top level) and whether the simulation guard covers it."""

    sub: n.Sub | None = None
    guarded: bool = False


def walk(body: Sequence[n.Stmt]) -> list[tuple[n.Stmt, Scope]]:
    """Every statement, nested ones included, in source order with its scope (worked out in the
    walk that gathers the lint facts, ``lint.facts.survey``)."""
    from edingcnc_lang.lint.facts import survey  # (that module builds on this one)

    return list(survey(body).walked)


# What a guard reads: #5380 (simulation) and #5397 (rendering, the job's preview); real macros guard their
# probes with either (the Sorotec macro with If [#5397 == 0] alone: its simulation may probe, for testing).
GUARD_PARAMS = frozenset({SIMULATION, RENDERING})


def simulation_value(index: int) -> float | None:
    """Parameter lookup for a run that simulates and renders: #5380 and #5397 are 1, nothing else is known."""
    return 1.0 if index in GUARD_PARAMS else None


def simulation_branches(stmt: n.If) -> tuple[bool, bool, bool]:
    """For an If whose condition reads #5380 or #5397: which branches never run in simulation or rendering (then, else),
    and whether the If ends the program or aborts whenever it runs in simulation.

    A condition that cannot be decided counts as guarding both branches (the author checked
    for simulation, so no finding) and as not ending the program.
    """
    value = evaluate(stmt.cond, simulation_value)
    if value is None:
        return True, True, False
    branch = stmt.then if value else stmt.orelse
    return not value, bool(value), any(ends_program(s) for s in branch)


def ends_program(stmt: n.Stmt) -> bool:
    """An unconditional end: a line with M2/M30 (no block delete) or an errmsg."""
    if isinstance(stmt, n.Message):
        return stmt.kind == "errmsg"
    if isinstance(stmt, n.Block) and not stmt.block_delete:
        return any(code in END_OF_PROGRAM for code, _word in block_codes(stmt)[1])
    return False


def block_codes(block: n.Block) -> tuple[tuple[Code, ...], tuple[Code, ...]]:
    """The literal G and the literal M numbers of a block, with their words, in line order."""
    g: list[Code] = []
    m: list[Code] = []
    for word in block.words:
        letter = word.letter
        if (letter == "G" or letter == "M") and isinstance(word.value, n.Number):
            (g if letter == "G" else m).append((code_key(word.value.value), word))
    return tuple(g), tuple(m)


def expressions(stmt: n.Stmt) -> Iterator[n.Expr]:
    """The expressions a statement evaluates itself (not those of nested statements).

    Assignment targets are not included (see ``written``); dlgmsg items are
    field indices, not reads, so they are left to the dialog rules.
    """
    if isinstance(stmt, n.Block):
        for word in stmt.words:
            yield word.value
        for assign in stmt.assigns:
            yield assign.target.index  # #[#1 + 2] = ... reads #1
            yield assign.value
    elif isinstance(stmt, (n.If, n.While)):
        yield stmt.cond
    elif isinstance(stmt, n.Message):
        yield from (item for item in stmt.items if not isinstance(item, (str, n.Stamp)))
    elif isinstance(stmt, n.LogFile) and stmt.mode is not None:
        yield stmt.mode
    elif isinstance(stmt, n.Kin):
        yield from stmt.args
    elif isinstance(stmt, n.PrepareLinDeltaHome) and stmt.velocity is not None:
        yield stmt.velocity


def reads(stmt: n.Stmt) -> list[n.Param]:
    """Every parameter the statement itself reads."""
    found: list[n.Param] = []
    if type(stmt) is n.Block:  # most statements: ``expressions`` unrolled, the same order
        for word in stmt.words:
            if type(word.value) is not n.Number:  # most word values
                found += params_in(word.value)
        for assign in stmt.assigns:
            if type(assign.target.index) is not n.Number:  # #[#1 + 2] = ... reads #1
                found += params_in(assign.target.index)
            found += params_in(assign.value)
        return found
    for expr in expressions(stmt):
        if not isinstance(expr, n.Number):  # most word values
            found += params_in(expr)
    return found


def assigned(stmt: n.Stmt) -> Iterator[n.Param]:
    """Assignment targets of a statement (as written, maybe computed)."""
    if isinstance(stmt, n.Block):
        for assign in stmt.assigns:
            yield assign.target


def dialog_fields(stmt: n.Dialog) -> Iterator[tuple[int, n.Number]]:
    """The bare integer field indices of a dlgmsg with their literal nodes."""
    for item in stmt.items[1:]:
        if isinstance(item, n.Number) and item.value.is_integer():
            yield int(item.value), item


def literal_index(param: n.Param) -> int | None:
    """The index of a parameter when it is a whole number known without running."""
    literal = param.index
    index = literal.value if type(literal) is n.Number else constant_index(param)  # #n: most of them
    return int(index) if index is not None and index.is_integer() else None
