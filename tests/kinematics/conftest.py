"""Shared fixtures of the kinematics tests."""
from __future__ import annotations

import shutil
from pathlib import Path

import pytest

from edingcnc_lang.kinematics.build import build_plugin

REPO = Path(__file__).resolve().parents[2]
ROTATEKINS_C = REPO / "kins" / "c" / "rotatekins.c"


@pytest.fixture(scope="session")
def rotatekins_so(tmp_path_factory: pytest.TempPathFactory) -> Path:
    """kins/c/rotatekins.c compiled once per session with the system C compiler."""
    if shutil.which("cc") is None:
        pytest.skip("no C compiler (cc) on PATH")
    return build_plugin(ROTATEKINS_C, tmp_path_factory.mktemp("rotatekins") / "rotatekins.so")
