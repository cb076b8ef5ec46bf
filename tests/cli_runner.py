"""``ecnc`` run in-process for tests: the exit code, and stdout and stderr apart as a script sees them."""
from __future__ import annotations

import contextlib
import io
from dataclasses import dataclass

from edingcnc_lang.cli import main


@dataclass(frozen=True)
class Result:
    exit_code: int
    stdout: str
    stderr: str

    @property
    def output(self) -> str:
        """Both streams, for checks that do not care where a text went."""
        return self.stdout + self.stderr


def invoke(*args: object) -> Result:
    """``ecnc ARGS...``.  An exception other than SystemExit is not caught: a CLI that would end
    in a traceback fails the test right there."""
    stdout, stderr = io.StringIO(), io.StringIO()
    with contextlib.redirect_stdout(stdout), contextlib.redirect_stderr(stderr):
        try:
            code = main([str(arg) for arg in args])
        except SystemExit as stop:  # argparse's own exit: --help, --version, usage errors
            assert isinstance(stop.code, int), stop.code
            code = stop.code
    return Result(code, stdout.getvalue(), stderr.getvalue())
