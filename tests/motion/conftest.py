"""Fixtures of the motion tests: ``ecnc run`` in-process, the compiled C plug-in."""
from __future__ import annotations

import shutil
from pathlib import Path

import pytest
from motion_helpers import REPO, Outcome, Sections, ini_text

from tests.cli_runner import invoke


@pytest.fixture
def run_job(tmp_path: Path):  # type: ignore[no-untyped-def]
    """run_job(job_text, sections=None, *options) -> Outcome of ``ecnc run job.nc --json [--ini cnc.ini] ...``."""
    def run(job: str, sections: Sections | None = None, *options: str) -> Outcome:
        job_path = tmp_path / "job.nc"
        job_path.write_text(job.replace("\n", "\r\n"), newline="")
        args = ["run", str(job_path), "--json", *options]
        if sections is not None:
            (tmp_path / "cnc.ini").write_text(ini_text(sections), newline="")
            args += ["--ini", str(tmp_path / "cnc.ini")]
        result = invoke(*args)  # an exception (a traceback) fails the test
        assert "Traceback" not in result.stderr
        return Outcome(result.exit_code, result.stdout, result.stderr)
    return run


@pytest.fixture(scope="session")
def compiled_rotatekins(tmp_path_factory: pytest.TempPathFactory) -> Path:
    """kins/c/rotatekins.c built with ``ecnc kins build`` in a session folder."""
    if shutil.which("cc") is None:
        pytest.skip("no C compiler (cc) on PATH")
    source = tmp_path_factory.mktemp("cplugin") / "rotatekins.c"
    shutil.copy(REPO / "kins" / "c" / "rotatekins.c", source)
    result = invoke("kins", "build", source)
    assert result.exit_code == 0, result.output
    return source.with_suffix(".so")
