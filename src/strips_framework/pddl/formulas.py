"""The formulas of a lifted PDDL task: preconditions, goals and derived-predicate bodies.

Terms are plain strings: a variable starts with ``?``, anything else is an object (a
constant). Equality is an :class:`Atom` with predicate ``=``. ``(and)`` is truth.

Each node is a :class:`~typing.NamedTuple` (built in microseconds, where an attrs class
costs a compile of its methods at every start-up). A tuple equals any tuple of the same
items, so the connectives, whose shapes coincide (``(and)`` and ``(or)``, ``exists`` and
``forall``), compare and hash by their type too (:func:`_typed_equality`).
"""

from __future__ import annotations

from typing import NamedTuple


def _eq(self: tuple, other: object) -> bool:
    return type(other) is type(self) and tuple.__eq__(self, other)  # type: ignore[arg-type]


def _ne(self: tuple, other: object) -> bool:
    return not _eq(self, other)


def _hash(self: tuple) -> int:
    return hash((type(self).__name__, tuple.__hash__(self)))


def _typed_equality(cls: type) -> type:
    """``cls`` (a NamedTuple) equal only to values of its own type."""
    cls.__eq__ = _eq  # type: ignore[method-assign,assignment]
    cls.__ne__ = _ne  # type: ignore[method-assign,assignment]
    cls.__hash__ = _hash  # type: ignore[method-assign,assignment]
    return cls


class Parameter(NamedTuple):
    """A typed variable or object; ``types`` has more than one entry for ``(either ...)``."""

    name: str
    types: tuple[str, ...] = ("object",)


class Atom(NamedTuple):
    """``(predicate arg ...)``; also a numeric function application ``(f arg ...)``."""

    predicate: str
    args: tuple[str, ...]

    def __str__(self) -> str:
        return "(" + " ".join((self.predicate, *self.args)) + ")"


@_typed_equality
class Not(NamedTuple):
    part: Formula


@_typed_equality
class And(NamedTuple):
    parts: tuple[Formula, ...]


@_typed_equality
class Or(NamedTuple):
    parts: tuple[Formula, ...]


@_typed_equality
class Imply(NamedTuple):
    condition: Formula
    consequence: Formula


@_typed_equality
class Exists(NamedTuple):
    params: tuple[Parameter, ...]
    body: Formula


@_typed_equality
class Forall(NamedTuple):
    params: tuple[Parameter, ...]
    body: Formula


Formula = Atom | Not | And | Or | Imply | Exists | Forall

TRUE = And(())


def substitute(args: tuple[str, ...], binding: dict[str, str]) -> tuple[str, ...]:
    """``args`` with every bound variable replaced by its value."""
    return tuple(binding.get(arg, arg) for arg in args)


def show(formula: Formula) -> str:
    """PDDL text of ``formula``, for messages."""
    if isinstance(formula, Atom):
        return str(formula)
    if isinstance(formula, Not):
        return f"(not {show(formula.part)})"
    if isinstance(formula, And | Or):
        word = "and" if isinstance(formula, And) else "or"
        return "(" + " ".join((word, *map(show, formula.parts))) + ")"
    if isinstance(formula, Imply):
        return f"(imply {show(formula.condition)} {show(formula.consequence)})"
    word = "exists" if isinstance(formula, Exists) else "forall"
    params = " ".join(f"{p.name} - {_show_types(p.types)}" for p in formula.params)
    return f"({word} ({params}) {show(formula.body)})"


def _show_types(types: tuple[str, ...]) -> str:
    return types[0] if len(types) == 1 else "(either " + " ".join(types) + ")"
