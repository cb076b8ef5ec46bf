"""Every error a run can stop with has a stable code (codes.RUNTIME_CODES, docs/errors.md).

The machine's refusals are classified by their message (one row of patterns per code), so this
test reads every message the interpreter, the stages and the motion stage can raise, straight from
the source, and fails on one that only the catch-all R899 would take: a new message gets its row.
"""
from __future__ import annotations

import ast
import re
from pathlib import Path

import pytest

from edingcnc_lang import RunOptions, run_string
from edingcnc_lang.codes import RUNTIME_CODES, runtime_code
from edingcnc_lang.errors import EcncError, MachineError
from edingcnc_lang.lint.explain import explain

PACKAGE = Path(__file__).resolve().parents[2] / "edingcnc_lang"
RAISERS = {"fail", "MachineError", "_limit_error"}
WHERE = ("machine", "motion", "pipeline")


def _text(node: ast.expr) -> str | None:
    """A message as written, each ``{...}`` of an f-string standing for ``1``; None for a computed one."""
    if isinstance(node, ast.Constant) and isinstance(node.value, str):
        return node.value
    if isinstance(node, ast.JoinedStr):
        return "".join(str(v.value) if isinstance(v, ast.Constant) else "1" for v in node.values)
    if isinstance(node, ast.BinOp) and isinstance(node.op, ast.Add):
        left, right = _text(node.left), _text(node.right)
        return None if left is None or right is None else left + right
    return None


def _literal_letters(text: str) -> int:
    return sum(ch.isalpha() for ch in text.replace("1", ""))


def messages() -> list[tuple[str, str]]:
    """(where, message) of every literal message; one that is mostly made of other messages
    (``f"{usage} (got ...)"``, ``f"{name}: {problem}"``) is left out: its parts are read where they are written."""
    found = []
    for folder in WHERE:
        for path in sorted((PACKAGE / folder).rglob("*.py")):
            for node in ast.walk(ast.parse(path.read_text(encoding="utf-8"))):
                if isinstance(node, ast.Call) and node.args:
                    func = node.func
                    name = func.attr if isinstance(func, ast.Attribute) else getattr(func, "id", "")
                    text = _text(node.args[0]) if name in RAISERS else None
                    if text is not None and _literal_letters(text) >= 6:
                        found.append((f"{path.relative_to(PACKAGE)}:{node.lineno}", text))
    return found


def test_the_source_has_messages_to_check() -> None:
    assert len(messages()) > 100


@pytest.mark.parametrize(("where", "message"), messages(), ids=lambda v: v if ":" in v else None)
def test_every_message_the_machine_raises_has_a_code(where: str, message: str) -> None:
    assert runtime_code("runtime", message) != "R899", f"{where}: {message!r} needs a row in codes.RUNTIME_CODES"


def test_codes_are_unique_well_formed_and_explained() -> None:
    for code, row in RUNTIME_CODES.items():
        assert re.fullmatch(r"R8\d\d", code) and row.code == code
        text = explain(code)
        assert text.startswith(f"{code} (runtime): {row.summary}")
        assert "\n\n" in text, f"docs/errors.md has no paragraph for {code}"


@pytest.mark.parametrize(("job", "code"), [
    ("#1 = [1 / 0]", "R813"),
    ("GoSub nowhere", "R812"),
    ("#5001 = 3", "R815"),
    ("G1 X10", "R819"),
    ("errmsg \"stop here\"", "R800"),
    ("G0 X1\nG1 G0 X2", "R817"),
    ("T200 M6", "R821"),
])
def test_a_run_error_carries_its_code_in_python_and_json(job: str, code: str) -> None:
    with pytest.raises(EcncError) as info:
        run_string(job + "\nM30\n", RunOptions(plan=False))
    assert info.value.code == code
    assert info.value.to_json()["code"] == code


def test_the_call_chain_is_structured_frames_innermost_first() -> None:
    job = "GoSub outer\nM30\nSub outer\nGoSub inner\nEndSub\nSub inner\n#1 = [1 / 0]\nEndSub\n"
    with pytest.raises(MachineError) as info:
        run_string(job, RunOptions(plan=False))
    frames = info.value.frames
    assert [(f.sub, f.path, f.line) for f in frames] == [("inner", "<string>", 4), ("outer", "<string>", 1)]
    assert info.value.to_json()["frames"] == [{"sub": "inner", "file": "<string>", "line": 4},
                                              {"sub": "outer", "file": "<string>", "line": 1}]
