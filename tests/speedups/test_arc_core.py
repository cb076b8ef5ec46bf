"""The compiled core's arcs are the Python core's, to the last bit (skipped where it is not built).

math.hypot is CPython's own algorithm, ported to C (``_speedups.hypot`` is its test entry point): it is
compared with ``math.hypot`` on any doubles.  Whole jobs of R and I/J arcs, and the examples/, write the
same trace on both cores.
"""
from __future__ import annotations

import math
import os
import shutil
from array import array
import struct
import subprocess
import sys
from pathlib import Path

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from edingcnc_lang.canon import Arc
from edingcnc_lang.kinematics.trajectory import arc_frame_rows
from edingcnc_lang.motion.arc_table import ArcTable
from edingcnc_lang.motion.reach import arcs_beyond

pytestmark = pytest.mark.slow  # the whole module (pyproject's slow marker)

compiled = pytest.importorskip("edingcnc_lang._speedups", reason="the compiled core is not built here")

ROOT = Path(__file__).resolve().parents[2]


def _bits(value: float) -> bytes:
    return struct.pack("<d", value)


doubles = st.one_of(st.floats(), st.floats(-1e4, 1e4), st.floats(-1e-300, 1e-300),
                    st.sampled_from([0.0, -0.0, 5e-324, 2.2250738585072014e-308, 1.7976931348623157e308, math.inf,
                                     -math.inf, math.nan, 3.0, 4.0, 0.1]))


@settings(max_examples=3000, deadline=None)
@given(doubles, doubles)
def test_the_compiled_hypot_is_pythons(a: float, b: float) -> None:
    """Every bit, NaN's sign included (3.10's Py_NAN is negative), and equal arguments."""
    assert _bits(compiled.hypot(a, b)[0]) == _bits(math.hypot(a, b))
    assert _bits(compiled.hypot(a, a)[0]) == _bits(math.hypot(a, a))


def test_the_supported_pythons_run_the_ported_hypot() -> None:
    """On 3.10 to 3.13 the port passes its check at import (else it would call math.hypot: slower, not wrong)."""
    kind = compiled.hypot(3.0, 4.0)
    assert kind[0] == 5.0
    if (3, 10) <= sys.version_info[:2] <= (3, 13):
        assert kind[1] == ("3.10" if sys.version_info < (3, 12) else "3.12")


coordinates = st.one_of(st.floats(-1e4, 1e4), st.sampled_from([0.0, -0.0, 5.0, -5.0, 1e-9]))
poses = st.tuples(*[coordinates] * 6)
arcs = st.builds(Arc, st.tuples(coordinates, coordinates), st.sampled_from(["XY", "XZ", "YZ"]),
                 st.sampled_from([1, -1]), st.sampled_from([0, 0, 1, 3]))


@settings(max_examples=300, deadline=None)
@given(poses, st.lists(st.tuples(poses, st.none() | arcs), max_size=8))
def test_the_frames_of_a_batchs_arcs_as_doubles_are_the_same(start: tuple[float, ...],
                                                             moves: list[tuple[tuple[float, ...], Arc | None]]) -> None:
    """The bytes ArcTable reads on the compiled core are the doubles of the Python rows, and so is its table."""
    ends, arcs_of = [end for end, _ in moves], [arc for _, arc in moves]
    rows = arc_frame_rows(start, ends, arcs_of)
    assert bytes(compiled.arc_frame_bytes(start, ends, arcs_of)) == array("d", rows).tobytes()
    assert ArcTable.of(start, ends, arcs_of).rows.tobytes() == array("d", rows).tobytes()


small = st.one_of(st.floats(-20, 20), st.sampled_from([0.0, -0.0, 5.0, -5.0, 1e-9, math.nan]))
small_poses = st.tuples(*[small] * 6)
small_arcs = st.builds(Arc, st.tuples(small, small), st.sampled_from(["XY", "XZ", "YZ"]), st.sampled_from([1, -1]),
                       st.sampled_from([0, 0, 1, 3]))
bounds = st.tuples(*[st.floats(-25, 0)] * 6), st.tuples(*[st.floats(0, 25)] * 6)


@settings(max_examples=1500, deadline=None)
@given(small_poses, st.lists(st.tuples(small_poses, st.none() | small_arcs), max_size=6), *bounds)
def test_whether_a_batchs_arcs_reach_outside_is_the_same(start: tuple[float, ...],
                                                         moves: list[tuple[tuple[float, ...], Arc | None]],
                                                         lower: tuple[float, ...], upper: tuple[float, ...]) -> None:
    """The untimed run's limit check of a batch's arcs: their ends, the circles within the limits, the extremes
    of those that are not (every plane, both ways, full circles), NaN."""
    ends, arcs_of = [end for end, _ in moves], [arc for _, arc in moves]
    low, high = list(lower), list(upper)
    assert compiled.arcs_beyond(start, ends, arcs_of, low, high) is arcs_beyond(start, ends, arcs_of, low, high)


