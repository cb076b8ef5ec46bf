"""Sub names that mean something to the controller: it calls them, or an M code does."""
from __future__ import annotations

import re
from functools import lru_cache

from edingcnc_lang.machine.tables import TOOL_CHANGE_SUB

CONTROLLER_SUBS = frozenset(
    {TOOL_CHANGE_SUB, "home_all", "home_x", "home_y", "home_z", "home_a", "home_b", "home_c",
     "user_reset", "userreset", "start", "zhcmgrid", "zero_set_rotation", "xhc_probe_z"}
    | {f"user_{i}" for i in range(1, 51)}
    | {f"xhc_macro_{i}" for i in range(1, 10)}
)
_M_SUB = re.compile(r"m0*([1-9]\d{0,2})")


@lru_cache(maxsize=4096)  # asked for the sub of every call, and for every sub
def m_sub_number(name: str) -> int | None:
    """The M number a sub answers to (``Sub m100`` -> 100), or None for other names."""
    match = _M_SUB.fullmatch(name.lower())
    return int(match.group(1)) if match else None


def is_entry_point(name: str) -> bool:
    """True for subs the controller or an M code calls, which need no GoSub anywhere."""
    return name.lower() in CONTROLLER_SUBS or m_sub_number(name) is not None
