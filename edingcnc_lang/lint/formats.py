"""Rendering findings: text for people, JSON for scripts, GitHub annotations, SARIF 2.1.0.

json is imported by the two formats that write it: the text format of a lint does not load it.
"""
from __future__ import annotations

from collections.abc import Callable, Sequence

from edingcnc_lang.codes import CODES
from edingcnc_lang.diagnostics import Diagnostic
from edingcnc_lang.errors import printable



def text(findings: Sequence[Diagnostic], with_source: bool = True) -> str:
    """``PATH:LINE:COL: CODE message``, each followed by its source line and a caret."""
    out = []
    for d in findings:
        head = printable(f"{d.path}:{d.line}:{d.col}: {d.code} {d.message}")
        caret = d.format(with_source).partition("\n")[2] if with_source else ""
        out.append(f"{head}\n{caret}" if caret else head)
    return "\n".join(out)


def as_json(findings: Sequence[Diagnostic], with_source: bool = True) -> str:
    import json

    return json.dumps([{"path": d.path, "line": d.line, "col": d.col, "code": d.code,
                        "severity": d.severity.value, "message": d.message} for d in findings], indent=1)


def _escape_data(value: str) -> str:
    return value.replace("%", "%25").replace("\r", "%0D").replace("\n", "%0A")


def _escape_property(value: str) -> str:
    return _escape_data(value).replace(":", "%3A").replace(",", "%2C")


def github(findings: Sequence[Diagnostic], with_source: bool = True) -> str:
    """GitHub Actions workflow commands: one ``::error``/``::warning`` annotation a finding."""
    return "\n".join(
        f"::{d.severity.value} file={_escape_property(d.path)},line={d.line},col={d.col},"
        f"title={_escape_property(d.code)}::{_escape_data(d.message)}" for d in findings)


def sarif(findings: Sequence[Diagnostic], with_source: bool = True) -> str:
    """SARIF 2.1.0 for code-scanning services (lint/sarif.py)."""
    from edingcnc_lang.lint.sarif import sarif as render

    return render(findings, with_source)


FORMATS: dict[str, Callable[[Sequence[Diagnostic], bool], str]] = {
    "text": text, "json": as_json, "github": github, "sarif": sarif,
}


def list_codes() -> str:
    """Every code with its severity and summary, one a line (``--list-codes``)."""
    return "\n".join(f"{c.code}  {c.severity.value:<7}  {c.summary}" for c in CODES.values())
