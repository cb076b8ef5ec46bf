"""Rendering findings: text for people, JSON for scripts, GitHub annotations, SARIF 2.1.0.

json is imported by the two formats that write it: the text format of a lint does not load it.
"""
from __future__ import annotations

from collections.abc import Callable, Sequence
from pathlib import Path

from edingcnc_lang import __version__
from edingcnc_lang.codes import CODES, Severity
from edingcnc_lang.diagnostics import Diagnostic
from edingcnc_lang.errors import printable

SARIF_SCHEMA = "https://json.schemastore.org/sarif-2.1.0.json"
_SARIF_LEVEL = {Severity.ERROR: "error", Severity.WARNING: "warning"}


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


def _uri(path: str) -> str:
    """SARIF wants URIs: relative paths as POSIX references, absolute ones as file: URIs."""
    p = Path(path)
    return p.as_uri() if p.is_absolute() else p.as_posix()


def sarif(findings: Sequence[Diagnostic], with_source: bool = True) -> str:
    """One SARIF run whose rules are the whole code table (so every result's ruleIndex resolves)."""
    codes = list(CODES.values())
    index = {c.code: i for i, c in enumerate(codes)}
    rules = [{"id": c.code, "shortDescription": {"text": c.summary},
              "defaultConfiguration": {"level": _SARIF_LEVEL[c.severity]}} for c in codes]
    results = [{
        "ruleId": d.code, "ruleIndex": index[d.code], "level": _SARIF_LEVEL[d.severity],
        "message": {"text": d.message},
        "locations": [{"physicalLocation": {
            "artifactLocation": {"uri": _uri(d.path)},
            "region": {"startLine": d.line, "startColumn": d.col}}}],
    } for d in findings]
    log = {"$schema": SARIF_SCHEMA, "version": "2.1.0", "runs": [{
        "tool": {"driver": {"name": "ecnc lint", "version": __version__, "rules": rules}},
        "results": results}]}
    import json

    return json.dumps(log, indent=1)


FORMATS: dict[str, Callable[[Sequence[Diagnostic], bool], str]] = {
    "text": text, "json": as_json, "github": github, "sarif": sarif,
}


def list_codes() -> str:
    """Every code with its severity and summary, one a line (``--list-codes``)."""
    return "\n".join(f"{c.code}  {c.severity.value:<7}  {c.summary}" for c in CODES.values())
