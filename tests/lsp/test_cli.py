"""``ecnc lsp`` is the server an editor starts; without pygls it says what to install."""
from __future__ import annotations

import subprocess
import sys
from pathlib import Path

import pytest

from tests.lsp.client import LspClient

pytestmark = pytest.mark.slow  # the whole module (pyproject's slow marker)


def test_ecnc_lsp_serves_until_the_client_exits(tmp_path: Path) -> None:
    job = tmp_path / "job.nc"
    job.write_text("G0 X10+5\n")
    lsp = LspClient([sys.executable, "-m", "edingcnc_lang", "lsp", "--stdio"])
    lsp.initialize(tmp_path)
    found = lsp.diagnostics(lsp.open(job))
    assert [(d["code"], d["message"]) for d in found] == [("E105", "expression needs brackets: X10+5 (write X[10+5])")]
    assert lsp.close() == 0


def test_without_the_lsp_extra_the_error_names_the_install_command() -> None:
    hide = "import sys; sys.modules['pygls'] = None; from edingcnc_lang.cli import main; sys.exit(main(['lsp']))"
    result = subprocess.run([sys.executable, "-c", hide], capture_output=True, text=True, stdin=subprocess.DEVNULL)
    assert result.returncode == 2
    assert result.stderr.startswith("error: the language server needs pygls")
    assert "pip install 'edingcnc-lang[lsp]'" in result.stderr
    assert "Traceback" not in result.stderr


def test_initialization_options_select_and_ignore_codes(tmp_path: Path) -> None:
    job = tmp_path / "job.nc"
    job.write_text("G38.2 Z-5 F100\nG1 X5 F0\nG0 X10+5\n")
    lsp = LspClient()
    lsp.initialize(tmp_path, {"ignore": "g504,E1"})
    assert [d["code"] for d in lsp.diagnostics(lsp.open(job))] == ["G503"]
    assert lsp.close() == 0
    lsp = LspClient()
    lsp.initialize(tmp_path, {"select": "Q9"})  # no such code: a warning, and every code is reported
    found = lsp.diagnostics(lsp.open(job))
    assert {d["code"] for d in found} == {"G504", "G503", "E105"}
    warning = next(m for m in lsp.notifications if m.get("method") == "window/showMessage")
    assert "no code starts with Q9" in warning["params"]["message"]
    assert lsp.close() == 0


def test_a_malformed_message_is_one_line_on_stderr_and_the_server_goes_on(tmp_path: Path) -> None:
    job = tmp_path / "job.nc"
    job.write_text("G0 X10+5\n")
    lsp = LspClient([sys.executable, "-m", "edingcnc_lang", "lsp", "--stdio"])
    lsp.initialize(tmp_path)
    assert lsp.proc.stdin is not None
    lsp.proc.stdin.write(b"Content-Length: 9\r\n\r\n{not json")  # not JSON at all
    lsp.notify("textDocument/hover", {"bad": 1})  # JSON, but not a hover request's shape
    found = lsp.diagnostics(lsp.open(job))
    assert [d["code"] for d in found] == ["E105"]  # still serving
    lsp.request("shutdown")
    lsp.notify("exit")
    assert lsp.proc.wait(timeout=30) == 0
    assert lsp.proc.stderr is not None
    err = lsp.proc.stderr.read().decode()
    assert "ecnc lsp: error: Unable to handle message: JSONDecodeError" in err
    assert "Traceback" not in err
