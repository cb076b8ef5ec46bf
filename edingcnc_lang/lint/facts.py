"""One walk over a file that sorts out what most rules look at.

Most rules care about one kind of thing: the G and M numbers of blocks, the
parameters read or assigned, the dialogs.  Gathering them in the single walk that
also works out each statement's scope (``walk.walk``), with each parameter's literal
index worked out once, spares those rules a walk over every statement and keeps
linting a big macro file fast: a rule about G, M or T words visits only the blocks
that have one, the unreachable-code rule only the lists that hold an end.  With the
compiled core the walk itself runs in C (``_lexer.survey``); ``_Survey.visit`` and the
functions it calls are its reference, and the tests compare the two.
"""
from __future__ import annotations

from collections.abc import Callable, Sequence
from functools import cached_property, partial
from operator import itemgetter
from typing import NamedTuple

from edingcnc_lang.syntax import nodes as n
from edingcnc_lang import speedups
from edingcnc_lang.records import record
from edingcnc_lang.syntax.fastparse import COMPILED_READER
from edingcnc_lang.machine.tables import code_key
from edingcnc_lang.lint.evaluate import params_in
from edingcnc_lang.lint.walk import END_OF_PROGRAM, GUARD_PARAMS, Code, Scope, literal_index, reads, simulation_branches

Use = tuple[n.Param, "int | None", Scope]  # a parameter read or assigned, its literal index, where
Walked = tuple[tuple[n.Stmt, Scope], ...]


_INDEX = itemgetter(1)  # a Use's literal index
_new_codes = tuple.__new__  # BlockCodes(...) without the named tuple's Python-level __new__: one per coded block


class BlockCodes(NamedTuple):
    """A block, where it sits, and its literal G and M numbers in line order."""

    block: n.Block
    scope: Scope
    g: tuple[Code, ...]
    m: tuple[Code, ...]


@record(frozen=True, eq=False)  # one per file: compared by identity
class FileFacts:
    """A file's statements sorted by what the rules ask about them."""

    walked: Walked  # every statement with its scope, as walk.walk gives them
    coded: tuple[BlockCodes, ...]  # the blocks with a G, M or T word (literal or not): the others hold no code
    reads: tuple[Use, ...]  # every parameter read, in source order
    targets: tuple[Use, ...]  # every assignment target, in source order
    dialogs: tuple[tuple[n.Dialog, Scope], ...]
    commands: tuple[n.Command, ...]
    callers: tuple[tuple[n.Stmt, Scope], ...]  # statements that may run a sub: GoSub, blocks with M codes
    heads: tuple[n.If | n.While, ...]  # every If and While
    # The parameters each statement that reads any reads (by id(): nodes hash by value, deeply).
    reads_of: dict[int, tuple[tuple[n.Param, int | None], ...]]
    codes_of: dict[int, BlockCodes]  # the coded blocks, by id()
    ending: frozenset[int]  # the statements (by id()) that end the program: walk.ends_program
    # In each list of statements that holds an end followed by more: the first end and the first
    # statement after it that is not a Sub definition (it never runs).
    unreachable: tuple[tuple[n.Stmt, n.Stmt], ...]

    @cached_property
    def read_indices(self) -> frozenset[int | None]:
        """The literal indices of every parameter read (None for a computed one): the few rules about
        indices look at each index once, and at the single reads only when one may be reported."""
        return frozenset(map(_INDEX, self.reads))

    @cached_property
    def target_indices(self) -> frozenset[int | None]:
        """The literal indices of every assignment target (None for a computed one)."""
        return frozenset(map(_INDEX, self.targets))


def indexed_reads(stmt: n.Stmt) -> tuple[tuple[n.Param, int | None], ...]:
    """The parameters a statement reads, each with its literal index (None if computed)."""
    return tuple((param, literal_index(param)) for param in reads(stmt))


