"""The linter: finds mistakes in macro files and jobs without running them (``ecnc lint``)."""
from __future__ import annotations

from .driver import LintOptions, UnknownCode, lint_paths, parse_codes

__all__ = ["LintOptions", "UnknownCode", "lint_paths", "parse_codes"]
