"""Alignment by geometry: the same path written another way is the same; inserted and removed moves
differ at their own lines only, whatever their number."""
from __future__ import annotations

import math
from pathlib import Path

import pytest

from edingcnc_lang.diff import diff_files

HEAD = "G21 G90 G17 G54\nT1 M6\nS10000 M3\nG0 X0 Y0 Z5\nG1 Z-1 F500\n"
PASSES = "".join(f"G1 X{40 * (k % 2)} Y{2 * k} F800\nG1 Y{2 * k + 2}\n" for k in range(20))
TAIL = "G0 Z5\nM30\n"


def write(folder: Path, name: str, text: str) -> Path:
    path = folder / name
    path.write_text(text, encoding="ascii")
    return path


def line_of(path: Path, text: str) -> int:
    return next(i for i, line in enumerate(path.read_text().splitlines(), start=1) if line == text)


def arc_as_lines(degrees: float) -> str:
    """A half circle of radius 10 about (10, 0) from (0, 0) to (20, 0), clockwise, as straight lines."""
    steps = round(180 / degrees)
    points = [(10 - 10 * math.cos(math.radians(k * degrees)), 10 * math.sin(math.radians(k * degrees)))
              for k in range(1, steps + 1)]
    return "".join(f"G1 X{x:.6f} Y{y:.6f}\n" for x, y in points)


def test_an_arc_and_a_fine_polyline_on_it_are_the_same(tmp_path: Path) -> None:
    arc = write(tmp_path, "arc.nc", HEAD + "G2 X20 Y0 I10 J0\n" + TAIL)
    fine = write(tmp_path, "fine.nc", HEAD + arc_as_lines(0.5) + TAIL)  # chords 0.0001 mm off the arc
    assert diff_files(arc, fine).same
    coarse = write(tmp_path, "coarse.nc", HEAD + arc_as_lines(10.0) + TAIL)  # chords 0.038 mm off
    comparison = diff_files(arc, coarse)
    assert not comparison.same
    assert comparison.max_deviation == pytest.approx(10 * (1 - math.cos(math.radians(5))), rel=0.05)


def test_an_arc_split_in_three_is_the_same(tmp_path: Path) -> None:
    whole = write(tmp_path, "whole.nc", HEAD + "G2 X20 Y0 I10 J0\n" + TAIL)
    x1, y1 = 10 - 10 * math.cos(math.radians(60)), 10 * math.sin(math.radians(60))
    x2, y2 = 10 - 10 * math.cos(math.radians(120)), 10 * math.sin(math.radians(120))
    parts = write(tmp_path, "parts.nc", HEAD + f"G2 X{x1:.9f} Y{y1:.9f} I10 J0\n"
                  f"G2 X{x2:.9f} Y{y2:.9f} I{10 - x1:.9f} J{-y1:.9f}\nG2 X20 Y0 I{10 - x2:.9f} J{-y2:.9f}\n" + TAIL)
    assert diff_files(whole, parts).same


def test_a_lead_in_at_the_start_differs_there_only(tmp_path: Path) -> None:
    old = write(tmp_path, "old.nc", HEAD + PASSES + TAIL)
    new = write(tmp_path, "new.nc", HEAD + "G1 X-3 Y-3\nG1 X0 Y0\n" + PASSES + TAIL)
    [change] = diff_files(old, new).changes["deviations"]
    assert change.new_lines == (line_of(new, "G1 X-3 Y-3"), line_of(new, "G1 X0 Y0"))


def test_a_pass_split_by_a_retract_differs_at_the_retract_only(tmp_path: Path) -> None:
    old = write(tmp_path, "old.nc", HEAD + PASSES + TAIL)
    split = PASSES.replace("G1 X40 Y10 F800\n", "G1 X20 Y10 F800\nG0 Z5\nG0 Z-1\nG1 X40 Y10\n", 1)
    new = write(tmp_path, "new.nc", HEAD + split + TAIL)
    comparison = diff_files(old, new)
    [change] = comparison.changes["deviations"]
    assert change.what == "added"
    assert change.new_lines == (line_of(new, "G0 Z5"), line_of(new, "G0 Z-1"))
    assert comparison.changes["feeds"] == []  # the cut after the retract lines up again


def test_removed_passes_are_only_in_old_at_their_lines(tmp_path: Path) -> None:
    old = write(tmp_path, "old.nc", HEAD + PASSES + TAIL)
    lines = PASSES.splitlines(keepends=True)
    new = write(tmp_path, "new.nc", HEAD + "".join(lines[:10] + lines[14:]) + TAIL)  # two passes gone
    comparison = diff_files(old, new)
    removed = [c for c in comparison.changes["deviations"] if c.old_lines]
    assert removed, comparison.to_json()
    gone = {line_of(old, text.rstrip()) for text in lines[10:14]}
    assert all(low >= min(gone) - 1 and high <= max(gone) + 1 for c in removed for low, high in [c.old_lines])
    assert comparison.changes["feeds"] == comparison.changes["spindle"] == []


