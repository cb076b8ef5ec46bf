"""The dialect's own expressions for the debugger: conditions, log points, evaluate, setVariable.

Text is parsed by the project's line parser (as the right side of an assignment) and evaluated
by the interpreter's ``Evaluator``; nothing is ever handed to Python's ``eval``.  The console
also answers what the machine asks the operator: ``ok #4100=5``, ``cancel`` for a dlgmsg;
``ok``, ``miss`` or ``trip Z-3.2`` for a G38.2.
"""
from __future__ import annotations

import math
import re

from edingcnc_lang.syntax import nodes as n
from edingcnc_lang.canon import AXES, Pose
from edingcnc_lang.errors import EcncError
from edingcnc_lang.machine.evaluator import Evaluator
from edingcnc_lang.host import DialogAnswer
from edingcnc_lang.syntax.line_parser import parse_line
from edingcnc_lang.syntax.tree_builder import LineError

SCRATCH = "#1 = "  # the parser reads an expression as the value of an assignment
LOG_PART = re.compile(r"\{([^{}]*)\}")


class ExpressionError(Exception):
    """Text that is not an expression of the dialect, or one that cannot be evaluated here."""


def parse_expression(text: str) -> n.Expr:
    """``#3 == 3``, ``[#5001 > 10] and [#5008 == 2]``, ``[2 * SIN[30]]``: one expression."""
    block = _parse(SCRATCH + text, text)
    if not isinstance(block, n.Block) or len(block.assigns) != 1 or block.words or block.message:
        raise ExpressionError(f"{text.strip()!r} is not one expression of the dialect")
    return block.assigns[0].value


def parse_assignment(text: str) -> tuple[n.Param, n.Expr] | None:
    """``#4100 = 5``: the parameter and the value expression; None for anything that is not
    exactly one assignment (then the text is an expression to evaluate)."""
    if "=" not in text.replace("==", "").replace("<=", "").replace(">=", ""):
        return None
    try:
        block = parse_line(text)
    except (LineError, EcncError):
        return None
    if isinstance(block, n.Block) and len(block.assigns) == 1 and not block.words and not block.message:
        assign = block.assigns[0]
        return assign.target, assign.value
    return None


def parse_parameter(text: str) -> n.Param:
    """``#4005``, ``#[4000 + 5]``: a parameter, read as the dialect reads the target of an assignment;
    an ExpressionError with the parser's reason for anything else (``#-620``, ``5380``)."""
    shown = text.strip() if len(text) <= 40 else text.strip()[:40] + "..."
    refused = f"{shown!r} is not a parameter (#n)"
    if "=" in text:
        raise ExpressionError(refused)
    try:
        block = parse_line(f"{text} = 0")
    except (LineError, EcncError) as err:
        raise ExpressionError(f"{refused}: {err.message}") from None
    if not isinstance(block, n.Block) or len(block.assigns) != 1 or block.words or block.message:
        raise ExpressionError(refused)
    return block.assigns[0].target


def _parse(line: str, shown: str) -> object:
    try:
        return parse_line(line)
    except LineError as err:
        raise ExpressionError(f"{shown.strip()!r}: {err.message}") from None
    except EcncError as err:
        raise ExpressionError(f"{shown.strip()!r}: {err.message}") from None


def evaluate(evaluator: Evaluator, expr: n.Expr) -> float:
    """The value of ``expr`` now; a domain error (division by zero, ...) as an ExpressionError."""
    try:
        return evaluator.value(expr)
    except EcncError as err:
        raise ExpressionError(err.message) from None


def interpolate(evaluator: Evaluator, template: str) -> str:
    """A log point's message: every ``{expression}`` replaced by its value (``T{#5011}`` -> ``T2``)."""
    from edingcnc_lang.machine.state import format_value

    def value(match: re.Match[str]) -> str:
        try:
            return format_value(evaluate(evaluator, parse_expression(match.group(1))))
        except ExpressionError as err:
            return f"<{err}>"
    return LOG_PART.sub(value, template)


def dialog_answer(text: str) -> DialogAnswer | None:
    """``ok``, ``ok #4100=5 #4101=2``, ``ok:#4100=5`` or ``cancel`` as a DialogAnswer; None if the
    text is no answer at all.  Raises ExpressionError for an answer that is malformed."""
    words = text.strip()
    head = re.match(r"(?i)(ok|cancel)\b:?", words)
    if head is None:
        return None
    rest = [part for part in re.split(r"[\s,]+", words[head.end():]) if part]
    try:
        return DialogAnswer.parse(head.group(1).lower() + (":" + ",".join(rest) if rest else ""))
    except ValueError as err:
        raise ExpressionError(str(err)) from None


def probe_answer(text: str, target: Pose) -> tuple[bool, Pose | None] | None:
    """A G38.2 answered from the console: ``ok`` (trips at its target), ``miss`` (no contact) or
    ``trip Z-3.2`` (trips there, machine coordinates; other axes from the target).  Returns
    (answered, trip point); None if the text is no probe answer."""
    words = text.strip().split()
    if not words or words[0].lower() not in ("ok", "miss", "trip"):
        return None
    head = words[0].lower()
    if head == "miss":
        return True, None
    point = list(target)
    for word in words[1:]:
        letter, number = word[:1].upper(), word[1:]
        if letter not in AXES:
            raise ExpressionError(f"trip {word!r}: expected axis words such as Z-3.2")
        try:
            point[AXES.index(letter)] = float(number)
        except ValueError:
            raise ExpressionError(f"trip {word!r}: {number!r} is not a number") from None
        if not math.isfinite(point[AXES.index(letter)]):
            raise ExpressionError(f"trip {word!r}: not a finite number")
    return True, tuple(point)
