"""cnc.ini reading, MachineConfig loading and validation, and [VARIABLES] write-back."""
from __future__ import annotations

import math
import os
import shutil
from pathlib import Path

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from edingcnc_lang.config import ini as ini_module
from edingcnc_lang.config.machine_config import (
    PERSISTED,
    MachineConfig,
    is_persisted,
    load_config,
    save_variables,
)
from edingcnc_lang.errors import ConfigError
from edingcnc_lang.config.ini import read_ini
from edingcnc_lang.syntax.input_limits import MAX_INI_BYTES

SAMPLE = Path("/work/shared/samples/cnc.ini")
DATA = Path(__file__).resolve().parents[1] / "data" / "config"

needs_sample = pytest.mark.skipif(not SAMPLE.is_file(), reason="shared sample cnc.ini not present")


def write(tmp_path: Path, text: str, name: str = "cnc.ini", eol: str = "\n") -> Path:
    path = tmp_path / name
    path.write_bytes(text.replace("\n", eol).encode())
    return path


# --------------------------------------------------------------------------- the sample ini

@pytest.fixture
def sample_copy(tmp_path: Path) -> Path:
    copy = tmp_path / "machine" / "cnc.ini"
    copy.parent.mkdir()
    shutil.copyfile(SAMPLE, copy)
    return copy


@needs_sample
def test_sample_joints_tools_and_interpreter(sample_copy: Path) -> None:
    cfg = load_config(sample_copy)
    assert cfg.path == str(sample_copy)
    assert [j.name for j in cfg.joints] == ["X", "Y", "Z", "A", "B", "C"]
    x, _, z, a = cfg.joints[:4]
    assert (x.positive_limit, x.negative_limit) == (600.0, 0.0)
    assert x.home_velocity == -20.0  # the trailing ";sign determines direction" is gone
    assert (x.max_velocity, x.max_acceleration, x.resolution) == (100.0, 1000.0, 800.0)
    assert (z.positive_limit, z.negative_limit) == (0.0, -120.0)
    assert a.visible is False and a.home_position == -99999.0
    assert cfg.initial_string == "G17 G21 G40 G49 G54 G80 G90 G94 F500"
    assert cfg.g4_in_milliseconds is False and cfg.g64_active is True
    assert cfg.g64_p == pytest.approx(0.05)
    assert cfg.full_circle_theta_epsilon == pytest.approx(1e-6)
    assert sorted(cfg.tools) == list(range(1, 100))
    assert cfg.tools[2].length == 15.0 and cfg.tools[2].diameter == 3.0
    assert cfg.tools[99].description == "Tool number 99"


@needs_sample
def test_sample_kinematics_trajectory_tanknife_variables(sample_copy: Path) -> None:
    cfg = load_config(sample_copy)
    assert cfg.kinematics_name == "trivial"
    assert float(cfg.kinematics_settings["lindeltaradius"]) == 125.0
    assert float(cfg.kinematics_settings["lindeltaarmlength"]) == 250.0
    assert cfg.cartesian_positive_limits == (300.0,) * 6
    assert cfg.cartesian_negative_limits == (-300.0,) * 6
    assert cfg.cartesian_max_velocity == (25.0,) * 6
    assert cfg.cartesian_max_acceleration == (50.0,) * 6
    assert (cfg.user_output_start, cfg.user_output_count) == (0, 0)
    assert cfg.interpolation_time == 0.005 and cfg.g0_velocity_factor == 1.0
    tk = cfg.tanknife
    assert (tk.angle_for_lift_up, tk.lift_up_distance, tk.z_hi, tk.z_lo) == (5.0, 3.0, 10.0, -2.0)
    assert tk.bending_angle == 0.0 and tk.rewind_turns == 0
    assert cfg.variables[5220] == 1.0 and cfg.variables[4099] == 0.0
    assert len(cfg.variables) == 156


