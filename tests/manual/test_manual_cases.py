"""The EdingCNC 4.03 manual's examples and rules as golden cases (issue 21), next to the LinuxCNC goldens.

Each file in ``cases/`` starts with comment lines: the first names its section (``; §3.6.20.2 ...``);
``; ini: NAME`` runs it on a cnc.ini of this folder; ``; manual: KIND X Y Z [feed=F] [sync=P]
[spindle=RPM]`` is a move and ``; manual-event: KIND key=value ...`` an event the manual says must
happen, all in this order among what the run emits; ``; manual-error: L<line> <text>`` is the error (its line in the file)
it must stop with.  Those checks come from the manual's text and never change with a regeneration.
``expected/NAME.txt`` records everything the run emitted (``--regen-goldens`` rewrites it), so any
other change of behaviour shows up in review too.
"""
from __future__ import annotations

import math
import re
from collections.abc import Callable
from pathlib import Path

import pytest

from edingcnc_lang.canon import Event, Move
from edingcnc_lang.errors import EcncError
from edingcnc_lang.runner import RunOptions, run_string

HERE = Path(__file__).parent
CASES = sorted((HERE / "cases").glob("*.nc"))
SECTION = re.compile(r"^; §(3(?:\.\d+)+) \S")


def header(path: Path) -> list[str]:
    lines = []
    for line in path.read_text(encoding="utf-8").splitlines():
        if not line.startswith(";"):
            break
        lines.append(line)
    return lines


def directives(path: Path, name: str) -> list[str]:
    prefix = f"; {name}: "
    return [line[len(prefix):] for line in header(path) if line.startswith(prefix)]


def number(value: float) -> str:
    value = round(value, 6) + 0.0
    return str(int(value)) if value == int(value) else repr(value)


def shown(value: object) -> str:
    return number(value) if isinstance(value, float) else str(value)


def render_move(move: Move) -> str:
    axes = " ".join(f"{a}{number(v)}" for a, v in zip("XYZABC", move.end) if a in "XYZ" or v)
    extra = (f" F{number(move.feed)}" if move.kind != "rapid" else "") + (f" sync{number(move.sync)}" if move.sync else "")
    return f"L{move.line} {move.kind} {axes}{extra} S{number(move.spindle)}"


def render_event(event: Event) -> str:
    return f"L{event.line} {event.kind} " + " ".join(f"{k}={shown(v)}" for k, v in event.data.items())


def run_case(path: Path) -> tuple[list[Move | Event], EcncError | None]:
    stream: list[Move | Event] = []
    ini = directives(path, "ini")
    options = RunOptions(macro=HERE / "empty_macro.cnc", ini=HERE / ini[0] if ini else None,
                         on_move=lambda move, _joints: stream.append(move), on_event=stream.append)
    try:
        run_string(path.read_text(encoding="utf-8"), options, path=path.name)
    except EcncError as err:
        return stream, err
    return stream, None


def move_check(spec: str) -> Callable[[Move | Event], bool]:
    kind, *rest = spec.split()
    xyz = [float(v) for v in rest[:3]]
    words = dict(w.split("=") for w in rest[3:])

    def matches(item: Move | Event) -> bool:
        if not isinstance(item, Move) or item.kind != kind:
            return False
        if not all(math.isclose(a, b, abs_tol=1e-6) for a, b in zip(item.end[:3], xyz)):
            return False
        got = {"feed": item.feed, "sync": item.sync, "spindle": item.spindle}
        return all(math.isclose(got[k], float(v), abs_tol=1e-6) for k, v in words.items())
    return matches


def event_check(spec: str) -> Callable[[Move | Event], bool]:
    kind, _, rest = spec.partition(" ")
    words: dict[str, str] = {}
    key = ""
    for token in rest.split(" ") if rest else []:
        if "=" in token:
            key, _, value = token.partition("=")
            words[key] = value
        else:  # a value with spaces (a message text)
            words[key] += " " + token

    def same(got: object, want: str) -> bool:
        if isinstance(got, (int, float)) and not isinstance(got, bool):
            return math.isclose(float(got), float(want), abs_tol=1e-9)
        return str(got) == want

    def matches(item: Move | Event) -> bool:
        return (isinstance(item, Event) and item.kind == kind
                and all(k in item.data and same(item.data[k], v) for k, v in words.items()))
    return matches


@pytest.fixture(params=CASES, ids=[p.stem for p in CASES])
def case(request: pytest.FixtureRequest) -> Path:
    return request.param  # type: ignore[no-any-return]


def test_every_case_names_its_section_and_checks_something(case: Path) -> None:
    assert SECTION.match(header(case)[0]), "the first line names the manual's section: ; §3.x.y ..."
    assert any(directives(case, d) for d in ("manual", "manual-event", "manual-error"))


def test_the_run_does_what_the_manual_says(case: Path) -> None:
    stream, error = run_case(case)
    checks = [(line.partition(": ")[0][2:], line.partition(": ")[2]) for line in header(case)
              if line.startswith(("; manual: ", "; manual-event: "))]
    position = 0
    for kind, spec in checks:
        matches = move_check(spec) if kind == "manual" else event_check(spec)
        found = next((i for i in range(position, len(stream)) if matches(stream[i])), None)
        assert found is not None, f"{case.name}: not found in order: {kind}: {spec}"
        position = found + 1
    wanted = directives(case, "manual-error")
    if wanted:
        assert error is not None, f"{case.name}: the run should stop with: {wanted[0]}"
        line, _, text = wanted[0].partition(" ")
        assert (f"L{error.location.line if error.location else 0}", text in error.message) == (line, True), \
            f"{case.name}: {error.message}"
    else:
        assert error is None, f"{case.name}: {error}"


def test_the_run_matches_its_golden(case: Path, golden: Callable[[Path, str], None]) -> None:
    stream, error = run_case(case)
    lines = [render_move(i) if isinstance(i, Move) else render_event(i) for i in stream]
    if error is not None:
        lines.append(f"error: L{error.location.line if error.location else 0}: {error.message}")
    golden(HERE / "expected" / f"{case.stem}.txt", "\n".join(lines) + "\n")


def test_goldens_and_cases_pair_up() -> None:
    assert sorted(p.stem for p in (HERE / "expected").glob("*.txt")) == [p.stem for p in CASES]
    assert len(CASES) >= 20
