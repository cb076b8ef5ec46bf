"""Worked examples with hand-computed values: the seed's delta home, rotatekins, CoreXY, KIN modes, bend knife."""
from __future__ import annotations

import math

import numpy as np
import pytest

from edingcnc_lang.errors import ConfigError, MachineError
from edingcnc_lang.kinematics import abi
from edingcnc_lang.kinematics.base import KinematicsDomainError, KinematicsPlugin
from edingcnc_lang.kinematics.builtin import (
    CoreXYKinematics,
    CylinderMapping,
    TrivialKinematics,
    bend_knife_correction,
)
from edingcnc_lang.kinematics.shipped import import_shipped

DeltaKins = import_shipped("deltakins").DeltaKins
RotateKins = import_shipped("rotatekins").RotateKins
SEED_DELTA = {"lindeltaradius": "125.000000", "lindeltaarmlength": "250.000000"}


def control(kins: KinematicsPlugin, control_id: int, *values: float) -> list[float]:
    data = [*values, *[0.0] * (12 - len(values))]
    assert kins.control(control_id, data) == 0
    return data


# --- deltakins -------------------------------------------------------------------------------

def test_delta_home_switches_give_z_200() -> None:
    """Seed §4.1: L = 250, R = 125, all joints at sqrt(250^2 - 125^2) + 200 = 416.5063509."""
    pos = DeltaKins(SEED_DELTA).forward((416.5063509, 416.5063509, 416.5063509, 0.0, 0.0, 0.0))
    np.testing.assert_allclose(pos, (0.0, 0.0, 200.0, 0.0, 0.0, 0.0), atol=1e-6)


def test_delta_lowest_centre_position_is_sqrt_l2_r2() -> None:
    joints = DeltaKins(SEED_DELTA).inverse((0.0, 0.0, 0.0, 1.0, 2.0, 3.0))
    assert joints == pytest.approx((math.sqrt(250**2 - 125**2),) * 3 + (1.0, 2.0, 3.0), abs=1e-12)


def test_delta_towers_follow_lineardeltakins_layout() -> None:
    """Under joint X's tower (0, R) its arm hangs straight down: jx = z + L."""
    jx, jy, jz, *_ = DeltaKins(SEED_DELTA).inverse((0.0, 100.0, 10.0, 0, 0, 0))
    assert jx == pytest.approx(10.0 + math.sqrt(250**2 - 25**2))
    assert jy == pytest.approx(jz)
    assert jy == pytest.approx(10.0 + math.sqrt(250**2 - (125 * math.sqrt(3) / 2) ** 2 - 162.5**2))


def test_delta_unreachable_names_the_sample() -> None:
    kins = DeltaKins(SEED_DELTA)
    rows = np.zeros((5, 6))
    rows[3, 0] = 400.0
    with pytest.raises(KinematicsDomainError) as err:
        kins.inverse_many(rows)
    assert err.value.sample == 3
    assert "X400 Y0 Z0 is out of reach" in err.value.message
    assert err.value.exit_code == 70


def test_delta_safety_radius() -> None:
    kins = DeltaKins({**SEED_DELTA, "lindeltasafetyradius": "50"})
    kins.inverse((30.0, 40.0, 0.0, 0, 0, 0))          # exactly 50 from the centre: allowed
    with pytest.raises(KinematicsDomainError, match="linDeltaSafetyRadius = 50") as err:
        kins.inverse((30.0, 40.1, 0.0, 0, 0, 0))
    assert err.value.sample is None


def test_delta_user_output_is_last_joints() -> None:
    kins = DeltaKins(SEED_DELTA)
    rows = np.array([[0.0, 0.0, 0.0, 0, 0, 0], [10.0, 20.0, 30.0, 0, 0, 0]])
    joints = kins.inverse_many(rows)
    assert kins.user_output() == tuple(joints[-1, :3])
    assert control(kins, abi.USER_OUTPUT)[:4] == [*joints[-1, :3], 0.0]


