"""Shared pytest options: ``--regen-goldens`` rewrites golden files instead of comparing.

Hypothesis profiles: ``ci`` (the default, and what ``.ci/run`` selects) derandomizes every property
test so a run is repeatable; ``dev`` draws fresh random examples, ten times as many, for local
hunting: ``python -m pytest --hypothesis-profile=dev``; ``fuzz`` runs 20,000 random examples per test
(``python -m pytest tests/fuzz --hypothesis-profile=fuzz``).
"""
from __future__ import annotations

import json
import os
import subprocess
import sys
from collections.abc import Callable, Iterator
from pathlib import Path

import pytest
from hypothesis import settings

ROOT = Path(__file__).resolve().parent.parent

settings.register_profile("ci", derandomize=True, deadline=None, print_blob=True)
settings.register_profile("dev", deadline=None, max_examples=1000)
settings.register_profile("fuzz", deadline=None, max_examples=20_000)  # tests/fuzz, long local hunts
settings.load_profile("ci")


def pytest_addoption(parser: pytest.Parser) -> None:
    parser.addoption("--regen-goldens", action="store_true", default=False,
                     help="rewrite golden files from the current output")


@pytest.fixture
def golden(request: pytest.FixtureRequest):
    """Compare text with a golden file, or rewrite it under --regen-goldens."""
    regen = request.config.getoption("--regen-goldens")

    def check(path: Path, actual: str) -> None:
        if regen or not path.exists():
            path.parent.mkdir(parents=True, exist_ok=True)
            path.write_text(actual, encoding="utf-8")
            if not regen:
                pytest.fail(f"golden file {path} did not exist; written now, review and commit it")
        assert actual == path.read_text(encoding="utf-8"), f"differs from {path} (rerun with --regen-goldens if intended)"

    return check


@pytest.fixture(scope="module")
def python_core() -> Iterator[Callable[[Path], str]]:
    """A worker process on the pure-Python core that runs a job and answers its outcome (``tests/core_outcome.py``),
    for the tests that hold the compiled core to it."""
    from edingcnc_lang import speedups

    if speedups.SPEEDUPS is None:
        pytest.skip("this process runs the Python core already: nothing to compare")
    worker = subprocess.Popen([sys.executable, "-c", "from tests.core_outcome import serve; serve()"], cwd=ROOT,
                              stdin=subprocess.PIPE, stdout=subprocess.PIPE, text=True,
                              env={**os.environ, speedups.PURE_ENV: "1"})

    def ask(job: Path) -> str:
        assert worker.stdin is not None and worker.stdout is not None
        worker.stdin.write(f"{job}\n")
        worker.stdin.flush()
        return str(json.loads(worker.stdout.readline()))
    yield ask
    assert worker.stdin is not None
    worker.stdin.close()
    worker.wait(timeout=60)
