"""The C rotatekins, compiled here and loaded through ctypes, behaves exactly like kins/rotatekins.py."""
from __future__ import annotations

import ctypes
import shutil
from pathlib import Path

import numpy as np
import pytest

from edingcnc_lang.errors import PluginError
from edingcnc_lang.kinematics import abi
from edingcnc_lang.kinematics.base import KinematicsDomainError, as_pose
from edingcnc_lang.kinematics.build import build_plugin
from edingcnc_lang.kinematics.ctypes_plugin import (
    CncCartDouble,
    CncJointDouble,
    CompiledKinematics,
    KinControlData,
)
from edingcnc_lang.kinematics.loader import load_kinematics
from edingcnc_lang.kinematics.shipped import import_shipped

RotateKins = import_shipped("rotatekins").RotateKins


def test_abi_layout() -> None:
    assert ctypes.sizeof(CncCartDouble) == ctypes.sizeof(CncJointDouble) == 48
    assert ctypes.sizeof(KinControlData) == 96


def test_c_and_python_agree_on_1000_poses(rotatekins_so: Path) -> None:
    c_kins, py_kins = CompiledKinematics(rotatekins_so), RotateKins({})
    assert (c_kins.kin_type(), c_kins.version()) == (py_kins.kin_type(), py_kins.version())
    for kins in (c_kins, py_kins):
        assert kins.control(abi.ON, [3.5, -8.25] + [0.0] * 10) == 0
        assert kins.control(abi.USER1, [-20.0, 41.0] + [0.0] * 10) == 0
    rows = np.random.default_rng(2024).uniform(-500.0, 500.0, (1000, 6))
    for row in rows:
        pose = as_pose(row)
        c_joints, py_joints = c_kins.inverse(pose, 12.0), py_kins.inverse(pose, 12.0)
        np.testing.assert_allclose(c_joints, py_joints, rtol=0, atol=1e-9)
        np.testing.assert_allclose(c_kins.forward(c_joints), py_kins.forward(py_joints), rtol=0, atol=1e-9)
    np.testing.assert_allclose(c_kins.user_output(), [*py_kins.user_output(), *[0.0] * 9], atol=1e-12)
    assert c_kins.user_output()[:3] == (-20.0, 41.0, rows[-1, 5])


def test_c_controls(rotatekins_so: Path) -> None:
    kins = CompiledKinematics(rotatekins_so)
    data = [7.0, 9.0] + [0.0] * 10
    assert kins.control(abi.USER1, data) == 0
    out = [0.0] * 12
    assert kins.control(abi.USER3, out) == 0 and out[:2] == [7.0, 9.0]
    assert kins.control(abi.USER6, [0.0] * 12) == -1
    assert kins.has_export("KinematicsInverse") and not kins.has_export("KinematicsInverseMaxFeed")
    assert kins.inverse_max_feed((0.0,) * 6, (1.0,) * 6) is None


def test_loader_finds_the_so_beside_a_dll_name(rotatekins_so: Path) -> None:
    kins = load_kinematics("rotatekins.dll", {}, [rotatekins_so.parent])
    assert isinstance(kins, CompiledKinematics) and kins.kin_type() == 3


MISSING_FORWARD = """
#include "edingcnc_kins.h"
int KINS_CALL KinematicsInverse(CNC_CART_DOUBLE pos, CNC_JOINT_DOUBLE *j, const CNC_KINEMATICS_INVERSE_FLAGS *i,
                                CNC_KINEMATICS_FORWARD_FLAGS *f, double t) { return pos.x > 1.0; }
int KINS_CALL KinematicsControl(int id, KIN_CONTROLDATA *d) { return -1; }
CNC_KINEMATICS_TYPE KINS_CALL KinematicsType(void) { return CNC_KINEMATICS_TYPE_CUSTOM_1; }
char *KINS_CALL KinematicsVersion(void) { return "half"; }
"""


@pytest.fixture()
def half_plugin(tmp_path: Path) -> Path:
    if shutil.which("cc") is None:
        pytest.skip("no C compiler (cc) on PATH")
    source = tmp_path / "half.c"
    source.write_text(MISSING_FORWARD)
    return build_plugin(source, check_exports=False)


def test_missing_export_is_a_plugin_error(half_plugin: Path) -> None:
    with pytest.raises(PluginError, match=r"half\.so: it does not export KinematicsForward"):
        load_kinematics(str(half_plugin), {})


def test_nonzero_inverse_is_a_domain_error(half_plugin: Path, tmp_path: Path) -> None:
    full = tmp_path / "full.c"
    full.write_text(MISSING_FORWARD + """
int KINS_CALL KinematicsForward(CNC_JOINT_DOUBLE j, CNC_CART_DOUBLE *p, const CNC_KINEMATICS_FORWARD_FLAGS *f,
                                CNC_KINEMATICS_INVERSE_FLAGS *i, double t) { return 0; }""")
    kins = CompiledKinematics(build_plugin(full))
    with pytest.raises(KinematicsDomainError, match="X2 Y0 .* out of reach") as err:
        kins.inverse_many(np.array([[0.0] * 6, [2.0] + [0.0] * 5]))
    assert err.value.sample == 1
    assert kins.user_output() == ()


def test_compiler_error_is_a_plugin_error(tmp_path: Path) -> None:
    if shutil.which("cc") is None:
        pytest.skip("no C compiler (cc) on PATH")
    source = tmp_path / "broken.c"
    source.write_text("int KinematicsType(void) { return }\n")
    with pytest.raises(PluginError, match=r"(?s)compiling .*broken\.c failed.*error: expected expression"):
        build_plugin(source)


def test_missing_compiler_is_a_plugin_error(tmp_path: Path) -> None:
    source = tmp_path / "x.c"
    source.write_text("")
    with pytest.raises(PluginError, match="cannot run the C compiler 'no-such-cc'"):
        build_plugin(source, cc="no-such-cc")
