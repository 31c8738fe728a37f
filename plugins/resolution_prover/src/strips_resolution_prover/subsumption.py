"""Subsumption between clauses, and the index that finds candidates cheaply.

``C`` subsumes ``D`` when some substitution maps the literals of ``C`` one-to-one onto
literals of ``D`` (multiset subsumption, as in E; it never deletes a clause in favour of
its own factor) and ``C`` made no parameter binding that ``D`` did not also make (``C`` is
then at least as general an answer). Since a substitution never lowers the weight of a
term, ``C`` can only subsume ``D`` if it has no more literals, no more weight, and a
subset of its features (literal counts per key, symbol counts, depths: see
:func:`~strips_resolution_prover.pclause.features_of`): those tests reject almost every
candidate before any matching is tried. The matcher (:func:`_match`) is bounded by
:data:`MATCH_BUDGET` steps, which count into the attempt's effort."""

from __future__ import annotations

from collections.abc import Iterator
from collections.abc import Set as AbstractSet

from strips_framework.logic.clauses import Literal
from strips_framework.logic.terms import Term
from strips_resolution_prover.discrimination import DiscriminationTree
from strips_resolution_prover.feature_index import FeatureVectorIndex
from strips_resolution_prover.pclause import PClause


def _may_subsume(c: PClause, d: PClause) -> bool:
    return (
        len(c.literals) <= len(d.literals)
        and c.weight <= d.weight
        and c.features <= d.features
        and (not c.bindings or set(c.bindings) <= set(d.bindings))
    )


def match_term(pattern: Term, target: Term, subst: dict[int, Term]) -> bool:
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
            if not match_term(pattern[k], target[k], subst):
                return False
        return True
    return pattern == target


#: Matcher steps (a literal pairing tried) one subsumption test may take before it
#: answers "not shown subsumed". Multi-literal subsumption is NP-complete, and clauses
#: such as ``~R(f(c),X0) | ... | ~R(f(c),X7) | ...`` make plain backtracking try every
#: injective mapping (case 512 of the differential run took minutes). Keeping a clause
#: is always sound and never loses completeness, so the bound costs only redundancy.
MATCH_BUDGET = 5000


class MatchWork:
    """Matcher steps an attempt spent, so that subsumption counts into its effort."""

    __slots__ = ("steps",)

    def __init__(self) -> None:
        self.steps = 0


class _OutOfSteps(Exception):
    pass


#: A pattern literal's matches: (target literal index, the bindings of its variables).
Candidates = list[tuple[int, dict[int, Term]]]


def _candidates(literal: Literal, target: tuple[Literal, ...]) -> Candidates:
    positive, atom = literal
    found: Candidates = []
    for j, (target_positive, target_atom) in enumerate(target):
        if target_positive is positive and target_atom[0] == atom[0]:
            subst: dict[int, Term] = {}
            if match_term(atom, target_atom, subst):
                found.append((j, subst))
    return found


def _assignable(options: list[Candidates], used: list[bool]) -> bool:
    """Whether each option list gets its own unused target literal (a bipartite
    matching, by augmenting paths): the one-to-one condition without the substitution,
    exact for literals that share no variable with the rest of the pattern."""
    owner: dict[int, int] = {}

    def augment(i: int, seen: set[int]) -> bool:
        for j, _ in options[i]:
            if used[j] or j in seen:
                continue
            seen.add(j)
            if j not in owner or augment(owner[j], seen):
                owner[j] = i
                return True
        return False

    return all(augment(i, set()) for i in range(len(options)))


def _match(pattern: tuple[Literal, ...], target: tuple[Literal, ...], work: MatchWork) -> bool:
    """Multiset matching of ``pattern`` onto ``target``, as Vampire's and E's matchers do
    it: each pattern literal's matches are found on its own first (a literal with none
    ends the test), the literals whose variables occur elsewhere in the pattern are
    assigned by backtracking, most constrained first, and the rest, independent of the
    substitution, by a bipartite matching at each leaf."""
    work.steps += len(pattern) * len(target)
    if len(pattern) == 1:  # a unit: any one match (backward subsumption by unit givens)
        positive, atom = pattern[0]
        return any(
            target_positive is positive and match_term(atom, target_atom, {})
            for target_positive, target_atom in target
        )
    options: list[Candidates] = []
    for literal in pattern:
        found = _candidates(literal, target)
        if not found:
            return False
        options.append(found)
    used = [False] * len(target)
    occurrences: dict[int, int] = {}
    for found in options:
        for var in found[0][1]:
            occurrences[var] = occurrences.get(var, 0) + 1
    linked = sorted(
        (found for found in options if any(occurrences[v] > 1 for v in found[0][1])), key=len
    )
    free = [found for found in options if all(occurrences[v] == 1 for v in found[0][1])]
    budget = work.steps + MATCH_BUDGET

    def assign(i: int, subst: dict[int, Term]) -> bool:
        if i == len(linked):
            return not free or _assignable(free, used)
        for j, bindings in linked[i]:
            work.steps += 1
            if work.steps > budget:
                raise _OutOfSteps
            if used[j] or any(subst.get(v, t) != t for v, t in bindings.items()):
                continue
            used[j] = True
            if assign(i + 1, {**subst, **bindings}):
                return True
            used[j] = False
        return False

    try:
        return assign(0, {})
    except _OutOfSteps:
        return False


