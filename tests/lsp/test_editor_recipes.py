"""docs/editors.md's set-ups: Emacs's run by a real Emacs (the mode and eglot from the page's elisp
block start ``ecnc lsp``, and the findings and hover arrive; skipped without Emacs and eglot,
Debian: apt-get install emacs-nox elpa-eglot, eglot is built in from Emacs 29), Helix's checked as
TOML."""
from __future__ import annotations

import os
import re
import shutil
import subprocess
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2]
EMACS = shutil.which("emacs")

CHECK = """
(find-file (expand-file-name "job.nc"))
(message "mode: %s" major-mode)
(apply #'eglot (eglot--guess-contact))
(let ((deadline (+ (float-time) 60)) found)
  (while (and (< (float-time) deadline) (not found))
    (accept-process-output nil 0.5)
    (flymake-start)
    (setq found (flymake-diagnostics)))
  (dolist (d found) (message "diag: %s" (flymake-diagnostic-text d))))
(goto-char (point-min))
(forward-line 1)
(let ((hover (jsonrpc-request (eglot-current-server) :textDocument/hover (eglot--TextDocumentPositionParams))))
  (message "hover: %s" (plist-get (plist-get hover :contents) :value)))
(kill-emacs 0)
"""


@pytest.mark.slow
@pytest.mark.skipif(EMACS is None, reason="Emacs is not installed")
def test_eglot_with_the_documented_setup_shows_findings_and_hover(tmp_path: Path) -> None:
    has_eglot = subprocess.run([EMACS or "emacs", "--batch", "--eval", "(progn (package-initialize) (require 'eglot))"],
                               capture_output=True, timeout=60)
    if has_eglot.returncode != 0:
        pytest.skip("eglot is not installed (Emacs 29 has it; Debian: elpa-eglot)")
    text = (ROOT / "docs" / "editors.md").read_text(encoding="utf-8")
    block = re.search(r"```elisp\n(.*?)```", text, re.DOTALL)
    assert block, "docs/editors.md has no elisp block"
    (tmp_path / "init.el").write_text("(package-initialize)\n(require 'eglot)\n" + block.group(1))
    (tmp_path / "check.el").write_text(CHECK)
    (tmp_path / "job.nc").write_text("G0 X1\nG1 X5 F0\n")
    # ecnc on PATH is this checkout's, as an editor would find the user's
    shim = tmp_path / "bin"
    shim.mkdir()
    (shim / "ecnc").write_text(f"#!/bin/sh\nPYTHONPATH={ROOT} exec {sys.executable} -m edingcnc_lang \"$@\"\n")
    (shim / "ecnc").chmod(0o755)
    done = subprocess.run([EMACS or "emacs", "--batch", "-l", "init.el", "-l", "check.el"], cwd=tmp_path,
                          capture_output=True, text=True, timeout=180,
                          env={**os.environ, "PATH": f"{shim}{os.pathsep}{os.environ['PATH']}"})
    log = done.stdout + done.stderr
    assert "mode: edingcnc-mode" in log, log[-3000:]
    assert "diag: ecnc [G503]: F0 on a G1 move" in log, log[-3000:]
    assert "hover: **G1**: straight feed move" in log, log[-3000:]


def test_the_helix_languages_toml_is_valid_and_starts_ecnc() -> None:
    """Helix is not at hand to run: its languages.toml block parses, and names the server and the
    debugger as ecnc takes them."""
    try:
        import tomllib
    except ModuleNotFoundError:  # Python 3.10
        import tomli as tomllib  # type: ignore[no-redef]

    text = (ROOT / "docs" / "editors.md").read_text(encoding="utf-8")
    block = re.search(r"## Helix.*?```toml\n(.*?)```", text, re.DOTALL)
    assert block
    config = tomllib.loads(block.group(1))
    (language,) = config["language"]
    assert language["file-types"] == ["cnc", "nc", "ngc", "tap"] and language["language-servers"] == ["ecnc"]
    assert (config["language-server"]["ecnc"]["command"], config["language-server"]["ecnc"]["args"]) == ("ecnc", ["lsp"])
    debugger = language["debugger"]
    assert (debugger["command"], debugger["args"], debugger["transport"]) == ("ecnc", ["debug"], "stdio")
    assert debugger["templates"][0]["args"]["program"] == "{0}"
