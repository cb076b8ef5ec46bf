"""``ecnc parse FILE [--json]``: check the syntax of a file, optionally dump its AST."""
from __future__ import annotations

import sys

import click

from edingcnc_lang.errors import EXIT_OK
from edingcnc_lang.cli.base import Command
from edingcnc_lang.cli.options import json_option
from edingcnc_lang.cli.value_types import INPUT_FILE
from edingcnc_lang.cli.streams import job_to_read_twice


@click.command("parse", cls=Command, short_help="Parse FILE without running it (exit 65 on syntax errors).")
@click.argument("file", metavar="FILE", type=INPUT_FILE)
@json_option("Print the AST as JSON.")
@click.option("--no-spans", is_flag=True, help="Leave source positions out of the JSON.")
def parse(file: str, as_json: bool, no_spans: bool) -> int:
    """Parse FILE without running it (exit 65 on syntax errors); FILE - reads standard input."""
    from edingcnc_lang.syntax.parser import check_file, read_statements
    from edingcnc_lang.syntax.serialize import write_program

    with job_to_read_twice(file) as (path, name):
        check_file(path, name)  # streams: memory stays flat however long the file is
        if as_json:  # then written as it is read again
            reader = read_statements(path, name=name)
            write_program(name or file, reader, lambda: reader.unit, sys.stdout, with_spans=not no_spans)
    return EXIT_OK
