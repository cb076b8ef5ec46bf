"""``ecnc parse FILE [--json]``: check the syntax of a file, optionally dump its AST."""
from __future__ import annotations

import argparse
from typing import TYPE_CHECKING

from ..errors import EXIT_OK, EcncError, Location
from .common import add_command, existing_file, whole_trees

if TYPE_CHECKING:
    from .common import Subcommands


def add_parser(commands: Subcommands) -> None:
    parser = add_command(commands, "parse", parse, "Parse FILE without running it (exit 65 on syntax errors).")
    parser.add_argument("file", metavar="FILE", type=existing_file)
    parser.add_argument("--json", dest="as_json", action="store_true", help="Print the AST as JSON.")
    parser.add_argument("--no-spans", action="store_true", help="Leave source positions out of the JSON.")


def parse(args: argparse.Namespace) -> int:
    import json

    from ..parser import check_file, parse_file
    from ..serialize import to_data

    if args.as_json:
        with whole_trees():
            program = parse_file(args.file)
            try:
                text = json.dumps(to_data(program, with_spans=not args.no_spans), indent=1)
            except RecursionError:  # thousands of nested blocks: parsed fine, too deep to write out
                raise EcncError("blocks are nested too deeply to write the tree as JSON",
                                Location(args.file)) from None
        print(text)
    else:
        check_file(args.file)  # streams: memory stays flat however long the file is
    return EXIT_OK
