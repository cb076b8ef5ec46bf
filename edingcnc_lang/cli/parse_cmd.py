"""``ecnc parse FILE [--json]``: check the syntax of a file, optionally dump its AST."""
from __future__ import annotations

import sys

import click

from ..errors import EXIT_OK
from .base import Command
from .options import json_option
from .params import INPUT_FILE
from .streams import job_to_read_twice


@click.command("parse", cls=Command, short_help="Parse FILE without running it (exit 65 on syntax errors).")
@click.argument("file", metavar="FILE", type=INPUT_FILE)
@json_option("Print the AST as JSON.")
@click.option("--no-spans", is_flag=True, help="Leave source positions out of the JSON.")
def parse(file: str, as_json: bool, no_spans: bool) -> int:
    """Parse FILE without running it (exit 65 on syntax errors); FILE - reads standard input."""
    from ..parser import check_file, read_statements
    from ..serialize import write_program

    with job_to_read_twice(file) as (path, name):
        check_file(path, name)  # streams: memory stays flat however long the file is
        if as_json:  # then written as it is read again
            reader = read_statements(path, name=name)
            write_program(name or file, reader, lambda: reader.unit, sys.stdout, with_spans=not no_spans)
    return EXIT_OK
