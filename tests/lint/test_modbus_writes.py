"""Issue 21 item 8, in the linter: what a new user tripped on."""
from __future__ import annotations

from pathlib import Path

import pytest

from tests.cli_runner import invoke


@pytest.mark.parametrize("line", ["modbus s1 f3 a100 n1 u100", "MODBUS S1 F3 A100 N1 U100"])
def test_a_modbus_read_writes_its_target_variable(tmp_path: Path, line: str) -> None:
    """``modbus ... uNNN`` stores what it reads in #NNN, so reading #NNN afterwards is no V302."""
    (tmp_path / "job.nc").write_text(f"{line}\nG0 X#100\nG0 Y#101\n")
    out = invoke("lint", "--no-source", "--select", "V302", tmp_path / "job.nc").stdout
    assert "#100" not in out
    assert ":3:5: V302 #101" in out  # another variable is still reported
