"""Literals and clauses: the prover's working form of a wff.

A literal is the pair ``(positive, atom)``. A :class:`Clause` is a disjunction of literals
whose variables are integers local to the clause, plus the parameter bindings made while
deriving it: the paper (III.A) requires that a binding made to a parameter in one
resolution step holds for every descendant, so the binding travels with the clause.
"""

from __future__ import annotations

from collections.abc import Iterable

from strips_framework.logic.terms import Atom, Param, Term, atom_to_str, term_to_str
from strips_framework.records import Record

Literal = tuple[bool, Atom]


def _binding_tuple(items: Iterable[tuple[Param, Term]]) -> tuple[tuple[Param, Term], ...]:
    return tuple(sorted(items, key=lambda pair: (pair[0].name, pair[0].tag)))


class Clause(Record):
    """A disjunction of literals; the empty clause is a contradiction.

    ``bindings`` are the parameter bindings made on the way to this clause (answer
    extraction); ``label`` says where an input clause came from, for proofs and errors.
    Two clauses are equal when their literals and bindings are (the label is not
    compared); the prover hashes clauses often, so the hash is computed once.
    """

    literals: tuple[Literal, ...]
    bindings: tuple[tuple[Param, Term], ...]
    label: str

    FIELDS = ("literals", "bindings", "label")
    __slots__ = ("literals", "bindings", "label", "_hash")

    def __init__(
        self,
        literals: Iterable[Literal],
        bindings: Iterable[tuple[Param, Term]] = (),
        label: str = "",
    ) -> None:
        self.literals = tuple(literals)
        self.bindings = _binding_tuple(bindings)
        self.label = label
        self._hash = hash(("Clause", self.literals, self.bindings))

    def __eq__(self, other: object) -> bool:
        return (
            type(other) is Clause
            and other.literals == self.literals
            and other.bindings == self.bindings
        )

    def __hash__(self) -> int:
        return self._hash

    def __reduce__(self) -> tuple[type[Clause], tuple[object, ...]]:
        # Rebuilt from its fields: a string's hash differs between processes.
        return (Clause, (self.literals, self.bindings, self.label))

    @property
    def is_empty(self) -> bool:
        return not self.literals

    @property
    def is_unit(self) -> bool:
        return len(self.literals) == 1

    def binding_map(self) -> dict[Param, Term]:
        return dict(self.bindings)

    def __str__(self) -> str:
        return clause_to_str(self)


def literal_to_str(literal: Literal, var_names: dict[int, str] | None = None) -> str:
    positive, atom = literal
    if not positive and atom[0] == "=" and len(atom) == 3:
        return f"{term_to_str(atom[1], var_names)} != {term_to_str(atom[2], var_names)}"
    text = atom_to_str(atom, var_names)
    return text if positive else f"~{text}"


def clause_to_str(clause: Clause) -> str:
    if not clause.literals:
        text = "false"
    else:
        text = " | ".join(literal_to_str(lit) for lit in clause.literals)
    if clause.bindings:
        bound = ", ".join(f"{p.name}={term_to_str(t)}" for p, t in clause.bindings)
        text += f"  [{bound}]"
    return text

