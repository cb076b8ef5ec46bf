"""Every examples/<name>/ folder runs: cnc.ini + job.nc, its C plug-in built first with ``ecnc kins build``."""
from __future__ import annotations

import shutil
from pathlib import Path

import pytest
from motion_helpers import REPO

from tests.cli_runner import invoke

FOLDERS = sorted(p.parent for p in (REPO / "examples").glob("*/job.nc"))


def test_every_required_example_exists() -> None:
    names = {folder.name for folder in FOLDERS}
    assert {"rotate", "delta", "cylinder", "parallel", "tanknife", "cplugin"} <= names
    assert all((folder / "cnc.ini").is_file() for folder in FOLDERS)


@pytest.mark.parametrize("folder", FOLDERS, ids=lambda p: p.name)
def test_example_runs(folder: Path, tmp_path: Path) -> None:
    work = shutil.copytree(folder, tmp_path / folder.name)
    for source in work.glob("*.c"):
        if shutil.which("cc") is None:
            pytest.skip("no C compiler (cc) on PATH")
        built = invoke("kins", "build", source)
        assert built.exit_code == 0, built.output
    result = invoke("run", "--ini", work / "cnc.ini", work / "job.nc", "--json", "--samples", tmp_path / "samples.npz")
    assert result.exit_code == 0, result.stderr
    assert "Traceback" not in result.stderr
    assert (tmp_path / "samples.npz").stat().st_size > 0
