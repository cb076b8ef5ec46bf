"""Frozen dataclasses built in a fraction of the decorator's time (the syntax tree, the linter's records).

``dataclass(frozen=True)`` compiles five or six generated methods per class at import time on
Python 3.10-3.12 (``__init__``, ``__repr__``, ``__eq__``, ``__hash__``, ``__setattr__``,
``__delattr__``: one ``exec`` each); for the syntax tree's 26 classes that was about 30 ms of
every command's start-up. ``record`` still lets ``dataclasses.dataclass`` read the fields (so
``fields``, ``replace``, ``is_dataclass``, ``__match_args__`` and the slots are the standard
ones) but compiles only ``__init__``, when it is first called, and shares one function per other
method among all classes, each driven by the class's tuple of compared fields. Equality (spans with
``compare=False`` left out), hashing, repr, copying and immutability behave as the decorator's.
Type checkers see the decorator itself.
"""
from __future__ import annotations

from dataclasses import MISSING, FrozenInstanceError, dataclass, fields
from inspect import Parameter, Signature
from operator import attrgetter
from typing import TYPE_CHECKING, Any, Callable, TypeVar

T = TypeVar("T")

if TYPE_CHECKING:  # to a type checker, the decorator it stands for
    from dataclasses import dataclass as record
else:
    def record(*, frozen: bool, eq: bool = True, slots: bool = False) -> Callable[[type[T]], type[T]]:
        """``dataclass(frozen=True, eq=..., slots=...)``, as the classes declare it."""
        if not frozen:
            raise TypeError("records.record makes frozen dataclasses only")
        return lambda cls: _build(cls, eq, slots)


def _build(cls: type[T], eq: bool, slots: bool) -> type[T]:
    for name, method in _SHARED.items():
        if eq or name not in ("__eq__", "__hash__"):  # without eq: compared and hashed by identity
            setattr(cls, name, method)
    made: Any = dataclass(cls, init=False, repr=False, eq=False, slots=slots)  # type: ignore[call-overload]
    for f in fields(made):
        if not f.init or f.hash is not None:
            raise TypeError(f"{cls.__name__}.{f.name}: records.record takes plain fields, defaults and factories only")
    if eq:
        made._record_key = staticmethod(_key(tuple(f.name for f in fields(made) if f.compare)))
    made.__init__ = _first_init(made)
    if slots:  # as dataclass(frozen=True, slots=True): copy and pickle set the fields past __setattr__
        made.__getstate__, made.__setstate__ = _getstate, _setstate
    return made  # type: ignore[no-any-return]


def _key(names: tuple[str, ...]) -> Callable[[Any], tuple[Any, ...]]:
    """The tuple of a record's compared fields, which equality and the hash are taken over."""
    if len(names) > 1:
        return attrgetter(*names)
    if names:
        one = attrgetter(names[0])
        return lambda record: (one(record),)
    return lambda record: ()


def _first_init(cls: Any) -> Callable[..., None]:
    """An ``__init__`` that compiles the class's own on its first call and hands over to it: most
    records of the syntax tree are made by the compiled reader without their ``__init__``, so a
    command compiles only those it calls (each compile took ~0.2 ms of the start-up). It has the
    signature of the one it stands for."""
    def __init__(self: Any, *args: Any, **kwargs: Any) -> None:
        cls.__init__ = init = _init(cls)
        init(self, *args, **kwargs)

    __init__.__qualname__ = f"{cls.__qualname__}.__init__"
    __init__.__signature__ = Signature(  # type: ignore[attr-defined]
        [Parameter("self", Parameter.POSITIONAL_OR_KEYWORD),
         *(Parameter(f.name, Parameter.POSITIONAL_OR_KEYWORD, annotation=f.type,
                     default=_default(f)) for f in fields(cls))],
        return_annotation=None)
    return __init__


class _Factory:
    """The default of a field made by its ``default_factory`` (shown as the decorator shows it)."""

    def __repr__(self) -> str:
        return "<factory>"


_FACTORY = _Factory()


def _default(f: Any) -> Any:
    """A field's default in the signature."""
    if f.default is not MISSING:
        return f.default
    return Parameter.empty if f.default_factory is MISSING else _FACTORY


def _init(cls: Any) -> Callable[..., None]:
    """The ``__init__`` the decorator writes: one parameter per field, defaults kept (a factory called for
    each record that does not give the field), each field set past the frozen ``__setattr__``."""
    params, body, namespace = [], [], {"_set": object.__setattr__, "_FACTORY": _FACTORY}
    for f in fields(cls):
        value = f.name
        if f.default is not MISSING:
            namespace[f"_default_{f.name}"] = f.default
            params.append(f"{f.name}=_default_{f.name}")
        elif f.default_factory is not MISSING:
            namespace[f"_factory_{f.name}"] = f.default_factory
            params.append(f"{f.name}=_FACTORY")
            value = f"_factory_{f.name}() if {f.name} is _FACTORY else {f.name}"
        else:
            params.append(f.name)
        body.append(f" _set(self, {f.name!r}, {value})")
    if hasattr(cls, "__post_init__"):
        body.append(" self.__post_init__()")
    exec(f"def __init__(self, {', '.join(params)}):\n" + "\n".join(body or [" pass"]), namespace)
    init: Any = namespace["__init__"]
    init.__qualname__ = f"{cls.__qualname__}.__init__"
    init.__annotations__ = {**{f.name: f.type for f in fields(cls)}, "return": None}
    return init  # type: ignore[no-any-return]


def _eq(self: Any, other: Any) -> Any:
    if other.__class__ is self.__class__:
        return self._record_key(self) == self._record_key(other)
    return NotImplemented


def _hash(self: Any) -> int:
    return hash(self._record_key(self))


def _repr(self: Any) -> str:
    shown = ", ".join(f"{f.name}={getattr(self, f.name)!r}" for f in fields(self) if f.repr)
    return f"{self.__class__.__qualname__}({shown})"


def _setattr(self: Any, name: str, value: Any) -> None:
    raise FrozenInstanceError(f"cannot assign to field {name!r}")


def _delattr(self: Any, name: str) -> None:
    raise FrozenInstanceError(f"cannot delete field {name!r}")


def _getstate(self: Any) -> list[Any]:
    return [getattr(self, f.name) for f in fields(self)]


def _setstate(self: Any, state: list[Any]) -> None:
    for f, value in zip(fields(self), state):
        object.__setattr__(self, f.name, value)


_SHARED = {"__eq__": _eq, "__hash__": _hash, "__repr__": _repr, "__setattr__": _setattr, "__delattr__": _delattr}
