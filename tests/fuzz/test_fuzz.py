"""Fuzzing (issue 17): whatever the input, parse, print, lint and run end in a result or an EcncError,
never another exception, a hang or a write outside the log folder.

CI runs the derandomized ``ci`` profile (a hundred examples each, a few seconds); hunt locally with
``python -m pytest tests/fuzz --hypothesis-profile=fuzz`` (random, 20,000 examples each).
"""
from __future__ import annotations

import os
import tempfile
from pathlib import Path

from hypothesis import HealthCheck, given, settings

from edingcnc_lang.config import load_config
from edingcnc_lang.errors import EcncError
from edingcnc_lang.heightmap import ZhcTable
from edingcnc_lang.lint import lint_paths
from edingcnc_lang.parser import parse_text
from edingcnc_lang.printer import program_text
from edingcnc_lang.runner import RunOptions, run_file
from edingcnc_lang.source import read_text

from .strategies import INI_SEEDS, ZHC_TABLE_SEEDS, mutants, programs

EMPTY_MACRO = Path(__file__).resolve().parents[1] / "interpreter" / "data" / "empty_macro.cnc"
RELAXED = settings(deadline=None, suppress_health_check=[HealthCheck.too_slow, HealthCheck.data_too_large])


def _everything(data: bytes) -> None:
    """Parse, print, lint and run ``data`` as a job in a fresh folder; only EcncError may come out."""
    with tempfile.TemporaryDirectory() as folder:
        root = Path(folder)
        logs = root / "logs"
        logs.mkdir()
        job = logs / "job.nc"
        job.write_bytes(data)
        text = read_text(job)
        try:
            program = parse_text(text, str(job))
        except EcncError:
            program = None
        if program is not None:
            parse_text(program_text(program))  # the printed form of what parsed parses again
        lint_paths([job])
        try:
            run_file(job, RunOptions(macro=EMPTY_MACRO, max_steps=3000, log_dir=logs))
        except EcncError:
            pass
        assert os.listdir(root) == ["logs"]  # nothing written outside the log folder


@RELAXED
@given(programs)
def test_programs_from_the_grammar_never_crash(text: str) -> None:
    _everything(text.encode("utf-8", "surrogatepass"))


@RELAXED
@given(mutants())
def test_mutants_of_real_files_never_crash(data: bytes) -> None:
    _everything(data)


def _read_only_ecnc_errors(data: bytes, read) -> None:  # type: ignore[no-untyped-def]
    """Write ``data`` to a file and ``read`` it: only EcncError may come out."""
    with tempfile.TemporaryDirectory() as folder:
        path = Path(folder) / "file"
        path.write_bytes(data)
        try:
            read(path)
        except EcncError:
            pass


@RELAXED
@given(mutants(INI_SEEDS))
def test_mutants_of_real_inis_never_crash(data: bytes) -> None:
    _read_only_ecnc_errors(data, load_config)


@RELAXED
@given(mutants(ZHC_TABLE_SEEDS))
def test_mutants_of_a_height_table_never_crash(data: bytes) -> None:  # ZHCL reads what a job archive ships
    _read_only_ecnc_errors(data, ZhcTable.load)
