"""``ecnc kins check/compare/plot``: the shipped plug-ins pass, each broken plug-in is caught by its finding."""
from __future__ import annotations

import shutil
from pathlib import Path

import pytest

from edingcnc_lang.errors import PluginError
from edingcnc_lang.kinematics.build import build_plugin
from edingcnc_lang.kinematics.workbench import CheckOptions, check_plugin, compare_plugins
from edingcnc_lang.kinematics.workbench.findings import FINDING_CODES, report_from_json
from edingcnc_lang.kinematics.workbench.workspace import parse_box

pytestmark = pytest.mark.slow  # the whole module (pyproject's slow marker)

ROOT = Path(__file__).resolve().parents[2]
BROKEN = Path(__file__).resolve().parent / "broken"
QUICK = dict(samples=600, segments=80, speed=False)
needs_cc = pytest.mark.skipif(shutil.which("cc") is None, reason="no C compiler (cc) to build the C plug-ins")


def codes(report) -> set[str]:
    return {f.code for f in report.findings}


@pytest.mark.parametrize("name, ini", [
    ("trivial", None),
    ("corexy", None),
    ("rotatekins", "examples/rotate/cnc.ini"),
    ("deltakins", "examples/delta/cnc.ini"),
    ("deltakins", None),
])
def test_shipped_plugins_pass(name: str, ini: str | None) -> None:
    report = check_plugin(name, CheckOptions(ini=str(ROOT / ini) if ini else None, **QUICK))
    assert report.ok, report.format()
    assert [s.name for s in report.sections] == ["domain", "round trip", "continuity", "singularity", "control",
                                                 "compiled"]


@pytest.fixture(scope="module")
def built(tmp_path_factory: pytest.TempPathFactory) -> Path:
    if shutil.which("cc") is None:
        pytest.skip("no C compiler (cc) to build the C plug-ins")
    folder = tmp_path_factory.mktemp("cplugins")
    for source in (ROOT / "kins/c/rotatekins.c", ROOT / "examples/cplugin/mycorexy.c", BROKEN / "crash_corner.c"):
        build_plugin(source, folder / f"{source.stem}.so")
    return folder


@needs_cc
def test_compiled_plugins_pass_and_report_their_abi(built: Path) -> None:
    for so in ("rotatekins.so", "mycorexy.so"):
        report = check_plugin(str(built / so), CheckOptions(ini=str(ROOT / "examples/rotate/cnc.ini"), **QUICK))
        assert report.ok, report.format()
        compiled = next(s for s in report.sections if s.name == "compiled")
        assert "KinematicsInverse" in compiled.figures["exports"]
        assert compiled.figures["struct_sizes"]["KIN_CONTROLDATA"] == 96


@needs_cc
def test_crash_in_a_compiled_plugin_is_a_finding_naming_call_and_pose(built: Path) -> None:
    report = check_plugin(str(built / "crash_corner.so"), CheckOptions(**QUICK))
    [finding] = report.findings
    assert finding.code == "K602"
    assert "KinematicsInverse crashed the process (SIGSEGV)" in finding.message
    assert finding.pose is not None and finding.pose[0] > 90 and finding.pose[1] > 90


@pytest.mark.parametrize("plugin, box, expected", [
    ("scaled_forward.py", None, {"K101", "K102"}),
    ("wrapping_angle.py", (-100, -10, -50, 50, 0, 10), {"K202"}),
    ("nan_corner.py", None, {"K401"}),
    ("branch_flip.py", (50, 150, -50, 50, 0, 10), {"K201"}),
    ("drifting.py", None, {"K503", "K504"}),
    ("polar_atan.py", None, {"K101", "K201"}),
    ("trunnion_sign.py", None, {"K101", "K102"}),  # the default cube: A is proven over a turn
])
def test_broken_plugins_are_caught_by_the_right_finding(plugin: str, box, expected: set[str]) -> None:
    report = check_plugin(str(BROKEN / plugin), CheckOptions(box=box, **QUICK))
    assert codes(report) == expected, report.format()


