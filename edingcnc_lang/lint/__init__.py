"""The linter: finds mistakes in macro files and jobs without running them (``ecnc lint``)."""
from __future__ import annotations

from edingcnc_lang.lint.driver import LintOptions, UnknownCode, lint_paths, parse_codes
from edingcnc_lang.lint.parallel import lint_paths_parallel

__all__ = ["LintOptions", "UnknownCode", "lint_paths", "lint_paths_parallel", "parse_codes"]
