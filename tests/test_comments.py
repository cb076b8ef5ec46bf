"""Comments and docstrings name files that exist: a module renamed or merged leaves no comment
pointing at the old name (fourteen once named a ``machine.py`` that had become ``interpreter.py``)."""
from __future__ import annotations

import io
import re
import tokenize
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
# files named in comments that are not in this repository, each with where it is
ELSEWHERE = {"cnc_types.h": "the EdingCNC controller's API"}
NAMED = re.compile(r"(?<![\w/.-])([A-Za-z_][\w/]*\.(?:py|c|h|lark))\b")


def _files() -> set[str]:
    skip = {".git", "build", "dist"}
    return {p.name for p in ROOT.rglob("*") if p.is_file() and not skip & set(p.parts)
            and not any(part.startswith((".venv", "venv")) for part in p.parts)}


def _named(path: Path) -> list[tuple[int, str]]:
    """(line, file name) for every file a comment or docstring of ``path`` names."""
    found = []
    for token in tokenize.generate_tokens(io.StringIO(path.read_text(encoding="utf-8")).readline):
        if token.type == tokenize.COMMENT or (token.type == tokenize.STRING and token.string.lstrip("rbu").startswith(('"""', "'''"))):
            found += [(token.start[0], m.group(1)) for m in NAMED.finditer(token.string)]
    return found


def test_every_file_a_comment_names_exists() -> None:
    files = _files() | set(ELSEWHERE)
    missing = [f"{path.relative_to(ROOT)}:{line}: names {name}"
               for path in sorted((ROOT / "edingcnc_lang").rglob("*.py")) for line, name in _named(path)
               if name.rsplit("/", 1)[-1] not in files]
    assert not missing, "\n".join(missing)


def test_the_check_sees_a_missing_module(tmp_path: Path) -> None:
    source = tmp_path / "part.py"
    source.write_text('"""Merged in ``interpreter.py``."""\n# machine.py builds the table\nx = "not.py"\n',
                      encoding="utf-8")
    assert _named(source) == [(1, "interpreter.py"), (2, "machine.py")]
