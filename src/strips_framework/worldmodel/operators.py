"""Operator instances and their application to world models (III.B)."""

from __future__ import annotations

from collections.abc import Iterable

from strips_framework.logic.formulas import Formula, substitute_free
from strips_framework.logic.terms import WILDCARD, Atom, Param, Term, is_ground, term_to_str
from strips_framework.logic.unify import substitute
from strips_framework.records import Record
from strips_framework.worldmodel.problem import OperatorSchema
from strips_framework.worldmodel.world import WorldModel


def _bindings(items: Iterable[tuple[Param, Term]]) -> tuple[tuple[Param, Term], ...]:
    return tuple(sorted(items, key=lambda pair: (pair[0].name, pair[0].tag)))


class OperatorInstance(Record):
    """A schema with some or all of its parameters bound.

    Unbound parameters are still parameters; an instance is applied only once all of
    them are bound to ground terms. Two instances are equal when their schemas' names
    and their bindings are (the schema itself is not compared); the search hashes
    instances often, so the hash is computed once.
    """

    schema: OperatorSchema
    binding: tuple[tuple[Param, Term], ...]
    schema_name: str

    FIELDS = ("schema", "binding")
    COMPARED = ("binding", "schema_name")
    __slots__ = ("schema", "binding", "schema_name", "_hash")

    def __init__(self, schema: OperatorSchema, binding: Iterable[tuple[Param, Term]]) -> None:
        self.schema = schema
        self.binding = _bindings(binding)
        self.schema_name = schema.name
        self._hash = hash((type(self).__name__, self.binding, self.schema_name))

    def __eq__(self, other: object) -> bool:
        return (
            type(other) is type(self)
            and other.binding == self.binding  # type: ignore[attr-defined]
            and other.schema_name == self.schema_name  # type: ignore[attr-defined]
        )

    def __hash__(self) -> int:
        return self._hash

    def __reduce__(self) -> tuple[type[OperatorInstance], tuple[object, ...]]:
        # Rebuilt from its fields: a string's hash differs between processes.
        return (type(self), (self.schema, self.binding))

    def binding_map(self) -> dict[Param, Term]:
        return dict(self.binding)

    def arguments(self) -> tuple[Term, ...]:
        bound = self.binding_map()
        return tuple(substitute(p, bound) for p in self.schema.parameters)

    @property
    def is_ground(self) -> bool:
        return all(is_ground(arg) for arg in self.arguments())

    def precondition(self) -> Formula:
        return substitute_free(self.schema.precondition, self.binding_map())

    def bind(self, more: dict[Param, Term]) -> OperatorInstance:
        """This instance with ``more`` bindings added (earlier bindings win)."""
        merged = {**more, **self.binding_map()}
        resolved = {p: substitute(t, merged) for p, t in merged.items()}
        own = set(self.schema.parameters)
        return OperatorInstance(self.schema, [(p, t) for p, t in resolved.items() if p in own])

    def effects(self) -> tuple[tuple[Atom, ...], tuple[Atom, ...]]:
        """The instantiated ``(delete_list, add_list)``."""
        bound = self.binding_map()
        deletes = tuple(substitute(a, bound) for a in self.schema.delete_list)
        adds = tuple(substitute(a, bound) for a in self.schema.add_list)
        return deletes, adds

    def steps(self) -> tuple[OperatorInstance, ...]:
        """The primitive instances this one stands for in a plan: itself (an instance of
        a MACROP stands for the steps of its triangle table)."""
        return (self,)

    def admits(self) -> bool:
        """Whether the operator allows this binding once its precondition is proved (a
        MACROP forbids bindings under which one of its steps would undo another's work)."""
        return True

    def apply(self, model: WorldModel) -> WorldModel:
        """The world model after this (ground) instance: delete, then add."""
        if not self.is_ground:
            raise ValueError(f"cannot apply {self}: parameters are unbound")
        delete_patterns, adds = self.effects()
        deleted = frozenset(
            fact
            for pattern in delete_patterns
            for fact in model.facts_matching(pattern)
            if may_delete(pattern, fact)
        )
        return model.changed(deleted, frozenset(adds))

    def __str__(self) -> str:
        return f"{self.schema.name}({', '.join(map(term_to_str, self.arguments()))})"

    def ipc(self) -> str:
        """The IPC plan-file form ``(name arg ...)``; names keep the case the user wrote
        (plan validators compare names case-insensitively)."""
        return "(" + " ".join([self.schema.name, *map(term_to_str, self.arguments())]) + ")"


def may_delete(pattern: Term, term: Term) -> bool:
    """Whether the delete-list ``pattern`` matches ``term``: ``$`` and parameters not yet
    bound match anything (in a ground instance only ``$`` is left)."""
    if pattern == WILDCARD or type(pattern) is Param:
        return True
    if type(pattern) is tuple:
        return (
            type(term) is tuple
            and len(pattern) == len(term)
            and pattern[0] == term[0]
            and all(may_delete(p, t) for p, t in zip(pattern[1:], term[1:]))
        )
    return pattern == term
