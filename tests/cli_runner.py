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


def invoke(*args: object, input: str | bytes | None = None, env: dict[str, str] | None = None) -> Result:  # noqa: A002
    """``ecnc ARGS...``.  An exception is not caught: a CLI that would end in a traceback fails
    the test right there."""
    result = CliRunner().invoke(ecnc, [str(arg) for arg in args], input=input, env=env, catch_exceptions=False,
                                prog_name="ecnc")
    return Result(result.exit_code, result.stdout, result.stderr)
