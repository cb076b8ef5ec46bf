"""Fuzzing (issue 17): whatever the input, parse, print, lint and run end in a result or an EcncError,
never another exception, a hang or a write outside the log folder.

CI runs the derandomized ``ci`` profile (a hundred examples each, a few seconds); hunt locally with
``python -m pytest tests/fuzz --hypothesis-profile=fuzz`` (random, 20,000 examples each).
"""
from __future__ import annotations

import os
import tempfile
from pathlib import Path

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from edingcnc_lang.config.machine_config import load_config
from edingcnc_lang.errors import EcncError
from edingcnc_lang.config.heightmap import ZhcTable
from edingcnc_lang.lint import lint_paths
from edingcnc_lang.syntax.parser import parse_text
from edingcnc_lang.syntax.printer import program_text
from edingcnc_lang.runner import RunOptions, run_file
from edingcnc_lang.syntax.source import read_text

from .strategies import INI_SEEDS, ZHC_TABLE_SEEDS, mutants, programs

pytestmark = pytest.mark.slow  # the whole module (pyproject's slow marker)

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
        assert job.read_bytes() == data  # nor over the job (logfile "job.nc", ZHCS job.nc)


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


# ----------------------------------------------------------------------------- every command
# Each command of ``ecnc`` (cli.COMMANDS) with generated jobs and arguments: ``invoke`` lets no
# exception through, so a traceback fails the test; stdout must stay one JSON document with --json.

_ARGS = st.sampled_from(["--json", "--max-steps=50", "--answer=ok:#1=1_0", "--answer=ok", "--feed-override=１００",
                         "--block-delete", "--strict", "-q"])
_KINS = st.sampled_from([["kins", "list"], ["kins", "inverse", "trivial", "1", "2", "３"],
                         ["kins", "forward", "trivial", "1", "2", "3", "nan"],
                         ["kins", "check", "trivial", "--box", "10", "100", "-50", "50", "-5", "5", "--samples", "3",
                          "--no-speed"],
                         ["kins", "check", "trivial", "--box=nan,1,2,3,4,5"], ["kins", "check", "trivial", "--samples=1e9"],
                         ["kins", "compare", "trivial", "trivial", "--samples", "3"],
                         ["kins", "plot", "trivial", "-o", "out.txt", "--resolution", "1000000"],
                         ["kins", "build", "job.nc", "-o", "job.nc"],
                         ["help", "run"], ["help", "E100"], ["lsp", "--help"], ["mdi", "--help"]])


@settings(RELAXED, max_examples=40)  # a CLI run each: fewer examples than the in-process tests
@given(programs, st.sampled_from(["run", "lint", "parse", "view", "plot"]), st.lists(_ARGS, max_size=3))
def test_every_command_on_generated_jobs_ends_in_an_exit_code(text: str, command: str, extra: list[str]) -> None:
    from tests.cli_runner import invoke

    if command in ("lint", "parse", "plot", "view"):  # their options differ: the job alone
        extra = ["--json"] if command in ("lint", "parse") and "--json" in extra else []
    with tempfile.TemporaryDirectory() as folder:
        root = Path(folder)
        job = root / "job.nc"
        job.write_bytes(text.encode("utf-8", "surrogatepass"))
        out = ["-o", str(root / ("job.svg" if command == "plot" else "job.html"))] if command in ("plot", "view") else []
        result = invoke(command, job, *out, *extra, *(["--macro", str(EMPTY_MACRO)] if command == "run" else []))
        assert result.exit_code in (0, 1, 2, 65, 70), result.output
        if "--json" in extra and result.stdout.strip():
            import json

            json.loads(result.stdout)  # one document, whatever the job printed
        assert job.read_bytes() == text.encode("utf-8", "surrogatepass")


@settings(RELAXED, max_examples=30)
@given(_KINS)
def test_the_other_commands_end_in_an_exit_code(argv: list[str]) -> None:
    from tests.cli_runner import invoke

    with tempfile.TemporaryDirectory() as folder:
        previous = os.getcwd()
        os.chdir(folder)
        try:
            Path("job.nc").write_text("G0 X1\n")
            result = invoke(*argv)
        finally:
            os.chdir(previous)
        assert result.exit_code in (0, 1, 2, 65, 70), result.output


def _dap(*messages: dict[str, object]) -> bytes:
    """Debug Adapter Protocol requests as an editor frames them."""
    import json

    out = b""
    for seq, message in enumerate(messages, 1):
        body = json.dumps({"seq": seq, "type": "request", **message}).encode()
        out += b"Content-Length: %d\r\n\r\n" % len(body) + body
    return out


@settings(RELAXED, max_examples=24)  # a CLI run each
@given(programs, st.sampled_from(["diff", "sim", "test", "debug"]), st.binary(max_size=40))
def test_the_newer_commands_on_generated_jobs_end_in_an_exit_code(text: str, command: str, noise: bytes) -> None:
    """``ecnc diff``, ``sim``, ``test`` and ``debug`` on generated jobs (``debug`` driven over DAP,
    with junk after the session): an exit code, one JSON document with --json, the job untouched."""
    import json

    from tests.cli_runner import invoke

    data = text.encode("utf-8", "surrogatepass")
    with tempfile.TemporaryDirectory() as folder:
        root = Path(folder)
        job = root / "job.nc"
        job.write_bytes(data)
        stdin: bytes | None = None
        if command == "diff":
            (root / "old.nc").write_bytes(data + b"\nG0 X1\n")
            argv: list[object] = ["diff", root / "old.nc", job, "--json", "--macro", EMPTY_MACRO]
        elif command == "sim":
            argv = ["sim", job, "--stock", "-20,-20,-20,20,20,5", "--resolution", "2", "--json", "--macro", EMPTY_MACRO]
        elif command == "test":
            (root / "test_generated.toml").write_text(
                f'[[test]]\nname = "generated"\njob_file = "job.nc"\nmacro = {json.dumps(str(EMPTY_MACRO))}\n')
            argv = ["test", root]
        else:
            argv = ["debug"]
            stdin = _dap({"command": "initialize", "arguments": {"adapterID": "ecnc"}},
                         {"command": "launch", "arguments": {"program": str(job), "macro": str(EMPTY_MACRO),
                                                              "noDebug": True}},
                         {"command": "configurationDone"}, {"command": "disconnect"}) + noise
        result = invoke(*argv, input=stdin)
        assert result.exit_code in (0, 1, 2, 65, 70), result.output
        if "--json" in argv and result.stdout.strip():
            json.loads(result.stdout)
        assert job.read_bytes() == data
