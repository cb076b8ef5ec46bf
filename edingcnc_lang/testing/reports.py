"""The reports of ``ecnc test``: coverage as text, JSON or HTML pages, and JUnit XML for CI."""
from __future__ import annotations

import html
import json
import os
import re
import xml.etree.ElementTree as ET
from collections.abc import Iterable, Sequence
from pathlib import Path

from edingcnc_lang.errors import printable
from edingcnc_lang.syntax.source import iter_file_lines
from edingcnc_lang.testing.coverage import FileCoverage
from edingcnc_lang.testing.session import Summary
from edingcnc_lang.outputs import write_text

COVERAGE_FORMATS = ("term", "json", "html", "lcov", "cobertura")


def percent(hit: int, total: int) -> str:
    return f"{100.0 * hit / total:.0f}%" if total else "-"


def ranges(lines: Iterable[int]) -> str:
    """``3-5, 9, 12-13``: line numbers folded into runs."""
    runs: list[list[int]] = []
    for line in sorted(lines):
        if runs and line == runs[-1][1] + 1:
            runs[-1][1] = line
        else:
            runs.append([line, line])
    return ", ".join(str(a) if a == b else f"{a}-{b}" for a, b in runs)


def coverage_term(files: Sequence[FileCoverage]) -> str:
    """A block per macro file: lines, branches, the lines missed and the subs never run."""
    out = []
    for cov in files:
        out.append(f"{cov.path}: lines {len(cov.lines_hit)}/{cov.lines_total} "
                   f"({percent(len(cov.lines_hit), cov.lines_total)}), branches {cov.branches_hit}/"
                   f"{cov.branches_total} ({percent(cov.branches_hit, cov.branches_total)})")
        for sub, lines in cov.missed_by_sub():  # grouped by sub: a wall of ranges says nothing
            out.append(f"  lines not run {'in ' + sub if sub else 'outside the subs'}: {ranges(lines)}")
        if cov.branches_missed:
            out.append("  branches not taken: " + ", ".join(f"{line} {name}" for line, name in cov.branches_missed))
        if cov.subs_never_run:
            out.append(f"  subs no test ran: {', '.join(cov.subs_never_run)}")
    return "\n".join(out)


def coverage_json(files: Sequence[FileCoverage]) -> str:
    return json.dumps({"files": {cov.path: cov.to_json() for cov in files}}, indent=2) + "\n"


def write_coverage_html(files: Sequence[FileCoverage], folder: Path) -> Path:
    """``index.html`` listing the files, and a page per file with its lines coloured; returns the index."""
    folder.mkdir(parents=True, exist_ok=True)
    rows = []
    for number, cov in enumerate(files, 1):
        page = f"{number:02d}_{re.sub(r'[^A-Za-z0-9_.-]+', '_', Path(cov.path).name)}.html"
        write_text(folder / page, _file_page(cov))
        rows.append(f"<tr><td><a href=\"{html.escape(page)}\">{html.escape(cov.path)}</a></td>"
                    f"<td>{len(cov.lines_hit)}/{cov.lines_total} ({percent(len(cov.lines_hit), cov.lines_total)})</td>"
                    f"<td>{cov.branches_hit}/{cov.branches_total}</td>"
                    f"<td>{html.escape(', '.join(cov.subs_never_run)) or '-'}</td></tr>")
    body = ("<table><tr><th>macro file</th><th>lines</th><th>branches</th><th>subs no test ran</th></tr>"
            + "\n".join(rows) + "</table>")
    index = folder / "index.html"
    write_text(index, _page("Macro coverage", body))
    return index


def _file_page(cov: FileCoverage) -> str:
    missed, hit = set(cov.missed), cov.lines_hit
    partial: dict[int, list[str]] = {}
    for line, name in cov.branches_missed:
        partial.setdefault(line, []).append(name)
    rows = []
    for number, text in enumerate(iter_file_lines(cov.path), 1):
        css = "missed" if number in missed else "partial" if number in partial else "hit" if number in hit else ""
        note = f" title=\"branch not taken: {', '.join(partial[number])}\"" if number in partial else ""
        rows.append(f"<tr class=\"{css}\"{note}><td class=\"n\">{number}</td>"
                    f"<td><pre>{html.escape(text) or ' '}</pre></td></tr>")
    head = (f"<p>lines {len(hit)}/{cov.lines_total} ({percent(len(hit), cov.lines_total)}), branches "
            f"{cov.branches_hit}/{cov.branches_total}; subs no test ran: "
            f"{html.escape(', '.join(cov.subs_never_run)) or 'none'}</p>"
            "<p><span class=\"hit\">run</span> <span class=\"missed\">not run</span> "
            "<span class=\"partial\">a branch not taken</span></p>")
    return _page(cov.path, head + "<table class=\"src\">\n" + "\n".join(rows) + "\n</table>")


