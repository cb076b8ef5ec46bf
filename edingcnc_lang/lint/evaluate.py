"""Static evaluation of expressions with unknown values (three-valued, never raises).

The linter folds literal indices such as ``#[5400 + 5]`` and decides which
branch of ``If [[#5380 == 0] and [#5397 == 0]]`` runs in simulation without
knowing the other parameters: anything it cannot know is ``None``, and
``AND``/``OR`` still answer when one side settles the result.
"""
from __future__ import annotations

import math
import operator
from collections.abc import Callable, Mapping

from edingcnc_lang.syntax import nodes as n

Lookup = Callable[[int], "float | None"]


def _div(a: float, b: float) -> float | None:
    return a / b if b else None


def _mod(a: float, b: float) -> float | None:
    if not b:
        return None
    r = math.fmod(a, b)
    return r + abs(b) if r < 0 else r


def _pow(a: float, b: float) -> float | None:
    try:
        result = a ** b
    except (OverflowError, ZeroDivisionError):
        return None
    return result if isinstance(result, float | int) else None


_ARITHMETIC: Mapping[str, Callable[[float, float], float | None]] = {
    "+": operator.add, "-": operator.sub, "*": operator.mul, "/": _div, "MOD": _mod, "**": _pow,
    "XOR": lambda a, b: float(bool(a) != bool(b)),
}

_COMPARE: Mapping[str, Callable[[float, float], bool]] = {
    "==": operator.eq, "<>": operator.ne, "<": operator.lt, ">": operator.gt,
    "<=": operator.le, ">=": operator.ge,
}


def unknown(_index: int) -> float | None:
    """A lookup that knows no parameter: evaluation folds literals only."""
    return None


def evaluate(expr: n.Expr, lookup: Lookup = unknown) -> float | None:
    """The value of ``expr``, or None when it depends on something unknown."""
    # exact type tests: node classes are final, and this runs for most words
    if type(expr) is n.Number:
        return expr.value
    if type(expr) is n.Param:
        index = evaluate(expr.index, lookup)
        return lookup(int(index)) if index is not None and index.is_integer() else None
    if type(expr) is n.Binary:
        return _binary(expr, lookup)
    if type(expr) is n.Compare:
        left, right = evaluate(expr.left, lookup), evaluate(expr.right, lookup)
        if left is None or right is None:
            return None
        return float(_COMPARE[expr.op](left, right))
    if type(expr) is n.Unary:
        value = evaluate(expr.operand, lookup)
        return None if value is None else (-value if expr.op == "-" else value)
    return None  # function calls: not needed for indices and guards


def _binary(expr: n.Binary, lookup: Lookup) -> float | None:
    left, right = evaluate(expr.left, lookup), evaluate(expr.right, lookup)
    op = expr.op
    if op == "AND" or op == "OR":
        decisive = 0.0 if op == "AND" else 1.0  # the value that settles the result alone
        if (left is not None and float(bool(left)) == decisive) or (right is not None and float(bool(right)) == decisive):
            return decisive
        return None if left is None or right is None else 1.0 - decisive
    if left is None or right is None:
        return None
    return _ARITHMETIC[op](left, right)


def constant_index(param: n.Param) -> float | None:
    """The index of ``#n`` or ``#[literal expression]``; None when it depends on parameters."""
    return evaluate(param.index)


def params_in(expr: n.Expr) -> list[n.Param]:
    """Every parameter reference in ``expr``, outer ones first (``##5`` gives both)."""
    if type(expr) is n.Param and type(expr.index) is n.Number:  # ``#1000``: the most common expression
        return [expr]
    found: list[n.Param] = []
    stack: list[n.Expr] = [expr]
    while stack:  # exact type tests: node classes are final, and this runs for every expression
        node = stack.pop()
        if type(node) is n.Number:
            continue
        if type(node) is n.Param:
            found.append(node)
            stack.append(node.index)
        elif type(node) is n.Binary or type(node) is n.Compare:
            stack += (node.right, node.left)
        elif type(node) is n.Unary:
            stack.append(node.operand)
        elif type(node) is n.Call:
            stack += reversed(node.args)
    return found
