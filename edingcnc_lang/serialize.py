"""AST -> JSON-ready data, for ``ecnc parse --json`` and the golden AST dumps."""
from __future__ import annotations

from dataclasses import fields, is_dataclass
from typing import Any

from . import nodes as n


def to_data(node: Any, with_spans: bool = True) -> Any:
    """Convert a node (or tuple of nodes) into dicts, lists and scalars.

    Every node becomes ``{"type": ClassName, ...fields}``; spans become
    ``[line, col, end_line, end_col]`` (the path is given once, by the program).
    """
    if isinstance(node, n.Span):
        return [node.line, node.col, node.end_line, node.end_col]
    if is_dataclass(node) and not isinstance(node, type):
        data: dict[str, Any] = {"type": type(node).__name__}
        for f in fields(node):
            if not with_spans and f.name in ("span", "end_span"):
                continue
            data[f.name] = to_data(getattr(node, f.name), with_spans)
        return data
    if isinstance(node, tuple):
        return [to_data(item, with_spans) for item in node]
    return node