def test_a_long_stretch_removed_is_found_again_far_ahead(tmp_path: Path) -> None:
    """400 cuts removed (more than the window around the cursor) from a 3,000-move job: the walk
    finds its place again, so a feed changed near the end is still reported at its own line."""
    cuts = [f"G1 X{0.5 * k:.1f} Y{10 * (k % 2)}\n" for k in range(3000)]
    old = write(tmp_path, "old.nc", HEAD + "G1 F800\n" + "".join(cuts) + TAIL)
    changed = cuts[:1000] + cuts[1400:2900] + [cuts[2900].rstrip() + " F900\n"] + cuts[2901:]
    new = write(tmp_path, "new.nc", HEAD + "G1 F800\n" + "".join(changed) + TAIL)
    comparison = diff_files(old, new)
    removed = [c for c in comparison.changes["deviations"] if c.what in ("removed", "replaced")]
    first_gone, last_gone = line_of(old, cuts[1000].rstrip()), line_of(old, cuts[1399].rstrip())
    assert removed and all(first_gone - 1 <= c.old_lines[0] and c.old_lines[1] <= last_gone + 1 for c in removed)
    [feed] = comparison.changes["feeds"]
    assert feed.new_lines[0] == line_of(new, cuts[2900].rstrip() + " F900")
    assert (feed.old, feed.new) == (800, 900)


def test_a_path_driven_the_other_way_is_one_reversed_change(tmp_path: Path) -> None:
    """The passes driven last first (climb milling become conventional): the same path, one change, found by
    the moves themselves (no geometry search: a long job reversed costs what any other does)."""
    old = write(tmp_path, "old.nc", HEAD + PASSES + TAIL)
    ends = [(0, 0)] + [(40 * (k % 2), y) for k in range(20) for y in (2 * k, 2 * k + 2)]
    back = f"G1 X{ends[-1][0]} Y{ends[-1][1]} F800\n" + "".join(f"G1 X{x} Y{y}\n" for x, y in ends[-2::-1])
    new = write(tmp_path, "new.nc", HEAD + back + TAIL)
    comparison = diff_files(old, new)
    reversed_ = [c for c in comparison.changes["deviations"] if c.what == "reversed"]
    assert len(reversed_) == 1 and reversed_[0].moves >= 39  # all but the move to where the passes start
    assert comparison.changes["feeds"] == []


def test_a_few_points_against_a_long_stretch_find_what_all_against_all_finds(tmp_path: Path, monkeypatch) -> None:
    """The boxes leave out only segments farther than the nearest: the distances, segments and places are
    those of measuring every pair, ties (points on vertices, a path driven twice) included."""
    import numpy as np

    from edingcnc_lang.diff import align
    from edingcnc_lang.diff.record import record, sample
    from edingcnc_lang.runner import RunOptions

    moves = []
    for k in range(600):
        x = 40 * (k % 2)
        moves.append(f"G{2 + k % 2} X{x} Y{k * 0.5:.1f} R25\n" if k % 5 == 3 else f"G1 X{x} Y{k * 0.5:.1f}\n")
    helix = "G17 G2 X40 Y309.5 Z-2 I0 J5\nG18 G3 X50 Z-2 I5 K0\nG19 G2 Y299.5 Z-2 J-5 K0\n"
    job = write(tmp_path, "long.nc", HEAD + "".join(moves) + helix + "G1 X0 Y0\n" + "".join(moves[:50]) + TAIL)
    samples = sample(record(job, RunOptions()))
    stretch = align.Stretch(samples, 0, int(samples.owner[-1]) + 1)
    rng = np.random.default_rng(7)
    points = np.vstack((samples.points[rng.choice(len(samples.points), 30)],       # on the path
                        samples.points[rng.choice(len(samples.points), 20)] + rng.normal(0, 0.3, (20, 3)),
                        rng.uniform(-20, 60, (20, 3))))                             # near it and far
    monkeypatch.setattr(align, "BRUTE", 1 << 30)  # every pair
    expected = align.nearest(points, stretch, 1.0)
    boxed, by_boxes = [], align._by_boxes
    monkeypatch.setattr(align, "BRUTE", 256)       # a long stretch: by boxes
    monkeypatch.setattr(align, "_by_boxes", lambda *args: boxed.append(1) or by_boxes(*args))
    found = align.nearest(points, stretch, 1.0)
    assert boxed and len(stretch) > 256 and len(points) * 64 < len(stretch)
    for mine, theirs in zip(found, expected):
        assert np.array_equal(mine, theirs)
