"""The knowledge table: complete for the dialect's tables, and found however a user spells a topic."""
from __future__ import annotations

import pytest

from edingcnc_lang import knowledge
from edingcnc_lang.machine import tables
from edingcnc_lang.machine.tables import code_name


@pytest.mark.parametrize(("letter", "groups"), [("G", tables.G_GROUPS), ("M", tables.M_GROUPS)])
def test_every_code_of_the_modal_tables_is_described(letter: str, groups: dict[int, str]) -> None:
    for key, group in groups.items():
        entry = knowledge.code(letter, key / 10)
        assert entry is not None, code_name(letter, key)
        assert entry.title and f"Modal group: {group.replace('_', ' ')}" in entry.facts


def test_every_named_system_parameter_has_a_name() -> None:
    named = {name: value for name, value in vars(tables).items()
             if name.isupper() and isinstance(value, int) and 5000 < value < 6000}
    for name, number in named.items():
        if name.startswith("TOOL_") and number % 100 == 0:  # the tool tables: the base plus the tool number
            assert knowledge.variable(number + 1) and knowledge.variable(number + tables.MAX_TOOL), name
        else:
            assert knowledge.variable(number) is not None, name


@pytest.mark.parametrize(("topic", "first_line"), [
    ("G38.2", "G38.2: straight probe"),
    ("g01", "G1: straight feed move"),
    ("M 6", "M6: tool change"),
    ("#5067", "#5067: probe tripped"),
    ("5003", "#5003: work position Z"),
    ("#5243", "#5243: G55 offset Z"),
    ("#5412", "#5412: tool 12 length"),
    ("#2", "#2: M-code sub argument B"),
    ("DLGMSG", "dlgmsg: dialog"),
    ("atan", "ATAN: arc tangent in degrees"),
    ("gosub", "GoSub: call a subroutine"),
])
def test_describe(topic: str, first_line: str) -> None:
    text = knowledge.describe(topic)
    assert text is not None and text.splitlines()[0] == first_line


@pytest.mark.parametrize("topic", ["G38.2", "M3", "#5067", "#4100", "dlgmsg", "SQRT", "GoSub"])
def test_help_and_hover_say_the_same(topic: str) -> None:
    """``ecnc help`` and the editor's hover are one entry in two dresses: the same lines, the same
    words (``Words:``, ``Usage:``, ``Modal group:``), only the markdown differs."""
    entry = knowledge.lookup(topic)
    assert entry is not None
    plain = entry.markdown().replace("**", "").replace("`", "").split("\n\n")
    assert plain == entry.text().splitlines()


@pytest.mark.parametrize("topic", ["G999", "#0", "#6000", "M500", "frobnicate", ""])
def test_describe_unknown_topics(topic: str) -> None:
    assert knowledge.describe(topic) is None


def test_read_only_and_persistent_facts_come_from_the_tables() -> None:
    assert "Read-only: the machine sets it." in knowledge.variable(5001).facts  # type: ignore[union-attr]
    assert "Read-only: the machine sets it." in knowledge.variable(5380).facts  # type: ignore[union-attr]
    assert "Persistent: kept in cnc.ini [VARIABLES]." in knowledge.variable(4100).facts  # type: ignore[union-attr]
    assert knowledge.variable(27).facts == ()  # type: ignore[union-attr]


def test_every_grammar_command_is_in_the_table() -> None:
    """A command added to the grammar needs its row (hover, completion and help read it)."""
    import re
    from pathlib import Path

    grammar = (Path(knowledge.__file__).parent.parent / "syntax" / "grammar" / "macro.lark").read_text()
    names: set[str] = set()
    for rule in ("MESSAGE_KW", "SWITCH_KW", "COMMAND_KW"):
        alternatives = re.search(rf"^{rule}\.\d+: /\((.*?)\)", grammar, re.MULTILINE)
        assert alternatives, rule
        names |= set(alternatives.group(1).split("|"))
    names |= {"dlgmsg", "logfile", "home", "hometandem", "kin", "preparelindeltahome"}
    for name in names:
        assert knowledge.word(name) is not None, f"add a row for {name} to edingcnc_lang/knowledge/command_texts.py"


def test_ecnc_help_explains_language_words_from_the_table() -> None:
    from tests.cli_runner import invoke

    for topic in ("G38.2", "m6", "#5067", "dlgmsg"):
        result = invoke("help", topic)
        assert result.exit_code == 0 and result.stdout.strip() == knowledge.describe(topic)
    assert invoke("lint", "--explain", "G1").stdout.startswith("G1: straight feed move")
    assert invoke("help", "G503").stdout.startswith("G503 (error)")  # the lint code wins
    assert invoke("help", "G999").exit_code == 2


@pytest.mark.parametrize("topic", ["G" + "9" * 310, "M" + "9" * 400, "G 1" + "0" * 20, "#" + "9" * 5000, "9" * 5000,
                                   "G\u0663", "#\u0665\u0660\u0660\u0668"])
def test_a_number_past_every_table_names_nothing(topic: str) -> None:
    """``ecnc help`` and the LSP's hover share this lookup: G and 310 nines was an OverflowError,
    5,000 digits a ValueError; digits other than ASCII ones name nothing (the parser's rule)."""
    assert knowledge.lookup(topic) is None and knowledge.describe(topic) is None


def test_leading_zeros_and_the_largest_numbers_still_look_up() -> None:
    assert knowledge.lookup("#" + "0" * 30 + "5008").name == "#5008"
    assert knowledge.code("G", 1e308) is None and knowledge.code("G", float("nan")) is None
    assert knowledge.code_key_of(38.2) == 382 and knowledge.parameter_number("0" * 5000) == 0


@pytest.mark.parametrize("topic", ["G" + "9" * 310, "#" + "9" * 5000])
def test_ecnc_help_refuses_it_with_a_usage_error(topic: str) -> None:
    from tests.cli_runner import invoke

    result = invoke("help", topic)
    assert result.exit_code == 2 and "no command or lint code" in result.output and len(result.output) < 500