def test_a_rotary_axis_that_moves_other_joints_is_proven_over_a_turn() -> None:
    """Without --box or --ini, A B C are held at 0 unless turning one moves another joint: a
    trunnion's A, the virtual C of rotatekins; never a rotary passed through (trivial, deltakins)."""
    def box(name: str) -> tuple[tuple[float, float], ...]:
        return tuple(tuple(pair) for pair in check_plugin(name, CheckOptions(**QUICK)).box)

    assert box(str(BROKEN / "trunnion_sign.py"))[3:] == ((-180.0, 180.0), (0.0, 0.0), (0.0, 0.0))
    assert box("rotatekins")[3:] == ((0.0, 0.0), (0.0, 0.0), (-180.0, 180.0))
    for name in ("trivial", "deltakins", str(BROKEN / "polar_atan.py")):
        assert box(name)[3:] == ((0.0, 0.0),) * 3, name
    given = check_plugin(str(BROKEN / "trunnion_sign.py"), CheckOptions(box=(-10, 10, -10, 10, -10, 10), **QUICK))
    assert given.ok  # a --box is taken as given, even one that holds A


def test_a_jump_is_shown_with_both_poses_and_joints() -> None:
    report = check_plugin(str(BROKEN / "branch_flip.py"), CheckOptions(box=(50, 150, -50, 50, 0, 10), **QUICK))
    [jump] = report.findings
    assert jump.pose[1] <= 0.0 <= jump.other_pose[1] or jump.other_pose[1] <= 0.0 <= jump.pose[1]
    assert abs(jump.joints[1] - jump.other_joints[1]) > 100.0
    assert "jumps by" in jump.message and "jY" in jump.message


def test_nan_finding_names_a_corner_pose() -> None:
    report = check_plugin(str(BROKEN / "nan_corner.py"), CheckOptions(**QUICK))
    [nan] = report.findings
    assert nan.pose[0] ** 2 + nan.pose[1] ** 2 > 120.0 ** 2
    assert "KinematicsDomainError" in nan.message


def test_reports_are_reproducible_and_survive_json() -> None:
    options = CheckOptions(ini=str(ROOT / "examples/delta/cnc.ini"), seed=7, **QUICK)
    first, second = check_plugin("deltakins", options), check_plugin("deltakins", options)
    assert first.to_json() == second.to_json()
    assert report_from_json(first.to_json()).to_json() == first.to_json()
    assert first.to_json()["box"]["source"] == "cnc.ini [KINEMATICS] limits"
    assert 0.0 < first.to_json()["checks"]["domain"]["reachable_fraction"] < 0.2


def test_workspace_from_joint_limits_through_the_forward(tmp_path: Path) -> None:
    ini = tmp_path / "cnc.ini"
    ini.write_text("[JOINT_0]\npositiveLimit = 300\nnegativeLimit = 0\n[JOINT_1]\npositiveLimit = 50\n"
                   "negativeLimit = -50\n[JOINT_2]\npositiveLimit = 0\nnegativeLimit = -100\n", encoding="latin-1")
    report = check_plugin("corexy", CheckOptions(ini=str(ini), **QUICK))
    assert report.box_source.startswith("cnc.ini joint limits")
    (x_lo, x_hi), (y_lo, y_hi) = report.box[0], report.box[1]
    assert -30 < x_lo < x_hi < 180 and -30 < y_lo < y_hi < 180  # x = (jx + jy) / 2, y = (jx - jy) / 2


def test_compare_agrees_with_itself_and_finds_the_scaled_copy() -> None:
    same = compare_plugins("corexy", "corexy", CheckOptions(**QUICK))
    assert same.ok and max(d.largest for d in same.inverse + same.forward) == 0.0
    scaled = compare_plugins(str(BROKEN / "scaled_forward.py"), "trivial", CheckOptions(**QUICK))
    assert not scaled.ok
    worst = next(d for d in scaled.forward if d.name == "X")
    assert worst.largest == pytest.approx(1.0) and abs(worst.pose[0]) == pytest.approx(100.0)


@needs_cc
def test_compare_c_port_with_its_python_original(built: Path) -> None:
    result = compare_plugins(str(built / "rotatekins.so"), "rotatekins",
                             CheckOptions(ini=str(ROOT / "examples/rotate/cnc.ini"), **QUICK))
    assert result.ok, result.format()
    assert result.samples == 600


