"""Regenerate the reference part of docs/api.md from the package's docstrings and signatures.

Everything above the marker line is written by hand (the guide, the promise); everything below it
is this script's: each name of ``edingcnc_lang.__all__`` with its signature, docstring, fields and
public methods, then the vocabulary of events a run emits.  tests/api/test_api_docs.py fails when
the file and the code disagree; run this after changing a public docstring:

    python scripts/gen_api_docs.py
"""
from __future__ import annotations

import ast
import dataclasses
import inspect
import re
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
DOC = ROOT / "docs" / "api.md"
MARKER = "<!-- reference: generated below by scripts/gen_api_docs.py from the docstrings; do not edit below -->"
# type aliases have no docstring of their own
ALIASES = {
    "Pose": "Six floats: x y z a b c (mm and degrees), or the joints jx .. jc.",
    "Stmt": "Any statement node of the syntax tree (a union of the statement classes of ``syntax.nodes``).",
}


def _doc(obj: object) -> str:
    return inspect.cleandoc(obj.__doc__ or "") if getattr(obj, "__doc__", None) else ""


def _signature(obj: object) -> str:
    try:
        text = str(inspect.signature(obj))  # type: ignore[arg-type]
    except (TypeError, ValueError):
        return ""
    return re.sub(r"<function (\w+) at 0x[0-9a-f]+>", r"\1", re.sub(r" at 0x[0-9a-f]+", "", text))


def _members(cls: type) -> list[str]:
    lines: list[str] = []
    if dataclasses.is_dataclass(cls):
        for f in dataclasses.fields(cls):
            if f.name.startswith("_"):
                continue
            shown = f.type if isinstance(f.type, str) else getattr(f.type, "__name__", str(f.type))
            if shown == "PathOption":  # RunOptions' file names (a descriptor)
                shown = "Path | None  (set as str or any path-like)"
            lines.append(f"- `{f.name}`: `{shown}`")
    for name, member in sorted(vars(cls).items()):
        if name.startswith("_") or not (inspect.isfunction(member) or isinstance(member, (property, classmethod))):
            continue
        target = member.fget if isinstance(member, property) else getattr(member, "__func__", member)
        doc = _doc(target).split("\n\n")[0].replace("\n", " ")
        head = f"`{name}`" if isinstance(member, property) else f"`{name}{_signature(target)}`"
        lines.append(f"- {head}: {doc}" if doc else f"- {head}")
    return lines


def reference() -> str:
    sys.path.insert(0, str(ROOT))
    import edingcnc_lang

    out = ["## Reference", ""]
    for name in edingcnc_lang.__all__:
        value = getattr(edingcnc_lang, name)
        out.append(f"### `{name}`")
        out.append("")
        if name in ALIASES:
            out += [ALIASES[name], ""]
            continue
        kind = "class" if inspect.isclass(value) else "function"
        module = getattr(value, "__module__", "")
        out.append(f"*{kind}, from `{module}`*" + (f": `{name}{_signature(value)}`" if kind == "function" else ""))
        out.append("")
        out.append(_doc(value))
        out.append("")
        if inspect.isclass(value) and not issubclass(value, BaseException):
            members = _members(value)
            if members:
                out += members + [""]
    out += events()
    return "\n".join(out).rstrip() + "\n"


def events() -> list[str]:
    """The kinds of ``Event`` the interpreter emits and the keys of their data, read from the source."""
    found: dict[str, set[str]] = {}
    for path in sorted((ROOT / "edingcnc_lang" / "machine").glob("*.py")):
        for node in ast.walk(ast.parse(path.read_text(encoding="utf-8"))):
            if not (isinstance(node, ast.Call) and getattr(node.func, "id", "") == "Event" and node.args):
                continue
            kind = node.args[0]
            if isinstance(kind, ast.Constant) and isinstance(kind.value, str):
                keys = found.setdefault(kind.value, set())
                data = node.args[3] if len(node.args) > 3 else None
                if isinstance(data, ast.Dict):
                    keys.update(k.value for k in data.keys if isinstance(k, ast.Constant) and isinstance(k.value, str))
    lines = ["## Events", "",
             "Every `Event` has `kind`, `path`, `line` and `data`; the kinds the interpreter emits and the keys of",
             "their `data` (messages and dialogs: `msg`, `warn`, `error`, `log`, `dialog`, each with `text`, also",
             "reach `RunResult.messages`):", "",
             "| kind | data keys |", "|---|---|"]
    for kind in sorted(found):
        lines.append(f"| `{kind}` | {', '.join(f'`{k}`' for k in sorted(found[kind])) or '(see the code)'} |")
    return lines + [""]


def render(current: str) -> str:
    head = current.split(MARKER)[0].rstrip() + "\n\n" if MARKER in current else current.rstrip() + "\n\n"
    return head + MARKER + "\n\n" + reference()


def main() -> None:
    DOC.write_text(render(DOC.read_text(encoding="utf-8")), encoding="utf-8")
    print(f"wrote {DOC.relative_to(ROOT)}")


if __name__ == "__main__":
    main()
