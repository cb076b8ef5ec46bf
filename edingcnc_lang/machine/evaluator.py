"""Expression evaluation: the dialect's arithmetic, logic, functions and parameters.

Angles are in degrees.  Every domain error (division by zero, SQRT of a
negative, ...) becomes a MachineError at the expression's position, so no NaN
ever flows into a move and no Python exception text reaches the user.
"""
from __future__ import annotations

import math
import operator
from collections.abc import Callable
from typing import Protocol

from edingcnc_lang.syntax import nodes as n
from edingcnc_lang.errors import Location, MachineError
from edingcnc_lang.machine.tables import FIRST_PARAM, LAST_PARAM


class ParameterReader(Protocol):
    def read(self, index: int) -> float: ...


def located(span: n.Span) -> Location:
    return Location(span.path, span.line, span.col)


def fail(message: str, span: n.Span) -> MachineError:
    return MachineError(message, located(span))


def param_index(value: float, span: n.Span) -> int:
    """A parameter number from a computed value: integral and within 1..5999."""
    index = int(round(value))
    if abs(value - index) > 1e-6:
        raise fail(f"parameter number {value!r} is not a whole number", span)
    if not FIRST_PARAM <= index <= LAST_PARAM:
        raise fail(f"parameter #{index} does not exist (valid: #{FIRST_PARAM}..#{LAST_PARAM})", span)
    return index


def _round_half_away(x: float) -> float:
    return float(math.floor(abs(x) + 0.5)) * (1.0 if x >= 0 else -1.0)


def _checked(name: str, valid: Callable[[float], bool], func: Callable[[float], float],
             why: str) -> Callable[[float, n.Span], float]:
    def apply(x: float, span: n.Span) -> float:
        if not valid(x):
            raise fail(f"{name}[{x!r}]: {why}", span)
        return func(x)
    return apply


def _any(_x: float) -> bool:
    return True


FUNCTIONS: dict[str, Callable[[float, n.Span], float]] = {
    "ABS": _checked("ABS", _any, abs, ""),
    "ACOS": _checked("ACOS", lambda x: -1.0 <= x <= 1.0, lambda x: math.degrees(math.acos(x)),
                     "the argument must lie between -1 and 1"),
    "ASIN": _checked("ASIN", lambda x: -1.0 <= x <= 1.0, lambda x: math.degrees(math.asin(x)),
                     "the argument must lie between -1 and 1"),
    "COS": _checked("COS", _any, lambda x: math.cos(math.radians(x)), ""),
    "SIN": _checked("SIN", _any, lambda x: math.sin(math.radians(x)), ""),
    "TAN": _checked("TAN", lambda x: abs(math.cos(math.radians(x))) > 1e-12, lambda x: math.tan(math.radians(x)),
                    "the tangent of this angle is infinite"),
    "EXP": _checked("EXP", lambda x: x < 709.0, math.exp, "the result is too large"),
    "LN": _checked("LN", lambda x: x > 0.0, math.log, "the argument must be greater than 0"),
    "SQRT": _checked("SQRT", lambda x: x >= 0.0, math.sqrt, "the argument must not be negative"),
    "FIX": _checked("FIX", _any, lambda x: float(math.floor(x)), ""),
    "FUP": _checked("FUP", _any, lambda x: float(math.ceil(x)), ""),
    "ROUND": _checked("ROUND", _any, _round_half_away, ""),
}


class Undefined(ArithmeticError):
    """An operation of the dialect with no value (division by zero, ...); the message says why.  The
    interpreter reports it at the operator, the linter (lint/evaluate.py) takes it for "not known"."""


def _divide(a: float, b: float) -> float:
    if b == 0.0:
        raise Undefined(f"division by zero ({a!r} / 0)")
    return a / b


def _mod(a: float, b: float) -> float:
    if b == 0.0:
        raise Undefined(f"{a!r} MOD 0: division by zero")
    result = math.fmod(a, b)
    return result + abs(b) if result < 0 else result


def _power(a: float, b: float) -> float:
    try:
        result = a ** b
    except (OverflowError, ZeroDivisionError):
        raise Undefined(f"{a!r} ** {b!r} has no finite value") from None
    if isinstance(result, complex):
        raise Undefined(f"{a!r} ** {b!r}: a negative number to a fractional power")
    return float(result)


# The dialect's arithmetic, the one table of it: the interpreter, the linter's folding (lint/evaluate.py)
# and through it the language server's hover evaluate with these.
BINARY: dict[str, Callable[[float, float], float]] = {
    "+": operator.add,
    "-": operator.sub,
    "*": operator.mul,
    "/": _divide,
    "MOD": _mod,
    "**": _power,
    "AND": lambda a, b: 1.0 if a != 0.0 and b != 0.0 else 0.0,
    "OR": lambda a, b: 1.0 if a != 0.0 or b != 0.0 else 0.0,
    "XOR": lambda a, b: 1.0 if (a != 0.0) != (b != 0.0) else 0.0,
}

COMPARE: dict[str, Callable[[float, float], bool]] = {
    "==": operator.eq, "<>": operator.ne, "<": operator.lt, ">": operator.gt, "<=": operator.le, ">=": operator.ge,
}


class Evaluator:
    """Evaluates expressions against a parameter store (no state of its own)."""

    def __init__(self, params: ParameterReader) -> None:
        self.params = params

    def value(self, expr: n.Expr) -> float:
        kind = type(expr)
        if kind is n.Number:
            return expr.value  # type: ignore[union-attr]
        if kind is n.Param:
            return self.params.read(self.index(expr))  # type: ignore[arg-type]
        if kind is n.Binary:
            try:
                result = BINARY[expr.op](self.value(expr.left), self.value(expr.right))  # type: ignore[union-attr]
            except Undefined as why:
                raise fail(str(why), expr.span) from None
            if math.isinf(result) or math.isnan(result):
                raise fail(f"the result of {expr.op} is not a finite number", expr.span)  # type: ignore[union-attr]
            return result
        if kind is n.Compare:
            return 1.0 if COMPARE[expr.op](self.value(expr.left), self.value(expr.right)) else 0.0  # type: ignore[union-attr]
        if kind is n.Unary:
            operand = self.value(expr.operand)  # type: ignore[union-attr]
            return -operand if expr.op == "-" else operand  # type: ignore[union-attr]
        if kind is n.Call:
            return self._call(expr)  # type: ignore[arg-type]
        raise TypeError(f"not an expression: {expr!r}")

    def index(self, param: n.Param) -> int:
        """The parameter number a Param refers to (``#[e]`` and ``##n`` evaluated)."""
        return param_index(self.value(param.index), param.span)

    def _call(self, call: n.Call) -> float:
        if call.name == "ATAN" and len(call.args) == 1:  # ATAN[x]: the plain arc tangent, in (-90, 90)
            return math.degrees(math.atan(self.value(call.args[0])))
        if call.name == "ATAN":
            y, x = (self.value(a) for a in call.args)
            angle = math.degrees(math.atan2(y, x))
            return 180.0 if angle == -180.0 else angle  # the range is (-180, 180]
        return FUNCTIONS[call.name](self.value(call.args[0]), call.span)
