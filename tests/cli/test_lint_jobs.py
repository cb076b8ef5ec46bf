"""``ecnc lint -j N``: many files on several processes, the same findings as one process."""
from __future__ import annotations

import json
from pathlib import Path

import pytest

from edingcnc_lang.lint import LintOptions, lint_paths, lint_paths_parallel
from edingcnc_lang.lint.parallel import split
from tests.cli_runner import invoke


def _shop(tmp_path: Path) -> Path:
    """A CAM shop's folder: independent jobs beside the controller's macro.cnc, some with mistakes."""
    shop = tmp_path / "jobs"
    shop.mkdir()
    (shop / "macro.cnc").write_text(";@unit mm\nSub park\n  G0 Z5\nEndSub\n")
    for index in range(12):
        body = ["G0 X1", "GoSub park"]
        if index % 3 == 0:
            body.append("G0 G1 X2")     # G500
        if index % 4 == 0:
            body.append("GoSub nowhere")  # S208
        (shop / f"job{index:02d}.nc").write_text("\n".join(body) + "\nM30\n")
    return shop


@pytest.mark.slow
def test_jobs_give_the_same_findings_as_one_process(tmp_path: Path) -> None:
    shop = _shop(tmp_path)
    one = invoke("lint", "--format", "json", shop)
    three = invoke("lint", "--format", "json", "-j", "3", shop)
    assert (one.exit_code, three.exit_code) == (1, 1)
    assert json.loads(three.stdout) == json.loads(one.stdout)
    assert {d["code"] for d in json.loads(one.stdout)} == {"G500", "S208"}


@pytest.mark.slow
def test_the_python_api_and_an_ini_among_the_paths(tmp_path: Path) -> None:
    shop = _shop(tmp_path)
    ini = tmp_path / "cnc.ini"
    ini.write_text("[TRAJECTORY]\ninterpolationTime = 0\n")
    serial = lint_paths([shop, ini], LintOptions())
    assert lint_paths_parallel([shop, ini], LintOptions(), jobs=2) == serial
    assert sum(d.code == "C701" for d in serial) == 1  # checked in every group, reported once


def test_split_keeps_neighbours_together() -> None:
    assert split(["a", "b", "c", "d", "e"], 2) == [["a", "b", "c"], ["d", "e"]]
    assert split(["a"], 3) == [["a"]]


def test_jobs_must_be_a_count() -> None:
    result = invoke("lint", "-j", "-1", ".")
    assert result.exit_code == 2 and "argument --jobs" in result.stderr


@pytest.mark.slow
def test_jobs_from_the_real_program(tmp_path: Path) -> None:
    """Worker processes start fresh (spawn): ``python -m edingcnc_lang`` must not run again in them."""
    import subprocess
    import sys

    shop = _shop(tmp_path)
    done = subprocess.run([sys.executable, "-m", "edingcnc_lang", "lint", "-j", "2", "--no-source", str(shop)],
                          capture_output=True, text=True, check=False, timeout=120)
    assert done.returncode == 1 and done.stderr == ""
    assert done.stdout == invoke("lint", "--no-source", shop).stdout


def test_the_program_keeps_its_trees_to_the_end_and_main_frees_them(tmp_path: Path, capsys) -> None:
    """``entry()`` ends the process without freeing anything, so lint leaves its parsed files to it (and
    out of the collector's sight); through ``main()`` (embedded) nothing is kept."""
    import gc

    from edingcnc_lang.cli import main, run_command_line
    from edingcnc_lang.lint.model import SourceFile

    shop = _shop(tmp_path)
    kept: list[object] = []
    frozen = gc.get_freeze_count()
    try:
        assert run_command_line(["lint", str(shop)], kept) == 1
        assert sorted(Path(s.path).name for s in kept if isinstance(s, SourceFile)) == \
            [*(f"job{i:02d}.nc" for i in range(12)), "macro.cnc"]
        assert gc.get_freeze_count() > frozen
    finally:
        gc.unfreeze()
    assert main(["lint", str(shop)]) == 1
    assert gc.get_freeze_count() == 0
    assert "G500" in capsys.readouterr().out
