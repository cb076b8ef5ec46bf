"""forward(inverse(p)) == p for every kinematics, over the positions each one can reach."""
from __future__ import annotations

import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from edingcnc_lang.kinematics import abi
from edingcnc_lang.kinematics.base import Kinematics
from edingcnc_lang.kinematics.builtin import CoreXYKinematics, CylinderMapping, TrivialKinematics
from edingcnc_lang.kinematics.shipped import import_shipped

DeltaKins = import_shipped("deltakins").DeltaKins
RotateKins = import_shipped("rotatekins").RotateKins

coord = st.floats(-1000.0, 1000.0, allow_nan=False)
angle = st.floats(-720.0, 720.0, allow_nan=False)
pose = st.tuples(coord, coord, coord, angle, angle, angle)
CYLINDER = {"aaxiscalibratedcilinderradius": "25", "aaxisrotationpointiscalibrated": "1",
            "aaxiscalibratedrotationpointy": "-40.5"}
FAST = settings(max_examples=60, deadline=None)
# The Cartesian axes each KIN mode takes over (forward reports them as 0).
TAKEN = {"X2A": "a", "Y2A": "a", "X2XA": "a", "Y2YA": "a", "Z2C": "c", "Z2ZC": "c", "Y2YAZ2ZC": "ac"}


def assert_round_trip(kins: Kinematics, p: tuple[float, ...], atol: float = 1e-9) -> None:
    back = kins.forward(kins.inverse(p))
    np.testing.assert_allclose(back, p, rtol=0, atol=atol)


@FAST
@given(pose)
def test_trivial(p: tuple[float, ...]) -> None:
    assert_round_trip(TrivialKinematics({}), p)


@FAST
@given(pose)
def test_corexy(p: tuple[float, ...]) -> None:
    assert_round_trip(CoreXYKinematics({}), p)


@FAST
@given(pose, coord, coord)
def test_rotatekins_on(p: tuple[float, ...], px: float, py: float) -> None:
    kins = RotateKins({})
    assert kins.control(abi.ON, [px, py] + [0.0] * 10) == 0
    assert_round_trip(kins, p)


@FAST
@given(st.floats(0.0, 120.0), st.floats(-math.pi, math.pi), st.floats(-100.0, 300.0), angle, angle, angle)
def test_deltakins(r: float, phi: float, z: float, a: float, b: float, c: float) -> None:
    """Everything within 120 mm of the centre is reachable with R = 125, L = 250."""
    assert_round_trip(DeltaKins({}), (r * math.cos(phi), r * math.sin(phi), z, a, b, c), atol=1e-8)


@pytest.mark.parametrize("mode", sorted(TAKEN))
@settings(max_examples=25, deadline=None)
@given(p=pose, work_zero=coord, hold_z=coord)
def test_kin_modes(mode: str, p: tuple[float, ...], work_zero: float, hold_z: float) -> None:
    kins = CylinderMapping(mode, CYLINDER, work_zero, hold_z)
    reachable = tuple(0.0 if axis in TAKEN[mode] else v for axis, v in zip("xyzabc", p))
    assert_round_trip(kins, reachable)
