"""The abstract syntax tree: frozen dataclasses with a source span on every node.

Built by ``records.record``, which makes the same classes as ``dataclass(frozen=True, slots=True)``
in a fraction of the start-up time.

Nothing here knows about Lark; the parser converts its trees into these nodes
and every later stage (checker, interpreter, linter, printer) works on them.
"""
from __future__ import annotations

from dataclasses import field
from typing import NamedTuple, Union

from edingcnc_lang.records import record


class Span(NamedTuple):
    """Source range of a node: 1-based line and column, end column exclusive.

    A named tuple rather than a dataclass: one is made for every node of every line,
    so it has to be cheap to build; it is just as immutable.
    """

    path: str
    line: int
    col: int
    end_line: int
    end_col: int


NO_SPAN = Span("<none>", 0, 0, 0, 0)


# --------------------------------------------------------------------------- expressions

@record(frozen=True, slots=True)
class Number:
    """A numeric literal; a leading sign is folded into the value."""

    value: float
    span: Span = field(default=NO_SPAN, compare=False)


@record(frozen=True, slots=True)
class Param:
    """``#n`` (index is a Number), ``#[e]`` or ``##n`` (index is another Param)."""

    index: "Expr"
    span: Span = field(default=NO_SPAN, compare=False)


@record(frozen=True, slots=True)
class Unary:
    """A sign in front of a non-literal operand: ``-#1``, ``+[#2 * 3]``."""

    op: str  # "-" or "+"
    operand: "Expr"
    span: Span = field(default=NO_SPAN, compare=False)


@record(frozen=True, slots=True)
class Binary:
    """Arithmetic and logic: ``** * / MOD + - OR XOR AND`` (op upper-cased)."""

    op: str
    left: "Expr"
    right: "Expr"
    span: Span = field(default=NO_SPAN, compare=False)


@record(frozen=True, slots=True)
class Compare:
    """Comparison; op is normalised to one of ``== <> < > <= >=``."""

    op: str
    left: "Expr"
    right: "Expr"
    span: Span = field(default=NO_SPAN, compare=False)


# The dialect's functions, the one table of their names: each takes one argument; ATAN, which may
# take two (``ATAN[y]/[x]``), is the last.  The grammar's FUNC and ATAN terminals, the fast reader
# (fastparse.py), the compiled reader (csrc/lexer_nodes.c, in this order), the evaluator and the
# texts of hover and help name exactly these (tests/parser/test_function_names.py pins them).
FUNCTION_NAMES = ("ABS", "ACOS", "ASIN", "COS", "EXP", "FIX", "FUP", "LN", "ROUND", "SIN", "SQRT", "TAN", "ATAN")


@record(frozen=True, slots=True)
class Call:
    """Function call; ``ATAN[y]/[x]`` has two arguments, the others one."""

    name: str  # upper-case
    args: tuple["Expr", ...]
    span: Span = field(default=NO_SPAN, compare=False)


Expr = Union[Number, Param, Unary, Binary, Compare, Call]


# --------------------------------------------------------------------------- block items

@record(frozen=True, slots=True)
class Word:
    """A letter word such as ``G1``, ``X[#1+2]`` or ``T[#5011]`` (letter upper-case)."""

    letter: str
    value: Expr
    span: Span = field(default=NO_SPAN, compare=False)


@record(frozen=True, slots=True)
class Assign:
    """``#n = expr``; takes effect after every expression of its line is evaluated."""

    target: Param
    value: Expr
    span: Span = field(default=NO_SPAN, compare=False)


# --------------------------------------------------------------------------- statements

@record(frozen=True, slots=True)
class Block:
    """One line of words and assignments (the ordinary G-code line).

    ``message`` holds the text of a ``(MSG ...)`` comment, ``line_number`` the
    N word, ``block_delete`` the leading ``/``.
    """

    words: tuple[Word, ...]
    assigns: tuple[Assign, ...] = ()
    message: str | None = None
    line_number: int | None = None
    block_delete: bool = False
    span: Span = field(default=NO_SPAN, compare=False)


@record(frozen=True, slots=True)
class PlainBlock:
    """A line of literal words only, as the run's fast path reads it (most CAM output).

    Equivalent to the Block the grammar builds for the same line (a property test
    checks this); it skips the per-word nodes because a run only needs each word's
    letter, value and column.
    """

    words: tuple[tuple[str, float, int], ...]  # (letter upper-case, value, column)
    line_number: int | None = None
    span: Span = field(default=NO_SPAN, compare=False)


@record(frozen=True, slots=True)
class PlainRun:
    """Consecutive top-level plain word lines, as (line number, text), for a run's fast path.

    The interpreter executes them directly from their text; each line is exactly what the
    corresponding PlainBlock (and Block) says.
    """

    path: str
    lines: tuple[tuple[int, str], ...]

    @property
    def span(self) -> Span:
        first, last = self.lines[0][0], self.lines[-1][0]
        return Span(self.path, first, 1, last, len(self.lines[-1][1]) + 1)


@record(frozen=True, slots=True)
class Stamp:
    """``%d`` in a message: the date and time when the message is shown."""

    span: Span = field(default=NO_SPAN, compare=False)


