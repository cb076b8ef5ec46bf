"""What a test expected against what its run did: one line of text per difference."""
from __future__ import annotations

from edingcnc_lang.testing.execute import JOB_NAME, MESSAGE_KINDS, Outcome
from edingcnc_lang.varmap.names import label, names_of_paths
from edingcnc_lang.testing.spec import shown

MAX_SHOWN_MESSAGES = 5


def failures(outcome: Outcome) -> list[str]:
    """Every difference, in the order of the test's keys; empty when the test passes."""
    case, expect = outcome.case, outcome.case.expect
    if outcome.test_problem:  # the run did not follow the test: nothing after it means anything
        return [outcome.test_problem]
    found: list[str] = []
    error = _one_line(outcome.error) if outcome.error else None
    if expect.error is None:
        if error:
            found.append(f"the run stopped: {error}")
    elif error is None:
        found.append(f"error: expected one containing {expect.error!r}, got none (the run ended by {outcome.ended_by})")
    elif expect.error not in (outcome.error or ""):
        found.append(f"error: expected one containing {expect.error!r}, got {error}")
    started = bool(outcome.params)
    wrong = [index for index in expect.vars if not started or not expect.vars[index].matches(outcome.var(index))]
    names = _names(outcome) if wrong else {}
    for index in wrong:
        want = expect.vars[index]
        got = shown(outcome.var(index)) if started else "nothing (the run did not start)"
        found.append(f"{label(index, names)}: expected {want}, got {got}")
    for axis, want in expect.position.items():
        if not started:
            found.append(f"position {axis}: expected {want}, got nothing (the run did not start)")
        elif not want.matches(outcome.position[axis]):
            found.append(f"position {axis}: expected {want}, got {shown(outcome.position[axis])}")
    texts = [text for kind, text in outcome.messages if kind in MESSAGE_KINDS]
    for wanted in expect.messages:
        if not any(wanted in text for text in texts):
            found.append(f"message {wanted!r}: expected, got {_some(texts)}")
    found.extend(outcome.violations)
    if len(case.answers) > outcome.dialogs:
        found.append(f"answers: {len(case.answers)} given, {_times(outcome.dialogs, 'dialog')} shown")
    if len(case.probe) > outcome.probes:
        hint = "; probing behind the simulation guard needs simulation = false" if case.simulation else ""
        found.append(f"probe: {len(case.probe)} given, the run probed {_times(outcome.probes, 'time')}{hint}")
    return found


def _names(outcome: Outcome) -> dict[int, str]:
    """What the job and its macro files call their numbers (``#1552 thread_major_diameter``)."""
    case = outcome.case
    texts = {JOB_NAME: case.job} if case.job_file is None and case.job else {}
    return names_of_paths(outcome.files, texts).labelled()


def _one_line(text: str) -> str:
    """An error as one line: its first line and its notes (the call chain), without the echoed source."""
    lines = text.splitlines()
    notes = [line.strip() for line in lines[1:] if line.startswith("  ") and not line.startswith("    ")]
    return "; ".join([lines[0], *notes]) if lines else text


def _some(texts: list[str]) -> str:
    if not texts:
        return "no messages"
    shown_texts = ", ".join(repr(t) for t in texts[:MAX_SHOWN_MESSAGES])
    more = f" and {len(texts) - MAX_SHOWN_MESSAGES} more" if len(texts) > MAX_SHOWN_MESSAGES else ""
    return f"{shown_texts}{more}"


def _times(count: int, what: str) -> str:
    return f"{count} {what}{'' if count == 1 else 's'}"
