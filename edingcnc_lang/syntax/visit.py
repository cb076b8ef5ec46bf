"""Walking a syntax tree: every node in source order, and a visitor with a method per node type.

The tree (``syntax/nodes.py``) is frozen records whose children are fields holding a node or a tuple
of nodes; these two helpers read the fields, so a tool that analyses a macro file (count the
``GoSub`` calls, list the parameters a sub writes) needs no list of which field holds what::

    from edingcnc_lang import parse_file
    from edingcnc_lang.syntax.visit import Visitor, walk
    from edingcnc_lang.syntax import nodes as n

    calls = [node.name for node in walk(parse_file("macro.cnc")) if isinstance(node, n.GoSub)]

    class Writes(Visitor):
        def __init__(self) -> None:
            self.numbers: list[int] = []

        def visit_Assign(self, node: n.Assign) -> None:
            if isinstance(node.target.index, n.Number):
                self.numbers.append(int(node.target.index.value))
            self.generic_visit(node)
"""
from __future__ import annotations

from collections.abc import Callable, Iterator
from dataclasses import fields, is_dataclass
from typing import Any

from edingcnc_lang.syntax import nodes as n


def children(node: object) -> Iterator[Any]:
    """The nodes directly under ``node`` (a ``Program``'s statements, a ``Block``'s words, an ``If``'s
    condition and both branches, an expression's operands), in source order."""
    if not is_dataclass(node):
        return
    for f in fields(node):
        value = getattr(node, f.name)
        if isinstance(value, tuple) and not isinstance(value, n.Span):
            yield from (item for item in value if is_dataclass(item))
        elif is_dataclass(value):
            yield value


def walk(node: object) -> Iterator[Any]:
    """``node`` and every node under it, depth first, in source order (iterative: no depth limit)."""
    stack = [node]
    while stack:
        current = stack.pop()
        yield current
        stack.extend(reversed(list(children(current))))


class Visitor:
    """Calls ``visit_<NodeType>(node)`` (``visit_GoSub``, ``visit_Binary``, ...) for each node it is
    handed, ``generic_visit`` when there is none; ``generic_visit`` visits the node's children, so a
    method that wants the nodes below calls it too (as Python's ``ast.NodeVisitor``)."""

    def visit(self, node: object) -> None:
        method: Callable[[Any], None] = getattr(self, f"visit_{type(node).__name__}", self.generic_visit)
        method(node)

    def generic_visit(self, node: object) -> None:
        for child in children(node):
            self.visit(child)
