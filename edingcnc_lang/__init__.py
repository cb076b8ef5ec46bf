"""edingcnc-lang: parser, interpreter, linter and kinematics simulator for EdingCNC G-code and macros."""
from __future__ import annotations

__version__ = "0.1.0"
