"""Line results that are not statements: the openers and closers of multi-line blocks.

A line such as ``If [#1 > 0]`` or ``EndWhile`` is not a statement on its own;
the parser's block assembly turns a run of lines between an opener and its
closer into an If/While/Sub node.
"""
from __future__ import annotations


from edingcnc_lang.syntax import nodes as n
from edingcnc_lang.records import record


@record(frozen=True)
class Open:
    """A line that opens a block: Sub, If or While (kept until its end line)."""

    kind: str  # "Sub" | "If" | "While"
    span: n.Span
    name: str = ""
    cond: n.Expr | None = None
    extra: int = 0  # stray ']' after the condition


@record(frozen=True)
class Close:
    """A line that ends a block (EndSub, EndIf, EndWhile) or switches an If to its Else part."""

    kind: str  # "EndSub" | "EndIf" | "EndWhile" | "Else"
    span: n.Span


LineResult = n.Stmt | Open | Close | None
