"""What ``ecnc plot`` and ``ecnc view`` do, as functions the CLI (and anyone else) calls.

Both run the job once through the embedding API and write one file; a run that stops with a
runtime error still gets its picture (the path as far as it went, the error in the title), and the
error is returned for the caller to report.
"""
from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path
from typing import Any

from edingcnc_lang.errors import EcncError, Location
from edingcnc_lang.outputs import check_outputs, ensure_parent
from edingcnc_lang.runner import RunOptions, input_files
from edingcnc_lang.picture_formats import picture_target
from edingcnc_lang.plot.lathe import in_work
from edingcnc_lang.plot.toolpath import Toolpath, record_job


@dataclass(frozen=True)
class Written:
    """The file written and the toolpath it shows (``path.error`` set when the run stopped early)."""

    out: Path
    path: Toolpath


def default_output(job: Path, suffix: str) -> Path:
    """``JOB.png`` (or ``.html``, ``-joints.png``) beside the job."""
    return job.with_name(job.stem + suffix)


def parse_line_range(text: str) -> tuple[int, int]:
    """``A:B``, ``A:`` or ``:B`` (job lines, both ends included) -> (first, last)."""
    first, colon, last = text.partition(":")
    try:
        low = int(first) if first.strip() else 1
        high = int(last) if last.strip() else 2**31 - 1
    except ValueError:
        raise ValueError(f"{text!r} is not a line range such as 120:480") from None
    if not colon or low < 1 or high < low:
        raise ValueError(f"{text!r} is not a line range such as 120:480 (first line 1 or more, not after the last)")
    return low, high


def _refuse_an_input(target: Path, jobs: list[Path | None], options: RunOptions) -> None:
    """UsageFailure when the picture would be written over a job or a file the run reads."""
    check_outputs({"-o": target}, [*jobs, *input_files(options)])


def plot_job(job: Path, options: RunOptions, out: Path | None = None, view: str = "auto", color: str = "tool",
             fit: str = "job", joints: bool = False, name: str | None = None) -> Written:
    """Run ``job`` and draw its toolpath (or with ``joints`` its joint positions over time) into ``out``;
    ``name`` is what messages and the title call the job (default its path)."""
    from edingcnc_lang.plot.render import plot_toolpath

    target = ensure_parent(out or default_output(job, "-joints.png" if joints else ".png"))
    _refuse_an_input(target, [job], options)
    fmt = picture_target(target)  # a wrong extension or a missing folder is told before the job runs
    path = record_job(job, options, samples=joints, name=name)
    if joints:
        from edingcnc_lang.plot.joints import plot_joints

        plot_joints(path, target, fmt)
    else:
        plot_toolpath(in_work(path), target, view=view, color=color, fit=fit, fmt=fmt)
    return Written(target, path)


def view_job(job: Path, options: RunOptions, out: Path | None = None, max_moves: int | None = None,
             lines: tuple[int, int] | None = None, view: str = "auto", name: str | None = None,
             old: Path | None = None, embed_sources: bool = False, changes: dict[str, Any] | None = None) -> Written:
    """Run ``job`` and write the viewer page for it (only the moves of job ``lines`` when given);
    with ``old`` (``ecnc view --diff OLD NEW``) that job is run too, drawn under NEW, and the page
    switches between them; ``changes`` (``diff.style.page_data``, made by the caller: plot does not
    import diff) colours the changed moves and lists them; ``embed_sources``: full paths and ecnc's
    own macro text in the page (viewer.view_data).

    ``auto`` opens a lathe job (no Y motion) in the lathe view and everything else in the iso view.
    """
    from edingcnc_lang.plot.views import auto_view
    from edingcnc_lang.plot.viewer import MAX_MOVES, write_view

    target = ensure_parent(out or default_output(job, ".html"))
    _refuse_an_input(target, [job, old], options)
    path = in_work(record_job(job, options, name=name))
    if lines is not None:
        path = path.select_lines(*lines)
        if not len(path):
            raise EcncError(f"lines {lines[0]} to {lines[1]} make no moves", Location(name or str(job)))
    if view == "auto":
        view = "lathe" if auto_view(path) == "lathe" else "iso"
    before = in_work(record_job(old, options)) if old is not None else None
    if before is not None and lines is not None:
        before = before.select_lines(*lines)
    write_view(path, target, max_moves or MAX_MOVES, view=view, old=before, embed_sources=embed_sources,
               changes=changes if lines is None else None)  # the changes number the whole jobs' moves
    return Written(target, path)
