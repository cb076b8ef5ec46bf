"""``ecnc test [PATH...]``: run the tests of ``test_*.toml`` files against macro files (docs/testing.md)."""
from __future__ import annotations

import os
import sys
from pathlib import Path
from typing import TYPE_CHECKING

import click

from edingcnc_lang.errors import EXIT_FINDINGS, EXIT_OK, EXIT_SYNTAX, printable
from edingcnc_lang.cli.base import Command, usage_error
from edingcnc_lang.cli.value_types import OUTPUT_FILE, ExistingPath, PlainInt
from edingcnc_lang.syntax.input_limits import MAX_TEST_JOBS
from edingcnc_lang.cli.style import styled, wants_colour

if TYPE_CHECKING:
    from edingcnc_lang.testing.coverage import CoverageData
    from edingcnc_lang.testing.session import TestResult
    from edingcnc_lang.testing.spec import TestCase


@click.command("test", cls=Command, short_help="Run the tests of test_*.toml files; exit 1 if one fails.")
@click.argument("paths", metavar="[PATH...]", nargs=-1, type=ExistingPath())
@click.option("-k", "keyword", metavar="EXPR",
              help="Only the tests whose FILE::NAME holds these words (and, or, not, parentheses).")
@click.option("-x", "--exitfirst", is_flag=True, help="Stop at the first failing test.")
@click.option("--junit", metavar="FILE", type=OUTPUT_FILE, help="Write the results as JUnit XML.")
@click.option("-j", "--jobs", metavar="N", type=PlainInt(0, MAX_TEST_JOBS), default=1,
              help="Run the test files on N processes (0: one per CPU).")
@click.option("--cov", "cov", is_flag=True, help="Report the coverage of the macro files the tests ran.")
@click.option("--cov-report", "cov_reports", metavar="term|json:FILE|html:DIR|lcov:FILE|cobertura:FILE", multiple=True,
              help="Coverage report (repeatable; implies --cov; default term); lcov and cobertura for CI services.")
@click.option("-q", "--quiet", is_flag=True, help="Only the failing tests and the summary line.")
def test(paths: tuple[str, ...], keyword: str | None, exitfirst: bool, junit: str | None, jobs: int,
         cov: bool, cov_reports: tuple[str, ...], quiet: bool) -> int:
    """Run the tests in PATHs (test_*.toml files, or folders searched for them; default: here).

    One line per test (PASS or FAIL, and what differs), then "N passed, M failed".
    Exit 0 all passed, 1 a test failed, 65 a test file does not load, 2 usage.
    """
    from edingcnc_lang.testing.session import run_cases, select
    from edingcnc_lang.testing.spec import TestFileError, discover, load_file

    reports = _coverage_reports(cov_reports) if cov or cov_reports else []
    if junit == "-":
        raise usage_error("--junit needs a file: standard output carries the report")
    files = discover(paths or (".",))
    if not files:
        raise usage_error(f"no test_*.toml files in {', '.join(paths or ('.',))}")
    loaded, broken = [], []
    for path in files:
        try:
            loaded.append(load_file(path))
        except TestFileError as err:
            broken.append(err.format())
    if broken:
        print(styled("\n".join(broken), sys.stderr), file=sys.stderr)
        return EXIT_SYNTAX
    try:
        chosen = [select(cases, keyword) for cases in loaded]
    except ValueError as err:
        raise usage_error(str(err)) from None
    chosen = [cases for cases in chosen if cases]
    if not chosen:
        raise usage_error(f"no test matches -k {keyword!r}")
    _refuse_inputs(junit, reports, files, loaded)
    colour = wants_colour(sys.stdout)

    def show(result: TestResult) -> None:
        if quiet and result.passed:
            return
        text = printable(result.text)  # a test's name or a job's msg text must not drive the terminal
        if colour:
            word, rest = text[:4], text[4:]
            text = click.style(word, fg="green" if word == "PASS" else "red", bold=True) + rest
        print(text, flush=True)

    summary = run_cases(chosen, stop_first=exitfirst, jobs=jobs or os.cpu_count() or 1, coverage=bool(reports),
                        report=show)
    print(summary.line)
    if junit:
        from edingcnc_lang.testing.reports import junit_xml

        _write(junit, junit_xml(summary))
    if reports and summary.coverage is not None:
        _coverage(reports, summary.coverage)
    return EXIT_FINDINGS if summary.failed else EXIT_OK


def _coverage_reports(given: tuple[str, ...]) -> list[tuple[str, str]]:
    """``term``, ``json:FILE``, ``html:DIR``, ``lcov:FILE``, ``cobertura:FILE`` as (kind, target);
    a bad one is a usage error."""
    reports = []
    for item in given or ("term",):
        kind, colon, target = item.partition(":")
        if kind not in ("term", "json", "html", "lcov", "cobertura") or (kind == "term") == bool(colon):
            raise usage_error(f"--cov-report {item!r}: write term, json:FILE, html:DIR, lcov:FILE or cobertura:FILE")
        if kind != "term" and not target:
            raise usage_error(f"--cov-report {item!r}: name the {'folder' if kind == 'html' else 'file'}")
        reports.append((kind, target))
    return reports


def _coverage(reports: list[tuple[str, str]], data: CoverageData) -> None:
    from edingcnc_lang.testing.coverage import summarise
    from edingcnc_lang.testing.coverage_formats import cobertura, lcov
    from edingcnc_lang.testing.reports import coverage_json, coverage_term, write_coverage_html

    files = summarise(data)
    for kind, target in reports:
        if kind == "term":
            print(coverage_term(files))
        elif kind in ("json", "lcov", "cobertura"):
            _write(target, {"json": coverage_json, "lcov": lcov, "cobertura": cobertura}[kind](files))
        else:
            print(f"coverage pages: {write_coverage_html(files, Path(target))}")


def _refuse_inputs(junit: str | None, reports: list[tuple[str, str]], files: list[Path],
                   loaded: list[list[TestCase]]) -> None:
    """Usage error (exit 2) before any test runs when a report would be written over a test file, a
    job, ini or macro file a test reads, or another report."""
    from edingcnc_lang.outputs import check_outputs
    from edingcnc_lang.runner import RunOptions, input_files

    outputs: dict[str, str | Path | None] = {"--junit": junit}
    for kind, target in reports:
        if kind == "json":
            outputs[f"--cov-report json:{target}"] = target
        elif kind == "html":
            if os.path.exists(target) and not os.path.isdir(target):
                raise usage_error(f"--cov-report html:{target}: {target} is a file, not a folder")
            outputs[f"--cov-report html:{target}"] = Path(target, "index.html")
    inputs: list[Path | None] = list(files)
    for setup in {(case.ini, case.macro, case.user_macro) for cases in loaded for case in cases}:
        inputs += input_files(RunOptions(ini=setup[0], macro=setup[1], user_macro=setup[2]))
    inputs += [case.job_file for cases in loaded for case in cases]
    check_outputs(outputs, inputs)


def _write(target: str, text: str) -> None:
    """A report written whole (or the old one left as it was), its folder made first."""
    from edingcnc_lang.outputs import write_error, write_text

    path = Path(target)
    try:
        path.parent.mkdir(parents=True, exist_ok=True)
    except OSError as err:
        raise write_error(path, err) from None
    write_text(path, text)
