"""A post-processor's test harness: run each job a post wrote on the machine's ini and check it.

    python examples/embedding/post_harness.py [JOB.nc ...]

For every job: it must run without an error (machine limits, tools, arcs: each error has its R
code), feed no faster than the post's maximum and finish within a time budget. Every failure is a record with a stable code, so a CI
report can group them. Without arguments it checks the examples folder's pocket job.
"""
from __future__ import annotations

import sys
from dataclasses import dataclass
from pathlib import Path

from edingcnc_lang import EcncError, Move, Pose, RunOptions, result_of, run_file

HERE = Path(__file__).resolve().parent


@dataclass(frozen=True)
class Failure:
    """One problem of one job: a code (``R816``, or the harness's own ``H`` codes), where, what."""

    job: str
    code: str
    line: int
    message: str


def check(job: Path, max_seconds: float = 3600.0, max_feed: float = 10000.0) -> list[Failure]:
    too_fast: list[Move] = []

    def on_move(move: Move, joints: Pose) -> None:
        if move.kind in ("linear", "arc") and move.feed > max_feed:
            too_fast.append(move)

    failures: list[Failure] = []
    try:
        result = run_file(job, RunOptions(on_move=on_move))
    except EcncError as err:
        where = err.location.line if err.location else 0
        failures.append(Failure(job.name, err.code, where, err.message))
        partial = result_of(err)
        if partial is None:
            return failures
        result = partial
    failures += [Failure(job.name, "H001", m.line, f"feed {m.feed:g} mm/min, above the post's {max_feed:g}")
                 for m in too_fast]
    seconds = result.estimate.seconds if result.estimate is not None else 0.0
    if seconds > max_seconds:
        failures.append(Failure(job.name, "H002", 0, f"takes {seconds:.0f} s, more than {max_seconds:.0f} s"))
    return failures


def main(argv: list[str]) -> int:
    jobs = [Path(name) for name in argv] or [HERE.parent / "pocket.nc"]
    failures = [failure for job in jobs for failure in check(job)]
    for failure in failures:
        print(f"{failure.job}:{failure.line}: {failure.code} {failure.message}")
    print(f"{len(jobs)} job(s), {len(failures)} failure(s)")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
