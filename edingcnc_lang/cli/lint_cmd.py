"""``ecnc lint PATH...``: report mistakes in macro files, jobs and cnc.ini without running them."""
from __future__ import annotations

import sys

import click

from ..errors import EXIT_FINDINGS, EXIT_OK
from .common import existing_file, reports_errors

# The keys of lint.formats.FORMATS (a test keeps them in step): importing the linter here would
# make every other command start slower.
FORMAT_NAMES = ("github", "json", "sarif", "text")


def _codes(ctx: click.Context, param: click.Parameter, value: str | None) -> tuple[str, ...]:
    from ..lint import UnknownCode, parse_codes

    try:
        return parse_codes(value)
    except UnknownCode as err:
        raise click.BadParameter(f"no code starts with {err} (see --list-codes)") from None


@click.command("lint")
@click.argument("paths", nargs=-1, type=click.Path(exists=True))
@click.option("--macro", type=existing_file(), help="Macro file to resolve GoSub against "
              "(default: macro.cnc beside each file).")
@click.option("--user-macro", type=existing_file(), help="User macro file to resolve GoSub against.")
@click.option("--ini", type=existing_file(), help="cnc.ini to check (its kinematics user outputs count as written).")
@click.option("--format", "fmt", type=click.Choice(FORMAT_NAMES), default="text", show_default=True)
@click.option("--select", callback=_codes, metavar="CODES", help="Only these codes or prefixes (E,S208,G5).")
@click.option("--ignore", callback=_codes, metavar="CODES", help="Leave out these codes or prefixes.")
@click.option("--no-source", is_flag=True, help="Text format: leave out the source line and caret.")
@click.option("--list-codes", "show_codes", is_flag=True, help="Print every code with its severity and summary.")
@reports_errors
def lint(paths: tuple[str, ...], macro: str | None, user_macro: str | None, ini: str | None, fmt: str,
         select: tuple[str, ...], ignore: tuple[str, ...], no_source: bool, show_codes: bool) -> None:
    """Check PATHs (files, or folders of *.cnc *.nc *.ngc *.tap *.txt); exit 1 if anything is found."""
    from ..lint import LintOptions, lint_paths
    from ..lint.formats import FORMATS, list_codes

    if show_codes:
        click.echo(list_codes())
        return
    if not paths and not ini:
        raise click.UsageError("give at least one file or folder to lint")
    findings = lint_paths(paths, LintOptions(macro, user_macro, ini, select, ignore))
    output = FORMATS[fmt](findings, not no_source)
    if output or fmt != "text":
        click.echo(output)
    sys.exit(EXIT_FINDINGS if findings else EXIT_OK)
