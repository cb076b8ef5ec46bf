"""Which core runs the hot loops: the compiled one (``_speedups.c``, ``_lexer.c``) or the pure-Python reference.

The one place that chooses: ``ECNC_PURE_PYTHON`` is read here, once, at import, and each compiled
extension is loaded here or not at all.  The compiled core is optional: ``pip install`` builds it
when a C compiler is there and goes on without it when not.  It does exactly what the Python
functions do (the equivalence tests run both), and every caller picks its function the same way,
``speedups.compiled("name") or python_reference``: the check pass's scan
(``syntax.parser.non_plain_lines``), runs of plain ``G0``/``G1`` lines (``machine.plain_runs.plain_moves``),
trace rows (``motion.sinks.trace_rows``), the bounds of a batch (``motion.reach.column_bounds``), the arcs
of the bulk path (``machine.plain_arcs.plain_arcs``) and the frames of arcs
(``kinematics.trajectory.arc_frame`` and ``arc_frame_rows``, as doubles for ``motion.arc_table``), whether
a batch's arcs reach outside the limits (``motion.reach.arcs_beyond``), the planner's windows of moves
(``motion.planner.stage``, ``plan_window``), the runs of corners of cutter compensation
(``pipeline.comp_runs.comp_lines``); the macro line reader and the lint's walk
take ``LEXER`` (``syntax.fastparse``, ``lint.facts``).  ``ecnc --version`` says which core runs.
The 3-axis sim's sweep takes ``SWEEP`` (``_sweep.c``, ``sim.sweep``; not built on Python 3.10).

This module sits at the foundation: it imports nothing of the package but the extensions.
"""
from __future__ import annotations

import os
from typing import Any

PURE_ENV = "ECNC_PURE_PYTHON"
PURE = os.environ.get(PURE_ENV, "") not in ("", "0")  # the Python core asked for


def _load(name: str) -> Any:
    """The compiled extension ``name``, or None on the Python core or when it is not built."""
    if PURE:
        return None
    from importlib import import_module

    try:
        return import_module(f"edingcnc_lang.{name}")
    except ImportError:
        return None


SPEEDUPS: Any = _load("_speedups")  # the hot loops of runs, or None
LEXER: Any = _load("_lexer")        # the macro line reader and the lint's walk, or None
SWEEP: Any = _load("_sweep")        # the 3-axis sim's sweep into the height field, or None (Python 3.10)


def _core_name() -> str:
    """What ``ecnc --version`` reports: "compiled" when both extensions run, "python" when neither does,
    else which one is missing."""
    if SPEEDUPS is None:
        return "python"
    return "compiled" if LEXER is not None else "compiled (without _lexer)"


CORE = _core_name()


def compiled(name: str) -> Any:
    """The compiled function ``name`` of ``_speedups``, or None on the Python core (the caller's reference runs)."""
    return None if SPEEDUPS is None else getattr(SPEEDUPS, name)
