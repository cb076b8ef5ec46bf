"""``ecnc sim`` on the jobs in ``golden/``: the report as a user sees it, against the stored text.

Each job's first line is the command's arguments (``; ecnc sim --stock ...``); the report is in
``NAME.txt`` beside it (the seconds the simulation took are left out).  Rewrite with
``python -m pytest tests/sim/test_golden.py --regen-goldens``.
"""
from __future__ import annotations

import re
import shlex
from pathlib import Path

import pytest

from tests.cli_runner import invoke

GOLDEN = Path(__file__).resolve().parent / "golden"


@pytest.mark.parametrize("job", sorted(p.name for p in GOLDEN.glob("*.nc")))
def test_report(job, golden, monkeypatch):
    monkeypatch.chdir(GOLDEN)
    first = (GOLDEN / job).read_bytes().splitlines()[0].decode("latin-1")
    args = shlex.split(first.removeprefix("; ecnc sim"))
    result = invoke("sim", job, *args)
    text = re.sub(r", [0-9.]+ s\)", ")", result.stdout) + f"exit {result.exit_code}\n"
    golden(GOLDEN / f"{Path(job).stem}.txt", text)
