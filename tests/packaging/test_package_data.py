"""The package's data folders are real folders (no symlinks anywhere in git: a Windows clone checks a
symlink out as a text file and the install breaks), and the copies of the top-level ``kins/`` and
``stdlib/`` (the source of truth, which the product card names) are byte-equal to them."""
from __future__ import annotations

import importlib.util
import subprocess
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2]
spec = importlib.util.spec_from_file_location("sync_package_data", ROOT / "scripts" / "sync_package_data.py")
assert spec and spec.loader
sync = importlib.util.module_from_spec(spec)
spec.loader.exec_module(sync)


def test_no_symlink_is_tracked() -> None:
    listed = subprocess.run(["git", "ls-files", "-s"], cwd=ROOT, capture_output=True, text=True, check=False)
    if listed.returncode != 0:
        pytest.skip("not a git checkout")
    links = [line.split("\t", 1)[1] for line in listed.stdout.splitlines() if line.startswith("120000")]
    assert not links, f"symlinks in git: {links}"


@pytest.mark.parametrize("name", sync.FOLDERS)
def test_the_package_copy_is_the_top_level_folder(name: str) -> None:
    source, copy = ROOT / name, ROOT / "edingcnc_lang" / name
    assert not copy.is_symlink() and copy.is_dir()
    assert sync.tracked_files(copy) == sync.tracked_files(source), \
        f"edingcnc_lang/{name} lists other files than {name}/: run python scripts/sync_package_data.py"
    differ = [rel.as_posix() for rel in sync.tracked_files(source)
              if (source / rel).read_bytes() != (copy / rel).read_bytes()]
    assert not differ, f"edingcnc_lang/{name} differs from {name}/ in {differ}: run python scripts/sync_package_data.py"


def test_the_grammar_is_a_real_package_folder() -> None:
    grammar = ROOT / "edingcnc_lang" / "syntax" / "grammar"
    assert not grammar.is_symlink() and (grammar / "macro.lark").is_file() and (grammar / "gcode.lark").is_file()


def test_the_sync_script_runs_clean_on_an_equal_checkout() -> None:
    done = subprocess.run([sys.executable, str(ROOT / "scripts" / "sync_package_data.py")], capture_output=True,
                          text=True, check=False)
    assert (done.returncode, done.stdout) == (0, "")
