"""Properties of planned runs on random jobs (lines, rapids, full circles and helices): the samples
never ask more of a joint than its limits, and blending is never slower than exact stop nor faster
than running the path as one move."""
from __future__ import annotations

import math
import tempfile
from pathlib import Path

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from edingcnc_lang import RunOptions, run_string

pytestmark = pytest.mark.slow  # the whole module (pyproject's slow marker)

VELOCITY = np.array([120.0, 80.0, 30.0, 90.0, 90.0, 90.0])
ACCEL = np.array([1500.0, 900.0, 400.0, 2000.0, 2000.0, 2000.0])
SLACK = 1.0 + 1e-6
SAMPLED_SLACK = 1.001  # with kinematics on, the joints' speeds are measured on samples: 0.1 % of sampling error


def ini(folder: Path) -> Path:
    text = "".join(f"[JOINT_{i}]\r\nmaxVelocity = {VELOCITY[i]}\r\nmaxAcceleration = {ACCEL[i]}\r\n"
                   f"negativeLimit = -1000\r\npositiveLimit = 1000\r\n" for i in range(6))
    path = folder / "cnc.ini"
    path.write_text(text + "[TRAJECTORY]\r\ninterpolationTime = 0.005\r\nlafAngle = 5\r\n", newline="")
    return path


coordinate = st.integers(-400, 400).map(lambda v: v / 8.0)
point = st.tuples(coordinate, coordinate, coordinate)
move = st.tuples(st.sampled_from(["G0", "G1", "G1", "G1", "G2", "G3"]), point, st.integers(60, 12000))
jobs = st.lists(move, min_size=1, max_size=8)


def job_text(moves: list[tuple[str, tuple[float, float, float], int]], mode: str) -> str:
    lines = [mode]
    for code, (x, y, z), feed in moves:
        if code in ("G2", "G3"):  # a full circle about a centre x away (a helix when z moves)
            lines.append(f"{code} I{x or 1.0} J0 Z{z} F{feed}")
        else:
            lines.append(f"{code} X{x} Y{y} Z{z}" + (f" F{feed}" if code == "G1" else ""))
    return "\n".join(lines) + "\n"


@settings(max_examples=30)
@given(jobs, st.sampled_from(["G64", "G64 P0.05", "G61"]))
def test_samples_respect_every_joints_velocity_and_acceleration(moves: list, mode: str) -> None:
    with tempfile.TemporaryDirectory() as folder:
        samples = Path(folder) / "s.csv"
        ends: list[float] = []
        run_string(job_text(moves, mode), RunOptions(ini=ini(Path(folder)), samples=samples,
                                                     on_timed_move=lambda m, j, timing: ends.append(timing.end)))
        rows = samples.read_text().splitlines()[1:]
    if len(rows) < 3:
        return  # moves of zero length: nothing to measure
    data = np.array([[float(v) for v in row.split(",")] for row in rows])
    t, joints = np.concatenate(([0.0], data[:, 0])), np.vstack((np.zeros(6), data[:, 7:13]))
    velocity = np.diff(joints, axis=0) / np.diff(t)[:, None]
    assert (np.abs(velocity) <= VELOCITY * SLACK + 1e-9).all()
    # accelerations inside moves: a corner is a kink in the programmed path (the real machine blends it)
    mid = (t[2:] - t[:-2]) / 2.0
    acceleration = np.diff(velocity, axis=0) / mid[:, None]
    boundaries = np.array(ends)
    straddles = np.array([((boundaries > t0 + 1e-12) & (boundaries < t2 - 1e-12)).any()
                          for t0, t2 in zip(t[:-2], t[2:])])
    inside = acceleration[~straddles]
    assert (np.abs(inside) <= ACCEL * SLACK + 1e-6).all()


@settings(max_examples=40)
@given(st.lists(point, min_size=2, max_size=10), st.integers(600, 12000), st.sampled_from(["G64", "G64 P0.01"]))
def test_blending_is_between_exact_stop_and_one_move(points: list, feed: int, mode: str) -> None:
    moves = [("G1", p, feed) for p in points]
    with tempfile.TemporaryDirectory() as folder:
        machine = ini(Path(folder))
        blended = run_string(job_text(moves, mode), RunOptions(ini=machine)).estimate.seconds
        exact = run_string(job_text(moves, "G61"), RunOptions(ini=machine)).estimate.seconds
    # the no-corner bound: the whole path as one move, at the fastest speed and acceleration any move allows
    path = np.array([(0.0, 0.0, 0.0), *points])
    length = float(np.linalg.norm(np.diff(path, axis=0), axis=1).sum())
    speed = min(feed / 60.0, float(np.linalg.norm(VELOCITY[:3])))
    accel = float(np.linalg.norm(ACCEL[:3]))
    bound = (length / speed + speed / accel if length >= speed ** 2 / accel else 2 * math.sqrt(length / accel)) \
        if length else 0.0
    assert bound * (1 - 1e-9) <= blended <= exact * (1 + 1e-9)


@settings(max_examples=20)
@given(jobs.filter(lambda moves: all(code != "G0" for code, _, _ in moves)))
def test_corexy_samples_respect_the_joints(moves: list) -> None:
    """With kinematics on, the joints (here CoreXY's two belts) set the pace, not the axes."""
    with tempfile.TemporaryDirectory() as folder:
        machine = ini(Path(folder))
        machine.write_text(machine.read_text() + "[KINEMATICS]\r\nkinematicsDLLName = corexy\r\n", newline="")
        samples = Path(folder) / "s.csv"
        ends: list[float] = []
        run_string("KIN ON\n" + job_text(moves, "G64"), RunOptions(
            ini=machine, samples=samples, on_timed_move=lambda m, j, timing: ends.append(timing.end)))
        rows = samples.read_text().splitlines()[1:]
    if len(rows) < 3:
        return
    data = np.array([[float(v) for v in row.split(",")] for row in rows])
    t, joints = np.concatenate(([0.0], data[:, 0])), np.vstack((np.zeros(6), data[:, 7:13]))
    velocity = np.diff(joints, axis=0) / np.diff(t)[:, None]
    assert (np.abs(velocity) <= VELOCITY * SAMPLED_SLACK).all()
    acceleration = np.diff(velocity, axis=0) / ((t[2:] - t[:-2]) / 2.0)[:, None]
    straddles = np.array([((np.array(ends) > t0 + 1e-12) & (np.array(ends) < t2 - 1e-12)).any()
                          for t0, t2 in zip(t[:-2], t[2:])])
    assert (np.abs(acceleration[~straddles]) <= ACCEL * SAMPLED_SLACK).all()