def _page(title: str, body: str) -> str:
    return ("<!DOCTYPE html>\n<html><head><meta charset=\"utf-8\"><title>" + html.escape(title) + "</title><style>"
            "body{font-family:sans-serif} table{border-collapse:collapse} td,th{padding:0 .5em;text-align:left}"
            "pre{margin:0} .n{color:#888;text-align:right} .hit{background:#dfd} .missed{background:#fdd}"
            ".partial{background:#ffd}</style></head><body><h1>" + html.escape(title) + "</h1>" + body
            + "</body></html>\n")


def junit_xml(summary: Summary) -> str:
    """JUnit XML as CI services read it: a testsuite per test file, a testcase per test with
    ``<failure>`` (a check that did not hold), ``<error>`` (the run stopped with an error the test did
    not expect) or ``<skipped>`` (not run after -x), and the job's messages as ``<system-out>``."""
    import socket
    from datetime import datetime, timezone

    stamp = datetime.fromtimestamp(summary.started or 0, timezone.utc).strftime("%Y-%m-%dT%H:%M:%S")
    counts = {"tests": 0, "failures": 0, "errors": 0, "skipped": 0}
    root = ET.Element("testsuites", name="ecnc test")
    suites: dict[str, tuple[ET.Element, dict[str, int], list[float]]] = {}

    def case(file: str, name: str, line: int, seconds: float, kind: str) -> ET.Element:
        if file not in suites:
            suites[file] = (ET.SubElement(root, "testsuite", name=_xml(file), timestamp=stamp,
                                          hostname=_xml(socket.gethostname())), dict.fromkeys(counts, 0), [0.0])
        suite, tally, spent = suites[file]
        for key in ("tests", kind):
            if key in tally:
                tally[key] += 1
                counts[key] += 1
        spent[0] += seconds
        return ET.SubElement(suite, "testcase", classname=_xml(_classname(file)), name=_xml(name),
                             file=_xml(file), line=str(line), time=f"{seconds:.3f}")

    for result in summary.results:
        kind = "passed" if result.passed else "errors" if result.errored else "failures"
        element = case(result.file, result.name, result.line, result.seconds, kind)
        if not result.passed:
            problem = ET.SubElement(element, "error" if result.errored else "failure",
                                    message=_xml(result.failures[0]), type="error" if result.errored else "failure")
            problem.text = _xml("\n".join(result.failures))
        if result.messages:
            ET.SubElement(element, "system-out").text = _xml("\n".join(result.messages))
    for left in summary.not_run:
        element = case(left.file, left.name, left.line, 0.0, "skipped")
        ET.SubElement(element, "skipped", message="not run: -x stopped at the first failing test")
    for suite, tally, spent in suites.values():
        for key, value in tally.items():
            suite.set(key, str(value))
        suite.set("time", f"{spent[0]:.3f}")
    for key, value in counts.items():
        root.set(key, str(value))
    root.set("time", f"{summary.seconds:.3f}")
    root.set("timestamp", stamp)
    ET.indent(root)
    return '<?xml version="1.0" encoding="utf-8"?>\n' + ET.tostring(root, encoding="unicode") + "\n"


# What XML 1.0 cannot hold at all, after printable() has made the C0/C1 controls visible.
_NOT_XML = re.compile("[\ud800-\udfff\ufffe\uffff]")


def _xml(text: str) -> str:
    """``text`` as XML 1.0 allows it: every control character but tab and newline shown as
    ``\\xNN`` (a test's name or a job's message may hold any), lone surrogates as ``\\uNNNN``."""
    return _NOT_XML.sub(lambda m: f"\\u{ord(m[0]):04x}", printable(text))


def _classname(file: str) -> str:
    """``examples/tests/test_macro.toml`` -> ``examples.tests.test_macro`` (how CI tools group cases)."""
    stem = os.path.splitext(file)[0]
    return ".".join(part for part in re.split(r"[\\/]+", stem) if part not in ("", ".", ".."))
