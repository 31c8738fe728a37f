"""Which clauses a Datalog engine answers: safe definite Horn rules and conjunctive queries.

A prover that declares ``definite-horn`` (the join engine, ``joins``) computes a least
model and joins the goal's atoms over it; it needs no more than this shape, and refuses
anything else. The check that a problem fits its prover
(:func:`strips_framework.plugin.checks.check_problem`) asks these questions, so a run is
refused before it starts rather than halfway through a search, and a problem whose
axioms are rules such as ``CONNECTS(x, y, z) -> CONNECTS(x, z, y)`` is not sent to a
first-order prover for want of a word.
"""

from __future__ import annotations

from collections.abc import Sequence

from strips_framework.logic.clauses import Clause
from strips_framework.logic.terms import EQUALITY, Atom, Param, Term


def is_datalog_rule(clause: Clause) -> bool:
    """``clause`` is a definite Horn clause a least model can be built from: exactly one
    positive literal, no equality, no function term with variables in it (a ground one
    is just a name), and every variable of its head bound by its body (a fact has none)."""
    positive = [atom for sign, atom in clause.literals if sign]
    if len(positive) != 1:
        return False
    if any(atom[0] == EQUALITY or _open_function_term(atom) for _, atom in clause.literals):
        return False
    body = {v for sign, atom in clause.literals if not sign for v in _variables(atom)}
    return _variables(positive[0]) <= body


def is_conjunctive_query(negated_goal: Sequence[Clause], unique_names: bool) -> bool:
    """The negated goal is one clause of negated atoms (a conjunction of atoms, perhaps
    existentially quantified), with, under unique names, positive equations: the goal's
    inequalities, decided by comparing names. No function term with variables."""
    if len(negated_goal) != 1:
        return False
    for sign, atom in negated_goal[0].literals:
        if _open_function_term(atom):
            return False
        if sign != (atom[0] == EQUALITY) or (sign and not unique_names):
            return False
    return True


def _variables(atom: Atom) -> set[Term]:
    return {t for t in atom[1:] if type(t) is int or type(t) is Param}


def _open_function_term(atom: Atom) -> bool:
    return any(type(t) is tuple and _has_variables(t) for t in atom[1:])


def _has_variables(term: Term) -> bool:
    if type(term) is int or type(term) is Param:
        return True
    return type(term) is tuple and any(_has_variables(t) for t in term[1:])
