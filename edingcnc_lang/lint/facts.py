"""One walk over a file that sorts out what most rules look at.

Most rules care about one kind of thing: the G and M numbers of blocks, the
parameters read or assigned, the dialogs.  Gathering them in a single pass, with
each parameter's literal index worked out once, spares those rules a walk over
every statement and keeps linting a big macro file fast (rules about the block
structure, such as unreachable code, still follow the statements themselves).
"""
from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass

from edingcnc_lang.syntax import nodes as n
from edingcnc_lang.lint.walk import END_OF_PROGRAM, Code, Scope, block_codes, literal_index, reads

Use = tuple[n.Param, "int | None", Scope]  # a parameter read or assigned, its literal index, where


@dataclass(frozen=True, slots=True)
class BlockCodes:
    """A block, where it sits, and its literal G and M numbers in line order."""

    block: n.Block
    scope: Scope
    g: tuple[Code, ...]
    m: tuple[Code, ...]


@dataclass(frozen=True, eq=False)  # one per file: compared by identity
class FileFacts:
    """A file's statements sorted by what the rules ask about them."""

    blocks: tuple[BlockCodes, ...]
    reads: tuple[Use, ...]  # every parameter read, in source order
    targets: tuple[Use, ...]  # every assignment target, in source order
    dialogs: tuple[tuple[n.Dialog, Scope], ...]
    commands: tuple[n.Command, ...]
    callers: tuple[tuple[n.Stmt, Scope], ...]  # statements that may run a sub: GoSub, blocks with M codes
    # The parameters each statement reads (by id(): nodes hash by value, deeply).
    reads_of: dict[int, tuple[tuple[n.Param, int | None], ...]]
    codes_of: dict[int, BlockCodes]
    ending: frozenset[int]  # the statements (by id()) that end the program: walk.ends_program


def indexed_reads(stmt: n.Stmt) -> tuple[tuple[n.Param, int | None], ...]:
    """The parameters a statement reads, each with its literal index (None if computed)."""
    return tuple((param, literal_index(param)) for param in reads(stmt))


def gather(walked: Sequence[tuple[n.Stmt, Scope]]) -> FileFacts:
    """Everything the rules look up about a file's statements (as ``walk`` yields them)."""
    blocks: list[BlockCodes] = []
    all_reads: list[Use] = []
    targets: list[Use] = []
    dialogs: list[tuple[n.Dialog, Scope]] = []
    commands: list[n.Command] = []
    callers: list[tuple[n.Stmt, Scope]] = []
    reads_of: dict[int, tuple[tuple[n.Param, int | None], ...]] = {}
    codes_of: dict[int, BlockCodes] = {}
    ending: set[int] = set()
    for stmt, scope in walked:  # exact type tests: node classes are final, and this runs for every statement
        params = reads(stmt)
        if params:  # most statements read none
            found = tuple([(param, literal_index(param)) for param in params])
            all_reads += [(param, index, scope) for param, index in found]
        else:
            found = ()
        reads_of[id(stmt)] = found
        if type(stmt) is n.Block:
            codes = BlockCodes(stmt, scope, *block_codes(stmt))
            blocks.append(codes)
            codes_of[id(stmt)] = codes
            if stmt.assigns:
                targets += [(a.target, literal_index(a.target), scope) for a in stmt.assigns]
            if codes.m:
                callers.append((stmt, scope))
                if not stmt.block_delete and any(key in END_OF_PROGRAM for key, _word in codes.m):
                    ending.add(id(stmt))
        elif type(stmt) is n.GoSub:
            callers.append((stmt, scope))
        elif type(stmt) is n.Dialog:
            dialogs.append((stmt, scope))
        elif type(stmt) is n.Command:
            commands.append(stmt)
        elif type(stmt) is n.Message and stmt.kind == "errmsg":
            ending.add(id(stmt))
    return FileFacts(tuple(blocks), tuple(all_reads), tuple(targets), tuple(dialogs), tuple(commands),
                     tuple(callers), reads_of, codes_of, frozenset(ending))
