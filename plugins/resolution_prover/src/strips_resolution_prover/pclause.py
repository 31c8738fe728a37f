"""The prover's working clause: a slotted record built for the inner loop.

:class:`~strips_framework.logic.clauses.Clause` is the public value; creating one
copies its literals and sorts its bindings, which is too slow for the tens of thousands of
clauses a TPTP problem generates. Inside the loop clauses are :class:`PClause` records; they are converted back only
for results (proof, uncompleted proof).

Invariants every ``PClause`` keeps:
- variables are numbered ``0 .. nvars-1`` in order of first occurrence, so renaming apart
  is adding an offset and syntactically equal clauses have equal literal tuples;
- no literal occurs twice;
- a parameter bound in ``bindings`` no longer occurs in ``literals`` (the binding was
  substituted everywhere when it was made, paper III.A).
"""

from __future__ import annotations

from functools import lru_cache

from strips_framework.logic.clauses import Clause, Literal
from strips_framework.logic.terms import Param, Term
from strips_framework.logic.unify import substitute
from strips_resolution_prover.feature_index import feature_vector

Bindings = tuple[tuple[Param, Term], ...]


def binding_key(pair: tuple[Param, Term]) -> tuple[str, int]:
    """The order of ``Clause.bindings``; answers are compared and reported in this order."""
    return pair[0].name, pair[0].tag


class PClause:
    """A clause in the prover, with the bookkeeping the given-clause loop needs.

    ``sos`` marks set-of-support clauses (the negated goal and everything derived from it);
    ``parents`` are the ids of the premises, for proof extraction; ``dead`` is set when the
    clause is deleted (subsumed), so indexes and queues can drop it lazily.
    """

    __slots__ = (
        "_features",
        "_vector",
        "bindings",
        "dead",
        "id",
        "label",
        "literals",
        "nvars",
        "parents",
        "processed",
        "sos",
        "weight",
    )

    def __init__(
        self,
        literals: tuple[Literal, ...],
        nvars: int,
        bindings: Bindings,
        *,
        sos: bool,
        parents: tuple[int, ...] = (),
        label: str = "",
        weight: int | None = None,
    ) -> None:
        self.id = -1
        self.literals = literals
        self.nvars = nvars
        self.bindings = bindings
        self.weight = sum(term_weight(atom) for _, atom in literals) if weight is None else weight
        self._features: frozenset[object] | None = None
        self._vector: tuple[int, ...] | None = None
        self.sos = sos
        self.parents = parents
        self.label = label
        self.dead = False
        self.processed = False

    @property
    def features(self) -> frozenset[object]:
        """Subsumption features, computed on first use: most queued clauses never need them."""
        if self._features is None:
            self._features = features_of(self.literals)
        return self._features

    @property
    def vector(self) -> tuple[int, ...]:
        """The feature vector the subsumption index files it by (:mod:`.feature_index`),
        computed on first use."""
        if self._vector is None:
            self._vector = feature_vector(self.literals, len(self.bindings))
        return self._vector

    def fresh_copy(self, *, sos: bool) -> PClause:
        """A new, unregistered clause with this one's literals and derived data."""
        copy = PClause.__new__(PClause)
        copy.id = -1
        copy.literals = self.literals
        copy.nvars = self.nvars
        copy.bindings = self.bindings
        copy.weight = self.weight
        copy._features = self._features
        copy._vector = self._vector
        copy.sos = sos
        copy.parents = ()
        copy.label = self.label
        copy.dead = False
        copy.processed = False
        return copy

    def to_clause(self) -> Clause:
        return Clause(self.literals, self.bindings, label=self.label)

    def __repr__(self) -> str:
        return f"PClause#{self.id}({self.to_clause()})"


def term_weight(term: Term) -> int:
    """Symbol count with variables weighing 1 and every other symbol 2 (E's default)."""
    kind = type(term)
    if kind is int:
        return 1
    if kind is tuple:
        return 2 + sum(term_weight(arg) for arg in term[1:])
    return 2


