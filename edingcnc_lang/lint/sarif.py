"""SARIF 2.1.0 for code-scanning services (GitHub code scanning, GitLab, Azure DevOps).

What such a service needs beyond the bare results: artifact URIs that are valid URI references
(percent-encoded, relative to ``%SRCROOT%`` so the log does not depend on the checkout's folder),
rules that explain themselves (the ``ecnc help CODE`` texts), and fingerprints that follow a
finding when lines are inserted above it (so an alert is not closed and reopened elsewhere).
"""
from __future__ import annotations

import hashlib
import json
import os
import re
from collections.abc import Sequence
from pathlib import Path
from typing import Any
from urllib.parse import quote

from edingcnc_lang import HOMEPAGE, __version__
from edingcnc_lang.codes import CODES, Code, Severity
from edingcnc_lang.diagnostics import Diagnostic

SARIF_SCHEMA = "https://json.schemastore.org/sarif-2.1.0.json"
SRCROOT = "%SRCROOT%"
FINGERPRINT = "ecncLineHash/v1"  # partialFingerprints key: the rule, the line's text, the occurrence
RULES_URI = f"{HOMEPAGE}/blob/main/docs/lint.md#the-rules"
_LEVEL = {Severity.ERROR: "error", Severity.WARNING: "warning"}


def artifact_location(path: str, root: Path) -> dict[str, str]:
    """``{"uri", "uriBaseId"}`` for a path under ``root``, else an absolute ``file:`` URI.

    Each path segment is percent-encoded as UTF-8 (RFC 3986), so ``my macros/macro #2.cnc``
    becomes ``my%20macros/macro%20%232.cnc`` and a reader cannot take ``#2.cnc`` for a fragment.
    """
    p = Path(os.path.abspath(path)) if path != "<stdin>" else None
    if p is None:
        return {"uri": quote(path, safe="")}
    try:
        relative = p.relative_to(root)
    except ValueError:
        return {"uri": p.as_uri()}
    return {"uri": quote(relative.as_posix(), safe="/"), "uriBaseId": SRCROOT}


def _rule(code: Code) -> dict[str, Any]:
    """A reportingDescriptor whose help is the text of ``ecnc help CODE``."""
    from edingcnc_lang.lint.explain import explain

    text = explain(code.code)
    long = text.partition("\n\n")[2] or code.summary
    return {
        "id": code.code,
        "shortDescription": {"text": code.summary},
        "fullDescription": {"text": long},
        "help": {"text": text, "markdown": f"**{code.code}** ({code.severity.value}): {code.summary}\n\n{long}"},
        "helpUri": RULES_URI,
        "defaultConfiguration": {"level": _LEVEL[code.severity]},
    }


def _normalized(line: str) -> str:
    """The line's text as the fingerprint sees it: indentation and runs of blanks do not count."""
    return re.sub(r"\s+", " ", line).strip()


def fingerprints(findings: Sequence[Diagnostic]) -> list[str]:
    """A hash per finding of its rule, its line's normalized text and how many findings of that rule
    on an equal line came before it in its file: the line number is left out, so moving lines
    keeps it."""
    seen: dict[tuple[str, str, str], int] = {}
    out = []
    for d in findings:
        key = (d.path, d.code, _normalized(d.source))
        index = seen[key] = seen.get(key, -1) + 1
        digest = hashlib.sha256(f"{d.code}\0{key[2]}\0{index}".encode()).hexdigest()[:32]
        out.append(f"{digest}:{index + 1}")
    return out


def sarif(findings: Sequence[Diagnostic], with_source: bool = True, root: Path | None = None) -> str:
    """One SARIF run whose rules are the whole code table (so every result's ruleIndex resolves);
    paths are relative to ``root`` (default: the current folder), which is ``%SRCROOT%``."""
    base = Path(os.path.abspath(root or os.curdir))
    codes = list(CODES.values())
    index = {c.code: i for i, c in enumerate(codes)}
    results = [{
        "ruleId": d.code, "ruleIndex": index[d.code], "level": _LEVEL[d.severity],
        "message": {"text": d.message},
        "locations": [{"physicalLocation": {
            "artifactLocation": artifact_location(d.path, base),
            "region": {"startLine": max(d.line, 1), "startColumn": max(d.col, 1)}}}],
        "partialFingerprints": {FINGERPRINT: fingerprint},
    } for d, fingerprint in zip(findings, fingerprints(findings))]
    log = {"$schema": SARIF_SCHEMA, "version": "2.1.0", "runs": [{
        "tool": {"driver": {"name": "ecnc lint", "fullName": "ecnc lint (edingcnc-lang)", "version": __version__,
                            "semanticVersion": __version__, "informationUri": HOMEPAGE,
                            "rules": [_rule(c) for c in codes]}},
        "invocations": [{"executionSuccessful": True}],
        "originalUriBaseIds": {SRCROOT: {"uri": base.as_uri().rstrip("/") + "/"}},
        "columnKind": "unicodeCodePoints",
        "results": results}]}
    return json.dumps(log, indent=1)
