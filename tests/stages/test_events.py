"""The canon's typed events (events.py): every kind has a record, a payload and a JSON round trip.

The samples are made from each class's field types, so a new kind is tested as soon as its class
exists; the interpreter makes no event but through a registered class (no bare ``Event``), and a
job that exercises most kinds proves each event it emits is the registered record of its kind.
"""
from __future__ import annotations

import ast
import json
import types
import typing
from dataclasses import fields
from pathlib import Path
from typing import Any

import pytest

from edingcnc_lang import events as ev
from edingcnc_lang.runner import RunOptions, run_string

PACKAGE = Path(ev.__file__).parent


def _sample(hint: Any) -> Any:
    """A value of the type ``hint`` (the types event payloads use)."""
    origin, args = typing.get_origin(hint), typing.get_args(hint)
    if origin in (typing.Union, types.UnionType):
        return _sample(next(a for a in args if a is not type(None)))
    if origin is tuple:
        return tuple(_sample(a) for a in args) if Ellipsis not in args else (_sample(args[0]), _sample(args[0]))
    if origin is not None and "Mapping" in str(origin):
        return {"a": _sample(args[1])}
    return {int: 3, float: 2.5, str: "x", bool: True}[hint]


def sample(cls: type[ev.Event]) -> ev.Event:
    hints = typing.get_type_hints(cls, vars(ev))
    values = {f.name: None if f.name in cls.internal else _sample(hints[f.name]) for f in fields(cls)[2:]}
    return cls("job.nc", 7, **values)


def test_every_kind_has_its_own_record_class() -> None:
    assert len(ev.EVENT_KINDS) >= 30
    for kind, cls in ev.EVENT_KINDS.items():
        assert cls.kind == kind and issubclass(cls, ev.Event)
    assert set(ev.SWITCH_EVENTS) == {"tanknife", "homeisestop", "tcaguard", "laserengrave"}


@pytest.mark.parametrize("kind", sorted(ev.EVENT_KINDS))
def test_each_kind_round_trips_through_json(kind: str) -> None:
    """``data`` is what the JSON Lines events file prints; reading it back gives the same event."""
    event = sample(ev.EVENT_KINDS[kind])
    text = json.dumps({"kind": event.kind, "file": event.path, "line": event.line, "data": event.data})
    record = json.loads(text)
    again = ev.event_from_json(record["kind"], record["file"], record["line"], record["data"])
    assert type(again) is type(event) and json.dumps(again.data) == json.dumps(event.data)
    assert (again.kind, again.path, again.line) == (kind, "job.nc", 7)


def test_a_field_defaulting_to_none_is_left_out_of_the_payload_while_none() -> None:
    assert ev.ThcEvent("j", 1, 23).data == {"m": 23}
    assert ev.ThcEvent("j", 1, 21, True, 4.5).data == {"m": 21, "on": True, "q": 4.5}
    assert ev.OutputEvent("j", 1, 2, True, None).data == {"port": 2, "on": True, "pwm": None}  # no default: kept
    assert ev.ZhcEvent("j", 1, True, map=object()).data == {"on": True}  # internal: never in the payload
    assert list(ev.ModbusEvent("j", 1, "s1 f3", {"s": 1.0, "f": 3.0}, (5.0,)).data) == ["args", "s", "f", "values"]


def test_an_unknown_kind_is_refused() -> None:
    with pytest.raises(KeyError):
        ev.event_from_json("no_such_kind", "j", 1, {})


def test_a_misspelt_field_is_a_type_error() -> None:
    with pytest.raises(TypeError):
        ev.DwellEvent("j", 1, secnds=1.0)  # type: ignore[call-arg]


def test_nothing_makes_a_bare_event() -> None:
    """Every event the package makes is a kind's record: no ``Event(...)`` call outside events.py."""
    bare = []
    for path in PACKAGE.rglob("*.py"):
        for node in ast.walk(ast.parse(path.read_text(encoding="utf-8"))):
            if isinstance(node, ast.Call) and isinstance(node.func, ast.Name) and node.func.id == "Event":
                bare.append(f"{path.relative_to(PACKAGE)}:{node.lineno}")
    assert not bare


JOB = """\
M3 S1000
S1200
M8
M9
G4 P0.5
T2 M6
G64 P0.1 Q0.2
G61
M48
M50 P0
M54 P2
M54 E1 Q500
M11
M10
M21
M22 Q120
M104 S200
M106 S50
M26
G68 X1 Y1 R30
G69
G51 P2
G50
G41 D1
G1 X10 F100
G40
G1 X20
tanknife on
tanknife off
tcaguard on
service hello
msg "hi"
warnmsg "careful"
M0
M30
"""


def test_a_job_emits_registered_records_whose_json_round_trips(tmp_path: Path) -> None:
    made: list[ev.Event] = []
    run_string(JOB, RunOptions(on_event=made.append, log_dir=tmp_path))
    seen = {e.kind for e in made}
    assert len(seen) >= 20, seen
    for event in made:
        assert ev.EVENT_KINDS[event.kind] is type(event)
        again = ev.event_from_json(event.kind, event.path, event.line, json.loads(json.dumps(event.data, default=str)))
        assert json.dumps(again.data, default=str) == json.dumps(event.data, default=str)
