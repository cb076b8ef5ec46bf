"""inverse_many (vectorised) agrees with the scalar inverse sample by sample, state included."""
from __future__ import annotations

from collections.abc import Callable

import numpy as np
import pytest

from edingcnc_lang.kinematics import abi
from edingcnc_lang.kinematics.base import KinematicsDomainError, KinematicsPlugin, Pose, as_pose
from edingcnc_lang.kinematics.builtin import CoreXYKinematics, CylinderMapping, TrivialKinematics
from edingcnc_lang.kinematics.shipped import import_shipped

DeltaKins = import_shipped("deltakins").DeltaKins
RotateKins = import_shipped("rotatekins").RotateKins


def rotate_on() -> KinematicsPlugin:
    kins = RotateKins({})
    kins.control(abi.ON, [12.0, -3.0] + [0.0] * 10)
    return kins


FACTORIES: dict[str, Callable[[], KinematicsPlugin]] = {
    "trivial": lambda: TrivialKinematics({}),
    "corexy": lambda: CoreXYKinematics({}),
    "rotatekins": rotate_on,
    "deltakins": lambda: DeltaKins({}),
    **{f"KIN {mode}": (lambda m=mode: CylinderMapping(m, {"aaxiscalibratedcilinderradius": "30"}, 4.0, 7.0))
       for mode in ("X2A", "Y2A", "X2XA", "Y2YA", "Z2C", "Z2ZC", "Y2YAZ2ZC")},
}


def poses(n: int = 200) -> np.ndarray:
    rng = np.random.default_rng(7)
    rows = rng.uniform(-80.0, 80.0, (n, 6))
    rows[:, 3:] *= 4.0
    return rows


@pytest.mark.parametrize("name", sorted(FACTORIES))
def test_inverse_many_equals_scalar_loop(name: str) -> None:
    batch_kins, scalar_kins = FACTORIES[name](), FACTORIES[name]()
    rows = poses()
    batch = batch_kins.inverse_many(rows)
    scalar = np.array([scalar_kins.inverse(as_pose(r)) for r in rows])
    np.testing.assert_allclose(batch, scalar, rtol=0, atol=1e-12)
    assert batch.shape == rows.shape
    assert tuple(batch_kins.user_output()) == pytest.approx(tuple(scalar_kins.user_output()), abs=1e-12)


@pytest.mark.parametrize("name", sorted(FACTORIES))
def test_forward_many_equals_scalar(name: str) -> None:
    kins = FACTORIES[name]()
    joints = kins.inverse_many(poses())
    scalar = np.array([kins.forward(as_pose(j)) for j in joints])
    np.testing.assert_allclose(kins.forward_many(joints), scalar, rtol=0, atol=1e-12)


def test_base_class_fallback_loops_and_names_the_sample() -> None:
    class Limited(KinematicsPlugin):
        def inverse(self, pos: Pose, tool_length: float = 0.0) -> Pose:
            if pos[0] > 1.0:
                raise KinematicsDomainError(f"X{pos[0]:g} too far")
            return as_pose((2 * pos[0], *pos[1:]))

    rows = np.zeros((4, 6))
    rows[:, 0] = [0.0, 0.5, 1.0, 1.5]
    kins = Limited({})
    np.testing.assert_array_equal(kins.inverse_many(rows[:3])[:, 0], [0.0, 1.0, 2.0])
    with pytest.raises(KinematicsDomainError) as err:
        kins.inverse_many(rows)
    assert err.value.sample == 3 and err.value.message == "X1.5 too far"


def test_batch_shape_is_checked() -> None:
    with pytest.raises(ValueError, match=r"\(N, 6\)"):
        TrivialKinematics({}).inverse_many(np.zeros((3, 5)))
