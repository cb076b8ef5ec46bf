"""Static evaluation of expressions with unknown values (three-valued, never raises), with the
interpreter's own arithmetic (``machine.evaluator.BINARY``).

The linter folds literal indices such as ``#[5400 + 5]`` and decides which
branch of ``If [[#5380 == 0] and [#5397 == 0]]`` runs in simulation without
knowing the other parameters: anything it cannot know is ``None``, and
``AND``/``OR`` still answer when one side settles the result.
"""
from __future__ import annotations

from collections.abc import Callable

from edingcnc_lang.syntax import nodes as n
from edingcnc_lang.machine.evaluator import BINARY, COMPARE, Undefined

Lookup = Callable[[int], "float | None"]


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
        return float(COMPARE[expr.op](left, right))
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
    try:  # the interpreter's arithmetic; what has no value there is not known here
        return BINARY[op](left, right)
    except Undefined:
        return None


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
