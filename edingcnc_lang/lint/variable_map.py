"""The variable map of a set of files (``ecnc vars``): the linter's project, its uses and names,
and the findings of the variable rules, from one read of the files."""
from __future__ import annotations

import os
from collections.abc import Iterable

from edingcnc_lang.lint.driver import LintOptions, lint_paths
from edingcnc_lang.lint.model import load_source
from edingcnc_lang.lint.project import Project
from edingcnc_lang.lint.rules_names import uses_of
from edingcnc_lang.varmap.model import VarMap, assemble

# The findings the map shows: the variable rules (V300/V303/V304 are about expressions, not meanings).
VARIABLE_CODES = ("V301", "V302", "V305", "V306", "V307", "V308")


def variable_map(paths: Iterable[str | os.PathLike[str]], macro: str | None = None,
                 user_macro: str | None = None) -> VarMap:
    """Every variable the files under ``paths`` (and their macro files) use."""
    kept: list[object] = []
    findings = lint_paths(paths, LintOptions(macro, user_macro, select=VARIABLE_CODES), reader=load_source,
                          kept=kept)
    project = next(item for item in kept if isinstance(item, Project))
    uses = uses_of(project)
    return assemble(project.names, uses.writers, uses.readers, findings)
