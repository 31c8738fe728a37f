"""What is left of a goal a prover could not prove, for provers that keep no uncompleted
proof.

Means-ends analysis needs the clauses still to be refuted (paper, III.C). A saturation
prover keeps them as it goes; E and the join engine (``joins``) only say "not proved".
For them they are made here, the way a set-of-support search makes them: the negated
goal, then its binary resolvents with the model's clauses (breadth first, with the
paper's parameter rules through the core's unifier), at most :data:`LIMIT` clauses, and
then every clause dropped that another one subsumes with no more parameter bindings.
Ground facts cut a goal down (``~P(a) | ~Q(a)`` with ``P(a)`` leaves ``~Q(a)``), the model's
rules turn it into what would establish it (with ``CONNECTS(x, r1, r2) -> INROOM(x, r1)``,
``~INROOM(ROBOT, ROOM4)`` also leaves ``~CONNECTS(ROBOT, ROOM4, x)``), so an operator that
adds a rule's premise is found relevant. One implementation serves every such prover, so
their differences, and the searches driven by them, agree with the resolution prover's.
"""

from __future__ import annotations

import heapq
from collections.abc import Set as AbstractSet
from itertools import chain

from strips_framework.logic.clauses import Clause, Literal
from strips_framework.logic.terms import Param, Term
from strips_framework.logic.unify import match, substitute, unify
from strips_framework.worldmodel.proving import ProofTask

#: Clauses made at most: the uncompleted proof of a big model stays small and quick.
LIMIT = 120
#: A clause a goal clause may resolve with: its index, the clause, the literal's
#: position, its literals renamed apart.
_Partner = tuple[int, Clause, int, tuple[Literal, ...]]
#: Added to the model clause's variables to rename it apart from the goal clause's.
_OFFSET = 1 << 16


def _shift(term: Term) -> Term:
    kind = type(term)
    if kind is int:
        return term + _OFFSET
    if kind is tuple:
        return (term[0], *[_shift(arg) for arg in term[1:]])
    return term


def _renumber(term: Term, numbering: dict[int, int]) -> Term:
    kind = type(term)
    if kind is int:
        return numbering.setdefault(term, len(numbering))
    if kind is tuple:
        return (term[0], *[_renumber(arg, numbering) for arg in term[1:]])
    return term


def _shifted(clause: Clause) -> tuple[Literal, ...]:
    """``clause``'s literals renamed apart from a goal clause's (made once per clause)."""
    return tuple((sign, _shift(atom)) for sign, atom in clause.literals)


def _clash(atom: tuple, other: tuple) -> bool:
    """Whether two atoms cannot unify for a reason seen without a unifier: different
    arities or two different constants in one place (most pairs in a world model)."""
    if len(atom) != len(other):
        return True
    for a, b in zip(atom, other):
        if a != b and type(a) is str and type(b) is str:
            return True
    return False


def _resolvent(
    clause: Clause, i: int, partner: Clause, j: int, theirs: tuple[Literal, ...]
) -> Clause | None:
    """The resolvent on ``clause``'s literal ``i`` and ``partner``'s ``j``; ``theirs`` is
    :func:`_shifted` of ``partner``."""
    if _clash(clause.literals[i][1], theirs[j][1]):
        return None
    subst: dict = dict(clause.bindings)
    for param, value in partner.bindings:
        if unify(param, value, subst) is None:
            return None
    if unify(clause.literals[i][1], theirs[j][1], subst) is None:
        return None
    rest = [*clause.literals[:i], *clause.literals[i + 1 :], *theirs[:j], *theirs[j + 1 :]]
    numbering: dict[int, int] = {}
    literals = list(
        dict.fromkeys((sign, _renumber(substitute(atom, subst), numbering)) for sign, atom in rest)
    )
    if not literals or any((not sign, atom) in literals for sign, atom in literals):
        return None  # the empty clause (E would have found it) or a tautology
    bindings = sorted(
        ((key, substitute(key, subst)) for key in subst if type(key) is Param),
        key=lambda pair: (pair[0].name, pair[0].tag),
    )
    return Clause(literals, bindings, label=clause.label)


