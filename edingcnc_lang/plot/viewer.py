"""``ecnc view``: one self-contained HTML file with an interactive 3D view of the toolpath.

The page (``viewer.html``, ``viewer.css``, ``viewer.js`` beside this module, written for the
browser's own canvas API) is filled in with the job's data as JSON: point coordinates and the
per-move columns as little-endian base64 typed arrays, so a 10,000-move job stays well under a
megabyte.  Nothing is fetched when the page is opened.  A job with more moves than the budget is
thinned (``decimate``) and the page says so; ``select_lines`` on the toolpath (``--lines A:B``)
shows any stretch of it in full.
"""
from __future__ import annotations

import base64
import html
import json
import math
import os
import re
from collections.abc import Sequence
from dataclasses import dataclass
from importlib import resources
from pathlib import Path
from typing import Any

import numpy as np

from edingcnc_lang.plot import views as v
from edingcnc_lang.plot.toolpath import KINDS, RAPID_KINDS, Toolpath
from edingcnc_lang.outputs import write_text

MAX_MOVES = 25_000                  # moves in the page before it is thinned
VIEW_ARC_STEP = math.radians(6.0)   # 60 chords a turn: finer than a screen shows at a whole-job zoom
ASSETS = ("viewer.html", "viewer.css", "viewer.js")


@dataclass(frozen=True)
class Thinned:
    """Which moves the page shows: ``keep`` indices, and how many moves each stands for."""

    keep: np.ndarray
    count: np.ndarray


def decimate(path: Toolpath, max_moves: int) -> Thinned:
    """Keep every move when there are at most ``max_moves``; otherwise every k-th move of each run
    of feed moves with one tool, plus every rapid and the last move of every run, so the shape and
    the tool changes stay and the long runs of short cuts are what is merged."""
    count = len(path)
    if count <= max_moves:
        return Thinned(np.arange(count), np.ones(count, dtype=np.int64))
    rapid = np.isin(path.kinds, list(RAPID_KINDS))
    last = np.ones(count, dtype=bool)
    last[:-1] = (rapid[1:] != rapid[:-1]) | (path.tools[1:] != path.tools[:-1]) | rapid[:-1]
    forced = int(last.sum())
    stride = max(1, math.ceil((count - forced) / max(max_moves - forced, 1)))
    keep = np.flatnonzero(last | (np.arange(count) % stride == stride - 1))
    merged = np.diff(np.concatenate(([-1], keep)))
    return Thinned(keep, merged)


def _b64(array: np.ndarray, dtype: str) -> str:
    return base64.b64encode(np.ascontiguousarray(array, dtype=np.dtype(dtype).newbyteorder("<")).tobytes()).decode()


def view_data(path: Toolpath, max_moves: int = MAX_MOVES, view: str = "iso",
              embed_sources: bool = False) -> dict[str, Any]:
    """Everything the page shows, as JSON-ready values; ``view`` is the one the page opens with.

    A page gets shared: unless ``embed_sources``, files are named as ``_shown_names`` says (no
    absolute path of this computer) and the text of ecnc's own macro files is left out."""
    thinned = decimate(path, max_moves)
    points: list[np.ndarray] = []
    first = np.zeros(len(thinned.keep), dtype=np.int64)
    last = np.zeros(len(thinned.keep), dtype=np.int64)
    size = 0
    previous_end: np.ndarray | None = None
    for row, (index, merged) in enumerate(zip(thinned.keep.tolist(), thinned.count.tolist())):
        start = path.starts[index - merged + 1, :3]
        if merged == 1 and index in path.arcs:
            move = path.move_points(index, VIEW_ARC_STEP)
        else:
            move = np.vstack((start, path.ends[index, :3]))
        if previous_end is not None and np.allclose(previous_end, move[0], atol=1e-9):
            move = move[1:]
            first[row] = size - 1
        else:
            first[row] = size
        points.append(move)
        size += len(move)
        last[row] = size - 1
        previous_end = move[-1]
    keep = thinned.keep
    names = {p: p for p in path.paths} if embed_sources else _shown_names(path.paths)

    def hidden(text: str) -> str:
        for real in sorted(names, key=len, reverse=True):
            text = text.replace(real, names[real])
        return text

    sources = path.source_lines(keep, context=3 if len(keep) == len(path) else 0)
    bounds = path.bounds()
    abc = path.ends[keep, 3:]
    data: dict[str, Any] = {
        "job": names.get(path.job) or hidden(path.job), "title": hidden(v.title_text(path)), "moves": len(path), "shown": len(keep),
        "maxMoves": max_moves, "view": view, "kinds": list(KINDS), "rapidKinds": sorted(RAPID_KINDS),
        "files": [names[p] for p in path.paths], "toolColors": list(v.TOOL_COLORS), "kindColors": v.KIND_COLORS,
        "tools": v.feed_tools(path),
        # a lathe's part in work coordinates: the readout shows X as the program does (a diameter)
        "xDiameter": path.part and path.x_diameter,
        "points": _b64(np.vstack(points) if points else np.zeros((0, 3)), "f4"),
        "first": _b64(first, "i4"), "last": _b64(last, "i4"),
        "kind": _b64(path.kinds[keep], "u1"), "tool": _b64(path.tools[keep], "i4"),
        "line": _b64(path.lines[keep], "i4"), "file": _b64(path.files[keep], "u2"),
        "feed": _b64(path.feeds[keep], "f4"), "merged": _b64(thinned.count, "i4"),
        "time": _b64(path.times[keep, 1], "f4"), "speed": _b64(path.speeds[keep], "f4"),
        "abc": _b64(abc, "f4") if np.any(abc) else None,
        "joints": _b64(path.joints[keep], "f4") if path.kinematics.lower() not in ("trivial", "") else None,
        "jointRows": _moving_joints(path), "kinematics": path.kinematics,
        "workZero": list(path.work_zero),
        "part": [bounds[0].tolist(), bounds[1].tolist()] if bounds is not None else None,
        "limits": [path.limits[0].tolist(), path.limits[1].tolist()] if path.limits is not None else None,
        "source": {names[name]: {str(k): text for k, text in lines.items()}
                   for name, lines in sources.items() if embed_sources or not _packaged(name)},
        "error": hidden(path.error.format()) if path.error is not None else None,
        "seconds": path.seconds,
    }
    return data


