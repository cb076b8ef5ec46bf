"""Which core runs the hot loops: the compiled one (``_speedups.c``) or the pure-Python reference.

The compiled core is optional: ``pip install`` builds it when a C compiler is there and goes on
without it when not.  It does exactly what the Python functions do (the equivalence tests run
both): finding the lines that are not plain word lines in the check pass
(``syntax.parser.non_plain_lines``), turning runs of plain ``G0``/``G1`` lines into targets
(``machine.plain_runs.plain_moves``), formatting trace rows (``motion.sinks.trace_rows``), byte for byte,
the bounds of a batch's end points for the limit check (``motion.reach.column_bounds``), the arcs with
centre words or R of the bulk path (``machine.bulk.BulkPath._arc_of_words``) and the frames of a batch's arcs
(``kinematics.trajectory.arc_frame_rows``).  ``ECNC_PURE_PYTHON=1``
selects the Python core at run time; ``ecnc --version`` says which one runs.
"""
from __future__ import annotations

import os
from typing import Any

PURE_ENV = "ECNC_PURE_PYTHON"


def _compiled() -> Any:
    if os.environ.get(PURE_ENV, "") not in ("", "0"):
        return None
    try:
        from edingcnc_lang import _speedups  # type: ignore[attr-defined]
    except ImportError:
        return None
    return _speedups


def _core_name(core: Any) -> str:
    """What ``ecnc --version`` reports: "compiled" when both extensions are built (``_speedups``, and
    ``_lexer`` for the macro line reader), "python" when neither runs, else which one is missing."""
    if core is None:
        return "python"
    try:  # the parser loads it anyway
        from edingcnc_lang import _lexer  # type: ignore[attr-defined]  # noqa: F401
    except ImportError:
        return "compiled (without _lexer)"
    return "compiled"


_CORE = _compiled()
CORE = _core_name(_CORE)


def _pick(name: str, module: str) -> Any:
    """The compiled function ``name`` if that core runs, else the Python one from ``module``."""
    if _CORE is not None:
        return getattr(_CORE, name)
    from importlib import import_module

    return getattr(import_module(module, __package__), name)


def non_plain_lines(chunk: list[str]) -> list[int]:
    """``parser.non_plain_lines`` on the core that runs (see there)."""
    global non_plain_lines
    if _CORE is None:
        non_plain_lines = _pick("non_plain_lines", ".syntax.parser")
    else:
        from functools import partial

        from edingcnc_lang.syntax.input_limits import MAX_LINE_LENGTH, MAX_NUMBER_DIGITS

        non_plain_lines = partial(_CORE.non_plain_lines, MAX_LINE_LENGTH, MAX_NUMBER_DIGITS)
    return non_plain_lines(chunk)


def plain_moves(*args: Any) -> Any:
    """``machine.plain_runs.plain_moves`` on the core that runs (see there)."""
    global plain_moves
    plain_moves = _pick("plain_moves", ".machine.plain_runs")
    return plain_moves(*args)


def trace_rows(*args: Any) -> Any:
    """``motion.sinks.trace_rows`` on the core that runs (see there)."""
    global trace_rows
    trace_rows = _pick("trace_rows", ".motion.sinks")
    return trace_rows(*args)


def column_bounds(*args: Any) -> Any:
    """``motion.reach.column_bounds`` on the core that runs (see there)."""
    global column_bounds
    column_bounds = _pick("column_bounds", ".motion.reach")
    return column_bounds(*args)


def arc_frame_rows(*args: Any) -> Any:
    """``kinematics.trajectory.arc_frame_rows`` on the core that runs (see there)."""
    global arc_frame_rows
    arc_frame_rows = _pick("arc_frame_rows", ".kinematics.trajectory")
    return arc_frame_rows(*args)


def compiled(name: str) -> Any:
    """The compiled function ``name``, or None on the Python core: for a caller whose Python reference is
    its own method (``machine.bulk.BulkPath._arc_of_words`` for ``plain_arc``)."""
    return None if _CORE is None else getattr(_CORE, name)
