"""Printing the AST back as source text (canonical form).

Used by ``ecnc parse`` round trips and the property tests: parsing the printed
text gives the same AST.  Nested operations are always bracketed, so printing
never depends on operator precedence.
"""
from __future__ import annotations

import math
from decimal import Decimal
from functools import singledispatch

from edingcnc_lang.syntax import nodes as n

INDENT = "  "


def format_number(value: float) -> str:
    """Shortest decimal text that reads back as the same double, without exponent."""
    if value == int(value) and abs(value) < 1e15:
        return ("-" if math.copysign(1.0, value) < 0 else "") + str(abs(int(value)))
    text = repr(value)
    if "e" in text or "E" in text:
        text = format(Decimal(text), "f")
    return text


@singledispatch
def expr_text(expr: n.Expr) -> str:
    raise TypeError(f"not an expression: {expr!r}")


@expr_text.register
def _(expr: n.Number) -> str:
    return format_number(expr.value)


@expr_text.register
def _(expr: n.Param) -> str:
    index = expr.index
    if isinstance(index, n.Number) and math.copysign(1.0, index.value) > 0 or isinstance(index, n.Param):
        return "#" + expr_text(index)
    return "#" + bracketed(index)


@expr_text.register
def _(expr: n.Unary) -> str:
    return expr.op + operand_text(expr.operand)


@expr_text.register
def _(expr: n.Binary) -> str:
    left = operand_text(expr.left)
    if expr.op == "/" and isinstance(expr.left, n.Call) and len(expr.left.args) == 1:
        left = f"[{left}]"  # ATAN[x] / [y] would read as the two-operand ATAN
    return f"{left} {expr.op} {operand_text(expr.right)}"


@expr_text.register
def _(expr: n.Compare) -> str:
    return f"{operand_text(expr.left)} {expr.op} {operand_text(expr.right)}"


@expr_text.register
def _(expr: n.Call) -> str:
    return "/".join(f"{expr.name}[{expr_text(a)}]" if i == 0 else f"[{expr_text(a)}]"
                    for i, a in enumerate(expr.args))


def bracketed(expr: n.Expr) -> str:
    return f"[{expr_text(expr)}]"


def operand_text(expr: n.Expr) -> str:
    """An operand inside a larger expression: bracket anything that is not atomic."""
    if isinstance(expr, (n.Binary, n.Compare, n.Unary)) or (
            isinstance(expr, n.Number) and math.copysign(1.0, expr.value) < 0):
        return bracketed(expr)
    return expr_text(expr)


def value_text(expr: n.Expr) -> str:
    """A word value or command argument: a literal, parameter, call, or a bracketed expression."""
    if isinstance(expr, (n.Binary, n.Compare)):
        return bracketed(expr)
    return expr_text(expr)


def items_text(items: tuple[n.MessageItem, ...]) -> str:
    return " ".join(f'"{item}"' if isinstance(item, str) else "%d" if isinstance(item, n.Stamp)
                    else value_text(item) for item in items)


@singledispatch
def stmt_lines(stmt: n.Stmt, depth: int = 0) -> list[str]:
    raise TypeError(f"not a statement: {stmt!r}")


def _line(depth: int, text: str) -> list[str]:
    return [INDENT * depth + text]


@stmt_lines.register
def _(stmt: n.Block, depth: int = 0) -> list[str]:
    parts = ["/"] if stmt.block_delete else []
    if stmt.line_number is not None:
        parts.append(f"N{stmt.line_number}")
    if stmt.message is not None:
        parts.append(f"(MSG {stmt.message})")
    parts += [f"{expr_text(a.target)} = {value_text(a.value)}" for a in stmt.assigns]
    parts += [w.letter + word_value_text(w.value) for w in stmt.words]
    return _line(depth, " ".join(parts))


def word_value_text(expr: n.Expr) -> str:
    """A call is bracketed after a word letter: ``A SIN[0]`` printed as ``ASIN[0]`` would read as ASIN."""
    return bracketed(expr) if isinstance(expr, n.Call) else value_text(expr)


@stmt_lines.register
def _(stmt: n.Message, depth: int = 0) -> list[str]:
    return _line(depth, f"{stmt.kind} {items_text(stmt.items)}".rstrip())


@stmt_lines.register
def _(stmt: n.Dialog, depth: int = 0) -> list[str]:
    return _line(depth, f"dlgmsg {items_text(stmt.items)}".rstrip())


def _optional(value: n.Expr | None) -> str:
    """An optional trailing argument: " value", or nothing."""
    return f" {value_text(value)}" if value is not None else ""


@stmt_lines.register
def _(stmt: n.LogFile, depth: int = 0) -> list[str]:
    return _line(depth, f'logfile "{stmt.name}"{_optional(stmt.mode)}')


@stmt_lines.register
def _(stmt: n.Home, depth: int = 0) -> list[str]:
    return _line(depth, f"{'homeTandem' if stmt.tandem else 'home'} {stmt.axis.lower()}")


@stmt_lines.register
def _(stmt: n.Switch, depth: int = 0) -> list[str]:
    return _line(depth, f"{stmt.name} {'on' if stmt.on else 'off'}")


@stmt_lines.register
def _(stmt: n.Kin, depth: int = 0) -> list[str]:
    args = "".join(" " + value_text(a) for a in stmt.args)
    return _line(depth, f"KIN {stmt.mode}{args}")


@stmt_lines.register
def _(stmt: n.PrepareLinDeltaHome, depth: int = 0) -> list[str]:
    return _line(depth, f"PrepareLinDeltaHome{_optional(stmt.velocity)}")


@stmt_lines.register
def _(stmt: n.Command, depth: int = 0) -> list[str]:
    return _line(depth, f"{stmt.name} {stmt.args}".rstrip())


@stmt_lines.register
def _(stmt: n.GoSub, depth: int = 0) -> list[str]:
    return _line(depth, f"GoSub {stmt.name}")


def _body(body: tuple[n.Stmt, ...], depth: int) -> list[str]:
    return [line for stmt in body for line in stmt_lines(stmt, depth)]


@stmt_lines.register
def _(stmt: n.If, depth: int = 0) -> list[str]:
    lines = _line(depth, f"If {bracketed(stmt.cond)}") + _body(stmt.then, depth + 1)
    if stmt.has_else:
        lines += _line(depth, "Else") + _body(stmt.orelse, depth + 1)
    return lines + _line(depth, "EndIf")


@stmt_lines.register
def _(stmt: n.While, depth: int = 0) -> list[str]:
    return _line(depth, f"While {bracketed(stmt.cond)}") + _body(stmt.body, depth + 1) + _line(depth, "EndWhile")


@stmt_lines.register
def _(stmt: n.Sub, depth: int = 0) -> list[str]:
    return _line(depth, f"Sub {stmt.name}") + _body(stmt.body, depth + 1) + _line(depth, "EndSub")


def program_text(program: n.Program) -> str:
    """The whole program as canonical source, one statement per line."""
    head = [f";@unit {program.unit}"] if program.unit else []
    return "\n".join(head + _body(program.body, 0)) + "\n"
