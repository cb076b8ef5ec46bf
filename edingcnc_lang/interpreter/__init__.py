"""The interpreter: executes statements against a virtual machine state.

It evaluates expressions, keeps the modal state, offsets, tools and parameters, runs subs and
control flow, and emits every move and event to a ``Canon``.  It knows nothing of kinematics,
traces or files written: those sit behind the canon.  One Interpreter is one machine; there is
no global state.  See ``machine.py`` for the parts and the order to read them in.
"""
from __future__ import annotations

from .machine import Interpreter


__all__ = ["Interpreter"]
