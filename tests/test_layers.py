"""The layers hold: every import in the package is read (top level and inside functions) and
checked against the direction of docs/architecture.md, and no two sub-packages import each other.

A new edge against the direction fails here with the module and the import that made it; a
layer that must use something above it takes it as a parameter or a callback instead.
"""
from __future__ import annotations

import ast
from collections.abc import Iterator
from pathlib import Path

import pytest

PACKAGE = Path(__file__).resolve().parent.parent / "edingcnc_lang"
P = "edingcnc_lang"

# Each unit (a sub-package, or a module of the root) with the units it must never import.
# Lower layers first; a unit may import anything not listed against it.
ABOVE_SYNTAX = {"config", "machine", "pipeline", "motion", "kinematics", "runner", "mdi", "cli", "lint", "lsp",
                "plot", "debug", "testing", "diff", "sim", "knowledge"}
FRONT_ENDS = {"cli", "lsp", "mdi", "debug", "testing", "diff", "sim", "plot", "lint"}
FORBIDDEN: dict[str, set[str]] = {
    "syntax": ABOVE_SYNTAX,
    "config": ABOVE_SYNTAX - {"config"},
    # the machine executes the tree it is given: the syntax tree (syntax.nodes) and the input
    # limits, never the parser that builds it
    "machine": {"pipeline", "motion", "kinematics", "runner", *FRONT_ENDS,
                "syntax.parser", "syntax.line_parser", "syntax.fastparse", "syntax.tree_builder", "syntax.blocks"},
    # a stage may use the machine's geometry and tables, never the interpreter or the motion stage
    "pipeline": {"motion", "kinematics", "runner", *FRONT_ENDS, "syntax.parser",
                 *(f"machine.{m.stem}" for m in (PACKAGE / "machine").glob("*.py")
                   if m.stem not in ("geometry", "tables", "__init__"))},
    "kinematics": {"machine", "pipeline", "motion", "runner", *FRONT_ENDS},
    "motion": {"runner", "pipeline", *FRONT_ENDS, "syntax.parser"},
    "runner": FRONT_ENDS,
    "knowledge": {"runner", "pipeline", "motion", *FRONT_ENDS},
    "canon": {"syntax", "machine", "config", "pipeline", "motion", "kinematics", "runner", *FRONT_ENDS},
    "errors": {"syntax", "machine", "config", "pipeline", "motion", "kinematics", "runner", *FRONT_ENDS},
    "picture_formats": {"plot", "kinematics", "runner", "motion"},
    "outputs": {"syntax", "machine", "config", "pipeline", "motion", "kinematics", "runner", *FRONT_ENDS},
    # the products and tools built on a run do not import each other or a front end
    "plot": {"cli", "lsp", "debug", "testing", "diff", "sim", "lint"},
    "lint": {"cli", "lsp", "debug", "testing", "diff", "sim", "plot", "runner", "motion", "pipeline"},
    "diff": {"cli", "lsp", "debug", "testing", "sim", "lint"},
    "sim": {"cli", "lsp", "debug", "testing", "diff", "lint"},
    "debug": {"cli", "lsp", "testing", "diff", "sim", "lint", "plot"},
    "testing": {"cli", "lsp", "debug", "diff", "sim", "lint", "plot"},
    # the variable map's names and kinds: read by the linter, the debugger and ecnc test, so below them all
    "varmap": {"runner", "pipeline", "motion", "kinematics", *FRONT_ENDS},
}


def unit_of(module: str) -> str:
    """``edingcnc_lang.machine.flow`` -> ``machine``; a root module -> its name."""
    parts = module.split(".")
    return parts[1] if len(parts) > 1 else ""


def modules() -> Iterator[tuple[str, Path]]:
    for path in sorted(PACKAGE.rglob("*.py")):
        rel = path.relative_to(PACKAGE.parent).with_suffix("")
        yield ".".join(rel.parts[:-1] if path.name == "__init__.py" else rel.parts), path


