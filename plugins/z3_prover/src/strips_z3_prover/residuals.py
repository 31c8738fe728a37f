"""The uncompleted proof Z3 leaves: the negated goal, cut down by the model's facts.

Z3 answers "not entailed" without a derivation, but the means-ends search needs the part
of the goal still to be achieved, in the shape the builtin difference extractor and the
add-list relevance filter read (III.C): clauses of negated goal literals, with the
parameter bindings that led to them. After a failed attempt this module resolves the
negated goal's literals away against the model's ground facts, one at a time and in every
order, as the paper's uncompleted proof would: ``~NEXTTO(ROBOT, m) | ~INROOM(m, x)`` with
the fact ``INROOM(BOX1, ROOM1)`` leaves ``~NEXTTO(ROBOT, BOX1)`` with ``m = BOX1``, the
goal literal not entailed for that instance. ``limit`` bounds how many clauses are made.

A clause that another one subsumes is left out, as the resolution prover's subsumption
deletes it: ``~ONFLOOR | ~LOCINROOM(f, ROOM1)`` says nothing that ``~LOCINROOM(f, ROOM1)``
does not, and kept in the difference it made ``ONFLOOR``, a fact, look like something to
achieve (``climboffbox`` became relevant, and other-room took 30 nodes instead of 12).
"""

from __future__ import annotations

from collections.abc import Sequence

from strips_framework.logic.clauses import Clause, Literal
from strips_framework.logic.terms import Param, Term
from strips_framework.logic.unify import substitute, unify


def uncompleted_proof(
    negated_goal: Sequence[Clause], axioms: Sequence[Clause], limit: int
) -> tuple[Clause, ...]:
    """The negated goal and its unit resolvents with the facts of ``axioms``, at most
    ``limit`` clauses, in the order they were made (the extractor sorts by size)."""
    facts: dict[tuple[str, int], list[tuple]] = {}
    for clause in axioms:
        if clause.is_unit and clause.literals[0][0]:
            atom = clause.literals[0][1]
            facts.setdefault((atom[0], len(atom)), []).append(atom)
    made = list(dict.fromkeys(negated_goal))
    seen = set(made)
    position = 0
    while position < len(made) and len(made) < limit:
        clause = made[position]
        position += 1
        for resolvent in _resolvents(clause, facts):
            if resolvent.literals and resolvent not in seen:
                seen.add(resolvent)
                made.append(resolvent)
                if len(made) >= limit:
                    break
    return _unsubsumed(made)


def _unsubsumed(clauses: list[Clause]) -> tuple[Clause, ...]:
    """``clauses`` less those another one subsumes: one whose literals and parameter
    bindings are a proper part of theirs (an instance of both is a proof of the smaller)."""
    parts = [(frozenset(c.literals), frozenset(c.bindings)) for c in clauses]
    return tuple(
        clause
        for clause, (literals, bindings) in zip(clauses, parts)
        if not any(
            (other_literals, other_bindings) != (literals, bindings)
            and other_literals <= literals
            and other_bindings <= bindings
            for other_literals, other_bindings in parts
        )
    )


def _resolvents(clause: Clause, facts: dict[tuple[str, int], list[tuple]]):
    for i, (positive, atom) in enumerate(clause.literals):
        if positive:
            continue
        for fact in facts.get((atom[0], len(atom)), ()):
            subst = unify(atom, fact, dict(clause.bindings))
            if subst is None:
                continue
            rest = [lit for j, lit in enumerate(clause.literals) if j != i]
            yield _instance(rest, subst)


def _instance(literals: list[Literal], subst: dict) -> Clause:
    numbering: dict[int, int] = {}
    renamed = [
        (positive, _renumber(substitute(atom, subst), numbering)) for positive, atom in literals
    ]
    bindings = [
        (key, substitute(value, subst)) for key, value in subst.items() if type(key) is Param
    ]
    return Clause(dict.fromkeys(renamed), bindings, label="z3 residual")


def _renumber(term: Term, numbering: dict[int, int]) -> Term:
    """Variables numbered in order of first occurrence, so equal clauses compare equal."""
    if type(term) is int:
        return numbering.setdefault(term, len(numbering))
    if type(term) is tuple:
        return (term[0], *[_renumber(arg, numbering) for arg in term[1:]])
    return term
