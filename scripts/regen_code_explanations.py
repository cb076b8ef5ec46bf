"""Regenerate edingcnc_lang/lint/explanations.json from docs/lint.md, docs/kinematics.md and docs/errors.md (``ecnc help CODE``).

docs/lint.md is where each lint code is explained for people, docs/kinematics.md each ``ecnc kins
check`` finding code (K101 ...); this script copies, per code, its
table row (what is wrong, an example) and the paragraphs that start with the code (with the lists
and code blocks that follow them) into package data, so an installed ``ecnc`` can explain a code
without the docs at hand.  Run it after editing either:

    python scripts/regen_code_explanations.py
"""
from __future__ import annotations

import json
import re
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
DOCS = ROOT / "docs" / "lint.md"
KINS_DOCS = ROOT / "docs" / "kinematics.md"
ERRORS_DOCS = ROOT / "docs" / "errors.md"  # the R codes of errors that stop a run
OUT = ROOT / "edingcnc_lang" / "lint" / "explanations.json"

CODE = r"[A-Z]\d{3}"
ROW = re.compile(rf"^\| ({CODE}) \| \w+ \| (.*?) \|(?: (.*?) \|)?$")
KINS_ROW = re.compile(r"^\| (K\d{3}) \| [\w ]+ \| (.*?) \|()$")  # code | check | what is wrong
STARTS_WITH_CODE = re.compile(rf"^\*{{0,2}}({CODE})\b")
STARTS_WITH_KINS_CODE = re.compile(r"^\*{0,2}(K\d{3})\b")


def _plain(text: str) -> str:
    """Markdown emphasis, links and code fences as plain terminal text."""
    text = re.sub(r"^```\w*$\n?", "", text, flags=re.MULTILINE).rstrip()
    text = re.sub(r"\*\*(.+?)\*\*", r"\1", text)
    return re.sub(r"\[(.+?)\]\((.+?)\)", r"\1 (\2)", text)


def explanations(markdown: str, row: re.Pattern[str] = ROW,
                 starts: re.Pattern[str] = STARTS_WITH_CODE) -> dict[str, str]:
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
                match = row.match(line.strip())
                if match:
                    code, what, example = match.groups()
                    shown = example if example and example != "see below" else None
                    rows[code] = [f"What is wrong: {what}."] + ([f"Example: {shown}"] if shown else [])
            continue
        if first.startswith("#"):
            owner = None
            continue
        match = starts.match(first)
        if match:
            owner = match.group(1)
        if owner is not None:
            notes.setdefault(owner, []).append(block.strip("\n"))
    return {code: _plain("\n\n".join(["\n".join(rows.get(code, [])), *notes.get(code, [])]).strip())
            for code in sorted({*rows, *notes})}


def all_explanations() -> dict[str, str]:
    """The lint codes from docs/lint.md, the kins check codes from docs/kinematics.md and the run
    error codes from docs/errors.md."""
    kins = explanations(KINS_DOCS.read_text(encoding="utf-8"), KINS_ROW, STARTS_WITH_KINS_CODE)
    runtime = explanations(ERRORS_DOCS.read_text(encoding="utf-8"))
    return dict(sorted({**explanations(DOCS.read_text(encoding="utf-8")), **kins, **runtime}.items()))


def main() -> None:
    OUT.write_text(json.dumps(all_explanations(), indent=1, ensure_ascii=False) + "\n", encoding="utf-8")
    print(f"wrote {OUT.relative_to(ROOT)}")


if __name__ == "__main__":
    main()
