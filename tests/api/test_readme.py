"""The README's embedding example runs as written (against a small probing, dialog job)."""
from __future__ import annotations

import re
import subprocess
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]

JOB = """#27 = 5
dlgmsg "Setup" "depth" 27
G0 Z10
G38.2 Z-10 F100
msg "touched at "#5063
"""


def test_the_embedding_example_runs(tmp_path: Path) -> None:
    readme = (ROOT / "README.md").read_text(encoding="utf-8")
    section = readme[readme.index("## Embedding"):]
    code = re.search(r"```python\n(.*?)```", section, re.DOTALL).group(1)  # type: ignore[union-attr]
    (tmp_path / "job.nc").write_text(JOB)
    result = subprocess.run([sys.executable, "-c", code], cwd=tmp_path, capture_output=True, text=True)
    assert result.returncode == 0, result.stderr
    machine, tripped, moves = result.stdout.rsplit(" ", 2)
    assert tripped == "1.0" and moves.strip() == "3"   # the probe tripped: a rapid, the probe move, its back-off
    assert "-8.746" in machine  # 1 mm above the target, where the host said it touched, then 0.254 mm back (p. 25)


def test_errmsg_stops_a_run_with_its_own_error_type() -> None:
    from edingcnc_lang import JobAborted, MachineError, run_string

    try:
        run_string('errmsg "stop"\nG0 X1\n')
    except JobAborted as err:
        assert isinstance(err, MachineError) and err.message == "stop"
    else:
        raise AssertionError("errmsg did not stop the run")
