"""``ecnc diff OLD NEW``: what the machine does differently, not what the text says differently.

``diff_files`` runs both jobs (``record``), aligns their paths by geometry (``align``), compares
moves, values and events (``compare``); ``report`` writes the text, ``picture`` the drawing.
See docs/diff.md.
"""
from __future__ import annotations

from collections.abc import Callable
from pathlib import Path
from typing import TYPE_CHECKING

from edingcnc_lang.runner import RunOptions
from edingcnc_lang.diff.compare import LIMIT, TOLERANCE, Change, Comparison, compare
from edingcnc_lang.diff.record import Recording, record

if TYPE_CHECKING:
    from edingcnc_lang.diff.part import Cut

__all__ = ["Change", "Comparison", "Recording", "compare", "diff_files", "record"]


def diff_files(old: str | Path, new: str | Path, options: RunOptions | None = None,
               new_options: RunOptions | None = None, tolerance: float = TOLERANCE, limit: int = LIMIT,
               cut: Callable[[Path, RunOptions], Cut] | None = None,
               names: tuple[str | None, str | None] = (None, None)) -> Comparison:
    """Run ``old`` and ``new`` (``new_options``, default ``options``: where the machine itself
    changed) and compare what the machine does; with ``cut`` (a job and its options -> the stock it
    cut, as ``sim.simulate`` gives it) compare the parts too; ``names``: what the report calls the jobs
    (default their paths: a pipe's copy is named as the user gave it).  Run errors are raised as
    ``run_file`` raises them."""
    options = options or RunOptions()
    before = record(Path(old), options, names[0])
    after = record(Path(new), new_options or options, names[1])
    comparison = compare(before, after, tolerance, limit)
    if cut is not None:
        from edingcnc_lang.diff.part import compare_parts

        parts = cut(Path(old), options), cut(Path(new), new_options or options)
        comparison.add_part(compare_parts(*parts, before, after, tolerance))
    return comparison