@pytest.mark.parametrize("settings", [{"lindeltaradius": "300"}, {"lindeltaarmlength": "abc"}])
def test_delta_bad_geometry(settings: dict[str, str]) -> None:
    with pytest.raises(ConfigError, match="linDelta"):
        DeltaKins(settings)


# --- rotatekins ------------------------------------------------------------------------------

def test_rotatekins_rotates_about_the_switch_on_point() -> None:
    kins = RotateKins({})
    control(kins, abi.ON, 10.0, 20.0, 5.0)
    joints = kins.inverse((30.0, 20.0, 5.0, 1.0, 2.0, 90.0))
    assert joints == pytest.approx((10.0, 40.0, 5.0, 1.0, 2.0, 0.0), abs=1e-12)
    assert kins.user_output() == (10.0, 20.0, 90.0)
    assert kins.forward((10.0, 40.0, 5.0, 1.0, 2.0, 0.0)) == pytest.approx((30.0, 20.0, 5.0, 1.0, 2.0, 90.0))


def test_rotatekins_user_controls() -> None:
    kins = RotateKins({})
    control(kins, abi.ON)
    control(kins, abi.USER1, -5.0, 7.0)
    assert control(kins, abi.USER3)[:2] == [-5.0, 7.0]
    control(kins, abi.USER2, 45.0)
    # forward uses the stored angle: the motor point (-5 + sqrt 2, 7) is at C = 45
    pos = kins.forward((-5.0 + math.sqrt(2.0), 7.0, 0.0, 0.0, 0.0, 0.0))
    assert pos == pytest.approx((-4.0, 6.0, 0.0, 0.0, 0.0, 45.0))
    assert kins.control(99, [0.0] * 12) == -1


def test_rotatekins_off_passes_through_but_keeps_c_virtual() -> None:
    kins = RotateKins({})
    assert kins.inverse((1.0, 2.0, 3.0, 4.0, 5.0, 60.0)) == (1.0, 2.0, 3.0, 4.0, 5.0, 0.0)
    control(kins, abi.ON, 0.0, 0.0)
    control(kins, abi.OFF)
    assert kins.inverse((1.0, 2.0, 3.0, 0.0, 0.0, 90.0))[:2] == (1.0, 2.0)


def test_rotatekins_matches_linuxcnc_rotation_about_origin() -> None:
    """With the point at the origin this is LinuxCNC's rotatekins: jx = x cos c - y sin c."""
    kins = RotateKins({})
    control(kins, abi.ON)
    jx, jy, *_ = kins.inverse((3.0, 4.0, 0.0, 0.0, 0.0, 30.0))
    c = math.radians(30.0)
    assert (jx, jy) == pytest.approx((3 * math.cos(c) - 4 * math.sin(c), 3 * math.sin(c) + 4 * math.cos(c)))


# --- CoreXY, trivial ---------------------------------------------------------------------------

def test_corexy_belts() -> None:
    kins = CoreXYKinematics({})
    assert kins.inverse((3.0, 1.0, 2.0, 4.0, 5.0, 6.0)) == (4.0, 2.0, 2.0, 4.0, 5.0, 6.0)
    assert kins.forward((4.0, 2.0, 2.0, 0.0, 0.0, 0.0)) == (3.0, 1.0, 2.0, 0.0, 0.0, 0.0)
    assert kins.kin_type() == 5


def test_trivial_types_and_defaults() -> None:
    kins = TrivialKinematics({})
    assert kins.inverse((1, 2, 3, 4, 5, 6)) == (1.0, 2.0, 3.0, 4.0, 5.0, 6.0)
    assert kins.kin_type() == 1 and kins.user_output() == ()
    assert control(kins, abi.USER_OUTPUT) == [0.0] * 12


# --- KIN modes ---------------------------------------------------------------------------------

R25 = {"aaxiscalibratedcilinderradius": "25.0"}
DEG_PER_MM = 180.0 / (math.pi * 25.0)


