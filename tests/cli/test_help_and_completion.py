"""``ecnc help CODE`` / ``lint --explain``, and shell completion (click's ``_ECNC_COMPLETE``)."""
from __future__ import annotations

import json
import os
import shutil
import subprocess
import sys
from pathlib import Path

import pytest

from edingcnc_lang.codes import CODES, KINS_CODES, RUNTIME_CODES
from tests.cli_runner import invoke

ROOT = Path(__file__).resolve().parent.parent.parent


def test_help_code_prints_the_long_explanation() -> None:
    result = invoke("help", "v302")
    assert result.exit_code == 0
    assert result.stdout.startswith(f"V302 (warning): {CODES['V302'].summary}\n\n")
    assert "computed index" in result.stdout  # the paragraph of docs/lint.md about it
    assert invoke("lint", "--explain", "V302").stdout == result.stdout


def test_every_registered_code_has_an_explanation() -> None:
    texts = json.loads((ROOT / "edingcnc_lang" / "lint" / "explanations.json").read_text(encoding="utf-8"))
    assert sorted(texts) == sorted([*CODES, *KINS_CODES, *RUNTIME_CODES])


def test_the_explanations_are_those_of_the_docs() -> None:
    sys.path.insert(0, str(ROOT / "scripts"))
    try:
        from regen_code_explanations import all_explanations
    finally:
        sys.path.pop(0)
    texts = json.loads((ROOT / "edingcnc_lang" / "lint" / "explanations.json").read_text(encoding="utf-8"))
    assert texts == all_explanations(), "run scripts/regen_code_explanations.py"


def test_help_command_and_unknown_topics() -> None:
    assert invoke("help", "kins", "inverse").stdout.startswith("usage: ecnc kins inverse [OPTIONS] NAME X Y Z")
    assert invoke("help").stdout.startswith("usage: ecnc [OPTIONS] COMMAND")
    kins = invoke("help", "k101")
    assert kins.exit_code == 0
    assert kins.stdout.startswith("K101 (kins check, round trip): forward(inverse(p)) does not come back to p\n\n"
                                  "What is wrong: `forward(inverse(p))` is further from `p` than the tolerance")
    result = invoke("help", "Q999")
    assert result.exit_code == 2 and "no command or lint code 'Q999'" in result.stderr


def complete(words: str, env: dict[str, str] | None = None, cwd: Path | None = None) -> list[str]:
    """What ``ecnc`` offers for the last of ``words`` (bash protocol: ``type,value`` lines)."""
    parts = words.split(" ")
    result = subprocess.run([sys.executable, "-m", "edingcnc_lang"], capture_output=True, text=True, check=True,
                            cwd=cwd, env={**os.environ, "_ECNC_COMPLETE": "bash_complete", "COMP_WORDS": words,
                                          "COMP_CWORD": str(len(parts) - 1), "PYTHONPATH": str(ROOT), **(env or {})})
    return [line.split(",", 1)[1] for line in result.stdout.splitlines()]


@pytest.mark.slow
def test_completion_of_commands_options_codes_and_kinematics() -> None:
    assert {"run", "lint", "parse", "kins", "help"} <= set(complete("ecnc "))
    assert "--max-steps" in complete("ecnc run --m")
    assert complete("ecnc lint --select E100,S20") == [f"E100,S20{i}" for i in range(10)]
    assert {"trivial", "corexy", "rotatekins", "deltakins"} <= set(complete("ecnc kins inverse "))
    assert "V302" in complete("ecnc help V3")


@pytest.mark.slow
def test_completion_of_the_workbench_plugins_and_codes() -> None:
    """kins check/compare/plot take PLUGIN like inverse does; help completes the K codes too."""
    assert {"trivial", "rotatekins", "deltakins"} <= set(complete("ecnc kins check "))
    assert complete("ecnc kins compare rotatekins cor") == ["corexy"]
    assert complete("ecnc kins plot delt") == ["deltakins"]
    assert "K101" in complete("ecnc help K1")


@pytest.mark.slow
def test_completion_of_ini_files(tmp_path: Path) -> None:
    for name in ("cnc.ini", "OTHER.INI", "job.nc"):
        (tmp_path / name).write_text("")
    (tmp_path / "machines").mkdir()
    assert complete("ecnc run job.nc --ini ", cwd=tmp_path) == ["OTHER.INI", "cnc.ini", "machines/"]


@pytest.mark.slow
@pytest.mark.parametrize("shell", ["bash", "zsh", "fish"])
def test_the_completion_scripts_are_there(shell: str) -> None:
    script = subprocess.run([sys.executable, "-m", "edingcnc_lang"], capture_output=True, text=True, check=True,
                            env={**os.environ, "_ECNC_COMPLETE": f"{shell}_source", "PYTHONPATH": str(ROOT)}).stdout
    assert "_ECNC_COMPLETE" in script


@pytest.mark.skipif(shutil.which("bash") is None, reason="needs bash")
@pytest.mark.parametrize(("words", "offered"), [
    ("ecnc lint --select = V30", [c for c in CODES if c.startswith("V30")]),  # --select=V30: bash splits at the =
    ("ecnc lint --ignore = E100,S20", [f"E100,S20{i}" for i in range(10)]),
    ("ecnc lint --select V30", [c for c in CODES if c.startswith("V30")]),
    ("ecnc lint --select =", list(CODES)),  # --select=<Tab>
])
def test_bash_completes_after_option_equals(tmp_path: Path, words: str, offered: list[str]) -> None:
    """The bash script ecnc prints, sourced in bash, with COMP_WORDS as bash splits the line
    (``=`` is one of its COMP_WORDBREAKS): the values for the text after the ``=``."""
    folder = tmp_path / "bin"
    folder.mkdir()
    (folder / "ecnc").write_text(f"#!/bin/sh\nPYTHONPATH={ROOT} exec {sys.executable} -m edingcnc_lang \"$@\"\n")
    (folder / "ecnc").chmod(0o755)
    script = (f"source <(_ECNC_COMPLETE=bash_source ecnc)\nCOMP_WORDS=({words})\n"
              f"COMP_CWORD={len(words.split()) - 1}\n_ecnc_completion ecnc\nprintf '%s\\n' \"${{COMPREPLY[@]}}\"\n")
    done = subprocess.run(["bash", "-c", script], capture_output=True, text=True, timeout=60,
                          env={**os.environ, "PATH": f"{folder}{os.pathsep}{os.environ['PATH']}"})
    assert done.stdout.split() == offered, done.stderr
