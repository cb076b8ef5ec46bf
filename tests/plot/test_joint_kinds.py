"""Issue 21 item 8: ``plot --joints`` labels rotary joints in degrees, as the plug-in declares its joints."""
from __future__ import annotations

import re
from pathlib import Path

import pytest

from edingcnc_lang import RunOptions
from edingcnc_lang.errors import PluginError
from edingcnc_lang.kinematics.base import declared_joint_kinds
from edingcnc_lang.plot.joints import joint_kind, plot_joints
from edingcnc_lang.plot.toolpath import record_job
from tests.plot.jobs import write

ROOT = Path(__file__).resolve().parents[2]
SCARA = ROOT / "tests" / "kinematics" / "scara" / "cnc.ini"
JOB = "G1 X0 Y90 F1000\nKIN ON\nG1 X250 Y100 Z-10 F3000\nG1 X200 Y-100\n"


@pytest.mark.slow
def test_a_scara_s_arm_joints_are_in_degrees(tmp_path: Path) -> None:
    path = record_job(write(tmp_path, "scara.nc", JOB), RunOptions(ini=SCARA), samples=True)
    assert path.joint_kinds == ("rotary", "rotary", "linear", "rotary", "rotary", "rotary")
    assert [joint_kind(path, j) for j in range(3)] == ["rotary", "rotary", "linear"]
    out = plot_joints(path, tmp_path / "joints.svg")
    text = out.read_text()
    # matplotlib writes each text as glyph paths; the y labels' units are in the svg's comments
    for joint, name, unit in ((0, "X", "deg"), (1, "Y", "deg"), (2, "Z", "mm")):
        assert f"joint {joint} ({name})\n{unit}" in _texts(text)


def _texts(svg: str) -> str:
    """The texts matplotlib wrote into the svg (as comments beside the glyphs)."""
    return "\n".join(re.findall(r"<!-- (.*?) -->", svg, flags=re.S))


def test_without_a_declaration_the_joint_name_decides(tmp_path: Path) -> None:
    path = record_job(write(tmp_path, "plain.nc", "G1 X10 A90 F1000\n"), samples=True)
    assert path.joint_kinds is None
    assert [joint_kind(path, j) for j in (0, 3)] == ["linear", "rotary"]


class _Bad:
    name = "bad"
    JOINT_KINDS = ("rotary", "angular")


def test_a_malformed_declaration_is_the_plugin_s_error() -> None:
    with pytest.raises(PluginError, match="JOINT_KINDS must be six of 'linear' or 'rotary'"):
        declared_joint_kinds(_Bad())