def subsumes(c: PClause, d: PClause, work: MatchWork | None = None) -> bool:
    """Whether ``c`` is shown to subsume ``d`` (see the module docstring) within
    :data:`MATCH_BUDGET` steps, counted in ``work``."""
    if not _may_subsume(c, d):
        return False
    return _match(c.literals, d.literals, MatchWork() if work is None else work)


def _is_ground(term: Term) -> bool:
    """Whether ``term`` has no variables (parameters match only themselves, like constants)."""
    kind = type(term)
    if kind is int:
        return False
    if kind is tuple:
        return all(_is_ground(arg) for arg in term[1:])
    return True


class SubsumptionIndex:
    """Retained clauses, indexed for the three subsumption checks.

    - Ground units are kept in a hash table by literal: a ground unit subsumes exactly the
      clauses containing its literal, so the check is one lookup per literal. World models
      are mostly ground facts, so this is where STRIPS's checks end.
    - Other units are filed in a discrimination tree per sign
      (:mod:`~strips_resolution_prover.discrimination`), which finds the few whose
      symbols fit a literal.
    - Longer clauses are filed by their first parameter binding (``None`` if they made
      none) in a feature-vector index each (:mod:`~.feature_index`): a subsumer's
      bindings are among the subsumed clause's, and its feature counts no larger, so
      forward subsumption of ``d`` walks, under ``None`` and each of ``d``'s bindings,
      only the branches of the tries with counts at most ``d``'s. When a planner asks
      for all answers, the set of support holds many clauses that differ only in their
      bindings; the first level keeps them from being candidates for each other.
    - Backward subsumption of ``c`` walks the *deletable* clauses' feature-vector index
      for counts at least ``c``'s; with a set of support, usable clauses are never
      deleted, so they are not filed there at all.
    """

    def __init__(self) -> None:
        self._ground_units: dict[Literal, list[PClause]] = {}
        self._units = {sign: DiscriminationTree[PClause]() for sign in (True, False)}
        self._forward: dict[object, FeatureVectorIndex[PClause]] = {}
        self._backward = FeatureVectorIndex[PClause]()
        self._dead = 0

    def add(self, clause: PClause, *, deletable: bool) -> None:
        if not clause.literals:
            return
        positive, atom = literal = clause.literals[0]
        if len(clause.literals) == 1:
            if _is_ground(atom):
                self._ground_units.setdefault(literal, []).append(clause)
            else:
                self._units[positive].add(atom, clause)
        else:
            binding = clause.bindings[0] if clause.bindings else None
            self._forward.setdefault(binding, FeatureVectorIndex()).add(clause.vector, clause)
        if deletable:
            self._backward.add(clause.vector, clause)

    def is_subsumed_by_unit(self, d: PClause, hidden: AbstractSet[int] = frozenset()) -> bool:
        """Whether a unit clause matches a literal of ``d``. Clauses whose ids are in
        ``hidden`` are not there (a session's M0 clauses that the model does not see)."""
        bindings = set(d.bindings)
        return any(
            self.unit_matching(positive, atom, bindings, hidden) is not None
            for positive, atom in d.literals
        )

    def unit_matching(
        self,
        positive: bool,
        atom: tuple,
        bindings: AbstractSet[object],
        hidden: AbstractSet[int] = frozenset(),
    ) -> PClause | None:
        """A live unit clause of sign ``positive`` whose atom matches ``atom`` and whose
        parameter bindings are among ``bindings``, if one is retained: it subsumes a
        clause with the literal ``(positive, atom)``, and it cuts the opposite literal
        out of one (:meth:`~strips_resolution_prover.prover._Saturation._cut_by_units`)."""
        for unit in self._ground_units.get((positive, atom), ()):
            if self._usable(unit, bindings, hidden):
                return unit
        units = self._units[positive]
        if not units:
            return None
        for unit in units.generalizations(atom):
            if self._usable(unit, bindings, hidden) and match_term(unit.literals[0][1], atom, {}):
                return unit
        return None

    @staticmethod
    def _usable(unit: PClause, bindings: AbstractSet[object], hidden: AbstractSet[int]) -> bool:
        return (
            not unit.dead
            and unit.id not in hidden
            and (not unit.bindings or set(unit.bindings) <= bindings)
        )

    def is_subsumed(
        self, d: PClause, work: MatchWork, hidden: AbstractSet[int] = frozenset()
    ) -> bool:
        if self.is_subsumed_by_unit(d, hidden):
            return True
        if len(d.literals) < 2 or not self._forward:
            return False
        vector = d.vector
        for binding in (None, *d.bindings):
            index = self._forward.get(binding)
            if index is None:
                continue
            for c in index.at_most(vector):
                if not c.dead and c.id not in hidden and subsumes(c, d, work):
                    return True
        return False

    def subsumed_by(self, c: PClause, work: MatchWork) -> Iterator[PClause]:
        """Live deletable clauses other than ``c`` that ``c`` subsumes."""
        if not c.literals or not self._backward:
            return
        vector = c.vector
        for d in list(self._backward.at_least(vector)):
            if d is not c and not d.dead and subsumes(c, d, work):
                yield d

    def note_deleted(self) -> None:
        """Count a deletion; drop dead entries once they are a good share of the index."""
        self._dead += 1
        if self._dead > 256:
            self._dead = 0
            for key, clauses in self._ground_units.items():
                self._ground_units[key] = [c for c in clauses if not c.dead]
            for index in (*self._forward.values(), self._backward):
                index.prune(lambda c: not c.dead)
            for units in self._units.values():
                units.prune(lambda c: not c.dead)
