"""Every feature at every token of real macro files, in process: no exceptions, and every G/M code
and parameter the files use is explained on hover."""
from __future__ import annotations

from pathlib import Path

import pytest

from edingcnc_lang.lsp import actions, completion, hover, navigation
from edingcnc_lang.lsp.lexer import tokens
from edingcnc_lang.lsp.model import LanguageModel

pytestmark = pytest.mark.slow  # the whole module (pyproject's slow marker)

ROOT = Path(__file__).resolve().parents[2]
FILES = [ROOT / "stdlib" / "macro.cnc", ROOT / "examples" / "probe_corner.nc", ROOT / "examples" / "dialog_setup.nc"]


@pytest.mark.parametrize("path", FILES, ids=lambda p: p.name)
def test_every_token_of_a_real_file(path: Path) -> None:
    model = LanguageModel()
    name = str(path)
    file = model.source(name)
    assert file is not None
    for number, line in enumerate(file.lines):
        for token in tokens(line):
            text = hover.hover_text(model, name, number, token.start)
            if token.kind in ("code", "param", "command", "keyword", "function"):
                assert text, (number + 1, token)
            completion.complete(model, name, number, token.end)
            if token.kind == "sub":
                assert navigation.definition(model, name, number, token.start), (number + 1, token)
    assert navigation.document_symbols(model, name) or not file.subs
    for found in model.lint(name):
        actions.fixes(actions.ShownDiagnostic(found.code, found.line - 1, max(found.col - 1, 0), found.message), file.lines)
