"""AST -> JSON-ready data, for ``ecnc parse --json`` and the golden AST dumps."""
from __future__ import annotations

import json
import math
from collections.abc import Callable, Iterable
from dataclasses import fields, is_dataclass
from typing import Any, TextIO

from edingcnc_lang.syntax import nodes as n


def json_text(data: Any, **options: Any) -> str:
    """``json.dumps(data, **options)`` that is always valid JSON: a NaN or infinite number (a broken
    plug-in's or configuration's) becomes ``null``, never the bare ``NaN`` JSON parsers refuse."""
    try:
        return json.dumps(data, allow_nan=False, **options)
    except ValueError:
        return json.dumps(_finite(data), allow_nan=False, **options)


def _finite(data: Any) -> Any:
    if isinstance(data, float):
        return data if math.isfinite(data) else None
    if isinstance(data, dict):
        return {key: _finite(value) for key, value in data.items()}
    if isinstance(data, (list, tuple)):
        return [_finite(item) for item in data]
    return data


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


def write_program(path: str, body: Iterable[n.Stmt], unit: Callable[[], str | None], out: TextIO,
                  with_spans: bool = True) -> None:
    """Write ``json.dumps(to_data(Program(path, body, unit())), indent=1)`` statement by statement.

    ``body`` may be a streaming reader, so memory stays that of one statement; ``unit`` is asked
    after it, as a reader knows the ``@unit`` line only once it has read it.
    """
    out.write('{\n "type": "Program",\n "path": ' + json.dumps(path) + ',\n "body": [')
    first = True
    for stmt in body:
        out.write(("\n  " if first else ",\n  ") + json.dumps(to_data(stmt, with_spans), indent=1).replace("\n", "\n  "))
        first = False
    out.write("]" if first else "\n ]")
    out.write(',\n "unit": ' + json.dumps(unit()) + "\n}\n")
