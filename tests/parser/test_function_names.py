"""The dialect's function names live in one table (``syntax.nodes.FUNCTION_NAMES``); every other place
that names them is pinned to it here, so a function added or renamed in one place and not the others fails."""
from __future__ import annotations

import re
from pathlib import Path

from edingcnc_lang.knowledge.command_texts import FUNCTIONS as TEXTS
from edingcnc_lang.machine.evaluator import FUNCTIONS as EVALUATED
from edingcnc_lang.syntax import fastparse
from edingcnc_lang.syntax.nodes import FUNCTION_NAMES

PACKAGE = Path(fastparse.__file__).resolve().parent.parent
ONE_ARGUMENT = set(FUNCTION_NAMES) - {"ATAN"}


def test_atan_is_the_last_and_the_only_two_argument_function() -> None:
    assert FUNCTION_NAMES[-1] == "ATAN" and len(set(FUNCTION_NAMES)) == len(FUNCTION_NAMES)


def test_the_grammar_names_the_table() -> None:
    grammar = (PACKAGE / "syntax" / "grammar" / "gcode.lark").read_text(encoding="utf-8")
    func = re.search(r"^FUNC\.\d+: /\(([a-z|]+)\)", grammar, re.MULTILINE)
    atan = re.search(r"^ATAN\.\d+: /([a-z]+)\(", grammar, re.MULTILINE)
    assert func and atan
    assert {name.upper() for name in func.group(1).split("|")} == ONE_ARGUMENT
    assert atan.group(1).upper() == "ATAN"


def test_the_compiled_reader_names_the_table_in_its_order() -> None:
    source = (PACKAGE / "csrc" / "lexer_nodes.c").read_text(encoding="utf-8")
    found = re.search(r"FUNCTIONS\[\] = \{([^}]*)\}", source)
    assert found
    assert tuple(re.findall(r'"([A-Z]+)"', found.group(1))) == FUNCTION_NAMES


def test_the_fast_reader_and_the_evaluator_name_the_table() -> None:
    assert fastparse._FUNCTIONS == set(FUNCTION_NAMES)
    assert set(EVALUATED) == ONE_ARGUMENT  # ATAN is evaluated on its own (one or two arguments)


def test_hover_and_help_describe_every_function() -> None:
    assert [row[0] for row in TEXTS] == sorted(FUNCTION_NAMES)
