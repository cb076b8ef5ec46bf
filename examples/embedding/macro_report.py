"""A notebook-style analysis of a macro file: its subs, who calls whom, the parameters each sub
writes, and the lint findings by code.

    python examples/embedding/macro_report.py [macro.cnc]
"""
from __future__ import annotations

import sys
from collections import Counter
from importlib import resources
from pathlib import Path

from edingcnc_lang import LintOptions, Visitor, lint_paths, parse_file, walk
from edingcnc_lang.syntax import nodes as n

class SubFacts(Visitor):
    """Per sub: the subs it calls and the parameter numbers it writes (constant ones)."""

    def __init__(self) -> None:
        self.current = "(top level)"
        self.calls: dict[str, set[str]] = {}
        self.writes: dict[str, set[int]] = {}

    def visit_Sub(self, node: n.Sub) -> None:
        outer, self.current = self.current, node.name
        self.calls.setdefault(node.name, set())
        self.writes.setdefault(node.name, set())
        self.generic_visit(node)
        self.current = outer

    def visit_GoSub(self, node: n.GoSub) -> None:
        self.calls.setdefault(self.current, set()).add(node.name)

    def visit_Assign(self, node: n.Assign) -> None:
        if isinstance(node.target.index, n.Number):
            self.writes.setdefault(self.current, set()).add(int(node.target.index.value))
        self.generic_visit(node)


def report(path: Path) -> str:
    program = parse_file(path)
    facts = SubFacts()
    facts.visit(program)
    statements = sum(1 for node in walk(program) if not isinstance(node, (n.Number, n.Param)))
    findings = Counter(d.code for d in lint_paths([path], LintOptions()))
    lines = [f"{path.name}: {len(program.subs)} subs, {statements} nodes"]
    for name in sorted(facts.calls, key=str.lower):
        calls = ", ".join(sorted(facts.calls[name], key=str.lower)) or "-"
        writes = ", ".join(f"#{i}" for i in sorted(facts.writes.get(name, ()))) or "-"
        lines.append(f"  {name}: calls {calls}; writes {writes}")
    lines.append("findings: " + (", ".join(f"{code} x{count}" for code, count in sorted(findings.items())) or "none"))
    return "\n".join(lines)


def main(argv: list[str]) -> int:
    path = Path(argv[0]) if argv else Path(str(resources.files("edingcnc_lang") / "stdlib" / "macro.cnc"))
    print(report(path))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
