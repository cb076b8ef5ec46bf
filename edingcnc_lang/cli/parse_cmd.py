"""``ecnc parse FILE [--json]``: check the syntax of a file, optionally dump its AST."""
from __future__ import annotations

import sys

import click

from ..errors import EXIT_OK
from .base import Command
from .options import json_option
from .params import INPUT_FILE, STDIN
from .streams import STDIN_NAME, read_stdin


@click.command("parse", cls=Command, short_help="Parse FILE without running it (exit 65 on syntax errors).")
@click.argument("file", metavar="FILE", type=INPUT_FILE)
@json_option("Print the AST as JSON.")
@click.option("--no-spans", is_flag=True, help="Leave source positions out of the JSON.")
def parse(file: str, as_json: bool, no_spans: bool) -> int:
    """Parse FILE without running it (exit 65 on syntax errors); FILE - reads standard input."""
    from ..parser import check_file, parse_text, read_statements
    from ..serialize import write_program

    text = read_stdin() if file == STDIN else None
    if as_json and text is None:  # checked first, then written as it is read again: memory stays flat
        check_file(file)
        reader = read_statements(file)
        write_program(file, reader, lambda: reader.unit, sys.stdout, with_spans=not no_spans)
    elif as_json:
        program = parse_text(text, STDIN_NAME)  # type: ignore[arg-type]
        write_program(STDIN_NAME, program.body, lambda: program.unit, sys.stdout, with_spans=not no_spans)
    elif text is not None:
        parse_text(text, STDIN_NAME)
    else:
        check_file(file)  # streams: memory stays flat however long the file is
    return EXIT_OK
