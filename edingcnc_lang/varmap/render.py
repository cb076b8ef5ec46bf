"""The variable map as text: a table for the terminal, JSON, CSV (the spreadsheet users keep by
hand) and Markdown."""
from __future__ import annotations

import csv
import io
import json
from collections.abc import Sequence

from edingcnc_lang.varmap.model import Use, VarMap, Variable

COLUMNS = ("number", "name", "source", "kind", "written in", "read in")


def _where(uses: Sequence[Use]) -> str:
    """The subs that use it, each with its first line and how many more: ``probe:12 (+2), top level:3``."""
    per: dict[tuple[str, str], list[int]] = {}
    for use in uses:
        per.setdefault((use.path, use.sub or "top level"), []).append(use.line)
    shown = []
    for (_path, sub), lines in per.items():
        more = f" (+{len(lines) - 1})" if len(lines) > 1 else ""
        shown.append(f"{sub}:{lines[0]}{more}")
    return ", ".join(shown)


def _cells(variable: Variable) -> tuple[str, ...]:
    return (f"#{variable.number}", variable.name or "", variable.source or "", variable.kind,
            _where(variable.writers), _where(variable.readers))


def table(varmap: VarMap) -> str:
    """Aligned columns, one variable a line."""
    rows = [COLUMNS, *map(_cells, varmap.variables)]
    widths = [max(len(row[i]) for row in rows) for i in range(len(COLUMNS) - 1)]
    lines = ["  ".join([*(cell.ljust(w) for cell, w in zip(row, widths)), row[-1]]).rstrip() for row in rows]
    return "\n".join(lines)


def _use(use: Use) -> dict[str, object]:
    return {"file": use.path, "line": use.line, "sub": use.sub}


def as_json(varmap: VarMap) -> str:
    """``{"variables": [...], "findings": [...]}`` (docs/variables.md)."""
    return json.dumps({
        "variables": [{"number": v.number, "name": v.name, "source": v.source, "kind": v.kind,
                       "description": v.description,
                       "named_at": {"file": v.named_at.path, "line": v.named_at.line} if v.named_at else None,
                       "writers": [_use(u) for u in v.writers], "readers": [_use(u) for u in v.readers]}
                      for v in varmap.variables],
        "findings": [{"path": d.path, "line": d.line, "col": d.col, "code": d.code,
                      "severity": d.severity.value, "message": d.message} for d in varmap.findings],
    }, indent=2)


def _uses_cell(uses: Sequence[Use]) -> str:
    return "; ".join(f"{u.path}:{u.line} ({u.sub or 'top level'})" for u in uses)


def as_csv(varmap: VarMap) -> str:
    """One row per variable; writers and readers as ``file:line (sub)`` lists."""
    out = io.StringIO()
    writer = csv.writer(out, lineterminator="\n")
    writer.writerow(["number", "name", "source", "kind", "description", "writers", "readers"])
    for v in varmap.variables:
        writer.writerow([v.number, v.name or "", v.source or "", v.kind, v.description,
                         _uses_cell(v.writers), _uses_cell(v.readers)])
    return out.getvalue().rstrip("\n")


def _md(cell: str) -> str:
    return cell.replace("|", "\\|")


def markdown(varmap: VarMap) -> str:
    """A Markdown table (for a README or a wiki page)."""
    lines = ["| " + " | ".join(COLUMNS) + " |", "|" + "---|" * len(COLUMNS)]
    lines += ["| " + " | ".join(_md(c) for c in _cells(v)) + " |" for v in varmap.variables]
    return "\n".join(lines)


FORMATS = {"table": table, "json": as_json, "csv": as_csv, "markdown": markdown}