def test_y2a_uses_work_zero_when_not_calibrated() -> None:
    kins = CylinderMapping("Y2A", R25, work_zero=10.0)
    assert kins.inverse((1.0, 10.0 + 25.0 * math.pi, 3.0, 0, 0, 0)) == pytest.approx((1.0, 10.0, 3.0, 180.0, 0, 0))
    assert kins.kin_type() == 2


def test_y2a_uses_calibrated_rotation_point() -> None:
    settings = {**R25, "aaxisrotationpointiscalibrated": "1", "aaxiscalibratedrotationpointy": "-7.5"}
    kins = CylinderMapping("y2a", settings, work_zero=10.0)
    assert kins.inverse((0.0, 2.5, 0.0, 0, 0, 0)) == pytest.approx((0.0, -7.5, 0.0, 10.0 * DEG_PER_MM, 0, 0))


def test_x2a_wraps_x() -> None:
    kins = CylinderMapping("X2A", R25, work_zero=-5.0)
    assert kins.inverse((5.0, 2.0, 3.0, 99.0, 0, 0)) == pytest.approx((-5.0, 2.0, 3.0, 10.0 * DEG_PER_MM, 0, 0))


@pytest.mark.parametrize("mode", ["X2A", "Y2A"])
@pytest.mark.parametrize("radius", ["", "0", "-3"])
def test_cylinder_needs_a_radius(mode: str, radius: str) -> None:
    with pytest.raises(MachineError, match="aAxisCalibratedCilinderRadius must be > 0"):
        CylinderMapping(mode, {"aaxiscalibratedcilinderradius": radius})


@pytest.mark.parametrize(("mode", "joints"), [
    ("X2XA", (1.0, 2.0, 3.0, 1.0, 5.0, 6.0)),
    ("Y2YA", (1.0, 2.0, 3.0, 2.0, 5.0, 6.0)),
    ("Z2C", (1.0, 2.0, -42.0, 4.0, 5.0, 3.0)),
    ("Z2ZC", (1.0, 2.0, 3.0, 4.0, 5.0, 3.0)),
    ("Y2YAZ2ZC", (1.0, 2.0, 3.0, 2.0, 5.0, 3.0)),
])
def test_follower_modes(mode: str, joints: tuple[float, ...]) -> None:
    kins = CylinderMapping(mode, {}, hold_z=-42.0)
    assert kins.inverse((1.0, 2.0, 3.0, 4.0, 5.0, 6.0)) == joints


def test_unknown_mode() -> None:
    with pytest.raises(MachineError, match="unknown KIN mode 'Q2A'"):
        CylinderMapping("Q2A", {})


# --- bend knife -------------------------------------------------------------------------------

def test_bend_knife_45_degrees() -> None:
    # above z_hi: no correction; 3 mm below z_hi with C = 0 and beta = +90: 3 mm towards +Y
    assert bend_knife_correction(1.0, 2.0, 6.0, 0.0, 90.0, 5.0, 0.0) == (1.0, 2.0)
    jx, jy = bend_knife_correction(1.0, 2.0, 2.0, 0.0, 90.0, 5.0, 0.0)
    assert (jx, jy) == pytest.approx((1.0, 5.0))
    # below z_lo the correction stays at z_hi - z_lo
    assert bend_knife_correction(0.0, 0.0, -10.0, 90.0, -90.0, 5.0, 0.0) == pytest.approx((5.0, 0.0))
    assert bend_knife_correction(1.0, 2.0, -10.0, 30.0, 0.0, 5.0, 0.0) == (1.0, 2.0)


def test_bend_knife_vectorised() -> None:
    z = np.linspace(8.0, -3.0, 23)
    c = np.linspace(0.0, 300.0, 23)
    jx, jy = bend_knife_correction(np.zeros(23), np.ones(23), z, c, 90.0, 5.0, 1.0)
    expected = [bend_knife_correction(0.0, 1.0, zi, ci, 90.0, 5.0, 1.0) for zi, ci in zip(z, c)]
    np.testing.assert_array_equal(np.column_stack((jx, jy)), expected)