def is_module(dotted: str) -> bool:
    base = PACKAGE.parent / Path(*dotted.split("."))
    return base.with_suffix(".py").exists() or (base / "__init__.py").exists()


def imports(module: str, path: Path) -> Iterator[tuple[str, int]]:
    """Every package module ``module`` imports, with the line (relative imports resolved)."""
    package = module if path.name == "__init__.py" else module.rpartition(".")[0]
    for node in ast.walk(ast.parse(path.read_text(encoding="utf-8"))):
        if isinstance(node, ast.Import):
            targets = [alias.name for alias in node.names]
        elif isinstance(node, ast.ImportFrom):
            base = node.module or ""
            if node.level:
                anchor = package.split(".")[: len(package.split(".")) - (node.level - 1)]
                base = ".".join([*anchor, *([node.module] if node.module else [])])
            targets = [base, *(f"{base}.{alias.name}" for alias in node.names)]
        else:
            continue
        for target in targets:
            if (target == P or target.startswith(P + ".")) and is_module(target):
                yield target, node.lineno


def edges() -> list[tuple[str, str, str]]:
    """(importing module, imported module, FILE:LINE) for every import between two units."""
    found = []
    for module, path in modules():
        for target, line in imports(module, path):
            if target != P and unit_of(target) != unit_of(module):
                found.append((module, target, f"{path.relative_to(PACKAGE.parent)}:{line}"))
    return found


EDGES = edges()


def _matches(target: str, rule: str) -> bool:
    name = target[len(P) + 1:]
    return name == rule or name.startswith(rule + ".")


@pytest.mark.parametrize("unit", sorted(FORBIDDEN))
def test_no_import_against_the_direction(unit: str) -> None:
    wrong = [f"{where}: {module} imports {target}" for module, target, where in EDGES
             if unit_of(module) == unit and any(_matches(target, rule) for rule in FORBIDDEN[unit])]
    assert not wrong, "\n".join(wrong)


def test_no_two_sub_packages_import_each_other() -> None:
    graph: dict[str, set[str]] = {}
    for module, target, _where in EDGES:
        a, b = unit_of(module), unit_of(target)
        if a and b and (PACKAGE / a).is_dir() and (PACKAGE / b).is_dir():
            graph.setdefault(a, set()).add(b)
    cycles = sorted({tuple(sorted((a, b))) for a, targets in graph.items() for b in targets
                     if a in graph.get(b, set())})
    longer = _cycle(graph)
    assert not cycles and not longer, f"import cycles between sub-packages: {cycles or longer}"


def _cycle(graph: dict[str, set[str]]) -> list[str]:
    """A cycle through the sub-package graph, if there is one (depth-first search)."""
    state: dict[str, int] = {}
    stack: list[str] = []

    def visit(node: str) -> list[str]:
        state[node] = 1
        stack.append(node)
        for nxt in sorted(graph.get(node, ())):
            if state.get(nxt) == 1:
                return stack[stack.index(nxt):] + [nxt]
            if nxt not in state:
                found = visit(nxt)
                if found:
                    return found
        stack.pop()
        state[node] = 2
        return []

    for node in sorted(graph):
        if node not in state:
            found = visit(node)
            if found:
                return found
    return []


def test_the_rules_name_units_that_exist() -> None:
    """A rule for a folder or module that was renamed would silently check nothing."""
    units = {unit_of(module) for module, _ in modules()}
    assert set(FORBIDDEN) <= units, set(FORBIDDEN) - units


def test_the_layer_test_sees_a_forbidden_edge(tmp_path: Path) -> None:
    """The reader finds relative and lazy imports (the kind that slipped through before)."""
    source = tmp_path / "x.py"
    source.write_text("def f():\n    from ..syntax import parser\n", encoding="utf-8")
    found = list(imports(f"{P}.machine.x", source))
    assert (f"{P}.syntax.parser", 2) in found
