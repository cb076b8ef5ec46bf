"""Running many tests: selection by name (``-k``), stopping at the first failure (``-x``), test files
on several processes (``-j``), and the result of each test as the reports show it."""
from __future__ import annotations

import re
import time
from collections.abc import Callable, Generator, Sequence
from concurrent.futures import ProcessPoolExecutor
from concurrent.futures.process import BrokenProcessPool
from dataclasses import dataclass, field
from multiprocessing import get_context

from edingcnc_lang.syntax.input_limits import MAX_BRACKET_DEPTH
from edingcnc_lang.testing.coverage import CoverageData
from edingcnc_lang.testing.spec import TestCase


@dataclass(frozen=True)
class TestResult:
    """One test's verdict: no failures is a pass."""

    __test__ = False  # not a pytest test class, whatever its name

    name: str
    file: str
    line: int
    failures: tuple[str, ...]
    seconds: float = 0.0
    errored: bool = False  # the run stopped with an error the test did not expect, or the test could not be followed
    messages: tuple[str, ...] = ()  # what the job said (msg, warnmsg, logmsg ...) as ``kind: text``, for the reports

    @property
    def passed(self) -> bool:
        return not self.failures

    @property
    def text(self) -> str:
        """The report's line: ``PASS FILE:LINE: NAME`` or ``FAIL FILE:LINE: NAME: difference; ...``."""
        head = f"{'PASS' if self.passed else 'FAIL'} {self.file}:{self.line}: {self.name}"
        return head if self.passed else f"{head}: {'; '.join(self.failures)}"


@dataclass
class Summary:
    results: list[TestResult] = field(default_factory=list)
    coverage: CoverageData | None = None
    seconds: float = 0.0
    not_run: list[TestCase] = field(default_factory=list)  # left out when -x stopped at a failure
    started: float = 0.0  # when the run began (seconds since the epoch), for the reports' timestamp

    @property
    def passed(self) -> int:
        return sum(r.passed for r in self.results)

    @property
    def failed(self) -> int:
        return len(self.results) - self.passed

    @property
    def line(self) -> str:
        return f"{self.passed} passed, {self.failed} failed"


def check(case: TestCase, coverage: CoverageData | None = None) -> TestResult:
    """Run one test and judge it."""
    from edingcnc_lang.testing.checks import failures
    from edingcnc_lang.testing.execute import run_case

    outcome = run_case(case, coverage)
    errored = bool(outcome.test_problem) or (outcome.error is not None and case.expect.error is None)
    return TestResult(case.name, case.file, case.line, tuple(failures(outcome)), outcome.seconds, errored,
                      tuple(f"{kind}: {text}" for kind, text in outcome.messages))


def run_cases(files: Sequence[Sequence[TestCase]], *, stop_first: bool = False, jobs: int = 1,
              coverage: bool = False, report: Callable[[TestResult], None] = lambda _r: None) -> Summary:
    """Run the tests of each file in turn (``jobs`` > 1: files on that many processes), calling
    ``report`` with each result in file order as it is known."""
    started = time.perf_counter()
    summary = Summary(coverage=CoverageData() if coverage else None, started=time.time())
    each_file = _file_results(files, stop_first, jobs, coverage)
    try:
        for results, data in each_file:
            if summary.coverage is not None and data is not None:
                summary.coverage.update(data)
            for result in results:
                summary.results.append(result)
                report(result)
            if stop_first and any(not r.passed for r in results):
                break
    finally:
        each_file.close()  # at once, also on SIGTERM or Ctrl-C: the workers are ended there
    ran = {(r.file, r.line, r.name) for r in summary.results}
    summary.not_run = [case for cases in files for case in cases if (case.file, case.line, case.name) not in ran]
    summary.seconds = time.perf_counter() - started
    return summary


def run_file_cases(cases: Sequence[TestCase], stop_first: bool, coverage: bool
                   ) -> tuple[list[TestResult], CoverageData | None]:
    """One file's tests, in a worker or in this process."""
    data = CoverageData() if coverage else None
    results = []
    for case in cases:
        results.append(check(case, data))
        if stop_first and not results[-1].passed:
            break
    return results, data