def _indexed(params: list[n.Param]) -> list[tuple[n.Param, int | None]]:
    """``indexed_reads`` of a list of parameters, ``#n`` (most of them) without a call."""
    found = []
    for param in params:
        index = param.index
        if type(index) is n.Number:
            value = index.value
            found.append((param, int(value) if value.is_integer() else None))
        else:
            found.append((param, literal_index(param)))
    return found


def _block_reads(block: n.Block) -> list[n.Param]:
    """``walk.reads`` of a block, ``#n`` values without a call (the same order)."""
    found: list[n.Param] = []
    for word in block.words:
        value = word.value
        if type(value) is n.Number:
            continue
        if type(value) is n.Param and type(value.index) is n.Number:
            found.append(value)
        else:
            found += params_in(value)
    for assign in block.assigns:
        index = assign.target.index
        if type(index) is not n.Number:  # #[#1 + 2] = ... reads #1
            found += params_in(index)
        value = assign.value
        if type(value) is n.Param and type(value.index) is n.Number:
            found.append(value)
        elif type(value) is not n.Number:
            found += params_in(value)
    return found


Indexed = list[tuple[n.Param, "int | None"]]  # parameters read, each with its literal index
BlockFacts = tuple[tuple[Code, ...], tuple[Code, ...], bool, tuple[tuple[n.Param, "int | None"], ...]]


def block_facts(block: n.Block, scope: Scope, uses: list[Use], targets: list[Use]) -> BlockFacts:
    """A block's literal G and M numbers with their words in line order, whether it has a G, M or T word
    at all (literal or not), and the parameters it reads with their literal indices (``walk.reads``
    order), each also appended to ``uses`` with the scope; its assignment targets are appended to
    ``targets`` the same way.  The reference for the compiled ``_lexer.block_facts``."""
    g: list[Code] = []
    m: list[Code] = []
    coded = False
    for word in block.words:
        letter = word.letter
        if letter == "G" or letter == "M" or letter == "T":
            coded = True
            value = word.value
            if letter != "T" and type(value) is n.Number:
                (g if letter == "G" else m).append((code_key(value.value), word))
    found = tuple(_indexed(_block_reads(block)))
    uses.extend([(param, index, scope) for param, index in found])
    targets.extend([(a.target, literal_index(a.target), scope) for a in block.assigns])
    return tuple(g), tuple(m), coded, found


def expr_reads(expr: n.Expr) -> Indexed:
    """The parameters an expression reads with their literal indices (``evaluate.params_in`` order).
    The reference for the compiled ``_lexer.expr_reads``."""
    return _indexed(params_in(expr))


def _other_reads(stmt: n.Stmt) -> Indexed:
    """The reads of a statement that is not a block, a message, an If or a While (logfile, KIN, ...)."""
    return _indexed(reads(stmt))


def _compiled() -> Callable[[_Survey, Sequence[n.Stmt], Scope], None] | None:
    """``_Survey.visit`` on the compiled reader when it runs (see fastparse), else None."""
    if not COMPILED_READER:
        return None
    return partial(speedups.LEXER.survey, code_key, literal_index, Scope, simulation_branches, _other_reads, BlockCodes,
                   END_OF_PROGRAM, GUARD_PARAMS)


def survey(body: Sequence[n.Stmt]) -> FileFacts:
    """Every statement with its scope (``walk.walk``) and everything the rules look up about them."""
    found = _Survey()
    (_COMPILED_SURVEY or _Survey.visit)(found, body, Scope())
    return found.facts()


