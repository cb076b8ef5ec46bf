"""Frozen dataclasses built in a fraction of the decorator's time (the syntax tree, the linter's records).

``dataclass(frozen=True)`` compiles five or six generated methods per class at import time on
Python 3.10-3.12 (``__init__``, ``__repr__``, ``__eq__``, ``__hash__``, ``__setattr__``,
``__delattr__``: one ``exec`` each); for the syntax tree's 26 classes that was about 30 ms of
every command's start-up. ``record`` still lets ``dataclasses.dataclass`` read the fields (so
``fields``, ``replace``, ``is_dataclass``, ``__match_args__`` and the slots are the standard
ones) but compiles nothing: ``__init__`` is a closure over the class's fields, and every other
method is one function shared by all classes, driven by the class's tuple of compared fields. Equality (spans with
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
    made: Any = dataclass(cls, init=False, repr=False, eq=False, slots=slots)
    for f in fields(made):
        if not f.init or f.hash is not None:
            raise TypeError(f"{cls.__name__}.{f.name}: records.record takes plain fields, defaults and factories only")
    if eq:
        made._record_key = staticmethod(_key(tuple(f.name for f in fields(made) if f.compare)))
    made.__init__ = _init(made)
    if slots:  # as dataclass(frozen=True, slots=True): copy and pickle set the fields past __setattr__
        made.__getstate__, made.__setstate__ = _getstate, _setstate
    return made


def _key(names: tuple[str, ...]) -> Callable[[Any], tuple[Any, ...]]:
    """The tuple of a record's compared fields, which equality and the hash are taken over."""
    if len(names) > 1:
        return attrgetter(*names)
    if names:
        one = attrgetter(names[0])
        return lambda record: (one(record),)
    return lambda record: ()


class _Factory:
    """The default of a field made by its ``default_factory`` (shown as the decorator shows it)."""

    def __repr__(self) -> str:
        return "<factory>"


_FACTORY = _Factory()


def _init(cls: Any) -> Callable[..., None]:
    """The ``__init__`` the decorator writes, built without compiling one: one parameter per field, defaults
    kept (a factory called for each record that does not give the field), each field set past the frozen
    ``__setattr__``, then ``__post_init__``.  All fields given in order (the usual call) or the leading ones
    with the defaults after them take the short way; keywords are bound by the signature, whose errors
    are the decorator's."""
    names = tuple(f.name for f in fields(cls))
    defaults = [f.default if f.default is not MISSING else _FACTORY if f.default_factory is not MISSING else
                Parameter.empty for f in fields(cls)]
    factories = {f.name: f.default_factory for f in fields(cls) if f.default_factory is not MISSING}
    signature = Signature([Parameter("self", Parameter.POSITIONAL_OR_KEYWORD),
                           *(Parameter(f.name, Parameter.POSITIONAL_OR_KEYWORD, annotation=f.type, default=default)
                             for f, default in zip(fields(cls), defaults))], return_annotation=None)
    count, post_init = len(names), hasattr(cls, "__post_init__")
    # for the first k fields given: the defaults of the rest (None when one has none: bound instead) and
    # the fields among them a factory makes
    tails = [tuple(defaults[k:]) if Parameter.empty not in defaults[k:] else None for k in range(count + 1)]
    fresh = [[(i, factories[names[i]]) for i in range(k, count) if defaults[i] is _FACTORY] for k in range(count + 1)]
    slotted = "__slots__" in vars(cls)
    # each field's slot descriptor sets it, as object.__setattr__ would once it has found it
    setters = tuple(getattr(cls, name).__set__ for name in names) if slotted else ()

    def values(self: Any, args: tuple[Any, ...], kwargs: dict[str, Any]) -> tuple[Any, ...]:
        """All fields' values of a call that does not give them all in order."""
        tail = None if kwargs or len(args) > count else tails[len(args)]
        if tail is None:
            bound = signature.bind(self, *args, **kwargs).arguments
            return tuple(factories[name]() if name in factories and name not in bound else bound.get(name, default)
                         for name, default in zip(names, defaults))
        made = fresh[len(args)]
        if not made:
            return args + tail
        whole = [*args, *tail]
        for index, factory in made:
            whole[index] = factory()
        return tuple(whole)

    def __init__(self: Any, *args: Any, **kwargs: Any) -> None:
        if kwargs or len(args) != count:
            args = values(self, args, kwargs)
        if slotted:
            for setter, value in zip(setters, args):
                setter(self, value)
        else:
            vars(self).update(zip(names, args))
        if post_init:
            self.__post_init__()

    __init__.__qualname__ = f"{cls.__qualname__}.__init__"
    __init__.__signature__ = signature  # type: ignore[attr-defined]
    return __init__


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
