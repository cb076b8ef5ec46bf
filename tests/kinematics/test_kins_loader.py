"""Resolving kinematicsDLLName: registered names, the fallback table, .py and .so files, and every failure."""
from __future__ import annotations

import tomllib
from importlib import metadata
from pathlib import Path

import pytest

from edingcnc_lang.errors import PluginError
from edingcnc_lang.kinematics import loader
from edingcnc_lang.kinematics.builtin import CoreXYKinematics
from edingcnc_lang.kinematics.loader import ENTRY_POINT_GROUP, available_kinematics, load_kinematics

REPO = Path(__file__).resolve().parents[2]
PLUGIN_PY = """
from edingcnc_lang.kinematics.base import KinematicsPlugin

class Doubler(KinematicsPlugin):
    name = "doubler"
    def __init__(self, settings):
        super().__init__(settings)
        self.gain = self.setting("doublerGain", 2.0)
    def inverse(self, pos, tool_length=0.0):
        return tuple(self.gain * p for p in pos)
    def forward(self, joints, tool_length=0.0):
        return tuple(j / self.gain for j in joints)
"""


def fake_entry_points(monkeypatch: pytest.MonkeyPatch, **names: str) -> None:
    """Pretend the installed metadata registers exactly ``names`` (name -> "module:Class")."""
    entries = [metadata.EntryPoint(name=n, value=v, group=ENTRY_POINT_GROUP) for n, v in names.items()]
    monkeypatch.setattr(metadata, "entry_points", lambda group: [e for e in entries if e.group == group])


def test_pyproject_registers_the_fallback_table() -> None:
    project = tomllib.loads((REPO / "pyproject.toml").read_text())["project"]
    registered = project["entry-points"][ENTRY_POINT_GROUP]
    assert registered == {name: f"{module}:{cls}" for name, (module, cls) in loader.BUILTIN.items()}


@pytest.mark.parametrize(("name", "kin_type"), [
    ("trivial", 1), ("rotatekins.dll", 3), ("DeltaKins.DLL", 4), ("corexy", 5), ("deltakins.so", 4)])
def test_builtin_names_without_installed_metadata(monkeypatch: pytest.MonkeyPatch, name: str, kin_type: int) -> None:
    fake_entry_points(monkeypatch)
    assert load_kinematics(name, {}).kin_type() == kin_type


def test_entry_points_come_first(monkeypatch: pytest.MonkeyPatch) -> None:
    fake_entry_points(monkeypatch, trivial="edingcnc_lang.kinematics.builtin:CoreXYKinematics",
                      belts="edingcnc_lang.kinematics.builtin:CoreXYKinematics")
    assert isinstance(load_kinematics("trivial", {}), CoreXYKinematics)
    assert isinstance(load_kinematics("Belts.dll", {}), CoreXYKinematics)
    assert "belts" in loader.registered_names()


def test_broken_entry_point(monkeypatch: pytest.MonkeyPatch) -> None:
    fake_entry_points(monkeypatch, broken="no_such_module_xyz:Kins")
    with pytest.raises(PluginError, match="'broken': loading entry point no_such_module_xyz:Kins failed"):
        load_kinematics("broken", {})
    assert ("broken", 0) == available_kinematics()[0][:2]


def test_settings_reach_the_plugin() -> None:
    kins = load_kinematics("deltakins", {"lindeltaradius": "100", "lindeltaarmlength": "200"})
    assert kins.inverse((0, 0, 0, 0, 0, 0))[0] == pytest.approx((200**2 - 100**2) ** 0.5)


def test_constructor_config_error_becomes_plugin_error() -> None:
    with pytest.raises(PluginError, match="deltakins.*linDeltaRadius = 'x' is not a number"):
        load_kinematics("deltakins", {"lindeltaradius": "x"})


def test_unknown_name() -> None:
    with pytest.raises(PluginError, match=r"'mystery\.dll' not found.*\(corexy, deltakins, rotatekins, trivial"):
        load_kinematics("mystery.dll", {}, [Path("/nonexistent")])


def test_py_file_by_path_and_in_search_dir(tmp_path: Path) -> None:
    (tmp_path / "doubler.py").write_text(PLUGIN_PY)
    by_path = load_kinematics(str(tmp_path / "doubler.py"), {"doublergain": "3"})
    assert by_path.inverse((1, 2, 3, 4, 5, 6)) == (3, 6, 9, 12, 15, 18)
    by_name = load_kinematics("Doubler.dll", {}, [tmp_path])
    assert by_name.name == "doubler" and by_name.forward((2, 4, 6, 8, 10, 12)) == (1, 2, 3, 4, 5, 6)
    assert by_name.kin_type() == 18


def test_kinematics_attribute_picks_the_class(tmp_path: Path) -> None:
    (tmp_path / "two.py").write_text(PLUGIN_PY + "\nclass Other(Doubler):\n    pass\n\nKINEMATICS = Other\n")
    kins = load_kinematics(str(tmp_path / "two.py"), {})
    assert type(kins).__name__ == "Other" and kins.name == "doubler"
    (tmp_path / "anon.py").write_text(PLUGIN_PY.replace('name = "doubler"', "pass"))
    assert load_kinematics(str(tmp_path / "anon.py"), {}).name == str(tmp_path / "anon.py")


@pytest.mark.parametrize(("source", "reason"), [
    (PLUGIN_PY + "\nclass Other(Doubler):\n    pass\n", r"expected one KinematicsPlugin subclass.*Doubler, Other"),
    ("x = 1\n", r"expected one KinematicsPlugin subclass.*found: none"),
    ("import no_such_module_xyz\n", "importing it failed: ModuleNotFoundError"),
    ("def broken(:\n", "importing it failed: SyntaxError"),
    (PLUGIN_PY.replace("self.gain = ", "raise RuntimeError('no licence'); self.gain = "),
     "constructing it failed: RuntimeError: no licence"),
    ("class K:\n    def __init__(self, settings):\n        pass\nKINEMATICS = K\n", "it lacks kin_type, version"),
])
def test_py_plugin_failures_name_the_plugin(tmp_path: Path, source: str, reason: str) -> None:
    path = tmp_path / "userkins.py"
    path.write_text(source)
    with pytest.raises(PluginError, match=rf"(?s)kinematics plug-in .*userkins\.py: {reason}"):
        load_kinematics(str(path), {})


@pytest.mark.parametrize(("source", "where"), [
    ("import math\n\ndef broken(:\n", ":3:12: error: "),
    ("import math\n\ndef f():\n    return 1 / 0\n\nf()\n", ":4: error: "),
    ("import no_such_module_xyz\n", ":1: error: "),
])
def test_a_py_plugin_that_fails_to_import_names_its_own_line(tmp_path: Path, source: str, where: str) -> None:
    path = tmp_path / "userkins.py"
    path.write_text(source)
    with pytest.raises(PluginError) as info:
        load_kinematics(str(path), {})
    assert info.value.format().startswith(f"{path}{where}kinematics plug-in {path}: importing it failed: ")


def test_so_path_that_is_not_a_library(tmp_path: Path) -> None:
    path = tmp_path / "fake.so"
    path.write_text("not an ELF file")
    with pytest.raises(PluginError, match=r"fake\.so: cannot load the library"):
        load_kinematics(str(path), {})


def test_available_kinematics_lists_builtins() -> None:
    listed = {name: kin_type for name, kin_type, _ in available_kinematics()}
    assert {"trivial": 1, "rotatekins": 3, "deltakins": 4, "corexy": 5}.items() <= listed.items()