@needs_sample
def test_sample_macro_path_resolves_beside_the_ini(sample_copy: Path) -> None:
    assert load_config(sample_copy).macro_file is None  # C:\CNC4.03\macro.cnc exists nowhere
    (sample_copy.parent / "macro.cnc").write_text(";@unit mm\n")
    (sample_copy.parent / "user_macro.cnc").write_text(";@unit mm\n")
    cfg = load_config(sample_copy)
    assert cfg.macro_file == sample_copy.parent.absolute() / "macro.cnc"
    assert cfg.user_macro_file == sample_copy.parent.absolute() / "user_macro.cnc"


def test_macro_path_as_written_wins(tmp_path: Path) -> None:
    real = tmp_path / "elsewhere" / "macro.cnc"
    real.parent.mkdir()
    real.write_text(";@unit mm\n")
    (tmp_path / "macro.cnc").write_text(";@unit mm\n")
    ini = write(tmp_path, f'[INTERPRETER]\nmacroFileName = "{real}"\n'
                          'userMacroFileName = "elsewhere\\macro.cnc"\n')
    cfg = load_config(ini)
    assert cfg.macro_file == real
    assert cfg.user_macro_file == tmp_path / "elsewhere" / "macro.cnc"  # relative to the ini


# --------------------------------------------------------------------------- ini syntax

@pytest.mark.parametrize("eol", ["\n", "\r\n"])
def test_comments_quotes_case_and_duplicates(tmp_path: Path, eol: str) -> None:
    path = write(tmp_path, (DATA / "comments.ini").read_text(), eol=eol)
    ini = read_ini(path)
    assert ini.get_str("Interpreter", "INITIALSTRING", "") == "G80 F100 ;not a comment"
    assert ini.get("interpreter", "initialstring").line == 6
    assert ini.get_bool("INTERPRETER", "g4InMilliseconds", False) is True
    assert ini.get_str("INTERPRETER", "macroFileName", "") == "C:\\CNC4.03\\macro.cnc"
    assert ini.get_float("INTERPRETER", "g64pvalue", 0.0) == 0.25  # last of two wins
    assert ini.get("INTERPRETER", "g64pvalue").line == 12
    assert ini.get_float("JOINT_2", "negativeLimit", 0.0) == -80.5
    assert ini.get_float("JOINT_2", "maxVelocity", 7.0) == 7.0  # absent: default
    assert ini.section("unknown_section") == {"whatever": "ignored"}
    assert ini.section("no_such_section") == {}
    assert ini.get_str("TOOL_7", "description", "") == "6 mm end mill; 3 flutes"


def test_comment_fixture_as_machine_config(tmp_path: Path) -> None:
    path = write(tmp_path, (DATA / "comments.ini").read_text(), eol="\r\n")
    cfg = load_config(path)
    assert cfg.initial_string == "G80 F100 ;not a comment"
    assert cfg.reverse_g2g3 is True and cfg.full_circle_theta_epsilon == 1e-5
    assert cfg.joints[2].home_velocity == 8.0
    assert cfg.joints[2].max_velocity == MachineConfig.default().joints[2].max_velocity
    assert cfg.kinematics_name == "rotatekins.dll"
    assert cfg.cartesian_max_velocity[2] == 12.5
    assert cfg.tools[7].length == 42.5 and cfg.tools[7].diameter == 6.0
    assert list(cfg.tools) == [7]
    assert dict(cfg.variables) == {4000: 1.5, 4001: -2.25}  # #100 is not persisted


@pytest.mark.parametrize("name", ["latin1.ini", "utf8_bom.ini"])
def test_encodings(name: str) -> None:
    cfg = load_config(DATA / name)
    assert cfg.initial_string == "G80 ; Grüße"
    assert cfg.tools[1].description == "Schaftfräser Ø6"
    assert cfg.tools[1].length == 10.0


def test_bom_does_not_hide_the_first_section(tmp_path: Path) -> None:
    path = tmp_path / "cnc.ini"
    path.write_bytes(b"\xef\xbb\xbf[TRAJECTORY]\r\ninterpolationTime = 0.001\r\n")
    assert load_config(path).interpolation_time == 0.001


