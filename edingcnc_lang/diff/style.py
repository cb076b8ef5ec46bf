"""One colour per kind of change, shared by the picture (``picture.py``) and the page of ``ecnc view
--diff`` (``plot/viewer.py``): what a change is called in the legend and how it is drawn."""
from __future__ import annotations

from typing import Any

from edingcnc_lang.diff.compare import Change, Comparison

OLD_COLOR = "#cfcfcf"        # OLD's path where it is unchanged
SAME_COLOR = "#8f8f8f"       # NEW's path where it is unchanged
# kind of change -> colour, legend label
KINDS = {
    "added": ("#d62728", "only in NEW"),
    "removed": ("#ff7f0e", "only in OLD"),
    "replaced": ("#8c564b", "replaced (another way)"),
    "moved": ("#bcbd22", "moved (within 1 mm)"),
    "shifted": ("#1f77b4", "feature moved"),
    "depth": ("#17becf", "depth changed"),
    "reordered": ("#2ca02c", "at another place in the order"),
    "reversed": ("#000080", "driven the other way"),
    "value": ("#9467bd", "feed, speed or tool changed"),
    "rapid": ("#e377c2", "rapid lower than OLD's / into the stock"),
}
VALUES = ("feed", "spindle", "tool")
RAPIDS = ("rapid", "rapid_into_stock")


def kind_of(change: Change) -> str:
    """The colour key of ``change``."""
    if change.what in VALUES:
        return "value"
    if change.what in RAPIDS:
        return "rapid"
    return change.what if change.what in KINDS else "value"


def drawn(comparison: Comparison) -> list[Change]:
    """The changes that have moves to draw, in NEW's order."""
    names = ("deviations", "feeds", "spindle", "tool_moves", "rapids")
    found = [c for name in names for c in comparison.changes[name] if c.new_moves or c.old_moves]
    return sorted(found, key=lambda c: c.new_moves[0] if c.new_moves else (c.old_moves[0] if c.old_moves else 0))


def page_data(comparison: Comparison) -> dict[str, Any]:
    """The changes for the page of ``ecnc view --diff``: each with its text, colour and moves (indices
    into NEW's and OLD's moves), and the legend."""
    from edingcnc_lang.diff.report import headline

    changes = []
    for change in drawn(comparison):
        key = kind_of(change)
        changes.append({"what": change.what, "kind": key, "color": KINDS[key][0],
                        "text": headline(change, comparison.tolerance),
                        "new": list(change.new_moves) if change.new_moves and change.what != "removed" else None,
                        "at": change.new_moves[0] if change.new_moves else None,
                        "old": list(change.old_moves) if change.old_moves else None})
    return {"changes": changes, "kinds": {k: list(v) for k, v in KINDS.items()}, "same": comparison.same,
            "oldColor": OLD_COLOR, "sameColor": SAME_COLOR}
