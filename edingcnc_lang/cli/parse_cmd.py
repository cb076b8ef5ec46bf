"""``ecnc parse FILE [--json]``: check the syntax of a file, optionally dump its AST."""
from __future__ import annotations

import json

import click

from .common import existing_file, reports_errors


@click.command()
@click.argument("file", type=existing_file())
@click.option("--json", "as_json", is_flag=True, help="Print the AST as JSON.")
@click.option("--no-spans", is_flag=True, help="Leave source positions out of the JSON.")
@reports_errors
def parse(file: str, as_json: bool, no_spans: bool) -> None:
    """Parse FILE without running it (exit 65 on syntax errors)."""
    from ..parser import check_file, parse_file
    from ..serialize import to_data

    if as_json:
        program = parse_file(file)
        click.echo(json.dumps(to_data(program, with_spans=not no_spans), indent=1))
        return
    check_file(file)  # streams: memory stays flat however long the file is
