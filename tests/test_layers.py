"""The layers hold: every import in the package is read (top level and inside functions) and
checked against the layer map of docs/architecture.md (``LAYERS``), module by module: a root module
is a unit as a folder is, so no two units import each other, not even through a lazy import.

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

# The layer map (docs/architecture.md draws it), lowest first.  A unit is a module of the root, a
# sub-package, or a part of one named here ("motion.sinks"); each module belongs to the longest unit
# that names it.  A unit imports units of lower layers only, and units of its own layer only where the
# layer is open (its units build on each other without a cycle) or an edge is in ALLOWED.
LAYERS: list[tuple[str, bool, set[str]]] = [
    ("foundation", True, {"records", "errors", "codes", "diagnostics", "events", "canon", "picture_formats",
                          "gcpause", "speedups", "stdlib", "outputs"}),
    ("syntax", True, {"syntax", "parser"}),
    ("configuration", False, {"config", "host"}),
    ("machine", False, {"machine", "kinematics"}),
    ("stages", False, {"pipeline", "knowledge", "motion", "kins"}),
    ("sinks", False, {"motion.sinks"}),
    ("planner", False, {"motion.planner"}),
    # the variable map's names and kinds: read by the linter, the debugger and ecnc test, so below them all
    ("orchestration", True, {"runner", "run_records", "varmap"}),
    ("products", False, {"plot", "lint", "sim", "diff", "kinematics.workbench", "mdi"}),
    ("front ends", False, {"lsp", "debug", "testing"}),
    ("command line", False, {"cli"}),
    ("python -m", False, {"__main__"}),
]
LAYER = {unit: index for index, (_name, _open, units) in enumerate(LAYERS) for unit in units}
OPEN = {unit for _name, is_open, units in LAYERS if is_open for unit in units}

# The edges the map allows against it, each with its reason.
ALLOWED: dict[tuple[str, str], str] = {
    ("diff", "plot"): "ecnc diff draws its pictures in plot's views, colours and frame, so both pictures look "
                      "alike; plot never imports diff",
}

# Finer rules inside the allowed direction: a unit with the modules it must never import.
FORBIDDEN: dict[str, set[str]] = {
    # the machine executes the tree it is given: the syntax tree (syntax.nodes) and the input
    # limits, never the parser that builds it
    "machine": {"syntax.parser", "syntax.line_parser", "syntax.fastparse", "syntax.tree_builder", "syntax.blocks"},
    # a stage may use the machine's geometry and tables, never the interpreter
    "pipeline": {"syntax.parser",
                 *(f"machine.{m.stem}" for m in (PACKAGE / "machine").glob("*.py")
                   if m.stem not in ("geometry", "tables", "__init__"))},
    "motion": {"syntax.parser"},
}


def unit_of(module: str) -> str:
    """``edingcnc_lang.machine.flow`` -> ``machine``, ``edingcnc_lang.motion.sinks`` -> ``motion.sinks``; a
    root module -> its name; the package itself (the lazy public API) -> ""."""
    name = module[len(P) + 1:]
    parts = name.split(".")
    for size in range(len(parts), 0, -1):
        if ".".join(parts[:size]) in LAYER:
            return ".".join(parts[:size])
    return parts[0] if name else ""


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


def layer_violations(edges: list[tuple[str, str, str]]) -> list[str]:
    """Each edge against the map: to a higher layer, or across a closed layer, and not in ALLOWED."""
    wrong = []
    for module, target, where in edges:
        a, b = unit_of(module), unit_of(target)
        if not a or (a, b) in ALLOWED:
            continue
        if LAYER[b] > LAYER[a] or (LAYER[b] == LAYER[a] and a not in OPEN):
            wrong.append(f"{where}: {module} ({LAYERS[LAYER[a]][0]}) imports {target} ({LAYERS[LAYER[b]][0]})")
    return wrong


def unit_graph(edges: list[tuple[str, str, str]]) -> dict[str, set[str]]:
    graph: dict[str, set[str]] = {}
    for module, target, _where in edges:
        a, b = unit_of(module), unit_of(target)
        if a and b:
            graph.setdefault(a, set()).add(b)
    return graph


def test_every_unit_is_on_the_map() -> None:
    units = {unit_of(module) for module, _ in modules()} - {""}
    assert units <= set(LAYER), f"not on the layer map: {sorted(units - set(LAYER))}"


def test_no_import_against_the_layers() -> None:
    wrong = layer_violations(EDGES)
    assert not wrong, "\n".join(wrong)


def test_each_allowed_edge_is_still_made() -> None:
    """An exception nothing needs any more is taken off the list."""
    made = {(unit_of(module), unit_of(target)) for module, target, _ in EDGES}
    assert set(ALLOWED) <= made, set(ALLOWED) - made


def test_no_import_cycle_between_units() -> None:
    """Modules of the root count as units beside the folders: speedups.py and syntax/ importing each other
    is a cycle (lazy imports count too)."""
    longer = _cycle(unit_graph(EDGES))
    assert not longer, f"an import cycle between units: {' -> '.join(longer)}"


def test_the_layer_test_sees_a_cycle_through_a_root_module() -> None:
    edges = [(f"{P}.speedups", f"{P}.syntax.input_limits", "speedups.py:1"),
             (f"{P}.syntax.parser", f"{P}.speedups", "syntax/parser.py:1")]
    assert _cycle(unit_graph(edges)) == ["speedups", "syntax", "speedups"]
    assert layer_violations(edges) == [f"speedups.py:1: {P}.speedups (foundation) imports {P}.syntax.input_limits "
                                       "(syntax)"]


def test_the_layer_test_sees_a_sub_unit_edge() -> None:
    edges = [(f"{P}.motion.sinks", f"{P}.motion.planner.estimate", "motion/sinks.py:1"),
             (f"{P}.machine.state", f"{P}.runner", "machine/state.py:1")]
    assert len(layer_violations(edges)) == 2


def _cycle(graph: dict[str, set[str]]) -> list[str]:
    """A cycle through the graph of units, if there is one (depth-first search)."""
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
    assert set(LAYER) <= units, set(LAYER) - units


def test_the_layer_test_sees_a_forbidden_edge(tmp_path: Path) -> None:
    """The reader finds relative and lazy imports (the kind that slipped through before)."""
    source = tmp_path / "x.py"
    source.write_text("def f():\n    from ..syntax import parser\n", encoding="utf-8")
    found = list(imports(f"{P}.machine.x", source))
    assert (f"{P}.syntax.parser", 2) in found