def _file_results(files: Sequence[Sequence[TestCase]], stop_first: bool, jobs: int, coverage: bool
                  ) -> Generator[tuple[list[TestResult], CoverageData | None], None, None]:
    if jobs <= 1 or len(files) < 2:
        for cases in files:
            yield run_file_cases(cases, stop_first, coverage)
        return
    first = 0
    while first < len(files):
        pool = _pool(min(jobs, len(files) - first))
        finished = False
        try:
            futures = [pool.submit(run_file_cases, cases, stop_first, coverage) for cases in files[first:]]
            for future in futures:
                try:
                    result = future.result()
                except BrokenProcessPool:  # a worker died (killed, out of memory): every pending file is lost
                    break
                first += 1
                yield result
            else:
                finished = True
        finally:
            _end(pool, finished)
        if not finished:  # the file whose result was lost, alone, to tell whether it is the one that dies
            yield _alone(files[first], stop_first, coverage)
            first += 1


def _pool(workers: int) -> ProcessPoolExecutor:
    # spawn, not fork: the same on every platform (as ecnc lint -j)
    return ProcessPoolExecutor(max_workers=workers, mp_context=get_context("spawn"))


def _end(pool: ProcessPoolExecutor, finished: bool) -> None:
    """Shut ``pool`` down; unless every file finished (SIGTERM, Ctrl-C, -x, a dead worker) its
    workers are terminated first, so the command ends at once instead of when they are done."""
    if not finished:
        workers = list((getattr(pool, "_processes", None) or {}).values())
        for process in workers:
            process.terminate()
        for process in workers:
            process.join(1.0)  # ended by SIGTERM in milliseconds; then the pool's queues close cleanly
    pool.shutdown(wait=True, cancel_futures=True)


def _alone(cases: Sequence[TestCase], stop_first: bool, coverage: bool
           ) -> tuple[list[TestResult], CoverageData | None]:
    """One file's tests on a worker of their own; when that worker dies too, each test fails saying so."""
    pool = _pool(1)
    finished = False
    try:
        result = pool.submit(run_file_cases, cases, stop_first, coverage).result()
        finished = True
        return result
    except BrokenProcessPool:
        reason = ("the process running this test file ended abruptly (killed, or out of memory) before the "
                  "test finished",)
        return [TestResult(case.name, case.file, case.line, reason) for case in cases], None
    finally:
        _end(pool, finished)


# --- -k EXPR ----------------------------------------------------------------------------------

def keyword_matcher(expression: str) -> Callable[[str], bool]:
    """``-k``: words matched case-insensitively as parts of ``FILE::NAME``, joined with ``and``,
    ``or``, ``not`` and parentheses (``-k "tool and not measure"``).  A malformed expression raises
    ``ValueError``."""
    tokens = re.findall(r"\(|\)|[^\s()]+", expression)
    position = 0
    depth = 0  # "(" and "not" open at once: bounded, so a deep expression is an error, not a RecursionError

    def peek() -> str | None:
        return tokens[position].lower() if position < len(tokens) else None

    def take() -> str:
        nonlocal position
        if position >= len(tokens):
            raise ValueError(f"-k {expression!r}: the expression ends too early")
        position += 1
        return tokens[position - 1]

    def either() -> Callable[[str], bool]:
        parts = [both()]
        while peek() == "or":
            take()
            parts.append(both())
        return lambda text: any(p(text) for p in parts)

    def both() -> Callable[[str], bool]:
        parts = [single()]
        while peek() == "and":
            take()
            parts.append(single())
        return lambda text: all(p(text) for p in parts)

    def single() -> Callable[[str], bool]:
        nonlocal depth
        token = take()
        if token.lower() == "not" or token == "(":
            depth += 1
            if depth > MAX_BRACKET_DEPTH:
                raise ValueError(f"-k: more than {MAX_BRACKET_DEPTH} parentheses and 'not' inside each other "
                                 "(the nesting limit)")
            inner = single() if token.lower() == "not" else either()
            depth -= 1
            if token.lower() == "not":
                return lambda text: not inner(text)
            if take() != ")":
                raise ValueError(f"-k {expression!r}: a '(' is not closed")
            return inner
        if token == ")" or token.lower() in ("and", "or"):
            raise ValueError(f"-k {expression!r}: {token!r} where a word belongs")
        word = token.lower()
        return lambda text: word in text

    if not tokens:
        raise ValueError("-k needs an expression")
    matcher = either()
    if position != len(tokens):
        raise ValueError(f"-k {expression!r}: {tokens[position]!r} is not expected there")
    return lambda text: matcher(text.lower())


def select(cases: Sequence[TestCase], expression: str | None) -> list[TestCase]:
    """The tests whose ``FILE::NAME`` matches ``-k``; all without one."""
    if expression is None:
        return list(cases)
    matches = keyword_matcher(expression)
    return [case for case in cases if matches(f"{case.file}::{case.name}")]