def _subsumes(c: Clause, d: Clause) -> bool:
    """Set subsumption with ``c``'s bindings among ``d``'s (then ``c`` is as general)."""
    if len(c.literals) > len(d.literals) or not set(c.bindings) <= set(d.bindings):
        return False
    return _match_all(list(c.literals), list(d.literals), {})


def _match_all(pattern: list[Literal], target: list[Literal], subst: dict) -> bool:
    if not pattern:
        return True
    (sign, atom), rest = pattern[0], pattern[1:]
    for target_sign, target_atom in target:
        if target_sign is sign:
            extended = match(atom, target_atom, dict(subst))
            if extended is not None and _match_all(rest, target, extended):
                return True
    return False


class Residue:
    """The model's clauses indexed for :meth:`of`, by the sign and predicate of each of
    their literals. A session builds it once on M0 (:class:`~.prover.EProverSession`),
    so an attempt walks only the partners of its own clauses, not the model."""

    def __init__(self, axioms: tuple[Clause, ...]) -> None:
        #: (sign, predicate) -> (the axiom's index, the axiom, the literal's position,
        #: the axiom's literals renamed apart)
        self.by_key: dict[tuple[bool, str], list[_Partner]] = {}
        self._add(axioms, 0, self.by_key)

    @staticmethod
    def _add(
        axioms: tuple[Clause, ...], first: int, by_key: dict[tuple[bool, str], list[_Partner]]
    ) -> None:
        for number, axiom in enumerate(axioms, first):
            shifted = _shifted(axiom)
            for j, (sign, atom) in enumerate(axiom.literals):
                by_key.setdefault((sign, atom[0]), []).append((number, axiom, j, shifted))

    def of(
        self,
        negated_goal: tuple[Clause, ...],
        hidden: AbstractSet[int] = frozenset(),
        added: tuple[Clause, ...] = (),
    ) -> tuple[Clause, ...]:
        """The uncompleted proof of ``negated_goal`` over the indexed axioms less those
        numbered in ``hidden``, plus ``added`` after them (see the module docstring), in
        the order made: exactly what :func:`residue` gives the task of those axioms."""
        extra: dict[tuple[bool, str], list[_Partner]] = {}
        self._add(added, -len(added) - 1, extra)  # numbers no M0 clause has
        found = list(dict.fromkeys(negated_goal))
        known = set(found)
        waiting = [(len(c.literals), n, c) for n, c in enumerate(found)]
        heapq.heapify(waiting)
        while waiting and len(found) < LIMIT:
            clause = heapq.heappop(waiting)[2]
            for i, (sign, atom) in enumerate(clause.literals):
                key = (not sign, atom[0])
                for number, partner, j, theirs in chain(
                    self.by_key.get(key, ()), extra.get(key, ())
                ):
                    if len(found) >= LIMIT:
                        break
                    if number in hidden:
                        continue
                    made = _resolvent(clause, i, partner, j, theirs)
                    if made is not None and made not in known:
                        known.add(made)
                        found.append(made)
                        heapq.heappush(waiting, (len(made.literals), len(found), made))
        return _unsubsumed(found)


def _unsubsumed(found: list[Clause]) -> tuple[Clause, ...]:
    """``found`` less each clause another subsumes; of two that subsume each other, the
    first stays. A clause subsumes another only if each (sign, predicate) of its literals
    is among the other's, which is checked first (most pairs fail there)."""
    keys = [frozenset((sign, atom[0]) for sign, atom in c.literals) for c in found]
    kept: list[Clause] = []
    for n, c in enumerate(found):
        if not any(
            keys[m] <= keys[n] and _subsumes(d, c) and (m < n or not _subsumes(c, d))
            for m, d in enumerate(found)
            if m != n
        ):
            kept.append(c)
    return tuple(kept)


def residue(task: ProofTask) -> tuple[Clause, ...]:
    """The uncompleted proof of ``task`` (see the module docstring), in the order made."""
    return Residue(task.axioms).of(task.negated_goal)
