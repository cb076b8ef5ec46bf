"""Colour on a terminal only (NO_COLOR, pipes), and the progress line's rendering and rules."""
from __future__ import annotations

import io
import time

import pytest

from edingcnc_lang.cli import progress
from edingcnc_lang.cli.style import colour_diagnostics, styled, wants_colour


class Terminal(io.StringIO):
    def isatty(self) -> bool:
        return True


def test_colour_marks_severity_codes_and_carets() -> None:
    text = "job.nc:3:5: error: unclosed '['\n    G0 X[1\n        ^\njob.nc:1:1: V302 read\njob.nc:2: warning: w"
    coloured = colour_diagnostics(text)
    assert "\x1b[31m\x1b[1merror\x1b[0m" in coloured and "\x1b[33m\x1b[1mwarning\x1b[0m" in coloured
    assert "\x1b[33m\x1b[1mV302\x1b[0m" in coloured  # V302 is a warning
    assert "        \x1b[32m\x1b[1m^\x1b[0m" in coloured
    assert "    G0 X[1\n" in coloured  # the source line itself stays as it is


def test_colour_only_on_a_terminal_and_never_with_no_color(monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.delenv("NO_COLOR", raising=False)
    monkeypatch.setenv("TERM", "xterm")
    assert wants_colour(Terminal()) and not wants_colour(io.StringIO()) and not wants_colour(None)
    monkeypatch.setenv("NO_COLOR", "")
    assert not wants_colour(Terminal())
    assert styled("a.nc:1: error: x", Terminal()) == "a.nc:1: error: x"


def test_the_progress_line() -> None:
    line = progress.render(2500, 10000, "line 2,500/10,000  moves 2,400", 5.0)
    assert line == "[======>                 ]  25%  line 2,500/10,000  moves 2,400  0:05 elapsed  0:15 left"
    assert progress.render(0, 0, "checking 3 files", 65.0) == "checking 3 files  1:05 elapsed"


def test_progress_shows_after_the_delay_and_clears_itself(monkeypatch: pytest.MonkeyPatch) -> None:
    terminal = Terminal()
    monkeypatch.setattr("sys.stderr", terminal)
    monkeypatch.setattr(progress, "DELAY", 0.0)
    with progress.Progress(lambda: (1, 2, "half"), True):
        time.sleep(0.3)
    assert "half" in terminal.getvalue() and terminal.getvalue().endswith("\r\x1b[K")
    quiet = Terminal()
    monkeypatch.setattr("sys.stderr", quiet)
    with progress.Progress(lambda: (1, 2, "half"), False):
        time.sleep(0.05)
    assert quiet.getvalue() == ""


def test_progress_is_only_for_a_terminal(monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setattr("sys.stderr", io.StringIO())
    assert not progress.wanted(False)
    monkeypatch.setattr("sys.stderr", Terminal())
    assert progress.wanted(False) and not progress.wanted(True)


def test_lint_shows_no_progress_with_a_format_for_programs(monkeypatch: pytest.MonkeyPatch, tmp_path) -> None:
    """--format json, sarif or github is read by programs: like run's --json, no progress line."""
    from tests.cli_runner import invoke

    job = tmp_path / "job.nc"
    job.write_text("G0 X1\n")
    asked: list[bool] = []
    monkeypatch.setattr(progress, "wanted", lambda quiet: asked.append(quiet) or False)
    for fmt in ("text", "json", "sarif", "github"):
        assert invoke("lint", "--format", fmt, job).exit_code == 0
    assert asked == [False, True, True, True]
