"""The three integrations of docs/api.md run, and type-check under ``mypy --strict`` as an embedder's
code would (imports of the package followed silently, as from an installed wheel; .ci/wheel-check
runs the same check against the wheel itself)."""
from __future__ import annotations

import importlib.util
import shutil
import subprocess
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2]
EXAMPLES = ROOT / "examples" / "embedding"


def _load(name: str):  # type: ignore[no-untyped-def]
    spec = importlib.util.spec_from_file_location(name, EXAMPLES / f"{name}.py")
    assert spec is not None and spec.loader is not None
    module = importlib.util.module_from_spec(spec)
    sys.modules[name] = module  # (dataclasses look their module up there)
    spec.loader.exec_module(module)
    return module


def test_the_post_harness_passes_a_good_job_and_reports_a_bad_one_with_codes(tmp_path: Path) -> None:
    harness = _load("post_harness")
    assert harness.check(ROOT / "examples" / "pocket.nc") == []
    bad = tmp_path / "bad.nc"
    bad.write_text("G21 G90\nG1 X10 F20000\nT200 M6\nM30\n", encoding="utf-8")
    failures = harness.check(bad)
    assert [(f.code, f.line) for f in failures] == [("R821", 3), ("H001", 2)]


def test_the_live_preview_stops_when_the_button_is_pressed(tmp_path: Path) -> None:
    job = tmp_path / "long.nc"
    job.write_text("G21 G90 F1000\n" + "".join(f"G1 X{i % 40} Y{i % 9}\n" for i in range(20000)) + "M30\n",
                   encoding="utf-8")
    seen, drawn, stopped = _load("live_preview").preview(job, stop_after_moves=100)
    assert stopped and 100 <= seen < 20000 and drawn > 0


def test_the_macro_report_lists_subs_calls_and_writes() -> None:
    text = _load("macro_report").report(ROOT / "stdlib" / "macro.cnc")
    assert "change_tool: calls measure_tool" in text and text.splitlines()[-1].startswith("findings: ")


@pytest.mark.skipif(shutil.which("mypy") is None and importlib.util.find_spec("mypy") is None,
                    reason="mypy is not installed (CI installs it)")
@pytest.mark.slow
def test_the_examples_and_the_api_tests_pass_mypy_strict() -> None:
    done = subprocess.run([sys.executable, "-m", "mypy", "--strict", "--follow-imports=silent",
                           "--no-incremental", str(EXAMPLES), str(ROOT / "tests" / "api")],
                          capture_output=True, text=True, cwd=ROOT)
    assert done.returncode == 0, done.stdout + done.stderr
