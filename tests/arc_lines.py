"""Arc lines and machine states on which every reader of a run of arc lines (``plain_arcs``, compiled and
Python) is held to the general path's own reading (``bulk.arc_run`` over ``BulkPath._arc_of_words``)."""
from __future__ import annotations

from collections.abc import Callable
from dataclasses import replace
from typing import Any

import pytest

from edingcnc_lang import RunOptions
from edingcnc_lang.machine import bulk
from edingcnc_lang.runner import Run

# arc lines: centre words that fit (a half circle, a full circle, a helix), that nearly fit and that do
# not, words of another plane, F, N and comments; words out of CAM output's order, G texts of every form
ARC_LINES = ["G2 X10 Y0 I5 J0", "G2 X10 Y0 I5 J0 ;\udc80", "G3 X\ud8001 I1", "G3 X-10 Y0 I-5", "X10 Y10 I10",
             "G2 X0 Y0 Z-1 I5 J0", "G2 I5 Z-2", "G3 X4 Z4 I2 K2", "G2 Y6 Z0 J3 K0 F80", "G2 X20 R10",
             "G3 X10.0015 Y0 I5 J0", "G02 x10 y0 i5 j0.0001 f0", "G3 X10 Y0 I5 J0 F-1", "G2 X1 I1 I2", "G2 X5 Y5",
             "N7 G3 X10 Y0 I5 J0 (cut) F1200.5", "X3 Y4 J5 K1", "G2 X5 A10 B2 C3 I2.5 ; note", "G2.5 X1 I1",
             "G1 X1 I1", "G2 I5 J0", "G3 X1e3 I1", "G2 X10 Y0 I5 J0 M3", "J0 I5 Y0 X10 G2", "F500 G3 X-10 I-5",
             "G2.0 X10 I5", "G03 X2 Y2 J1", "G+3 X-2 I-1", "G002 X4 I2", "G3. X-4 I-2", "\tG2\tX10 I5\t; tab",
             "N12 F0 G2 X10 I5", "g2 x 10 i 5", "G2 X10 I5 J0 X1", "X-5 I-2.5 ;", "G2 X10 Y0 I5 J0 (a;b)",
             # R: under and over half a circle, too small to reach, R0, ends that meet, with a
             # centre word, another plane's, a helix, a long flat arc, out of order, twice
             "G3 X10 Y0 R5", "G2 X10 Y0 R-5.0001", "G3 X10 Y10 R-7.5", "G2 X10 R4.9", "G2 X10 R0",
             "G3 X0 Y0 R5", "G2 X10 R5 I5", "G3 Z5 X5 R3", "G2 Y6 Z6 R-4.5 F100", "G2 X10 Z-1 R6",
             "G3 X10 R10000000", "G2 X0.00001 R1", "N9 X3 Y4 R2.5 (r)", "R5 X10 G3", "G2 X10 R5 R6", "G3 X-10 r-5"]


ARC_STATES = [f"{plane} {distance} {units}\n{offsets}\n" for plane in ("G17", "G18", "G19")
              for distance in ("G90", "G91") for units in ("G21", "G20") for offsets in ("", "G10 L2 P1 X5 Y-3 Z1")]


def assert_arc_reader_is_the_general_paths(reader: Callable[..., Any]) -> None:
    """``reader`` (a ``plain_arcs``) as the bulk path uses it against the general path's target and arc_plan,
    in every plane, G90/G91, mm and inch, with offsets and reversed G2/G3: the same records or the same
    nothing, a line at a time and as runs of lines (from each line on, within a room of steps)."""
    with pytest.MonkeyPatch.context() as monkeypatch:
        monkeypatch.setattr(bulk, "_PLAIN_ARCS", reader)
        _compare()


def _compare() -> None:
    made, full, runs = 0, 0, 0
    numbered = tuple(enumerate(ARC_LINES, 5))
    for state in ARC_STATES:
        run = Run(RunOptions())
        run.execute_text(state, "job.nc")
        interp = run.interpreter
        for reverse in (False, True):
            interp.config = replace(interp.config, reverse_g2g3=reverse)
            read_arcs = interp._arc_reader()
            for start in ((0.0, 0.0, 0.0), (1.5, -2.25, 10.0)):
                pose = (*start, 0.0, 0.0, 0.0)
                for motion in (0, 20, 30):
                    for feed in (0.0, 300.0):
                        for index, (number, text) in enumerate(numbered):
                            one = read_arcs(((number, text),), 0, pose, motion, feed, 1)
                            assert one == bulk.arc_run(interp._arc_of_words, ((number, text),), 0, pose, motion,
                                                       feed, 1), (state, text, pose, motion)
                            made += len(one[3])
                            full += bool(one[3]) and one[6][0].full_turns == 1
                            for room in (2, 40):
                                several = read_arcs(numbered, index, pose, motion, feed, room)
                                assert several == bulk.arc_run(interp._arc_of_words, numbered, index, pose, motion,
                                                               feed, room), (state, text, pose, motion, room)
                                runs += len(several[3]) > 1
    assert made > 2000 and full > 50 and runs > 100