MessageItem = Union[str, Expr, Stamp]


@record(frozen=True, slots=True)
class Message:
    """``msg``, ``warnmsg``, ``errmsg`` or ``logmsg`` with concatenated items."""

    kind: str  # "msg" | "warnmsg" | "errmsg" | "logmsg"
    items: tuple[MessageItem, ...]
    span: Span = field(default=NO_SPAN, compare=False)


@record(frozen=True, slots=True)
class Dialog:
    """``dlgmsg "title" "label" 27 ...``; items kept as written so the linter sees mistakes."""

    items: tuple[MessageItem, ...]
    span: Span = field(default=NO_SPAN, compare=False)


@record(frozen=True, slots=True)
class LogFile:
    """``logfile NAME [mode]``: where logmsg writes (mode 0 starts the file afresh, 1 appends)."""

    name: str
    mode: Expr | None
    span: Span = field(default=NO_SPAN, compare=False)


@record(frozen=True, slots=True)
class Home:
    """``home x`` / ``homeTandem x`` (axis upper-case)."""

    axis: str
    tandem: bool = False
    span: Span = field(default=NO_SPAN, compare=False)


@record(frozen=True, slots=True)
class Switch:
    """On/off commands: tanknife, homeIsEstop, TCAGuard, ZHC, LaserEngrave (name lower-case)."""

    name: str
    on: bool
    span: Span = field(default=NO_SPAN, compare=False)


@record(frozen=True, slots=True)
class Kin:
    """``KIN ON|OFF|CTRL id p1..p6|<mapping>``; mode upper-case, args only for CTRL."""

    mode: str
    args: tuple[Expr, ...] = ()
    span: Span = field(default=NO_SPAN, compare=False)


@record(frozen=True, slots=True)
class PrepareLinDeltaHome:
    """``PrepareLinDeltaHome [velocity]``: moves the three delta joints home together, before ``home x`` etc."""

    velocity: Expr | None = None
    span: Span = field(default=NO_SPAN, compare=False)


@record(frozen=True, slots=True)
class Command:
    """Commands accepted but not modelled in detail (ZHC*, GetToolInfo, modbus, Exec, ...)."""

    name: str  # lower-case
    args: str
    span: Span = field(default=NO_SPAN, compare=False)
    # the arguments as expressions (``ZHCINIT [#4104] 10 5``), when they read as a list of them;
    # parsed with the line, so the machine evaluates them without a parser
    values: tuple[Expr, ...] | None = None


@record(frozen=True, slots=True)
class GoSub:
    """``GoSub name``: calls a Sub of the file or its macro files."""

    name: str  # as written; lookups are case-insensitive
    span: Span = field(default=NO_SPAN, compare=False)


@record(frozen=True, slots=True)
class If:
    """``If [cond] ... [Else ...] EndIf``; ``end_span`` is the EndIf line."""

    cond: Expr
    then: tuple["Stmt", ...]
    orelse: tuple["Stmt", ...] = ()
    has_else: bool = False
    extra_brackets: int = 0  # stray ']' after the condition, accepted like the controller does
    span: Span = field(default=NO_SPAN, compare=False)
    end_span: Span = field(default=NO_SPAN, compare=False)


@record(frozen=True, slots=True)
class While:
    """``While [cond] ... EndWhile``; ``end_span`` is the EndWhile line."""

    cond: Expr
    body: tuple["Stmt", ...]
    extra_brackets: int = 0
    span: Span = field(default=NO_SPAN, compare=False)
    end_span: Span = field(default=NO_SPAN, compare=False)


@record(frozen=True, slots=True)
class Sub:
    """``Sub name ... EndSub``: a subroutine, also the way M codes and controller events are defined."""

    name: str
    body: tuple["Stmt", ...]
    span: Span = field(default=NO_SPAN, compare=False)
    end_span: Span = field(default=NO_SPAN, compare=False)


@record(frozen=True, slots=True)
class BadLine:
    """A macro-file line that does not parse, kept in place: an error only if a run reaches it.

    The controller executes macro files line by line, so a line it never reaches cannot stop
    it; a tolerant load keeps such lines as BadLine and warns once (see runner.load_macro).
    """

    code: str
    message: str
    col: int
    span: Span = field(default=NO_SPAN, compare=False)
    source: str = field(default="", compare=False)  # the line, so the error shows it as the warning did


Stmt = Union[Block, PlainBlock, PlainRun, Message, Dialog, LogFile, Home, Switch, Kin, PrepareLinDeltaHome,
             Command, GoSub, If, While, Sub, BadLine]


@record(frozen=True, slots=True)
class Program:
    """A whole file: its statements and the ``@unit`` directive, if any."""

    path: str
    body: tuple[Stmt, ...]
    unit: str | None = None

    @property
    def subs(self) -> dict[str, Sub]:
        """Sub definitions by lower-case name (the first definition wins)."""
        found: dict[str, Sub] = {}
        for stmt in self.body:
            if isinstance(stmt, Sub):
                found.setdefault(stmt.name.lower(), stmt)
        return found
