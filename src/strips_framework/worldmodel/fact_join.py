"""Whether a conjunctive query holds in a world model by its facts alone: a join of the
query's atoms over the model's ground facts.

A means-ends search asks its prover about goals that are mostly conjunctions of atoms
(a translated PDDL precondition is one), and most attempts fail. A failed resolution
attempt cannot stop early: it gives up only when its effort runs out (on elevators of
IPC 2008, 300 given clauses and 20 to 130 ms, while a proof takes 1 to 3 given clauses).
When every atom of the query is of a predicate that only ground facts conclude, a
refutation can only resolve each goal literal on a fact, so the query is provable exactly
when some binding maps all of its atoms onto facts of the model at once: a join, decided
without the prover. The caller says which predicates only facts conclude
(:attr:`strips_framework.means_ends.goal_prover.GoalProver.derivable` is the rest).
"""

from __future__ import annotations

from collections.abc import Sequence

from strips_framework.logic.clauses import Literal
from strips_framework.logic.terms import EQUALITY, SKOLEM_PREFIX, Atom, Term
from strips_framework.logic.unify import substitute, unify
from strips_framework.worldmodel.world import WorldModel

#: Unifications a join may try before it gives up undecided (``None``): a query of a
#: dozen atoms over a large model could otherwise enumerate a product of candidates.
JOIN_BUDGET = 20_000


def facts_join(
    model: WorldModel, literals: Sequence[Literal], budget: int = JOIN_BUDGET
) -> bool | None:
    """Whether some binding of the variables and parameters of the negated goal clause
    ``literals`` refutes it on ``model``'s facts: each negative literal's atom a fact, and
    each positive equation (the goal's ``s != t``, under unique names) between two
    distinct names. ``None`` when that is undecided: an equation still has a variable or
    a Skolem term once the atoms are bound, or ``budget`` unifications ran out.

    The caller vouches that the clause is a conjunctive query whose atoms only facts
    conclude (:func:`strips_framework.logic.horn.is_conjunctive_query`); atoms are
    matched most-bound first, fewest candidates first, so a ground atom that is no fact
    ends the join at once."""
    atoms = [atom for positive, atom in literals if not positive]
    equations = [atom for positive, atom in literals if positive and atom[0] == EQUALITY]
    search = _Join(model, equations, budget)
    if search.extend(atoms, {}):
        return True
    return None if search.undecided or search.left <= 0 else False


class _Join:
    """One join's state: the budget left, and whether a match left an equation
    undecided. Plain recursion, not a generator: the run's time limit is an exception
    raised wherever the process is, and one raised while an abandoned generator is
    being finalized would be lost."""

    __slots__ = ("equations", "left", "model", "undecided")

    def __init__(self, model: WorldModel, equations: list[Atom], budget: int) -> None:
        self.model = model
        self.equations = equations
        self.left = budget
        self.undecided = False

    def extend(self, atoms: list[Atom], binding: dict) -> bool:
        """Whether an extension of ``binding`` maps all of ``atoms`` onto facts and
        makes every equation's sides distinct names; depth first, the atom with fewest
        candidate facts first. False also when the budget ran out."""
        if not atoms:
            verdict = _all_distinct(self.equations, binding)
            self.undecided = self.undecided or verdict is None
            return bool(verdict)
        best: tuple[list[Atom], Atom] | None = None
        for atom in atoms:
            candidates = list(self.model.facts_matching(substitute(atom, binding)))
            if not candidates:
                return False
            if best is None or len(candidates) < len(best[0]):
                best = (candidates, atom)
        assert best is not None
        candidates, chosen = best
        rest = [atom for atom in atoms if atom is not chosen]
        for fact in candidates:
            if self.left <= 0:
                return False
            self.left -= 1
            extended = unify(chosen, fact, dict(binding))
            if extended is not None and self.extend(rest, extended):
                return True
        return False


def _all_distinct(equations: list[Atom], binding: dict) -> bool | None:
    """True when every equation's sides are distinct names under ``binding``, False
    when one has the same name on both sides, ``None`` when one is not decided by names."""
    verdict: bool | None = True
    for _, left_side, right_side in equations:
        one, other = substitute(left_side, binding), substitute(right_side, binding)
        if not (_name(one) and _name(other)):
            verdict = None
        elif one == other:
            return False
    return verdict


def _name(term: Term) -> bool:
    """A constant that unique names make distinct from every other: no variable,
    parameter or Skolem constant (which may denote any object)."""
    return type(term) is str and not term.startswith(SKOLEM_PREFIX)
