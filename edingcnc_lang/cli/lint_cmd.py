"""``ecnc lint PATH...``: report mistakes in macro files, jobs and cnc.ini without running them."""
from __future__ import annotations

import argparse
from typing import TYPE_CHECKING

from ..errors import EXIT_FINDINGS, EXIT_OK
from .common import UsageError, add_command, existing_file, existing_path, whole_trees

if TYPE_CHECKING:
    from .common import Subcommands

# The keys of lint.formats.FORMATS (a test keeps them in step): importing the linter here would
# make every other command start slower.
FORMAT_NAMES = ("github", "json", "sarif", "text")


def _codes(value: str) -> tuple[str, ...]:
    from ..lint import UnknownCode, parse_codes

    try:
        return parse_codes(value)
    except UnknownCode as err:
        raise argparse.ArgumentTypeError(f"no code starts with {err} (see --list-codes)") from None


def add_parser(commands: Subcommands) -> None:
    parser = add_command(commands, "lint", lint,
                         "Check PATHs (files, or folders of *.cnc *.nc *.ngc *.tap *.txt); "
                         "exit 1 if anything is found.")
    parser.add_argument("paths", metavar="PATH", nargs="*", type=existing_path)
    parser.add_argument("--macro", metavar="FILE", type=existing_file,
                        help="Macro file to resolve GoSub against (default: macro.cnc beside each file).")
    parser.add_argument("--user-macro", metavar="FILE", type=existing_file,
                        help="User macro file to resolve GoSub against.")
    parser.add_argument("--ini", metavar="FILE", type=existing_file,
                        help="cnc.ini to check (its kinematics user outputs count as written).")
    parser.add_argument("--format", dest="fmt", choices=FORMAT_NAMES, default="text",
                        help="Output format (default: %(default)s).")
    parser.add_argument("--select", metavar="CODES", type=_codes, default=(),
                        help="Only these codes or prefixes (E,S208,G5).")
    parser.add_argument("--ignore", metavar="CODES", type=_codes, default=(),
                        help="Leave out these codes or prefixes.")
    parser.add_argument("--target", metavar="VERSION", choices=("4.03", "5"),
                        help="Controller version the findings describe: 4.03 or 5 (default: [tool.ecnc] target "
                             "in pyproject.toml/ecnc.toml, else the --ini's version line, else 5).")
    parser.add_argument("--no-source", action="store_true", help="Text format: leave out the source line and caret.")
    parser.add_argument("--list-codes", dest="show_codes", action="store_true",
                        help="Print every code with its severity and summary.")


def lint(args: argparse.Namespace) -> int:
    from ..lint import LintOptions, lint_paths
    from ..lint.formats import FORMATS, list_codes

    if args.show_codes:
        print(list_codes())
        return EXIT_OK
    if not args.paths and not args.ini:
        raise UsageError("give at least one file or folder to lint")
    with whole_trees():
        findings = lint_paths(args.paths, LintOptions(args.macro, args.user_macro, args.ini, args.select, args.ignore,
                                                    args.target))
    output = FORMATS[args.fmt](findings, not args.no_source)
    if output or args.fmt != "text":
        print(output)
    return EXIT_FINDINGS if findings else EXIT_OK
