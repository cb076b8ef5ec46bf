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
from collections.abc import Callable
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

        from edingcnc_lang.syntax.input_limits import MAX_GCODE_LINE, MAX_NUMBER_DIGITS

        non_plain_lines = partial(_CORE.non_plain_lines, MAX_GCODE_LINE, MAX_NUMBER_DIGITS)
    return non_plain_lines(chunk)


def _on_first_call(name: str, module: str) -> Callable[..., Any]:
    """A stand-in for ``name`` that picks it on its first call (``_pick``) and puts it in its place here, so
    ``speedups.<name>`` is then the chosen function itself and a Python reference loads only when used."""
    def first_call(*args: Any) -> Any:
        chosen = globals()[name] = _pick(name, module)
        return chosen(*args)

    first_call.__name__ = first_call.__qualname__ = name
    first_call.__doc__ = f"``{module.lstrip('.')}.{name}`` on the core that runs (see there)."
    return first_call


plain_moves = _on_first_call("plain_moves", ".machine.plain_runs")
trace_rows = _on_first_call("trace_rows", ".motion.sinks")
column_bounds = _on_first_call("column_bounds", ".motion.reach")
arc_frame_rows = _on_first_call("arc_frame_rows", ".kinematics.trajectory")


def compiled(name: str) -> Any:
    """The compiled function ``name``, or None on the Python core: for a caller whose Python reference is
    its own method (``machine.bulk.BulkPath._arc_of_words`` for ``plain_arc``)."""
    return None if _CORE is None else getattr(_CORE, name)
