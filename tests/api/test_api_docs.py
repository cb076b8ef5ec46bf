"""docs/api.md's reference is the code's: regenerating it changes nothing (``--regen-goldens`` rewrites it)."""
from __future__ import annotations

import importlib.util
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2]


def test_docs_api_md_is_generated_from_the_current_docstrings(request: pytest.FixtureRequest) -> None:
    spec = importlib.util.spec_from_file_location("gen_api_docs", ROOT / "scripts" / "gen_api_docs.py")
    assert spec is not None and spec.loader is not None
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    current = module.DOC.read_text(encoding="utf-8")
    expected = module.render(current)
    if request.config.getoption("--regen-goldens", default=False):
        module.DOC.write_text(expected, encoding="utf-8")
    assert current == expected, "docs/api.md is out of date: python scripts/gen_api_docs.py"
