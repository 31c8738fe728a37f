"""The formulas of a lifted PDDL task: preconditions, goals and derived-predicate bodies.

Terms are plain strings: a variable starts with ``?``, anything else is an object (a
constant). Equality is an :class:`Atom` with predicate ``=``. ``(and)`` is truth.

Each node is a :class:`~strips_framework.records.Record` (no attrs on the PDDL path: it is
built at every start-up); records compare by type too, so ``(and)`` never equals ``(or)``.
"""

from __future__ import annotations

from strips_framework.records import Record


class Parameter(Record):
    """A typed variable or object; ``types`` has more than one entry for ``(either ...)``."""

    name: str
    types: tuple[str, ...]

    __slots__ = ("name", "types")

    def __init__(self, name: str, types: tuple[str, ...] = ("object",)) -> None:
        self.name = name
        self.types = types


class Atom(Record):
    """``(predicate arg ...)``; also a numeric function application ``(f arg ...)``."""

    predicate: str
    args: tuple[str, ...]

    __slots__ = ("predicate", "args")

    def __init__(self, predicate: str, args: tuple[str, ...]) -> None:
        self.predicate = predicate
        self.args = args

    def __str__(self) -> str:
        return "(" + " ".join((self.predicate, *self.args)) + ")"


class Not(Record):
    part: Formula

    __slots__ = ("part",)

    def __init__(self, part: Formula) -> None:
        self.part = part


class And(Record):
    parts: tuple[Formula, ...]

    __slots__ = ("parts",)

    def __init__(self, parts: tuple[Formula, ...]) -> None:
        self.parts = parts


class Or(Record):
    parts: tuple[Formula, ...]

    __slots__ = ("parts",)

    def __init__(self, parts: tuple[Formula, ...]) -> None:
        self.parts = parts


class Imply(Record):
    condition: Formula
    consequence: Formula

    __slots__ = ("condition", "consequence")

    def __init__(self, condition: Formula, consequence: Formula) -> None:
        self.condition = condition
        self.consequence = consequence


class Exists(Record):
    params: tuple[Parameter, ...]
    body: Formula

    __slots__ = ("params", "body")

    def __init__(self, params: tuple[Parameter, ...], body: Formula) -> None:
        self.params = params
        self.body = body


class Forall(Record):
    params: tuple[Parameter, ...]
    body: Formula

    __slots__ = ("params", "body")

    def __init__(self, params: tuple[Parameter, ...], body: Formula) -> None:
        self.params = params
        self.body = body


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
