"""Literals and clauses: the prover's working form of a wff.

A literal is the pair ``(positive, atom)``. A :class:`Clause` is a disjunction of literals
whose variables are integers local to the clause, plus the parameter bindings made while
deriving it: the paper (III.A) requires that a binding made to a parameter in one
resolution step holds for every descendant, so the binding travels with the clause.
"""

from __future__ import annotations

from collections.abc import Iterable

from attrs import field, frozen

from strips_framework.logic.terms import Atom, Param, Term, atom_to_str, term_to_str

Literal = tuple[bool, Atom]


def _literal_tuple(items: Iterable[Literal]) -> tuple[Literal, ...]:
    return tuple(items)


def _binding_tuple(items: Iterable[tuple[Param, Term]]) -> tuple[tuple[Param, Term], ...]:
    return tuple(sorted(items, key=lambda pair: (pair[0].name, pair[0].tag)))


@frozen(cache_hash=True)
class Clause:
    """A disjunction of literals; the empty clause is a contradiction.

    ``bindings`` are the parameter bindings made on the way to this clause (answer
    extraction); ``label`` says where an input clause came from, for proofs and errors.
    """

    literals: tuple[Literal, ...] = field(converter=_literal_tuple)
    bindings: tuple[tuple[Param, Term], ...] = field(default=(), converter=_binding_tuple)
    label: str = field(default="", eq=False)

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

