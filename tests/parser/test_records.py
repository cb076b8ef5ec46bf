"""records.record builds the classes ``dataclass(frozen=True, ...)`` would: the same fields, init,
equality (span left out), hash, repr, copies, pickles and immutability, on twins built both ways."""
from __future__ import annotations

import copy
import dataclasses
import inspect
import pickle
from dataclasses import dataclass, field
from typing import Any

import pytest

from edingcnc_lang.syntax import nodes as n
from edingcnc_lang.records import record

SPAN = n.Span("a.cnc", 3, 1, 3, 9)


def _twins(**options: bool) -> tuple[Any, Any]:
    def body() -> dict[str, object]:
        return {"__annotations__": {"op": "str", "args": "tuple", "flag": "bool", "span": "n.Span"},
                "__module__": __name__, "flag": False, "span": field(default=n.NO_SPAN, compare=False)}
    stock: Any = dataclass(**options)(type("Twin", (), body()))  # type: ignore[call-overload]
    fast: Any = record(**options)(type("Twin", (), body()))  # type: ignore[call-overload]
    return stock, fast


@pytest.mark.parametrize("options", [{"frozen": True}, {"frozen": True, "slots": True},
                                     {"frozen": True, "eq": False}])
def test_a_record_behaves_as_the_dataclass(options: dict[str, bool]) -> None:
    stock, fast = _twins(**options)
    assert [(f.name, f.default, f.compare) for f in dataclasses.fields(stock)] == \
        [(f.name, f.default, f.compare) for f in dataclasses.fields(fast)]
    assert stock.__match_args__ == fast.__match_args__
    assert str(inspect.signature(stock)) == str(inspect.signature(fast))
    assert hasattr(stock, "__slots__") == hasattr(fast, "__slots__")
    values = [("+", (1, 2.5), True, SPAN), ("+", (1, 2.5), True, n.NO_SPAN), ("-", (), False, SPAN), ("+", (1,), True, SPAN)]
    made = [(stock(*v), fast(*v)) for v in values]
    assert [repr(s) for s, _ in made] == [repr(f) for _, f in made]
    for s1, f1 in made:
        for s2, f2 in made:
            assert (s1 == s2) == (f1 == f2) and (s1 != s2) == (f1 != f2)
            if s1 == s2:
                assert hash(f1) == hash(f2)
        assert (s1 == "x") == (f1 == "x")
        assert dataclasses.astuple(dataclasses.replace(f1, op="*")) == ("*", f1.args, f1.flag, f1.span)
        assert dataclasses.astuple(copy.deepcopy(f1)) == dataclasses.astuple(f1)
        assert dataclasses.astuple(copy.copy(f1)) == dataclasses.astuple(f1)
        for change in (lambda: setattr(f1, "op", "*"), lambda: delattr(f1, "op")):
            with pytest.raises(dataclasses.FrozenInstanceError):
                change()
    assert dataclasses.astuple(fast(flag=True, args=(), op="-")) == dataclasses.astuple(stock(flag=True, args=(), op="-"))
    assert str(inspect.signature(stock)) == str(inspect.signature(fast))  # (its __init__ compiled by now)
    with pytest.raises(TypeError):
        fast("+")  # a missing field, as the decorator's __init__ says


def test_node_classes_are_frozen_slotted_dataclasses() -> None:
    classes = [c for c in vars(n).values() if isinstance(c, type) and dataclasses.is_dataclass(c)]
    assert len(classes) >= 26
    for cls in classes:
        assert "__slots__" in vars(cls) and "__dict__" not in dir(cls), cls
        assert cls.__hash__ is not None and cls.__eq__ is not object.__eq__, cls
    number = n.Number(2.0, SPAN)
    assert number == n.Number(2.0) and hash(number) == hash(n.Number(2.0)) and number != n.Number(3.0)
    assert n.Stamp(SPAN) == n.Stamp() and n.Param(number) != number
    assert {n.GoSub("a"), n.GoSub("a", SPAN)} == {n.GoSub("a")}
    with pytest.raises(dataclasses.FrozenInstanceError):
        number.value = 3.0  # type: ignore[misc]
    tree = n.If(n.Compare("<", n.Param(number, SPAN), number), (n.GoSub("a", SPAN),), span=SPAN, end_span=SPAN)
    for again in (pickle.loads(pickle.dumps(tree)), copy.deepcopy(tree)):
        assert again == tree and again.span == SPAN and again.then[0].span == SPAN


def test_a_field_made_by_a_factory_is_made_for_each_record() -> None:
    """As a mutable default: the factory is called for every record that does not give the field."""
    def body() -> dict[str, object]:
        return {"__annotations__": {"kind": "str", "data": "dict"}, "__module__": __name__,
                "data": field(default_factory=dict)}
    stock: Any = dataclass(frozen=True, slots=True)(type("Event", (), body()))
    fast: Any = record(frozen=True, slots=True)(type("Event", (), body()))
    assert str(inspect.signature(stock)) == str(inspect.signature(fast)) == "(kind: 'str', data: 'dict' = <factory>) -> None"
    one, two = fast("dwell"), fast("dwell")
    assert one.data == {} and one.data is not two.data and one == two and repr(one) == repr(stock("dwell"))
    assert fast("dwell", {"s": 1}).data == {"s": 1} != one.data


def test_a_record_takes_plain_fields_only() -> None:
    with pytest.raises(TypeError, match="plain fields"):
        record(frozen=True)(type("Bad", (), {"__annotations__": {"items": "list"}, "__module__": __name__,
                                             "items": field(default=1, init=False)}))
