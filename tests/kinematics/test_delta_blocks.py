"""deltakins evaluates large batches block by block: the blocks must not show in the results.

Batches longer than one block are compared with the closed formula per sample, and an
unreachable or NaN sample in a later block is reported exactly as in a one-block batch.
"""
from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest

from edingcnc_lang.kinematics.base import KinematicsDomainError
from edingcnc_lang.kinematics.shipped import import_shipped

deltakins = import_shipped("deltakins")
SETTINGS = {"lindeltaradius": "125", "lindeltaarmlength": "250"}
COUNT = 2 * deltakins.BLOCK + 123  # three blocks, the last one partial


def poses(count: int) -> np.ndarray:
    rng = np.random.default_rng(7)
    return rng.uniform(-1.0, 1.0, (count, 6)) * [60.0, 60.0, 100.0, 90.0, 45.0, 180.0]


def closed_formula(kins: object, row: np.ndarray) -> list[float]:
    return [row[2] + math.sqrt(250.0**2 - (tx - row[0]) ** 2 - (ty - row[1]) ** 2)
            for tx, ty in kins.towers]  # type: ignore[attr-defined]


def test_every_block_matches_the_formula_and_keeps_abc() -> None:
    kins = deltakins.DeltaKins(SETTINGS)
    rows = poses(COUNT)
    joints = kins.inverse_many(rows)
    for i in (0, deltakins.BLOCK - 1, deltakins.BLOCK, COUNT - 1):
        assert joints[i, :3] == pytest.approx(closed_formula(kins, rows[i]), abs=1e-9)
    np.testing.assert_array_equal(joints[:, 3:], rows[:, 3:])
    assert kins.last_joints == tuple(joints[-1, :3])


def test_unreachable_sample_in_a_later_block_is_named_by_its_batch_index() -> None:
    kins = deltakins.DeltaKins(SETTINGS)
    rows = poses(COUNT)
    rows[deltakins.BLOCK + 5, 0] = 400.0
    rows[COUNT - 1, 1] = -400.0
    kins.last_joints = (1.0, 2.0, 3.0)
    with pytest.raises(KinematicsDomainError, match=r"X400 Y.* out of reach .* arm of joint") as err:
        kins.inverse_many(rows)
    assert err.value.sample == deltakins.BLOCK + 5
    assert kins.last_joints == (1.0, 2.0, 3.0)  # a failed batch leaves the user output alone


def test_safety_radius_in_a_later_block() -> None:
    kins = deltakins.DeltaKins({**SETTINGS, "lindeltasafetyradius": "100"})
    rows = poses(COUNT)  # within 60 * sqrt(2) < 100 of the centre
    rows[2 * deltakins.BLOCK + 1, :2] = (80.0, 80.0)
    with pytest.raises(KinematicsDomainError, match="beyond linDeltaSafetyRadius = 100") as err:
        kins.inverse_many(rows)
    assert err.value.sample == 2 * deltakins.BLOCK + 1


def test_nan_sample_is_not_unreachable_and_stays_nan() -> None:
    """The motion stage rejects non-finite joints itself; the plug-in must pass NaN through."""
    kins = deltakins.DeltaKins(SETTINGS)
    rows = poses(COUNT)
    rows[deltakins.BLOCK + 1, 2] = math.nan
    joints = kins.inverse_many(rows)
    assert np.isnan(joints[deltakins.BLOCK + 1, :3]).all()
    assert np.isfinite(np.delete(joints, deltakins.BLOCK + 1, axis=0)).all()


def test_empty_batch() -> None:
    assert deltakins.DeltaKins(SETTINGS).inverse_many(np.zeros((0, 6))).shape == (0, 6)


def test_an_arc_along_the_safety_circle_runs() -> None:
    """Points exactly on linDeltaSafetyRadius are inside, also the rounded samples of an arc along it."""
    from edingcnc_lang import RunOptions, run_string

    ini = Path(__file__).resolve().parents[2] / "examples" / "delta" / "cnc.ini"
    job = ("PrepareLinDeltaHome 40\nhome x\nhome y\nhome z\nKIN ON\nG0 Z50\nG1 X100 Y0 F3000\n"
           "G1 X0 Y100\nG2 X100 Y0 I0 J-100\nM30\n")
    result = run_string(job, RunOptions(ini=ini))
    assert result.machine[:2] == pytest.approx((100.0, 0.0), abs=1e-9)
    kins = deltakins.DeltaKins({**SETTINGS, "lindeltasafetyradius": "100"})
    with pytest.raises(KinematicsDomainError, match="beyond linDeltaSafetyRadius"):
        kins.inverse((100.001, 0.0, 0.0, 0.0, 0.0, 0.0))