def test_integral_float_is_accepted_as_int(tmp_path: Path) -> None:
    ini = read_ini(write(tmp_path, "[KINEMATICS]\nuserOutputNumVariables = 3.000000\n"))
    assert ini.get_int("KINEMATICS", "userOutputNumVariables", 0) == 3


# --------------------------------------------------------------------------- errors

@pytest.mark.parametrize(("text", "line", "fragment"), [
    ("[JOINT_0]\nname = X\nmaxVelocity = fast ;mm/s\n", 3, "maxVelocity in [JOINT_0]: expected a number, got 'fast'"),
    ("[TRAJECTORY]\n\ninterpolationTime = 0,005\n", 3, "interpolationTime in [TRAJECTORY]: expected a number"),
    ("[TOOL_4]\norientation = 1.5\n", 2, "orientation in [TOOL_4]: expected a whole number, got '1.5'"),
    ("[VARIABLES]\n#4000 = 0.0\n#4001 = nan\n", 3, "#4001 in [VARIABLES]: expected a number"),
    ("[VARIABLES]\n#4002 = 1e999\n", 2, "#4002 in [VARIABLES]: expected a number within the range"),
    ("[JOINT_0]\nmaxVelocity = -1e400\n", 2, "maxVelocity in [JOINT_0]: expected a number within the range"),
    # a limit of 0 or less is a mistake in the file, not "no limit"
    ("[JOINT_0]\nname = X\nmaxVelocity = 0\n", 3, "maxVelocity = 0 in [JOINT_0] must be 1e-06 to 1e+09 (mm/s)"),
    ("[JOINT_5]\nmaxAcceleration = -5 ; not used\n", 2, "maxAcceleration = -5 in [JOINT_5] must be 1e-06 to 1e+09"),
    ("[KINEMATICS]\nmaxVelocityB = 0.0\n", 2, "maxVelocityB = 0.0 in [KINEMATICS] must be 1e-06 to 1e+09"),
    ("[KINEMATICS]\nmaxVelocityX = 25\nmaxAccelerationC = -1\n", 3, "maxAccelerationC = -1 in [KINEMATICS]"),
])
def test_bad_number_is_located(tmp_path: Path, text: str, line: int, fragment: str) -> None:
    path = write(tmp_path, text, eol="\r\n")
    with pytest.raises(ConfigError) as info:
        load_config(path)
    err = info.value
    assert (err.location.path, err.location.line) == (str(path), line)
    assert fragment in err.message
    assert err.format().startswith(f"{path}:{line}: error: ")


@pytest.mark.parametrize(("body", "line", "fragment"), [
    ("userOutputStartVariable = 3980\nuserOutputNumVariables = 2\n", 2, "1..3979"),
    ("userOutputStartVariable = -1\nuserOutputNumVariables = 2\n", 2, "1..3979"),
    ("userOutputStartVariable = 100\nuserOutputNumVariables = 13\n", 3, "0..12"),
    ("userOutputStartVariable = 100\nuserOutputNumVariables = 0\n", 2, "nothing would be written"),
    ("userOutputStartVariable = 100\n", 2, "nothing would be written"),
])
def test_user_output_validation(tmp_path: Path, body: str, line: int, fragment: str) -> None:
    path = write(tmp_path, "[KINEMATICS]\n" + body)
    with pytest.raises(ConfigError) as info:
        load_config(path)
    assert info.value.location.line == line
    assert fragment in info.value.message


@pytest.mark.parametrize(("start", "count"), [(0, 0), (0, 5), (1, 1), (3979, 12)])
def test_user_output_accepted(tmp_path: Path, start: int, count: int) -> None:
    path = write(tmp_path, f"[KINEMATICS]\nuserOutputStartVariable = {start}\n"
                           f"userOutputNumVariables = {count}\n")
    cfg = load_config(path)
    assert (cfg.user_output_start, cfg.user_output_count) == (start, count)


