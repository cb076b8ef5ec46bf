"""Linting many files on several processes (``ecnc lint -j N``).

The files are split into groups of neighbours (sorted paths, so a folder's files stay together)
and each group is linted as a project of its own in a worker process, with its macro files and
every ``.ini`` given; the findings are merged, sorted and de-duplicated as ``lint_paths`` does.
Facts that join different files of one project (a variable written in one file and read in
another, a sub called from another job) are therefore seen within a group; each job still sees
its own macro files.  ``jobs=1`` is ``lint_paths`` itself: one project, one process.
"""
from __future__ import annotations

import os
from collections.abc import Iterable, Sequence
from dataclasses import replace

from edingcnc_lang.diagnostics import Diagnostic
from edingcnc_lang.gcpause import whole_trees
from edingcnc_lang.lint.driver import CONFIG_SUFFIX, LintOptions, Reader, expand, lint_paths
from edingcnc_lang.lint.model import stream_source
from edingcnc_lang.lint.targets import resolve

GROUPS_PER_JOB = 4  # more groups than workers, so a slow group does not leave the others idle


def lint_paths_parallel(paths: Iterable[str | os.PathLike[str]], options: LintOptions = LintOptions(),
                        jobs: int = 1, reader: Reader = stream_source,
                        kept: list[object] | None = None) -> list[Diagnostic]:
    """``lint_paths`` on ``jobs`` processes; the same findings for files that do not share facts.

    ``reader`` and ``kept`` as ``lint_paths`` when the files are checked in this process."""
    given = list(paths)
    files = expand(given)
    configs = [str(p) for p in files if p.suffix.lower() == CONFIG_SUFFIX]
    sources = sorted(str(p) for p in files if p.suffix.lower() != CONFIG_SUFFIX)
    if jobs <= 1 or len(sources) < 2 or not all(os.access(p, os.R_OK) for p in sources):
        return lint_paths(given, options, reader, kept)  # (an unreadable file is reported from here, with its path)
    # imported here: multiprocessing costs a one-process lint ~40 ms of start-up
    from concurrent.futures import ProcessPoolExecutor
    from multiprocessing import get_context

    groups = split(sources, min(len(sources), jobs * GROUPS_PER_JOB))
    # one controller version for every group: the one the whole command line resolves to
    options = replace(options, target=resolve(options.target, [os.fspath(p) for p in given],
                                              options.ini or (configs[0] if configs else None)))
    # spawn, not fork: the same on every platform, and safe beside the CLI's progress thread
    with ProcessPoolExecutor(max_workers=jobs, mp_context=get_context("spawn")) as pool:
        found = [d for part in pool.map(_lint_group, [[*group, *configs] for group in groups],
                                        [options] * len(groups)) for d in part]
    unique = {(d.path, d.line, d.col, d.code, d.message): d for d in found}
    return [unique[key] for key in sorted(unique)]


def _lint_group(paths: list[str], options: LintOptions) -> list[Diagnostic]:
    """One group, in a worker; the cyclic GC is paused as the CLI pauses it (the trees are acyclic)."""
    with whole_trees():
        return lint_paths(paths, options)


def split(items: Sequence[str], count: int) -> list[list[str]]:
    """``items`` in ``count`` contiguous groups of near equal size."""
    size, extra = divmod(len(items), count)
    groups, start = [], 0
    for index in range(count):
        end = start + size + (1 if index < extra else 0)
        groups.append(list(items[start:end]))
        start = end
    return [g for g in groups if g]

