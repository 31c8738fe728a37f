"""Subsumption between clauses, and the index that finds candidates cheaply.

``C`` subsumes ``D`` when some substitution maps the literals of ``C`` one-to-one onto
literals of ``D`` (multiset subsumption, as in E; it never deletes a clause in favour of
its own factor) and ``C`` made no parameter binding that ``D`` did not also make (``C`` is
then at least as general an answer). Since a substitution never lowers the weight of a
term, ``C`` can only subsume ``D`` if it has no more literals, no more weight, and a subset
of its (polarity, predicate) keys: those tests reject almost every candidate before any
matching is tried (see :func:`~strips_resolution_prover.pclause.features_of`).
"""

from __future__ import annotations

from collections.abc import Iterator

from strips_framework.logic.clauses import Literal
from strips_framework.logic.terms import Term
from strips_resolution_prover.pclause import PClause


def _may_subsume(c: PClause, d: PClause) -> bool:
    return (
        len(c.literals) <= len(d.literals)
        and c.weight <= d.weight
        and c.features <= d.features
        and (not c.bindings or set(c.bindings) <= set(d.bindings))
    )


def _match(pattern: Term, target: Term, subst: dict[int, Term]) -> bool:
    """Extend ``subst`` so that ``pattern``·``subst`` is ``target``; variables of the
    target are constants here, parameters match only themselves."""
    kind = type(pattern)
    if kind is int:
        bound = subst.get(pattern)
        if bound is None:
            subst[pattern] = target
            return True
        return bound == target
    if kind is tuple:
        if type(target) is not tuple or pattern[0] != target[0] or len(pattern) != len(target):
            return False
        for k in range(1, len(pattern)):
            if not _match(pattern[k], target[k], subst):
                return False
        return True
    return pattern == target


def _match_all(
    pattern: tuple[Literal, ...],
    i: int,
    target: tuple[Literal, ...],
    used: list[bool],
    subst: dict[int, Term],
) -> bool:
    if i == len(pattern):
        return True
    positive, atom = pattern[i]
    for j, (target_positive, target_atom) in enumerate(target):
        if used[j] or target_positive is not positive or target_atom[0] != atom[0]:
            continue
        extended = dict(subst)
        if not _match(atom, target_atom, extended):
            continue
        used[j] = True
        if _match_all(pattern, i + 1, target, used, extended):
            return True
        used[j] = False
    return False


def subsumes(c: PClause, d: PClause) -> bool:
    """Whether ``c`` subsumes ``d`` (see the module docstring)."""
    if not _may_subsume(c, d):
        return False
    return _match_all(c.literals, 0, d.literals, [False] * len(d.literals), {})


def _unit_key(positive: bool, atom: tuple) -> tuple[object, ...]:
    """A unit's index key: its predicate key and the top symbol of its first argument
    (``None`` for a variable or no argument); a unit can only match a literal whose key is
    the same or has a variable there."""
    top = atom[1] if len(atom) > 1 else None
    kind = type(top)
    if kind is tuple:
        top = top[0]
    elif kind is int:
        top = None
    return positive, atom[0], len(atom), top


class SubsumptionIndex:
    """Retained clauses, filed under the key of their first literal.

    A subsumer's keys are a subset of the subsumed clause's keys, so forward subsumption of
    ``d`` only looks at the clauses filed under one of ``d``'s keys: each candidate once.
    Backward subsumption of ``c`` looks at the clauses containing ``c``'s rarest key. Unit
    clauses are also kept apart, for the cheap check every new clause gets.
    """

    def __init__(self) -> None:
        self._by_first_key: dict[tuple[bool, str, int], list[PClause]] = {}
        self._by_key: dict[tuple[bool, str, int], list[PClause]] = {}
        self._units: dict[tuple[object, ...], list[PClause]] = {}
        self._dead = 0

    def add(self, clause: PClause) -> None:
        if not clause.literals:
            return
        positive, atom = clause.literals[0]
        first_key = (positive, atom[0], len(atom))
        self._by_first_key.setdefault(first_key, []).append(clause)
        if len(clause.literals) == 1:
            self._units.setdefault(_unit_key(positive, atom), []).append(clause)
        for key in clause.keyset:
            self._by_key.setdefault(key, []).append(clause)

    def is_subsumed_by_unit(self, d: PClause) -> bool:
        """Whether a unit clause matches a literal of ``d``."""
        bindings = set(d.bindings)
        for positive, atom in d.literals:
            key = _unit_key(positive, atom)
            for unit_key in (key, key[:3] + (None,)) if key[3] is not None else (key,):
                for unit in self._units.get(unit_key, ()):
                    if (
                        not unit.dead
                        and _match(unit.literals[0][1], atom, {})
                        and (not unit.bindings or set(unit.bindings) <= bindings)
                    ):
                        return True
        return False

    def is_subsumed(self, d: PClause) -> bool:
        for key in d.keyset:
            for c in self._by_first_key.get(key, ()):
                if not c.dead and subsumes(c, d):
                    return True
        return False

    def subsumed_by(self, c: PClause) -> Iterator[PClause]:
        """Live clauses other than ``c`` that ``c`` subsumes, in the order they were added."""
        if not c.literals:
            return
        lists = [self._by_key.get(key, []) for key in c.keyset]
        candidates = min(lists, key=len)
        for d in candidates:
            if d is not c and not d.dead and subsumes(c, d):
                yield d

    def note_deleted(self) -> None:
        """Count a deletion; drop dead entries once they are a good share of the index."""
        self._dead += 1
        if self._dead > 256:
            self._dead = 0
            for table in (self._by_first_key, self._by_key, self._units):
                for key, clauses in table.items():
                    table[key] = [c for c in clauses if not c.dead]
