"""Regenerate the reference part of docs/api.md from the package's docstrings and signatures.

Everything above the marker line is written by hand (the guide, the promise); everything below it
is this script's: each name of ``edingcnc_lang.__all__`` with its signature, docstring, fields and
public methods, then the vocabulary of events a run emits.  tests/api/test_api_docs.py fails when
the file and the code disagree; run this after changing a public docstring:

    python scripts/gen_api_docs.py
"""
from __future__ import annotations

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
    """The vocabulary of events, generated from their records (``edingcnc_lang.events``): per kind its
    class, its fields with their types, and what it means."""
    from dataclasses import fields

    from edingcnc_lang import events

    lines = ["## Events", "",
             "Every event is a frozen record of `edingcnc_lang.events`, a subclass of `Event` with `kind`, `path`",
             "and `line`; match them with `isinstance`. `event.data` is the payload as the `--events` file prints",
             "it (a field that is None is left out). The messages (`msg`, `warn`, `error`, `log`, `dialog`) also",
             "reach `RunResult.messages`.", "",
             "| kind | class | fields | what |", "|---|---|---|---|"]
    for kind, cls in sorted(events.EVENT_KINDS.items()):
        if cls.__module__ != events.__name__:  # a product's own events (a plot's), not the interpreter's
            continue
        shown = ", ".join(f"`{f.name}: {f.type}`".replace("|", "\\|") for f in fields(cls)[2:]
                          if f.name not in cls.internal)  # (a union's bar escaped: it would end the cell)
        what = _doc(cls).split("\n\n")[0].replace("\n", " ").replace("|", "\\|")
        lines.append(f"| `{kind}` | `{cls.__name__}` | {shown} | {what} |")
    return lines + [""]


def render(current: str) -> str:
    head = current.split(MARKER)[0].rstrip() + "\n\n" if MARKER in current else current.rstrip() + "\n\n"
    return head + MARKER + "\n\n" + reference()


def main() -> None:
    DOC.write_text(render(DOC.read_text(encoding="utf-8")), encoding="utf-8")
    print(f"wrote {DOC.relative_to(ROOT)}")


if __name__ == "__main__":
    main()