def _packaged(name: str) -> bool:
    """A file that comes with ecnc (its stock macro.cnc): the same for everyone, so not put in a page."""
    package = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
    try:
        return os.path.isabs(name) and os.path.commonpath([os.path.abspath(name), package]) == package
    except ValueError:  # another drive
        return False


def _shown_names(paths: Sequence[str]) -> dict[str, str]:
    """Each file as a shared page names it: ecnc's own as ``ecnc/stdlib/...``, one below the current
    folder relative to it, any other absolute path by its name alone (a second file of that name
    gets `` (2)``); names that were not absolute stay as given."""
    package = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
    names: dict[str, str] = {}
    for real in paths:
        name = real
        if os.path.isabs(real):
            if _packaged(real):
                name = "ecnc/" + os.path.relpath(real, package).replace(os.sep, "/")
            else:
                try:
                    relative = os.path.relpath(real)
                except ValueError:
                    relative = ".."
                name = relative.replace(os.sep, "/") if not relative.startswith("..") else os.path.basename(real)
        taken, count = set(names.values()), 1
        base = name
        while name in taken:
            count += 1
            name = f"{base} ({count})"
        names[real] = name
    return names


def _moving_joints(path: Toolpath) -> list[tuple[int, str]]:
    """(index, name) of the joints the readout shows: those that move in the job."""
    if not len(path):
        return []
    moving = np.ptp(path.joints, axis=0) > 1e-9
    return [(k, name) for k, name in enumerate(path.joint_names[:6]) if moving[k]]


def page(path: Toolpath, max_moves: int = MAX_MOVES, view: str = "iso", old: Toolpath | None = None,
         embed_sources: bool = False, changes: dict[str, Any] | None = None) -> str:
    """The whole HTML page for ``path``; with ``old`` (``ecnc view --diff OLD NEW``) the page holds
    both jobs, draws OLD under NEW, and a button switches between them; ``changes`` (``diff.style.page_data``)
    colours the changed moves and lists the changes, each a link to its place; ``embed_sources`` as view_data."""
    folder = resources.files(__package__)
    template, css, script = (folder.joinpath(name).read_text(encoding="utf-8") for name in ASSETS)
    payload = _payload(path, max_moves, view, embed_sources)
    other = "" if old is None else \
        f'<script type="application/json" id="job-data-old">{_payload(old, max_moves, view, embed_sources)}</script>'
    if old is not None and changes is not None:
        other += f'<script type="application/json" id="diff-data">{_safe(changes)}</script>'
    name = path.job.replace("\\", "/").rsplit("/", 1)[-1]
    parts = {"title": html.escape(f"{name} \u2014 ecnc view"), "css": css, "script": script, "other": other,
             "data": payload}
    # one pass over the template: a job named {{data}}.nc keeps its name in the title, not the payload
    return _PLACE.sub(lambda found: parts[found[1]], template)


_PLACE = re.compile(r"\{\{(title|css|script|other|data)\}\}")


def _payload(path: Toolpath, max_moves: int, view: str, embed_sources: bool) -> str:
    return _safe(view_data(path, max_moves, view, embed_sources))


def _safe(data: dict[str, Any]) -> str:
    payload = json.dumps(data, separators=(",", ":"), allow_nan=False)
    # a job line with "</script>" must not end the block, nor one with "{{data}}" take the page's place
    return payload.replace("</", "<\\/").replace("{{", "{\\u007b")


def write_view(path: Toolpath, out: Path, max_moves: int = MAX_MOVES, view: str = "iso",
               old: Toolpath | None = None, embed_sources: bool = False,
               changes: dict[str, Any] | None = None) -> Path:
    """Write the viewer page for ``path`` (and ``old``, to compare with, and its ``changes``) to ``out``."""
    write_text(out, page(path, max_moves, view, old, embed_sources, changes))
    return out