@pytest.mark.parametrize(("text", "line", "fragment"), [
    ("[TRAJECTORY]\ninterpolationTime = 0\n", 2, "greater than 0"),
    ("[INTERPRETER]\ntanknifeBendingAngle = 45\n", 2, "+90, -90 or 0"),
])
def test_other_validation(tmp_path: Path, text: str, line: int, fragment: str) -> None:
    with pytest.raises(ConfigError) as info:
        load_config(write(tmp_path, text))
    assert info.value.location.line == line and fragment in info.value.message


def test_missing_file_is_a_config_error(tmp_path: Path) -> None:
    with pytest.raises(ConfigError, match="cannot read machine configuration") as info:
        load_config(tmp_path / "nope.ini")
    assert info.value.location.path == str(tmp_path / "nope.ini")
    with pytest.raises(ConfigError):
        read_ini(tmp_path)  # a folder


# --------------------------------------------------------------------------- defaults

def test_defaults() -> None:
    cfg = MachineConfig.default()
    assert cfg.path is None and cfg.kinematics_name == "trivial"
    assert cfg.interpolation_time == 0.005
    assert [j.name for j in cfg.joints] == list("XYZABC")
    assert all(j.positive_limit >= 1e6 and j.negative_limit <= -1e6 for j in cfg.joints)
    assert all(j.home_position == 0.0 and j.max_velocity >= 1000 for j in cfg.joints)
    assert cfg.macro_file is None and not cfg.tools and not cfg.variables
    assert cfg.user_output_start == 0


def test_empty_ini_gives_defaults_with_its_path(tmp_path: Path) -> None:
    path = write(tmp_path, "; nothing here\n")
    cfg = load_config(path)
    assert cfg.path == str(path)
    assert cfg.joints == MachineConfig.default().joints
    assert cfg.tanknife == MachineConfig.default().tanknife


def test_persisted_ranges() -> None:
    assert is_persisted(4000) and is_persisted(4999) and is_persisted(5220)
    assert is_persisted(5386) and is_persisted(5393) and is_persisted(5008)
    assert not is_persisted(3999) and not is_persisted(5001) and not is_persisted(5387)
    assert not is_persisted(5015) and not is_persisted(5009)
    assert sum(len(r) for r in PERSISTED) == 1000 + 1 + 2 + 6 + 6 + 6 + 1 + 166 + 4


# --------------------------------------------------------------------------- save_variables

@needs_sample
def test_save_variables_changes_only_the_values(sample_copy: Path) -> None:
    before = sample_copy.read_bytes()
    save_variables(sample_copy, {4000: 12.5, 5221: -3.25, 27: 99.0})  # #27 is not persisted
    after = sample_copy.read_bytes()
    expected = (before.replace(b"#4000 = 0.000000\r\n", b"#4000 = 12.500000\r\n")
                .replace(b"#5221 = 0.000000\r\n", b"#5221 = -3.250000\r\n"))
    assert after == expected
    assert load_config(sample_copy).variables[4000] == 12.5


@pytest.mark.slow
@needs_sample
def test_save_variables_appends_missing_at_the_end_of_the_section(sample_copy: Path) -> None:
    before = sample_copy.read_bytes()
    save_variables(sample_copy, {4500: 1.0, 5390: 2.0})
    after = sample_copy.read_bytes()
    anchor = b"#5386 = 0.000000\r\n"
    assert after == before.replace(anchor, anchor + b"#4500 = 1.000000\r\n#5390 = 2.000000\r\n")
    variables = load_config(sample_copy).variables
    assert (variables[4500], variables[5390]) == (1.0, 2.0)


def test_save_variables_keeps_comments_and_following_sections(tmp_path: Path) -> None:
    text = ("[VARIABLES]\n#4000 = 1.000000 ;keep me\n\n[AFTER]\nx = 1\n")
    path = write(tmp_path, text)
    save_variables(path, {4000: 2.0, 4001: 3.0})
    assert path.read_text() == ("[VARIABLES]\n#4000 = 2.000000 ;keep me\n#4001 = 3.000000\n"
                                "\n[AFTER]\nx = 1\n")


