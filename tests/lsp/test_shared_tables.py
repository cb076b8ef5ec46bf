"""The language server reads the same tables as the interpreter and the linter, not copies of them."""
from __future__ import annotations

from edingcnc_lang.machine.evaluator import FUNCTIONS
from edingcnc_lang.lsp import lexer
from edingcnc_lang.machine.tables import m_code_sub, m_sub_name


def test_every_function_the_evaluator_knows_is_a_function_token() -> None:
    for name in FUNCTIONS:
        line = f"#1 = {name.lower()}[2]"
        kinds = {token.text.lower(): token.kind for token in lexer.tokens(line)}
        assert kinds[name.lower()] == "function", name


def test_m_code_subs_are_named_in_one_place() -> None:
    assert (m_sub_name(1000), m_sub_name(1005)) == ("m100", None)
    assert (m_code_sub(60), m_code_sub(1000), m_code_sub(35)) == ("change_tool", "m100", None)
