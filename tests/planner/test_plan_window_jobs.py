"""Whole jobs on the compiled core: straight ones timed without numpy, all to the same bytes as the Python core.

``ecnc run --trace`` and ``--json`` of a G1 job, a drilling job and a job of straight moves of every kind
(moves one by one, exact stop, homing, a tool change; the windows of straight moves are
planned in C, csrc/speedups_plan.c) must not load numpy at all; and the small versions of the
benchmark jobs (benchmarks/bench_run.py's writers: CAM, R and I/J arcs among them, whose windows of arcs are
planned in C too) and the examples run to the same trace, events,
estimate and limits report on both cores (the Python core in a worker process, tests/core_outcome.py).
"""
from __future__ import annotations

import importlib.util
import json
import subprocess
import sys
from collections.abc import Callable
from pathlib import Path
from types import ModuleType

import pytest

from edingcnc_lang import speedups
from tests.core_outcome import outcome

pytestmark = pytest.mark.slow  # the whole module (pyproject's slow marker)

ROOT = Path(__file__).resolve().parents[2]
needs_c = pytest.mark.skipif(speedups.compiled("plan_window") is None,
                             reason="the compiled core is not built (or the Python one runs)")

# runs the ecnc command (as ``entry`` does, which ends the process at once) and then says whether numpy was loaded
RUN_CLI = """
import sys
from edingcnc_lang.cli import run_command_line
code = run_command_line(sys.argv[1:], [])
print("numpy loaded:", "numpy" in sys.modules, file=sys.stderr)
sys.exit(code)
"""


# straight moves of every kind and state: the general path's single moves, exact stop and G64 P, an
# override, a dwell, a rotary axis, a tool change (the macro's moves), homing, a canned cycle
MIXED_JOB = """G21 G90 G64 P0.05
G0 X10 Y10 Z5 M3 S1000
G1 Z-1 F300 (plunge)
#1 = 5
G1 X[#1 * 4] Y20 F1200
G61
G1 X30
G64
M50 P120
G1 Y40 A30
G4 P0.5
T2 M6
G0 Z10
G28
G81 X5 Y5 Z-2 R1 F200
X10
G80
M30
"""


def _bench() -> ModuleType:
    """benchmarks/bench_run.py, for its job writers (the jobs the figures are measured on)."""
    spec = importlib.util.spec_from_file_location("bench_run", ROOT / "benchmarks" / "bench_run.py")
    assert spec is not None and spec.loader is not None
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


@pytest.fixture(scope="module")
def jobs(tmp_path_factory: pytest.TempPathFactory) -> dict[str, Path]:
    bench, folder = _bench(), tmp_path_factory.mktemp("straight-jobs")
    made = {"g1": folder / "g1.nc", "drill": folder / "drill.nc", "cam": folder / "cam.nc", "mixed": folder / "mixed.nc"}
    made["mixed"].write_text(MIXED_JOB)
    bench.write_g1_job(made["g1"], 6000)
    bench.write_drill_job(made["drill"], 1500)
    bench.write_cam_job(made["cam"], 3000)
    for name, r_form in (("rarcs", True), ("ijarcs", False)):
        made[name] = folder / f"{name}.nc"
        bench.write_arc_job(made[name], 3000, r_form)
    return made


@needs_c
@pytest.mark.parametrize("name", ["g1", "drill", "mixed"])
@pytest.mark.parametrize("output", ["--trace", "--json"])
def test_straight_jobs_are_timed_without_numpy(jobs: dict[str, Path], tmp_path: Path, name: str, output: str) -> None:
    args = [str(jobs[name]), "--trace", str(tmp_path / "trace.csv")] if output == "--trace" else [str(jobs[name]),
                                                                                                   "--json"]
    result = subprocess.run([sys.executable, "-c", RUN_CLI, "run", *args], capture_output=True, text=True, cwd=ROOT)
    assert result.returncode == 0, result.stderr
    assert "numpy loaded: False" in result.stderr
    if output == "--json":
        estimate = json.loads(result.stdout)["estimate"]
        assert estimate["seconds"] > 0.0 and estimate["distance"]["feed"] > 0.0
    else:
        rows = (tmp_path / "trace.csv").read_text().splitlines()
        assert len(rows) > (10 if name == "mixed" else 1000) and float(rows[-1].rsplit(",", 1)[1]) > 0.0


@pytest.mark.parametrize("name", ["g1", "drill", "cam", "rarcs", "ijarcs", "mixed"])
def test_benchmark_jobs_run_alike_on_both_cores(jobs: dict[str, Path], python_core: Callable[[Path], str],
                                                name: str) -> None:
    compiled = outcome(jobs[name])
    assert compiled.count("\n") > (10 if name == "mixed" else 1000) and compiled == python_core(jobs[name])


EXAMPLES = sorted(str(p.relative_to(ROOT)) for p in (ROOT / "examples").rglob("*.nc"))


@pytest.mark.parametrize("example", EXAMPLES)
def test_examples_run_alike_on_both_cores(python_core: Callable[[Path], str], tmp_path: Path, example: str) -> None:
    job = tmp_path / Path(example).name  # (the trace and events are written beside the job)
    source = ROOT / example
    job.write_bytes(source.read_bytes())
    for sibling in source.parent.iterdir():  # the files it calls or reads beside it
        if sibling.is_file() and sibling.name != job.name:
            (tmp_path / sibling.name).write_bytes(sibling.read_bytes())
    assert outcome(job) == python_core(job)
