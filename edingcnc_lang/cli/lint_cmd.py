"""``ecnc lint PATH...``: report mistakes in macro files, jobs and cnc.ini without running them."""
from __future__ import annotations

import click

from ..errors import EXIT_FINDINGS, EXIT_OK
from .base import Command, usage_error
from .common import whole_trees
from .options import ini_option, macro_options
from .params import EXISTING_PATH, LINT_CODES

# The keys of lint.formats.FORMATS (a test keeps them in step): importing the linter here would
# make every other command start slower.
FORMAT_NAMES = ("github", "json", "sarif", "text")


@click.command("lint", cls=Command,
               short_help="Check files, folders and cnc.ini; exit 1 if anything is found.")
@click.argument("paths", metavar="PATH...", nargs=-1, type=EXISTING_PATH)
@macro_options("Macro file to resolve GoSub against (default: macro.cnc beside each file).",
               "User macro file to resolve GoSub against.")
@ini_option("cnc.ini to check (its kinematics user outputs count as written).")
@click.option("--format", "fmt", type=click.Choice(FORMAT_NAMES), default="text", show_default=True,
              help="Output format.")
@click.option("--select", metavar="CODES", type=LINT_CODES, default=(), help="Only these codes or prefixes (E,S208,G5).")
@click.option("--ignore", metavar="CODES", type=LINT_CODES, default=(), help="Leave out these codes or prefixes.")
@click.option("--target", metavar="VERSION", type=click.Choice(("4.03", "5")),
              help="Controller version the findings describe (default: target under [tool.ecnc] in "
                   "ecnc.toml or pyproject.toml, else the --ini's version line, else 5).")
@click.option("--no-source", is_flag=True, help="Text format: leave out the source line and caret.")
@click.option("--list-codes", "show_codes", is_flag=True, help="Print every code with its severity and summary.")
def lint(paths: tuple[str, ...], macro: str | None, user_macro: str | None, ini: str | None, fmt: str,
         select: tuple[str, ...], ignore: tuple[str, ...], target: str | None, no_source: bool,
         show_codes: bool) -> int:
    """Check PATHs (files, or folders of *.cnc *.nc *.ngc *.tap *.txt); exit 1 if anything is found."""
    from ..lint import LintOptions, lint_paths
    from ..lint.formats import FORMATS, list_codes

    if show_codes:
        print(list_codes())
        return EXIT_OK
    if not paths and not ini:
        raise usage_error("give at least one file or folder to lint")
    with whole_trees():
        findings = lint_paths(list(paths), LintOptions(macro, user_macro, ini, select, ignore, target))
    output = FORMATS[fmt](findings, not no_source)
    if output or fmt != "text":
        print(output)
    return EXIT_FINDINGS if findings else EXIT_OK
