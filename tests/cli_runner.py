"""``ecnc`` run in-process for tests with click's ``CliRunner``: the exit code, and stdout and
stderr apart as a script sees them."""
from __future__ import annotations

from dataclasses import dataclass

from click.testing import CliRunner

from edingcnc_lang.cli import ecnc


@dataclass(frozen=True)
class Result:
    exit_code: int
    stdout: str
    stderr: str

    @property
    def output(self) -> str:
        """Both streams, for checks that do not care where a text went."""
        return self.stdout + self.stderr


ASSUMING = "ecnc: assuming "


def without_assumptions(stderr: str) -> str:
    """``stderr`` without the lines that say what a run assumed (no ini, the packaged macro): every run
    without ``--ini`` prints them; tests/cli/test_first_hour.py checks them, the other tests read past them."""
    return "".join(line for line in stderr.splitlines(keepends=True) if not line.startswith(ASSUMING))


def invoke(*args: object, input: str | bytes | None = None, env: dict[str, str] | None = None,  # noqa: A002
           assumptions: bool = False) -> Result:
    """``ecnc ARGS...``.  An exception is not caught: a CLI that would end in a traceback fails
    the test right there.  ``assumptions``: keep the ``ecnc: assuming`` lines in stderr."""
    result = CliRunner().invoke(ecnc, [str(arg) for arg in args], input=input, env=env, catch_exceptions=False,
                                prog_name="ecnc")
    stderr = result.stderr if assumptions else without_assumptions(result.stderr)
    return Result(result.exit_code, result.stdout, stderr)
