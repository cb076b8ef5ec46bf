"""The public API: every exported name resolves, says what it is, and the helpers do what they say."""
from __future__ import annotations

import math
import re
from pathlib import Path

import edingcnc_lang
from edingcnc_lang import Move, RunOptions, Visitor, move_length, move_points, parse_text, run_string, walk
from edingcnc_lang.syntax import nodes as n

ROOT = Path(edingcnc_lang.__file__).resolve().parent


def test_all_is_the_export_table_and_every_name_resolves_with_a_docstring() -> None:
    assert edingcnc_lang.__all__ == sorted(edingcnc_lang._EXPORTS)
    for name in edingcnc_lang.__all__:
        value = getattr(edingcnc_lang, name)
        if name not in ("Pose", "Stmt"):  # type aliases: documented in docs/api.md
            assert (value.__doc__ or "").strip(), f"{name} has no docstring"


def test_the_package_is_marked_typed() -> None:
    assert (ROOT / "py.typed").is_file()


def test_walk_visits_every_node_in_source_order() -> None:
    program = parse_text("#1 = [2 * SIN[30]]\nIf [#1 > 0]\nGoSub a\nElse\nGoSub b\nEndIf\nSub a\nGoSub c\nEndSub\n")
    assert [node.name for node in walk(program) if isinstance(node, n.GoSub)] == ["a", "b", "c"]
    assert [node.name for node in walk(program) if isinstance(node, n.Call)] == ["SIN"]


def test_a_visitor_calls_a_method_per_node_type() -> None:
    class Writes(Visitor):
        def __init__(self) -> None:
            self.numbers: list[int] = []

        def visit_Assign(self, node: n.Assign) -> None:
            assert isinstance(node.target.index, n.Number)
            self.numbers.append(int(node.target.index.value))
            self.generic_visit(node)

    visitor = Writes()
    visitor.visit(parse_text("#5 = 1\nSub x\n#7 = [#5 + 1]\nEndSub\n"))
    assert visitor.numbers == [5, 7]


def test_move_length_counts_full_turns_as_the_planner_does() -> None:
    moves: list[Move] = []
    result = run_string("G0 X10 Y0\nG2 X10 Y0 I-10 F100\nG3 X0 Y10 I-10\nG1 Z-1\nM30\n",
                        RunOptions(on_move=lambda move, joints: moves.append(move)))
    lengths = [move_length(move) for move in moves]
    assert [round(x, 6) for x in lengths] == [10.0, round(20 * math.pi, 6), round(5 * math.pi, 6), 1.0]
    assert result.estimate is not None
    points = move_points(moves[1], max_step=0.5)
    assert points.shape[1] == 6 and len(points) == math.ceil(20 * math.pi / 0.5) + 1
    assert all(abs(math.hypot(x, y) - 10) < 1e-9 for x, y in points[:, :2])


def test_docs_api_md_lists_every_public_name() -> None:
    text = (ROOT.parent / "docs" / "api.md").read_text(encoding="utf-8")
    for name in edingcnc_lang.__all__:
        assert re.search(rf"`{name}\b", text), f"docs/api.md does not describe {name}"