def features_of(literals: tuple[Literal, ...]) -> frozenset[object]:
    """Features that a clause's instances keep, for subsumption's subset pre-filter.

    A substitution only adds structure, and (multiset) subsumption maps literals one-to-one
    onto literals with the same (polarity, predicate) key, so a subsumer's features are a
    subset of the subsumed clause's. E's feature vectors hold counts; a count ``n`` is
    written here as the features ``(x, 1) .. (x, n)``, so that one frozenset comparison
    (in C) tests every count at once:

    - ``(key, k)``: at least ``k`` literals with that key;
    - ``(key, position, symbol)``: a literal with that key has ``symbol`` on top there;
    - ``(symbol, k)``: a constant, functor or parameter occurs at least ``k`` times;
    - ``(key, "depth", k)``: a literal with that key has a term nested ``k`` deep.
    """
    found: set[object] = set()
    counts: dict[object, int] = {}
    for positive, atom in literals:
        key = (positive, atom[0], len(atom))
        counts[key] = count = counts.get(key, 0) + 1
        found.add((key, count))
        for position in range(1, len(atom)):
            arg = atom[position]
            kind = type(arg)
            if kind is int:
                continue
            if kind is tuple:
                found.add((key, position, arg[0]))
                for k in range(1, _count_symbols(arg, counts, found) + 1):
                    found.add((key, "depth", k))
            else:
                found.add((key, position, arg))
                counts[arg] = count = counts.get(arg, 0) + 1
                found.add((arg, count))
    return frozenset(found)


def _count_symbols(term: tuple, counts: dict[object, int], found: set[object]) -> int:
    """Count the symbols of a compound ``term`` into ``counts`` and ``found`` (as in
    :func:`features_of`); its depth."""
    symbol = term[0]
    counts[symbol] = count = counts.get(symbol, 0) + 1
    found.add((symbol, count))
    deepest = 0
    for arg in term[1:]:
        kind = type(arg)
        if kind is tuple:
            deepest = max(deepest, _count_symbols(arg, counts, found))
        elif kind is not int:
            counts[arg] = count = counts.get(arg, 0) + 1
            found.add((arg, count))
    return deepest + 1


def term_depth(term: Term) -> int:
    if type(term) is tuple and len(term) > 1:
        return 1 + max(term_depth(arg) for arg in term[1:])
    return 0


def renumber(term: Term, numbering: dict[int, int]) -> Term:
    """Rename variables to ``0, 1, ...`` in order of first occurrence, sharing ``numbering``."""
    kind = type(term)
    if kind is int:
        number = numbering.get(term)
        if number is None:
            number = numbering[term] = len(numbering)
        return number
    if kind is tuple:
        return (term[0], *[renumber(arg, numbering) for arg in term[1:]])
    return term


def offset(term: Term, by: int) -> Term:
    """Rename apart: add ``by`` to every variable."""
    kind = type(term)
    if kind is int:
        return term + by
    if kind is tuple:
        return (term[0], *[offset(arg, by) for arg in term[1:]])
    return term


def from_clause(clause: Clause, *, sos: bool) -> PClause | None:
    """Import a public clause: substitute its bindings, number its variables, drop repeats.

    ``None`` for a tautology: the clause is true and takes no part in the search. A planner
    asks thousands of questions of world models that share most clauses, so imports are
    cached by clause (``Clause`` is frozen and caches its hash).
    """
    template = _import(clause)
    return None if template is None else template.fresh_copy(sos=sos)


def from_fact(clause: Clause) -> PClause | None:
    """:func:`from_clause` for a positive ground unit over constants, the bulk of a world
    model, without the general import's renumbering and cache (a session imports M0's
    facts once); ``None`` for any other clause."""
    if len(clause.literals) != 1 or clause.bindings:
        return None
    positive, atom = clause.literals[0]
    if not positive:
        return None
    for arg in atom[1:]:
        if type(arg) is not str:
            return None
    # term_weight: the predicate and each constant weigh 2.
    return PClause(clause.literals, 0, (), sos=False, label=clause.label, weight=2 * len(atom))


@lru_cache(maxsize=1 << 14)
def _import(clause: Clause) -> PClause | None:
    bound = dict(clause.bindings)
    numbering: dict[int, int] = {}
    literals: list[Literal] = []
    for positive, atom in clause.literals:
        if bound:
            atom = substitute(atom, bound)
        literal = (positive, renumber(atom, numbering))
        if (not positive, literal[1]) in literals:
            return None
        if literal not in literals:
            literals.append(literal)
    return PClause(tuple(literals), len(numbering), clause.bindings, sos=False, label=clause.label)
