"""Copy the top-level ``kins/`` and ``stdlib/`` (the source of truth) into the package (``edingcnc_lang/kins``,
``edingcnc_lang/stdlib``), which the wheel and an editable install read.

Both are real folders in git (no symlinks: a Windows clone checks a symlink out as a text file and the
install breaks); ``tests/packaging/test_package_data.py`` fails while a package copy differs from its top-level
file, and names this script.  Run it after editing a file under ``kins/`` or ``stdlib/``:

    python scripts/sync_package_data.py
"""
from __future__ import annotations

import shutil
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
FOLDERS = ("kins", "stdlib")  # top-level folder -> edingcnc_lang/<the same name>


def tracked_files(folder: Path) -> list[Path]:
    """The files of ``folder`` that belong to the project (no caches or build products), relative to it."""
    return sorted(p.relative_to(folder) for p in folder.rglob("*")
                  if p.is_file() and "__pycache__" not in p.parts and p.suffix not in (".pyc", ".so", ".dll", ".o"))


def main() -> int:
    for name in FOLDERS:
        source, target = ROOT / name, ROOT / "edingcnc_lang" / name
        wanted = tracked_files(source)
        for stale in set(tracked_files(target)) - set(wanted):
            (target / stale).unlink()
            print(f"removed edingcnc_lang/{name}/{stale.as_posix()}")
        for rel in wanted:
            (target / rel).parent.mkdir(parents=True, exist_ok=True)
            if not (target / rel).exists() or (target / rel).read_bytes() != (source / rel).read_bytes():
                shutil.copyfile(source / rel, target / rel)
                print(f"copied {name}/{rel.as_posix()}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
