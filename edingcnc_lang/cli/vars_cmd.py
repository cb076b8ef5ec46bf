"""``ecnc vars PATH...``: the map of every numbered variable, with its name, kind, writers and readers."""
from __future__ import annotations

import sys

import click

from edingcnc_lang.errors import EXIT_OK, EXIT_SYNTAX
from edingcnc_lang.cli.base import Command, usage_error
from edingcnc_lang.cli.options import macro_options
from edingcnc_lang.cli.value_types import ExistingPath

FORMATS = ("table", "json", "csv", "markdown")  # the keys of varmap.render.FORMATS (a test keeps them in step)


@click.command("vars", cls=Command, short_help="Map every # variable: name, kind, writers, readers.")
@click.argument("paths", metavar="PATH...", nargs=-1, type=ExistingPath())
@macro_options("Macro file to resolve GoSub against (default: macro.cnc beside each file).",
               "User macro file to resolve GoSub against.")
@click.option("--json", "fmt", flag_value="json", help="One JSON document (docs/variables.md).")
@click.option("--csv", "fmt", flag_value="csv", help="CSV, one row per variable (a spreadsheet).")
@click.option("--markdown", "fmt", flag_value="markdown", help="A Markdown table.")
@click.option("--unnamed", is_flag=True, help="Only the variables nothing names.")
@click.option("--sub", "sub", metavar="NAME", help="Only the variables sub NAME writes or reads (any case).")
def vars_command(paths: tuple[str, ...], macro: str | None, user_macro: str | None, fmt: str | None,
                 unnamed: bool, sub: str | None) -> int:
    """Map the numbered variables of PATHs (files, or folders of *.cnc *.nc *.ngc *.tap *.txt).

    Names come from ;@var annotations and variables.toml (docs/variables.md), dlgmsg labels,
    comments on assignments, header comments and the manual.
    """
    from edingcnc_lang.lint.variable_map import variable_map
    from edingcnc_lang.varmap.render import FORMATS as RENDER

    if not paths:
        raise usage_error("give at least one file or folder")
    varmap = variable_map(paths, macro, user_macro)
    if unnamed:
        varmap = varmap.unnamed()
    if sub:
        varmap = varmap.of_sub(sub)
    print(RENDER[fmt or "table"](varmap))
    for problem in varmap.problems:
        where = ":".join(str(p) for p in (problem.path, problem.line, problem.col) if p)
        print(f"{where}: error: {problem.message}", file=sys.stderr)
    return EXIT_SYNTAX if varmap.problems else EXIT_OK
