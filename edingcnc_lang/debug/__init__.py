"""``ecnc debug``: a step debugger for jobs and macro files over the Debug Adapter Protocol.

A thin protocol layer (``adapter``) over the run's own stepping (``session``), as debugpy is over
pydevd.  The interpreter runs in a worker thread; the ``Observer`` seam (machine/observe.py)
blocks it while the user looks around.  Modules, one job each:

- ``protocol``: Content-Length framing of DAP messages on a byte stream, and its limits
- ``arguments``: every request's arguments checked (types, ranges, lengths) before it acts
- ``launch``: the launch request's arguments
- ``breakpoints``: source and function breakpoints, verification, conditions, hit counts, log points
- ``expressions``: the dialect's expressions for conditions, evaluate, setVariable and console answers
- ``variables``: the stack and the scopes a user thinks in, and where each parameter was last written
- ``history``: what stepping back needs (the operator's inputs), re-execution targets
- ``session``: run control (breakpoints, stepping, pause, stepBack) in the worker thread
- ``adapter``: DAP requests and events

See docs/debugging.md.
"""
from __future__ import annotations

from edingcnc_lang.debug.adapter import serve

__all__ = ["serve"]
