"""Macro coverage in the formats coverage services read: LCOV tracefiles (Codecov, Coveralls,
genhtml) and Cobertura XML (GitLab's merge-request coverage, Codecov, Azure DevOps).

Paths are as the other reports name them: relative to the current folder (the project) when the
file lies below it.  A line is run once or not at all as far as the figures go (coverage records
whether a statement ran, not how often); each If and While is one branch point of two branches.
"""
from __future__ import annotations

import os
import time
import xml.etree.ElementTree as ET
from collections.abc import Sequence

from edingcnc_lang import __version__
from edingcnc_lang.testing.coverage import FileCoverage

COBERTURA_DTD = "http://cobertura.sourceforge.net/xml/coverage-04.dtd"


def lcov(files: Sequence[FileCoverage]) -> str:
    """An LCOV tracefile: a record per macro file with its subs (FN), branches (BRDA) and lines (DA)."""
    out = ["TN:"]
    for cov in files:
        out.append(f"SF:{cov.path}")
        for name, line, _run in cov.subs:
            out.append(f"FN:{line},{name}")
        for name, _line, run in cov.subs:
            out.append(f"FNDA:{int(run)},{name}")
        out += [f"FNF:{len(cov.subs)}", f"FNH:{sum(run for _n, _l, run in cov.subs)}"]
        blocks: dict[int, list[int]] = {}  # line -> [its branch point's number, branches listed so far]
        for line, _name, taken in cov.branches:
            block = blocks.setdefault(line, [len(blocks), 0])
            out.append(f"BRDA:{line},{block[0]},{block[1]},{int(taken) if line in cov.lines_hit else '-'}")
            block[1] += 1
        out += [f"BRF:{len(cov.branches)}", f"BRH:{sum(taken for _l, _n, taken in cov.branches)}"]
        out += [f"DA:{line},{int(line in cov.lines_hit)}" for line in sorted({*cov.lines_hit, *cov.missed})]
        out += [f"LF:{cov.lines_total}", f"LH:{len(cov.lines_hit)}", "end_of_record"]
    return "\n".join(out) + "\n"


def _rate(hit: int, total: int) -> str:
    return f"{hit / total:.4f}" if total else "1"


def cobertura(files: Sequence[FileCoverage]) -> str:
    """Cobertura XML (coverage-04.dtd): a package per folder, a class per macro file with a method
    per sub, its lines with hits and, on If/While lines, ``condition-coverage``."""
    lines_hit = sum(len(c.lines_hit) for c in files)
    lines_total = sum(c.lines_total for c in files)
    branches_hit = sum(c.branches_hit for c in files)
    branches_total = sum(c.branches_total for c in files)
    root = ET.Element("coverage", {
        "line-rate": _rate(lines_hit, lines_total), "branch-rate": _rate(branches_hit, branches_total),
        "lines-covered": str(lines_hit), "lines-valid": str(lines_total), "branches-covered": str(branches_hit),
        "branches-valid": str(branches_total), "complexity": "0", "version": __version__,
        "timestamp": str(int(time.time() * 1000))})
    ET.SubElement(ET.SubElement(root, "sources"), "source").text = os.path.abspath(os.curdir)
    packages = ET.SubElement(root, "packages")
    folders: dict[str, list[FileCoverage]] = {}
    for cov in files:
        folders.setdefault(os.path.dirname(cov.path).replace(os.sep, "/") or ".", []).append(cov)
    for folder, members in folders.items():
        package = ET.SubElement(packages, "package", {
            "name": folder.replace("/", "."), "complexity": "0",
            "line-rate": _rate(sum(len(c.lines_hit) for c in members), sum(c.lines_total for c in members)),
            "branch-rate": _rate(sum(c.branches_hit for c in members), sum(c.branches_total for c in members))})
        classes = ET.SubElement(package, "classes")
        for cov in members:
            _class(classes, cov)
    ET.indent(root)
    return ('<?xml version="1.0" encoding="utf-8"?>\n'
            f'<!DOCTYPE coverage SYSTEM "{COBERTURA_DTD}">\n' + ET.tostring(root, encoding="unicode") + "\n")


def _class(parent: ET.Element, cov: FileCoverage) -> None:
    path = cov.path.replace(os.sep, "/")
    element = ET.SubElement(parent, "class", {
        "name": os.path.basename(path), "filename": path, "complexity": "0",
        "line-rate": _rate(len(cov.lines_hit), cov.lines_total),
        "branch-rate": _rate(cov.branches_hit, cov.branches_total)})
    methods = ET.SubElement(element, "methods")
    for name, line, run in cov.subs:
        method = ET.SubElement(methods, "method", {"name": name, "signature": "", "complexity": "0",
                                                   "line-rate": str(int(run)), "branch-rate": "1"})
        ET.SubElement(ET.SubElement(method, "lines"), "line", number=str(line), hits=str(int(run)))
    lines = ET.SubElement(element, "lines")
    per_line: dict[int, list[bool]] = {}
    for line, _name, taken in cov.branches:
        per_line.setdefault(line, []).append(taken)
    for number in sorted({*cov.lines_hit, *cov.missed}):
        attributes = {"number": str(number), "hits": str(int(number in cov.lines_hit)), "branch": "false"}
        if number in per_line:
            done, ways = sum(per_line[number]), len(per_line[number])
            attributes |= {"branch": "true", "condition-coverage": f"{100 * done // ways}% ({done}/{ways})"}
        ET.SubElement(lines, "line", attributes)
