"""The interpreter's state is declared in one place, and an observer sees a read-only view of it.

Every attribute a part of the interpreter (a mixin on ``MachineState``) sets is one that
``MachineState.__init__`` declares, with its type and meaning, or a part's own ``__init__`` (the record
of a concern that owns its state), or a field of a part's own state
record (``parts.py``), which ``MachineState`` holds as one attribute; no name is declared twice
and no part keeps state in a class attribute (one mutable dict shared by every machine was one such);
a composed part (``devices.py``, ``zhc_commands.py``: functions of ``machine``) changes the machine
only inside its record.
"""
from __future__ import annotations

import ast
import dataclasses
import re
from pathlib import Path

import pytest

from edingcnc_lang import RunOptions, run_string
from edingcnc_lang.machine import parts, state
from edingcnc_lang.machine.observe import MachineView, Observer
from edingcnc_lang.syntax import nodes as n

MACHINE = Path(state.__file__).parent


def _parts() -> list[tuple[Path, ast.ClassDef]]:
    found = []
    for path in sorted(MACHINE.glob("*.py")):
        for node in ast.walk(ast.parse(path.read_text(encoding="utf-8"))):
            if isinstance(node, ast.ClassDef) and any(isinstance(b, ast.Name) and b.id == "MachineState"
                                                      for b in node.bases):
                found.append((path, node))
    return found


def _self_targets(function: ast.AST) -> set[str]:
    names = set()
    for node in ast.walk(function):
        targets = node.targets if isinstance(node, ast.Assign) else \
            [node.target] if isinstance(node, (ast.AnnAssign, ast.AugAssign)) else []
        for target in targets:
            for item in target.elts if isinstance(target, ast.Tuple) else [target]:
                if isinstance(item, ast.Attribute) and isinstance(item.value, ast.Name) and item.value.id == "self":
                    names.add(item.attr)
    return names


def _init(cls: ast.ClassDef) -> ast.FunctionDef | None:
    return next((f for f in cls.body if isinstance(f, ast.FunctionDef) and f.name == "__init__"), None)


def _declared() -> set[str]:
    tree = ast.parse((MACHINE / "state.py").read_text(encoding="utf-8"))
    cls = next(c for c in ast.walk(tree) if isinstance(c, ast.ClassDef) and c.name == "MachineState")
    init = _init(cls)
    assert init is not None
    return _self_targets(init).union(*[_self_targets(own) for _path, part in _parts() if (own := _init(part))])


@pytest.mark.slow
def test_the_parts_are_found() -> None:
    assert len(_parts()) >= 12


@pytest.mark.slow
def test_every_attribute_a_part_sets_is_declared_in_machine_state_init() -> None:
    declared = _declared()
    stray = [f"{path.name}: {cls.name}.{fn.name} sets self.{name}"
             for path, cls in _parts() for fn in cls.body if isinstance(fn, ast.FunctionDef)
             for name in sorted(_self_targets(fn) - declared)]
    assert not stray, "\n".join(stray)


def _records() -> dict[str, type]:
    """MachineState's attribute -> the part's state record it holds (``self.devices = DeviceState()``)."""
    tree = ast.parse((MACHINE / "state.py").read_text(encoding="utf-8"))
    cls = next(c for c in ast.walk(tree) if isinstance(c, ast.ClassDef) and c.name == "MachineState")
    init = next(f for f in cls.body if isinstance(f, ast.FunctionDef) and f.name == "__init__")
    return {target.attr: getattr(parts, node.value.func.id) for node in ast.walk(init) if isinstance(node, ast.Assign)
            for target in node.targets if isinstance(target, ast.Attribute) and isinstance(node.value, ast.Call)
            and isinstance(node.value.func, ast.Name)
            and getattr(getattr(parts, node.value.func.id, None), "__module__", None) == parts.__name__}