def test_box_validation() -> None:
    assert parse_box([1, 0, 0, 1, 0, 1]).box[0] == (0, 1)
    with pytest.raises(ValueError, match="6 to 12 numbers"):
        parse_box([0, 1, 0, 1])


def test_unknown_plugin_is_an_error_not_a_finding() -> None:
    with pytest.raises(PluginError, match="not found"):
        check_plugin("no_such_kins", CheckOptions(**QUICK))


def test_every_finding_code_is_documented() -> None:
    text = (ROOT / "docs" / "kinematics.md").read_text(encoding="utf-8")
    assert [code for code in FINDING_CODES if code not in text] == []


def test_envelope_picture_shows_reach_and_its_edge(tmp_path: Path) -> None:
    pytest.importorskip("matplotlib")
    import matplotlib.image as mpimg

    from edingcnc_lang.kinematics.workbench import check
    from edingcnc_lang.kinematics.workbench.envelope import plot_envelope

    machine = check.read_machine(None)
    kins = check.load_plugin("deltakins", machine)
    space = check.workspace_for(kins, CheckOptions(box=(-150, 150, -150, 150, -50, 100)), machine)
    path = plot_envelope(kins, space, tmp_path / "delta.png", "deltakins", resolution=24)
    pixels = mpimg.imread(path)[..., :3]
    green = ((abs(pixels[..., 0] - 0x4c / 255) < 0.02) & (abs(pixels[..., 1] - 0x9a / 255) < 0.02)).sum()
    grey = ((abs(pixels - 0xd9 / 255) < 0.02).all(axis=-1)).sum()
    assert green > 20_000 and grey > 5_000  # the reachable triangle and the unreachable rim are both drawn


@needs_cc
def test_kins_inverse_and_plot_survive_a_crashing_compiled_plugin(built: Path) -> None:
    """`ecnc kins inverse` calls a compiled plug-in in a child: a crash is exit 70 naming the call and
    the pose, never a dead ecnc (SIGSEGV); a pose that does not crash answers as in-process."""
    from tests.cli_runner import invoke

    crashed = invoke("kins", "inverse", str(built / "crash_corner.so"), "100", "100", "-100")
    assert crashed.exit_code == 70 and crashed.stdout == ""
    assert crashed.stderr.endswith("KinematicsInverse crashed the process (SIGSEGV) at X100 Y100 Z-100 A0 B0 C0\n")
    plotted = invoke("kins", "plot", str(built / "crash_corner.so"), "-o", str(built / "crash.png"),
                     "--resolution", "12")
    assert plotted.exit_code == 70 and "KinematicsInverse crashed the process (SIGSEGV) at X" in plotted.stderr
    compared = invoke("kins", "compare", "trivial", str(built / "crash_corner.so"), "--samples", "50")
    assert compared.exit_code == 70 and "(SIGSEGV) at X100 Y100" in compared.stderr
    fine = invoke("kins", "forward", str(built / "rotatekins.so"), "--", "-1", "2", "3")
    assert (fine.exit_code, fine.stdout) == (0, '{"x": -1.0, "y": 2.0, "z": 3.0, "a": 0.0, "b": 0.0, "c": 0.0}\n')


@pytest.mark.skipif(not hasattr(__import__("os"), "mkfifo"), reason="no FIFOs here")
def test_a_child_that_hangs_is_an_error_naming_the_wait(tmp_path: Path) -> None:
    """kins inverse/forward of a compiled plug-in run in a child; one that never returns is K604's
    text as an error, not a hang of ecnc (the child here waits on a FIFO nobody writes)."""
    import os

    from edingcnc_lang.kinematics.workbench.isolate import run_command_isolated

    fifo = tmp_path / "never.nc"
    os.mkfifo(fifo)
    with pytest.raises(PluginError, match=r"kinematics plug-in 'x\.so': the plug-in did not return within 1 s"):
        run_command_isolated(["run", str(fifo)], "x.so", timeout=1.0)
