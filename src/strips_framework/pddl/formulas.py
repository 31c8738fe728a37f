"""The formulas of a lifted PDDL task: preconditions, goals and derived-predicate bodies.

Terms are plain strings: a variable starts with ``?``, anything else is an object (a
constant). Equality is an :class:`Atom` with predicate ``=``. ``(and)`` is truth.
"""

from __future__ import annotations

from attrs import frozen


@frozen
class Parameter:
    """A typed variable or object; ``types`` has more than one entry for ``(either ...)``."""

    name: str
    types: tuple[str, ...] = ("object",)


@frozen
class Atom:
    """``(predicate arg ...)``; also a numeric function application ``(f arg ...)``."""

    predicate: str
    args: tuple[str, ...]

    def __str__(self) -> str:
        return "(" + " ".join((self.predicate, *self.args)) + ")"


@frozen
class Not:
    part: Formula


@frozen
class And:
    parts: tuple[Formula, ...]


@frozen
class Or:
    parts: tuple[Formula, ...]


@frozen
class Imply:
    condition: Formula
    consequence: Formula


@frozen
class Exists:
    params: tuple[Parameter, ...]
    body: Formula


@frozen
class Forall:
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