def _part_writes(function: ast.AST, records: dict[str, type], receiver: str = "self") -> set[tuple[str, str]]:
    """(record attribute, field) for every ``self.<record>.<field> = ...`` in ``function`` (``machine.``
    in a composed part's function), and ("", name) for a ``machine.<name> = ...`` of a composed part."""
    found = set()
    for node in ast.walk(function):
        targets = node.targets if isinstance(node, ast.Assign) else \
            [node.target] if isinstance(node, (ast.AnnAssign, ast.AugAssign)) else []
        for target in targets:
            for item in target.elts if isinstance(target, ast.Tuple) else [target]:
                if isinstance(item, ast.Attribute) and isinstance(item.value, ast.Attribute) and \
                        isinstance(item.value.value, ast.Name) and item.value.value.id == receiver and \
                        item.value.attr in records:
                    found.add((item.value.attr, item.attr))
                elif receiver != "self" and isinstance(item, ast.Attribute) and \
                        isinstance(item.value, ast.Name) and item.value.id == receiver:
                    found.add(("", item.attr))
    return found


def _composed() -> list[tuple[Path, ast.FunctionDef]]:
    """The functions of the composed parts: module functions whose first argument is ``machine``."""
    return [(path, node) for path in sorted(MACHINE.glob("*.py"))
            for node in ast.parse(path.read_text(encoding="utf-8")).body
            if isinstance(node, ast.FunctionDef) and node.args.args and node.args.args[0].arg == "machine"]


def test_every_part_record_is_held_once_and_declares_each_name_once() -> None:
    """A concern's state is one record (no field half-moved back into ``MachineState.__init__``)."""
    records = _records()
    made = [c for c in vars(parts).values()
            if isinstance(c, type) and c.__module__ == parts.__name__ and dataclasses.is_dataclass(c)]
    # a record may hold records of its own (CycleState.pending: PendingMoves, FlowState.stack: CallFrame);
    # the machine holds the others
    fields = " ".join(str(f.type) for record in records.values() for f in dataclasses.fields(record))
    made = [c for c in made if not re.search(rf"\b{c.__name__}\b", fields)]
    assert sorted(c.__name__ for c in records.values()) == sorted(c.__name__ for c in made)
    declared = _declared()
    owners: dict[str, list[str]] = {name: ["MachineState.__init__"] for name in declared - set(records)}
    for attribute, record in records.items():
        assert dataclasses.is_dataclass(record) and "__slots__" in vars(record), record
        for f in dataclasses.fields(record):
            owners.setdefault(f.name, []).append(f"{record.__name__} (machine.{attribute})")
    twice = {name: where for name, where in owners.items() if len(where) > 1}
    assert not twice, twice


@pytest.mark.slow
def test_a_part_writes_only_fields_its_record_declares() -> None:
    records = _records()
    stray = [f"{path.name}: {cls.name}.{fn.name} sets self.{attribute}.{name}"
             for path, cls in _parts() for fn in cls.body if isinstance(fn, ast.FunctionDef)
             for attribute, name in sorted(_part_writes(fn, records))
             if name not in {f.name for f in dataclasses.fields(records[attribute])}]
    assert not stray, "\n".join(stray)


@pytest.mark.slow
def test_a_composed_part_changes_the_machine_only_inside_its_record() -> None:
    """devices.py and zhc_commands.py see the machine through a Protocol; they set no attribute of it."""
    records, composed = _records(), _composed()
    assert {path.name for path, _ in composed} >= {"devices.py", "zhc_commands.py"}
    stray = [f"{path.name}: {fn.name} sets machine.{attribute + '.' if attribute else ''}{name}"
             for path, fn in composed for attribute, name in sorted(_part_writes(fn, records, "machine"))
             if not attribute or name not in {f.name for f in dataclasses.fields(records[attribute])}]
    assert not stray, "\n".join(stray)


EVERY_PART = "\n".join(["M8", "M54 P3", "M54 E2 Q500", "M104 S200", "M91", "M100 P1.01", "T2 M6", "G43", "G92 X1",
                        "G51 P2", "G50", "ZHCINIT 10 2 2", 'msg "hello"', 'logmsg "logged"', "GetToolInfo first 100",
                        "M57 P3", "M3 S1000", "M51 P50", "G68 R30", "M26", "TCAGuard on", "G0 X1", "M30", ""])