class _Survey:
    """What ``survey`` collects while it walks (a class, not closures: a recursive closure is a reference
    cycle, which would keep the whole tree alive until the cyclic collector runs).  ``visit`` is the
    reference for the compiled ``_lexer.survey``, which fills the same lists the same way."""

    def __init__(self) -> None:
        self.walked: list[tuple[n.Stmt, Scope]] = []
        self.coded: list[BlockCodes] = []
        self.reads: list[Use] = []
        self.targets: list[Use] = []
        self.dialogs: list[tuple[n.Dialog, Scope]] = []
        self.commands: list[n.Command] = []
        self.callers: list[tuple[n.Stmt, Scope]] = []
        self.heads: list[n.If | n.While] = []
        self.reads_of: dict[int, tuple[tuple[n.Param, int | None], ...]] = {}
        self.codes_of: dict[int, BlockCodes] = {}
        self.ending: set[int] = set()
        self.unreachable: list[tuple[n.Stmt, n.Stmt]] = []

    def facts(self) -> FileFacts:
        return FileFacts(tuple(self.walked), tuple(self.coded), tuple(self.reads),
                         tuple(self.targets), tuple(self.dialogs), tuple(self.commands), tuple(self.callers),
                         tuple(self.heads), self.reads_of, self.codes_of, frozenset(self.ending),
                         tuple(self.unreachable))

    def visit(self, body: Sequence[n.Stmt], scope: Scope) -> None:
        """The statements of one list, and those nested in them, in source order."""
        add, all_reads, reads_of, visit = self.walked.append, self.reads, self.reads_of, self.visit
        block_facts_of, expr_reads_of, targets = block_facts, expr_reads, self.targets
        here = scope
        end: n.Stmt | None = None  # the first statement of this list that ends the program
        dead = False  # the statement after it that never runs is found
        for stmt in body:
            add((stmt, here))
            ends = False
            if isinstance(stmt, n.Block):
                g, m, coded, found = block_facts_of(stmt, here, all_reads, targets)
                if found:
                    reads_of[id(stmt)] = found
                if coded:
                    codes = _new_codes(BlockCodes, (stmt, here, g, m))
                    self.coded.append(codes)
                    self.codes_of[id(stmt)] = codes
                if m:
                    self.callers.append((stmt, here))
                    ends = not stmt.block_delete and any(key in END_OF_PROGRAM for key, _word in m)
            elif isinstance(stmt, n.Sub):
                visit(stmt.body, Scope(stmt, False))
            elif isinstance(stmt, (n.If, n.While)):
                self.heads.append(stmt)
                pairs = expr_reads_of(stmt.cond)
                if pairs:
                    reads_of[id(stmt)] = tuple(pairs)
                    all_reads.extend([(param, index, here) for param, index in pairs])
                if isinstance(stmt, n.While):
                    visit(stmt.body, here)
                elif any(index in GUARD_PARAMS for _param, index in pairs):  # most conditions read neither guard
                    then_guard, else_guard, exits = simulation_branches(stmt)
                    guarded = Scope(scope.sub, True)
                    visit(stmt.then, guarded if then_guard else here)
                    visit(stmt.orelse, guarded if else_guard else here)
                    if not here.guarded and exits:
                        here = guarded  # the rest of this list only runs on a real machine
                else:
                    visit(stmt.then, here)
                    visit(stmt.orelse, here)
            elif isinstance(stmt, n.Dialog):  # (its items are field numbers, not reads)
                self.dialogs.append((stmt, here))
            else:
                if isinstance(stmt, n.Message):  # walk.reads of a message: its values' parameters
                    pairs = []
                    for item in stmt.items:
                        if not isinstance(item, (str, n.Stamp)):
                            pairs += expr_reads_of(item)
                    ends = stmt.kind == "errmsg"
                else:
                    pairs = _other_reads(stmt)
                    if isinstance(stmt, n.GoSub):
                        self.callers.append((stmt, here))
                    elif isinstance(stmt, n.Command):
                        self.commands.append(stmt)
                if pairs:
                    reads_of[id(stmt)] = tuple(pairs)
                    all_reads.extend([(param, index, here) for param, index in pairs])
            if end is not None:
                if not dead and not isinstance(stmt, n.Sub):
                    self.unreachable.append((end, stmt))
                    dead = True
            elif ends:
                end = stmt
            if ends:
                self.ending.add(id(stmt))


_COMPILED_SURVEY = _compiled()
