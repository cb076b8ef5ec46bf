"""``ecnc lint PATH...``: report mistakes in macro files, jobs and cnc.ini without running them."""
from __future__ import annotations

import os
import sys
from typing import TYPE_CHECKING

import click

from edingcnc_lang.errors import EXIT_FINDINGS, EXIT_OK
from edingcnc_lang.cli import progress
from edingcnc_lang.cli.base import Command, until_exit, usage_error
from edingcnc_lang.gcpause import whole_trees
from edingcnc_lang.cli.options import ini_option, macro_options
from edingcnc_lang.cli.value_types import INPUT_PATH, LINT_CODE, LINT_CODES, STDIN, PlainInt
from edingcnc_lang.cli.streams import STDIN_NAME, stdin_as_file
from edingcnc_lang.cli.style import styled

if TYPE_CHECKING:
    from edingcnc_lang.diagnostics import Diagnostic
    from edingcnc_lang.lint import LintOptions

# The keys of lint.formats.FORMATS (a test keeps them in step): importing the linter here would
# make every other command start slower.
FORMAT_NAMES = ("github", "json", "sarif", "text")


@click.command("lint", cls=Command,
               short_help="Check files, folders and cnc.ini; exit 1 if anything is found.")
@click.argument("paths", metavar="PATH...", nargs=-1, type=INPUT_PATH)
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
@click.option("--explain", metavar="CODE", type=LINT_CODE, help="Print the long explanation of CODE (as ecnc help CODE).")
@click.option("-q", "--quiet", is_flag=True, help="No progress line on stderr (shown on a terminal after a second).")
@click.option("-j", "--jobs", metavar="N", type=PlainInt(min=0), default=1,
              help="Check the files on N processes (0: one per CPU); see docs/lint.md.")
def lint(paths: tuple[str, ...], macro: str | None, user_macro: str | None, ini: str | None, fmt: str,
         select: tuple[str, ...], ignore: tuple[str, ...], target: str | None, no_source: bool,
         show_codes: bool, explain: str | None, quiet: bool, jobs: int) -> int:
    """Check PATHs (files, or folders of *.cnc *.nc *.ngc *.tap *.txt); exit 1 if anything is found.

    PATH - reads a job from standard input (its macro files: --macro, --user-macro).
    """
    from edingcnc_lang.lint import LintOptions, lint_paths_parallel
    from edingcnc_lang.lint.driver import expand
    from edingcnc_lang.lint.formats import FORMATS, list_codes

    if show_codes:
        print(list_codes())
        return EXIT_OK
    if explain:
        from edingcnc_lang.cli.help_cmd import explain_or_fail

        print(explain_or_fail(explain))
        return EXIT_OK
    if not paths and not ini:
        raise usage_error("give at least one file or folder to lint")
    options = LintOptions(macro, user_macro, ini, select, ignore, target)
    kept = until_exit()  # the trees and the facts about them are not freed one by one at the end
    show = progress.wanted(quiet or fmt != "text")  # json, sarif, github: output for programs, kept clean
    count = len(expand(p for p in paths if p != STDIN)) if show else 0
    with whole_trees(kept is not None), progress.Progress(lambda: (0, 0, f"checking {count:,} files"), show):
        findings = (_lint_with_stdin(paths, options) if STDIN in paths
                    else lint_paths_parallel(paths, options, jobs or os.cpu_count() or 1, kept=kept))
    output = FORMATS[fmt](findings, not no_source)
    if output or fmt != "text":
        print(styled(output, sys.stdout) if fmt == "text" else output)
    return EXIT_FINDINGS if findings else EXIT_OK


def _lint_with_stdin(paths: tuple[str, ...], options: LintOptions) -> list[Diagnostic]:
    """Lint with ``-`` among the paths: standard input is checked as a job named ``<stdin>``.

    The linter reads files, so the text goes to a file in a private temporary folder (no
    macro.cnc beside it there) and its findings are renamed back.
    """
    import dataclasses

    from edingcnc_lang.lint import lint_paths

    with stdin_as_file() as job:
        findings = lint_paths([str(job) if p == STDIN else p for p in paths], options)
    return [dataclasses.replace(d, path=STDIN_NAME) if d.path == str(job) else d for d in findings]