def test_a_run_leaves_only_declared_attributes_on_the_machine(tmp_path: Path) -> None:
    """At run time too: a part that set an attribute outside ``__init__`` and its record fails here."""
    from edingcnc_lang.runner import Run

    run = Run(RunOptions(log_dir=tmp_path))
    result = run.execute_text(EVERY_PART)
    machine = run.interpreter
    assert result.error is None and result.ended_by == "M30"
    assert machine.devices.outputs == {3: True} and machine.devices.pwm == {2: 500.0}
    assert machine.offsets.g92_active and machine.zhc.table is not None and machine.messages.log_file is not None
    assert machine.spindle.speed == 1000.0 and machine.spindle.direction == 5  # M30 stops the spindle
    assert machine.rotation.turn is not None and machine.rotation.turn.angle == 30.0
    assert machine.rotation.sent_pivot is not None and machine.guards.clamped and machine.guards.tca_guard
    assert set(vars(machine)) == _declared()
    for attribute, record in _records().items():
        assert type(getattr(machine, attribute)) is record


@pytest.mark.slow
def test_no_part_keeps_state_in_a_class_attribute() -> None:
    shared = [f"{path.name}: {cls.name}: {ast.unparse(node)}" for path, cls in _parts() for node in cls.body
              if isinstance(node, (ast.Assign, ast.AnnAssign)) and not (
                  isinstance(node, ast.AnnAssign) and node.value is None)]
    assert not shared, "\n".join(shared)


class _Watch(Observer):
    def __init__(self) -> None:
        self.views: list[object] = []
        self.seen: list[tuple[str, int, int, tuple[float, ...], float]] = []

    def statement(self, machine: MachineView, stmt: n.Stmt) -> None:
        self.views.append(machine)
        self.seen.append((machine.path, machine.line, len(machine.stack), machine.position, machine.variable(1)))


def test_an_observer_is_shown_a_read_only_view() -> None:
    watch = _Watch()
    run_string("#1 = 5\nG0 X3\n", RunOptions(observer=watch))
    assert all(type(view) is MachineView for view in watch.views)
    assert watch.seen[-1] == ("<string>", 2, 0, (0.0, 0.0, 0.0, 0.0, 0.0, 0.0), 5.0)
    view = watch.views[0]
    with pytest.raises(AttributeError):
        view.line = 3  # type: ignore[misc]
    with pytest.raises(AttributeError):
        view.pos = [1.0] * 6  # type: ignore[attr-defined]


def test_two_machines_do_not_share_a_cycle_shift() -> None:
    """G87's shift was a class attribute: one machine's cycle left it for the next."""
    from edingcnc_lang.machine.interpreter import Interpreter

    class Sink:
        def move(self, move: object) -> None: ...
        def move_batch(self, batch: object) -> None: ...
        def event(self, event: object) -> None: ...
        def kinematics(self, *args: object) -> tuple[float, ...]: return (0.0,) * 6

    first, second = Interpreter(Sink()), Interpreter(Sink())  # type: ignore[arg-type]
    first.cycle.shift[0] = 2.0
    assert second.cycle.shift == {} and first.zhc.table is None and second.cycle.pitch == 0.0


def test_the_spindle_override_as_its_record_keeps_it() -> None:
    """M51 P sets the percent, M49 switches it off keeping the value, M48 (and M30) on at 100 % (manual p. 61)."""
    spindle = parts.SpindleState()
    assert spindle.factor == 1.0
    spindle.set_override(51, 50.0)
    assert (spindle.override, spindle.override_on, spindle.factor) == (50.0, True, 0.5)
    spindle.set_override(49, None)
    assert (spindle.override, spindle.override_on, spindle.factor) == (50.0, False, 1.0)
    spindle.set_override(51, None)
    assert spindle.factor == 0.5
    spindle.set_override(48, None)
    assert (spindle.override, spindle.factor) == (100.0, 1.0)
