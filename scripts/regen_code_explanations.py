"""Regenerate edingcnc_lang/lint/explanations.json from docs/lint.md (``ecnc help CODE`` prints it).

docs/lint.md is where each lint code is explained for people; this script copies, per code, its
table row (what is wrong, an example) and the paragraphs that start with the code (with the lists
and code blocks that follow them) into package data, so an installed ``ecnc`` can explain a code
without the docs at hand.  Run it after editing docs/lint.md:

    python scripts/regen_code_explanations.py
"""
from __future__ import annotations

import json
import re
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
DOCS = ROOT / "docs" / "lint.md"
OUT = ROOT / "edingcnc_lang" / "lint" / "explanations.json"

CODE = r"[A-Z]\d{3}"
ROW = re.compile(rf"^\| ({CODE}) \| \w+ \| (.*?) \|(?: (.*?) \|)?$")
STARTS_WITH_CODE = re.compile(rf"^\*{{0,2}}({CODE})\b")


def _plain(text: str) -> str:
    """Markdown emphasis, links and code fences as plain terminal text."""
    text = re.sub(r"^```\w*$\n?", "", text, flags=re.MULTILINE).rstrip()
    text = re.sub(r"\*\*(.+?)\*\*", r"\1", text)
    return re.sub(r"\[(.+?)\]\((.+?)\)", r"\1 (\2)", text)


def explanations(markdown: str) -> dict[str, str]:
    """Per code: the table row as sentences, then the paragraphs about it."""
    rows: dict[str, list[str]] = {}
    notes: dict[str, list[str]] = {}
    owner: str | None = None
    blocks = re.split(r"\n\s*\n", markdown)
    for block in blocks:
        first = block.lstrip().splitlines()[0] if block.strip() else ""
        if first.startswith("|"):
            owner = None
            for line in block.splitlines():
                match = ROW.match(line.strip())
                if match:
                    code, what, example = match.groups()
                    shown = example if example and example != "see below" else None
                    rows[code] = [f"What is wrong: {what}."] + ([f"Example: {shown}"] if shown else [])
            continue
        if first.startswith("#"):
            owner = None
            continue
        match = STARTS_WITH_CODE.match(first)
        if match:
            owner = match.group(1)
        if owner is not None:
            notes.setdefault(owner, []).append(block.strip("\n"))
    return {code: _plain("\n\n".join(["\n".join(rows.get(code, [])), *notes.get(code, [])]).strip())
            for code in sorted({*rows, *notes})}


def main() -> None:
    OUT.write_text(json.dumps(explanations(DOCS.read_text(encoding="utf-8")), indent=1, ensure_ascii=False) + "\n",
                   encoding="utf-8")
    print(f"wrote {OUT.relative_to(ROOT)}")


if __name__ == "__main__":
    main()
