"""A change at the start, in the middle and at the end of a long job (3,000 moves of zigzag passes at
five depths, as CAM writes a roughing): each is one entry at its own lines, and nothing else, wherever
it sits.  The JSON of each comparison is a golden file in ``cases/long`` (``--regen-goldens``)."""
from __future__ import annotations

import json
from pathlib import Path

import pytest

from edingcnc_lang.diff import diff_files

LONG = Path(__file__).resolve().parent / "cases" / "long"


def job() -> list[str]:
    lines = ["G90 G94 G17 G21", "G54", "T1 M06", "S10000 M03", "G00 Z10.000"]
    for layer in range(5):
        z = -1.0 - layer
        lines += ["G00 X0.000 Y0.000", "G00 Z2.000", f"G01 Z{z:.3f} F300."]
        for k in range(300):
            y = 0.5 * k
            lines += [f"G01 X{60.0 if k % 2 == 0 else 0.0:.3f} Y{y:.3f} F1500.", f"G01 Y{y + 0.5:.3f}"]
        lines.append("G00 Z10.000")
    return lines + ["M05", "G00 X0.000 Y0.000", "M30"]


def edited(where: str) -> tuple[list[str], tuple[int, int]]:
    """The job with one edit, and the NEW lines it touches."""
    lines = job()
    if where == "start":  # the first cut of the first layer at another feed
        at = lines.index("G01 X60.000 Y0.000 F1500.")
        lines[at] = "G01 X60.000 Y0.000 F1200."
        lines[at + 1] += " F1500."
        return lines, (at + 1, at + 1)
    if where == "middle":  # a move inserted half way: a step 0.2 mm out and back
        at = len(lines) // 2
        while not lines[at].startswith("G01 X60.000"):
            at += 1
        y = float(lines[at].split("Y")[1].split()[0])
        lines[at + 1:at + 1] = [f"G01 X60.200 Y{y:.3f}", f"G01 X60.000 Y{y:.3f}"]
        return lines, (at + 2, at + 3)
    at = len(lines) - 10  # the end: one pass of the last layer left out
    del lines[at:at + 2]
    return lines, (at, at + 1)


@pytest.mark.parametrize("where", ["start", "middle", "end"])
def test_one_change_is_one_entry_wherever_it_is(where: str, tmp_path: Path, golden) -> None:
    old, new = tmp_path / "old.nc", tmp_path / "new.nc"
    old.write_text("\n".join(job()) + "\n", encoding="ascii")
    lines, (first, last) = edited(where)
    new.write_text("\n".join(lines) + "\n", encoding="ascii")
    doc = diff_files(old, new).to_json()
    golden(LONG / f"{where}.json", json.dumps(doc, indent=1) + "\n")
    found = [c for name in ("deviations", "feeds", "spindle", "rapids") for c in doc[name]] + doc["tools"]["moves"]
    assert len(found) == 1, found
    [change] = found
    lines_of = change.get("new_lines", [change["new_line"]] * 2)
    if where == "end":  # a pass removed: OLD's lines, beside where NEW goes on
        assert change["what"] in ("removed", "replaced") and change["old_line"] >= first - 1
    else:
        assert first <= lines_of[0] and lines_of[1] <= last + 1, change
    assert doc["moves"]["old"] > 3000
