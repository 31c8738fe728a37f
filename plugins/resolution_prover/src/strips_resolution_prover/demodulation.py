"""Demodulation: rewriting new clauses with oriented unit equations, to a normal form.

A retained positive unit ``l = r`` without parameter bindings, with ``l`` above ``r`` in
the Knuth-Bendix ordering (:mod:`.kbo`), rewrites every instance ``lσ`` in a new clause to
``rσ``. The rewritten clause follows from the original and the equation, so it replaces
the original (recording the equation among its parents, for the proof); since each step
goes down in a well-founded ordering, rewriting ends. This is what keeps equational
problems (groups, set algebra) from drowning in paramodulants that only differ by
rewritable subterms. Forward, on every new clause, and backward: a new equation rewrites
the retained clauses it applies to (:meth:`~strips_resolution_prover.prover._Saturation.
_rewrite_retained`), which are replaced by their normal forms, as in E, so an equation
such as ``c = a`` found late (SET018+4) simplifies the clauses that were kept before it.
"""

from __future__ import annotations

from strips_framework.logic.clauses import Literal
from strips_framework.logic.terms import Term
from strips_resolution_prover.equality import is_equality
from strips_resolution_prover.kbo import greater
from strips_resolution_prover.pclause import PClause
from strips_resolution_prover.subsumption import match_term

#: Rewrite steps per clause at most (a safety net: KBO makes every chain finite).
MAX_STEPS = 1000


def _key(term: Term) -> object:
    return (term[0], len(term)) if type(term) is tuple else term


class Demodulators:
    """The oriented unit equations, filed by the head symbol of their left side."""

    def __init__(self) -> None:
        self._rules: dict[object, list[tuple[Term, Term, PClause]]] = {}

    def __bool__(self) -> bool:
        return bool(self._rules)

    def add(self, clause: PClause) -> bool:
        """File ``clause`` if it is a positive unit equation without bindings that the
        ordering orients (either way round); whether it was filed."""
        if len(clause.literals) != 1 or clause.bindings:
            return False
        positive, atom = clause.literals[0]
        if not positive or not is_equality(atom):
            return False
        left, right = atom[1], atom[2]
        if greater(right, left):
            left, right = right, left
        elif not greater(left, right):
            return False
        self._rules.setdefault(_key(left), []).append((left, right, clause))
        return True

    def rewrite(self, literals: tuple[Literal, ...]) -> tuple[tuple[Literal, ...], list[int]]:
        """``literals`` in normal form, and the ids of the equations used (none: unchanged)."""
        used: list[int] = []
        out = tuple((positive, self._normal(atom, used)) for positive, atom in literals)
        return (out, used) if used else (literals, used)

    def _normal(self, atom: tuple, used: list[int]) -> tuple:
        return (atom[0], *[self._term(arg, used) for arg in atom[1:]])

    def _term(self, term: Term, used: list[int]) -> Term:
        if type(term) is int:
            return term
        for _ in range(MAX_STEPS):
            if type(term) is tuple:
                term = (term[0], *[self._term(arg, used) for arg in term[1:]])
            rewritten = self._step(term, used)
            if rewritten is None:
                return term
            term = rewritten
        return term

    def _step(self, term: Term, used: list[int]) -> Term | None:
        for left, right, clause in self._rules.get(_key(term), ()):
            if clause.dead:
                continue
            subst: dict[int, Term] = {}
            if match_term(left, term, subst):
                used.append(clause.id)
                return _apply(right, subst)
        return None


def _apply(term: Term, subst: dict[int, Term]) -> Term:
    kind = type(term)
    if kind is int:
        return subst[term]
    if kind is tuple:
        return (term[0], *[_apply(arg, subst) for arg in term[1:]])
    return term
