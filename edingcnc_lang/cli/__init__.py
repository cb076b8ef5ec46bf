"""The ``ecnc`` command line: one click group, one module per subcommand.

A subcommand module imports its implementation inside the command function, so ``ecnc --help``
and each command start without loading what the other commands need (the parser, numpy, ...).
"""
from __future__ import annotations

import click

from .. import __version__
from .kins_cmd import kins
from .lint_cmd import lint
from .parse_cmd import parse
from .run_cmd import run


@click.group(context_settings={"help_option_names": ["-h", "--help"]})
@click.version_option(__version__, prog_name="ecnc")
def main() -> None:
    """Parse, run, lint and simulate EdingCNC G-code and macro files."""


main.add_command(parse)
main.add_command(kins)
main.add_command(lint)
main.add_command(run)
