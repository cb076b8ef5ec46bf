"""The VS Code extension folder: its grammar is the one the knowledge table generates, its files fit together."""
from __future__ import annotations

import json
import re
import runpy
import shutil
import subprocess
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2]
VSCODE = ROOT / "editors" / "vscode"
GRAMMAR = VSCODE / "syntaxes" / "edingcnc.tmLanguage.json"


def test_committed_grammar_is_the_generated_one() -> None:
    script = runpy.run_path(str(ROOT / "scripts" / "regen_textmate_grammar.py"))
    assert GRAMMAR.read_text(encoding="utf-8") == script["render"](), \
        "run scripts/regen_textmate_grammar.py after changing edingcnc_lang.knowledge"


def _scopes(line: str) -> list[tuple[str, str]]:
    """What TextMate would colour, approximately: each pattern tried at each position, first wins."""
    patterns = [(p.get("name") or p["captures"]["1"]["name"], re.compile(p["match"]))
                for p in json.loads(GRAMMAR.read_text())["patterns"]]
    found, pos = [], 0
    while pos < len(line):
        best = None
        for name, regex in patterns:
            match = regex.search(line, pos)
            if match and match.end() > match.start() and (best is None or match.start() < best[1].start()):
                best = (name, match)
        if best is None:
            break
        found.append((best[0].split(".")[0] + "." + best[0].split(".")[1], best[1].group()))
        pos = best[1].end()
    return found


@pytest.mark.parametrize(("line", "expected"), [
    (";@unit mm", [("meta.directive", ";@unit mm")]),
    ("G0X10 M3 ; go", [("keyword.other", "G0"), ("variable.other", "X"), ("constant.numeric", "10"),
                        ("keyword.other", "M3"), ("comment.line", "; go")]),
    ('dlgmsg "Width" 27', [("support.function", "dlgmsg"), ("string.quoted", '"Width"'), ("constant.numeric", "27")]),
    ("GoSub drill", [("keyword.control", "GoSub drill")]),
    ("/N20 M3 S1000", [("constant.numeric", "/N20"), ("keyword.other", "M3"), ("variable.other", "S"),
                       ("constant.numeric", "1000")]),
    ("#1 = SQRT[#5067] MOD 2", [("variable.parameter", "#1"), ("keyword.operator", "="),
                                ("support.function", "SQRT"), ("variable.parameter", "#5067"),
                                ("keyword.operator", "MOD"), ("constant.numeric", "2")]),
])
def test_grammar_colours_real_lines(line: str, expected: list[tuple[str, str]]) -> None:
    assert _scopes(line) == expected


def test_extension_manifest_fits_the_server() -> None:
    manifest = json.loads((VSCODE / "package.json").read_text())
    language = manifest["contributes"]["languages"][0]
    assert set(language["extensions"]) == {".cnc", ".nc", ".ngc", ".tap"}
    assert (VSCODE / language["configuration"]).is_file()
    assert (VSCODE / manifest["contributes"]["grammars"][0]["path"]).resolve() == GRAMMAR
    settings = manifest["contributes"]["configuration"]["properties"]
    assert settings["edingcnc.server.command"]["default"] == ["ecnc", "lsp"]
    json.loads((VSCODE / language["configuration"]).read_text())


@pytest.mark.parametrize(("line", "words"), [
    ("G38.2 Z-5 F100", ["G38.2", "Z", "5", "F100"]),
    ("#5403 = #5063", ["#5403", "#5063"]),
    ("GoSub measure_tool", ["GoSub", "measure_tool"]),
    ("M101 P12000", ["M101", "P12000"]),
])
def test_a_word_is_what_the_server_hovers(line: str, words: list[str]) -> None:
    """VS Code selects (double-click) and highlights by ``wordPattern``: a code is one word with its
    decimals (``G38.2``, not ``G38``), a parameter keeps its ``#``."""
    import re

    pattern = json.loads((VSCODE / "language-configuration.json").read_text())["wordPattern"]
    assert [m.group() for m in re.finditer(pattern, line)] == words


@pytest.mark.skipif(shutil.which("node") is None, reason="node is not installed")
def test_extension_script_is_valid_javascript() -> None:
    subprocess.run(["node", "--check", str(VSCODE / "src" / "extension.js")], check=True)
