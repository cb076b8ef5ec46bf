"""``ecnc parse FILE [--json]``: check the syntax of a file, optionally dump its AST."""
from __future__ import annotations

import click

from ..errors import EXIT_OK
from .base import Command
from ..gcpause import whole_trees
from .options import json_option
from .params import INPUT_FILE, STDIN
from .streams import STDIN_NAME, read_stdin


@click.command("parse", cls=Command, short_help="Parse FILE without running it (exit 65 on syntax errors).")
@click.argument("file", metavar="FILE", type=INPUT_FILE)
@json_option("Print the AST as JSON.")
@click.option("--no-spans", is_flag=True, help="Leave source positions out of the JSON.")
def parse(file: str, as_json: bool, no_spans: bool) -> int:
    """Parse FILE without running it (exit 65 on syntax errors); FILE - reads standard input."""
    import json

    from ..parser import check_file, parse_file, parse_text
    from ..serialize import to_data

    text = read_stdin() if file == STDIN else None
    if as_json:
        with whole_trees():
            program = parse_file(file) if text is None else parse_text(text, STDIN_NAME)
            dump = json.dumps(to_data(program, with_spans=not no_spans), indent=1)  # limits.py bounds the depth
        print(dump)
    elif text is not None:
        parse_text(text, STDIN_NAME)
    else:
        check_file(file)  # streams: memory stays flat however long the file is
    return EXIT_OK
