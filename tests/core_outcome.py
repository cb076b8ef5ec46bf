"""What a run of a job gives, as one text, for comparing the compiled core with the pure-Python one.

The test runs the job in its own process (the core it was started with) and asks a worker process
started with ``ECNC_PURE_PYTHON=1`` (``serve``) for the same job's outcome: the trace (every move's
end and planned time, written in batches), the events file and the result (position, parameters
such as GetJobDistance, limits report, estimate) or the error.
"""
from __future__ import annotations

import json
import sys
from pathlib import Path

from edingcnc_lang import EcncError, RunOptions, run_file


def traced_run(job: Path, ini: Path) -> tuple[str, str, list[object]]:
    """The trace, the result (or the error and the state it left) and every move and event of running ``job``
    with ``ini``: what a batched run and the same run one move at a time must share."""
    seen: list[object] = []
    trace = job.with_suffix(".csv")
    options = RunOptions(ini=ini, trace=trace, on_move=lambda m, j: seen.append(m), on_event=seen.append)
    try:
        result = str(run_file(job, options).to_json())
    except EcncError as err:
        result = err.format() + str(err.result.to_json())  # type: ignore[attr-defined]
    return trace.read_text(), result, seen


def outcome(job: Path) -> str:
    """The trace, the events and the result of running ``job`` (or its error), as text."""
    trace, events = job.with_suffix(".csv"), job.with_suffix(".events")
    try:
        result = run_file(job, RunOptions(trace=trace, events=events))
        error = None
    except EcncError as err:
        result, error = getattr(err, "result", None), err.format()
    summary = None if result is None else (result.machine, result.position, sorted(result.variables.items()),
                                           result.limits, result.estimate, result.moves, result.modal)
    return "\n".join((trace.read_text() if trace.exists() else "", events.read_text() if events.exists() else "",
                      repr(summary), repr(error)))


def serve() -> None:
    """Answer job paths read from stdin, one a line, with their outcome as a JSON string a line."""
    for line in sys.stdin:
        print(json.dumps(outcome(Path(line.strip()))), flush=True)