def test_an_arc_reaches_outside_only_at_its_extremes() -> None:
    """A half circle whose ends lie inside and whose top does not, either way round: the same answer as Python's."""
    for turn, beyond_top in ((1, True), (-1, False)):  # from (1, 0) to (-1, 0) about the origin: over the top or not
        arc = Arc((0.0, 0.0), "XY", turn)
        start, end = (1.0, 0.0, 0.0, 0.0, 0.0, 0.0), (-1.0, 0.0, 0.0, 0.0, 0.0, 0.0)
        low, high = [-5.0, -5.0, -5.0, -5.0, -5.0, -5.0], [5.0, 0.5, 5.0, 5.0, 5.0, 5.0]
        assert compiled.arcs_beyond(start, [end], [arc], low, high) is beyond_top
        assert arcs_beyond(start, [end], [arc], low, high) is beyond_top


def test_a_hypot_that_differs_at_import_is_called_instead() -> None:
    """The check at import: when math.hypot gives other bits than the port on one input of its table, the
    compiled core calls math.hypot itself (a fresh process, math.hypot replaced before the import)."""
    code = ("import math, sys; real = math.hypot\n"
            "math.hypot = lambda a, b: 0.25 if (a, b) == (0.5, 0.5) else real(a, b)\n"
            "from edingcnc_lang import _speedups\n"
            "print(_speedups.hypot(0.5, 0.5), _speedups.hypot(3.0, 4.0))")
    done = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True)
    assert done.stdout.split() == ["(0.25,", "'call')", "(5.0,", "'call')"]


def _arc_job(r_form: bool) -> str:
    """R or I/J arcs in every plane, over and under half a circle, full circles, helices, G91 and inch, CRLF."""
    lines = ["G21 G17 G90 G94 F800", "G0 X0 Y0 Z0"]
    for i in range(120):
        x = 2.0 * (i + 1)
        lines.append(f"G{2 + i % 2} X{x:.4f} Y0 Z{-0.01 * i:.3f} R{1.0 if i % 3 else -1.0}" if r_form
                     else f"G{2 + i % 2} X{x:.4f} Y0 I1.0 J{0.0 if i % 4 else -0.0}")
    lines += ["G2 X240 Y0 I-1 J0" if not r_form else "G3 X242 Y2 R2", "G18", "G2 X244 Z2 R2" if r_form else
              "G2 X242 Z0 I1 K0", "G19", "G3 Y3 Z3 R1.5" if r_form else "G3 Y2 Z0 J1 K0", "G17 G91",
              *(["G2 X1 Y1 R1", "G3 X1 Y-1 R-1"] if r_form else ["G2 X2 I1 J0", "G3 X-2 I-1 J0"]) * 30,
              "G20", "G3 X0.1 Y0 R0.05" if r_form else "G3 X0.1 Y0 I0.05 J0", "G21 G90 G0 Z5", "M30"]
    return "\r\n".join(lines) + "\r\n"


def _trace(job: Path, trace: Path, pure: bool, ini: Path | None = None) -> int:
    env = {**os.environ, "ECNC_PURE_PYTHON": "1" if pure else "0"}
    done = subprocess.run([sys.executable, "-m", "edingcnc_lang", "run", str(job), "--trace", str(trace),
                           *(["--ini", str(ini)] if ini else [])], env=env, capture_output=True, text=True)
    return done.returncode


@pytest.mark.parametrize("r_form", [True, False], ids=["R", "IJ"])
def test_both_cores_write_the_same_trace_of_arcs(tmp_path: Path, r_form: bool) -> None:
    job = tmp_path / "arcs.nc"
    job.write_text(_arc_job(r_form), newline="")
    pure, fast = tmp_path / "pure.csv", tmp_path / "fast.csv"
    assert _trace(job, pure, pure=True) == _trace(job, fast, pure=False) == 0
    assert pure.read_bytes() == fast.read_bytes()
    assert fast.read_text().count(",arc,") > 150


def test_both_cores_write_the_same_traces_of_the_examples(tmp_path: Path) -> None:
    examples = tmp_path / "examples"  # a copy: a job may write files beside itself (the ZHC table)
    shutil.copytree(ROOT / "examples", examples)
    jobs = sorted(examples.rglob("*.nc"))
    traced = 0
    for job in jobs:
        ini = job.parent / "cnc.ini"
        pure, fast = tmp_path / "pure.csv", tmp_path / "fast.csv"
        codes = (_trace(job, pure, True, ini if ini.exists() else None),
                 _trace(job, fast, False, ini if ini.exists() else None))
        assert codes[0] == codes[1], job
        if codes[0] == 0:
            assert pure.read_bytes() == fast.read_bytes(), job
            traced += 1
            pure.unlink()
            fast.unlink()
    assert traced >= 15