def test_save_variables_creates_the_section(tmp_path: Path) -> None:
    path = tmp_path / "cnc.ini"
    path.write_bytes(b"[SYSTEM]\r\nversion = 1")  # no final line ending
    save_variables(path, {4002: -0.5})
    assert path.read_bytes() == b"[SYSTEM]\r\nversion = 1\r\n\r\n[VARIABLES]\r\n#4002 = -0.500000\r\n"


def test_save_variables_keeps_latin1_and_bom_bytes(tmp_path: Path) -> None:
    for name in ("latin1.ini", "utf8_bom.ini"):
        path = tmp_path / name
        original = (DATA / name).read_bytes()
        path.write_bytes(original)
        save_variables(path, {4000: 7.0})
        assert path.read_bytes() == original + b"\n[VARIABLES]\n#4000 = 7.000000\n"


def test_save_variables_is_atomic(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    path = write(tmp_path, "[VARIABLES]\r\n#4000 = 1.000000\r\n")
    before = path.read_bytes()

    def fail(src: str, dst: str) -> None:
        raise OSError(28, "No space left on device")

    monkeypatch.setattr(ini_module.os, "replace", fail)
    with pytest.raises(ConfigError, match="No space left on device"):
        save_variables(path, {4000: 5.0})
    assert path.read_bytes() == before
    assert os.listdir(tmp_path) == ["cnc.ini"]  # the temporary file is gone


def test_save_variables_rejects_non_finite(tmp_path: Path) -> None:
    path = write(tmp_path, "[VARIABLES]\n#4000 = 1.000000\n")
    with pytest.raises(ValueError):
        save_variables(path, {4000: math.inf})
    assert path.read_text() == "[VARIABLES]\n#4000 = 1.000000\n"


@pytest.mark.slow
@settings(max_examples=40, deadline=None)
@given(st.dictionaries(st.sampled_from([4000, 4001, 4777, 5008, 5390]),
                       st.floats(min_value=-1e6, max_value=1e6), max_size=5), st.none() | st.integers(1, 9))
def test_save_then_load_round_trips(tmp_path_factory: pytest.TempPathFactory,
                                    values: dict[int, float], system: int | None) -> None:
    if system is not None:  # #5220 is a coordinate system 1..9 (manual 3.3: anything else is an error)
        values = {**values, 5220: float(system)}
    path = tmp_path_factory.mktemp("rt") / "cnc.ini"
    path.write_bytes(b"[INTERPRETER]\r\ng64Active = 1\r\n\r\n[VARIABLES]\r\n#4001 = 9.000000\r\n")
    save_variables(path, values)
    loaded = load_config(path).variables
    for number, value in values.items():
        assert loaded[number] == pytest.approx(value, abs=1e-6)
    assert b"\n" not in path.read_bytes().replace(b"\r\n", b"")


def test_axis_limits_are_the_joints_on_a_trivial_machine_and_the_cartesian_box_with_kinematics() -> None:
    """One answer for the limits report and the pictures: which travel applies to the axes."""
    from edingcnc_lang.config.machine_config import MachineConfig, load_config

    root = Path(__file__).resolve().parents[2]
    delta = load_config(root / "examples/delta/cnc.ini")
    assert delta.axis_limits() == (list(delta.cartesian_negative_limits), list(delta.cartesian_positive_limits))
    assert delta.axis_limits()[1][:3] == [400.0, 400.0, 200.0]  # not the carriages' 0..420 mm
    plain = MachineConfig.default()
    assert plain.axis_limits() == ([j.negative_limit for j in plain.joints], [j.positive_limit for j in plain.joints])


@pytest.mark.slow
def test_an_ini_past_the_size_limit_is_an_error_not_gigabytes(tmp_path: Path) -> None:
    ini = tmp_path / "cnc.ini"
    ini.write_bytes(b"[VARIABLES]\n" + b"#4000 = 1\n" * (MAX_INI_BYTES // 10))  # just past the limit
    with pytest.raises(ConfigError, match=r"machine configuration larger than 1 MB \(the limit"):
        read_ini(ini)
    ini.write_bytes(ini.read_bytes()[:MAX_INI_BYTES])  # at the limit: read
    assert read_ini(ini).get("variables", "#4000") is not None
