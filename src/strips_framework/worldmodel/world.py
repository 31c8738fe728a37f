"""World models as the paper stores them (III.B, III.D).

All models share one :class:`InitialModel` (M0), which is never copied. A
:class:`WorldModel` is M0 plus two short lists: ``deletions`` (indices of M0 clauses no
longer present) and ``additions`` (ground atoms present but not in M0). A derived clause
of M0 is visible only while every primitive clause it rests on is still present.
"""

from __future__ import annotations

from collections.abc import Iterable, Iterator

from strips_framework.logic.clauses import Clause
from strips_framework.logic.cnf import SkolemNames, clausify
from strips_framework.logic.terms import WILDCARD, Atom
from strips_framework.records import Record
from strips_framework.worldmodel.problem import Problem

#: Where facts are filed: ``(predicate, arity)``, or that and an argument ``position`` with
#: the constant (or ``(functor, arity)``) found there.
_FactKey = tuple[str, int] | tuple[str, int, int, object]


class InitialModel:
    """M0: its clauses, and for each derived clause the indices of its supports.

    ``rigid`` names the predicates, as ``(name, arity)``, that no operator adds and no
    rule of M0 concludes: a model's facts of them are M0's less its deletions, so a
    rigid atom that is not a fact never becomes true, and literals of them are not
    what operators can change (a prover may bind variables through them first; see
    :func:`rigid_predicates`). Empty when nothing is known about operators.
    ``facts`` maps each ground unit fact of M0 to its index in ``clauses``, so operators
    can find what to delete without scanning; ``dependents`` maps a clause index to the
    derived clauses resting on it, so a model's hidden clauses are found from its
    deletions alone (:meth:`WorldModel.hidden`). ``_filed`` files the facts by predicate
    and by each argument, for :meth:`WorldModel.facts_matching`.

    Not changed once built, and compared by identity: every model of a search shares
    the one M0, and comparing its indexes would cost more than the search saves.
    """

    __slots__ = ("clauses", "supports", "rigid", "facts", "dependents", "_filed")

    def __init__(
        self,
        clauses: Iterable[Clause],
        supports: dict[int, frozenset[int]] | None = None,
        rigid: Iterable[tuple[str, int]] = frozenset(),
    ) -> None:
        self.clauses: tuple[Clause, ...] = tuple(clauses)
        self.supports: dict[int, frozenset[int]] = {} if supports is None else supports
        self.rigid: frozenset[tuple[str, int]] = frozenset(rigid)
        facts = {
            c.literals[0][1]: i
            for i, c in enumerate(self.clauses)
            if c.is_unit and c.literals[0][0] and i not in self.supports
        }
        self.facts: dict[Atom, int] = facts
        dependents: dict[int, list[int]] = {}
        for derived, rests_on in self.supports.items():
            for index in rests_on:
                dependents.setdefault(index, []).append(derived)
        self.dependents: dict[int, tuple[int, ...]] = {i: tuple(d) for i, d in dependents.items()}
        filed: dict[_FactKey, list[Atom]] = {}
        for atom in facts:
            predicate, arity = atom[0], len(atom) - 1
            filed.setdefault((predicate, arity), []).append(atom)
            for position, arg in enumerate(atom[1:]):
                symbol = (arg[0], len(arg)) if type(arg) is tuple else arg
                filed.setdefault((predicate, arity, position, symbol), []).append(atom)
        self._filed = filed

    def candidates(self, pattern: Atom) -> list[Atom]:
        """M0's facts with ``pattern``'s predicate and its constant at the most selective
        argument position where it has one (variables, parameters and ``$`` match
        anything): a superset of the facts that match, found without scanning M0."""
        predicate, arity = pattern[0], len(pattern) - 1
        best = self._filed.get((predicate, arity), [])
        for position, arg in enumerate(pattern[1:]):
            kind = type(arg)
            if kind is str and arg != WILDCARD:
                symbol: object = arg
            elif kind is tuple:
                symbol = (arg[0], len(arg))
            else:
                continue
            bucket = self._filed.get((predicate, arity, position, symbol), [])
            if len(bucket) < len(best):
                best = bucket
        return best


class WorldModel(Record):
    """M0 with ``deletions`` (indices into M0) and ``additions`` (ground atoms).

    Two models are equal when their deletions and additions are (the search compares
    models of one problem, which share M0); the hash, which duplicate detection asks for
    at every node, is computed once. The additions are read in a fixed order (sorted
    once, when first asked for): a frozenset of strings iterates in an order that
    changes with each process's string hashing, and the searches that read a model's
    facts must make the same nodes in every process.
    """

    initial: InitialModel
    deletions: frozenset[int]
    additions: frozenset[Atom]

    FIELDS = ("initial", "deletions", "additions")
    COMPARED = ("deletions", "additions")
    __slots__ = (*FIELDS, "_hash", "_ordered")

    def __init__(
        self,
        initial: InitialModel,
        deletions: frozenset[int] = frozenset(),
        additions: frozenset[Atom] = frozenset(),
    ) -> None:
        self.initial = initial
        self.deletions = deletions
        self.additions = additions
        self._hash = hash(("WorldModel", deletions, additions))
        self._ordered: tuple[Atom, ...] | None = None

    def __eq__(self, other: object) -> bool:
        return (
            type(other) is WorldModel
            and other.deletions == self.deletions
            and other.additions == self.additions
        )

    def __hash__(self) -> int:
        return self._hash

    def __repr__(self) -> str:  # M0 is left out: it can hold thousands of clauses
        return f"WorldModel(deletions={self.deletions!r}, additions={self.additions!r})"

    def __reduce__(self) -> tuple[type[WorldModel], tuple[object, ...]]:
        # Rebuilt from its fields: a string's hash differs between processes.
        return (WorldModel, (self.initial, self.deletions, self.additions))

    def clauses(self) -> Iterator[Clause]:
        """The visible clauses: M0 less deletions and stale derived clauses, plus additions."""
        deleted = self.deletions
        supports = self.initial.supports
        for i, clause in enumerate(self.initial.clauses):
            if i in deleted:
                continue
            rests_on = supports.get(i)
            if rests_on is not None and not rests_on.isdisjoint(deleted):
                continue
            yield clause
        yield from self.added_clauses()

    def added_clauses(self) -> tuple[Clause, ...]:
        """The additions as unit clauses, in a fixed order (a prover's search, and so its
        answers, must not depend on hash order)."""
        return tuple(Clause(((True, atom),), label="added") for atom in self.ordered_additions())

    def ordered_additions(self) -> tuple[Atom, ...]:
        """The additions in a fixed order (by ``repr``), the same in every process."""
        ordered = self._ordered
        if ordered is None:
            ordered = self._ordered = tuple(sorted(self.additions, key=repr))
        return ordered

    def hidden(self) -> set[int]:
        """The indices of M0's clauses this model does not see: its deletions and the
        derived clauses resting on one. Costs time in the deletions, not in |M0|."""
        hidden = set(self.deletions)
        dependents = self.initial.dependents
        for index in self.deletions:
            hidden.update(dependents.get(index, ()))
        return hidden

    def holds(self, atom: Atom) -> bool:
        """Whether the ground primitive ``atom`` is present as a fact (no reasoning)."""
        if atom in self.additions:
            return True
        index = self.initial.facts.get(atom)
        return index is not None and index not in self.deletions

    def facts(self) -> Iterator[Atom]:
        """The ground facts present: M0's undeleted facts, then the additions."""
        for atom, index in self.initial.facts.items():
            if index not in self.deletions:
                yield atom
        yield from self.ordered_additions()

    def facts_matching(self, pattern: Atom) -> Iterator[Atom]:
        """The facts present that may match ``pattern`` (see
        :meth:`InitialModel.candidates`); callers apply their own exact test. Costs time
        in the candidates and the additions, not in |M0|."""
        index = self.initial.facts
        deleted = self.deletions
        for atom in self.initial.candidates(pattern):
            if index[atom] not in deleted:
                yield atom
        predicate, size = pattern[0], len(pattern)
        for atom in self.ordered_additions():
            if atom[0] == predicate and len(atom) == size:
                yield atom

    def changed(self, deleted: frozenset[Atom], added: frozenset[Atom]) -> WorldModel:
        """The model after deleting then adding ground atoms (III.D)."""
        facts = self.initial.facts
        new_deletions = self.deletions | {facts[a] for a in deleted if a in facts}
        additions = (self.additions - deleted) | {a for a in added if a not in facts}
        # An atom of M0 that was deleted and is added back is visible again.
        revived = {facts[a] for a in added if a in facts}
        return WorldModel(self.initial, new_deletions - revived, frozenset(additions))


def initial_model(problem: Problem, skolem: SkolemNames) -> InitialModel:
    """M0 of ``problem``: facts, clausified axioms, and derived facts with their supports."""
    clauses = [Clause(((True, atom),), label="fact") for atom in problem.facts]
    index = {atom: i for i, atom in enumerate(problem.facts)}
    for number, axiom in enumerate(problem.axioms, start=1):
        clauses.extend(clausify(axiom, label=f"axiom {number}", skolem=skolem))
    supports: dict[int, frozenset[int]] = {}
    for fact in problem.derived:
        supports[len(clauses)] = frozenset(index[atom] for atom in fact.supports)
        clauses.append(Clause(((True, fact.atom),), label="derived"))
    return InitialModel(clauses, supports, rigid_predicates(problem, clauses))


def rigid_predicates(problem: Problem, clauses: Iterable[Clause]) -> frozenset[tuple[str, int]]:
    """The predicates of ``problem``'s facts that no operator adds, no derived fact has
    (a derived fact comes back when its supports do) and no non-unit clause of M0's
    ``clauses`` concludes: only deletions change them."""
    concluded = {
        (atom[0], len(atom) - 1)
        for clause in clauses
        if not clause.is_unit
        for positive, atom in clause.literals
        if positive
    }
    changing = {(atom[0], len(atom) - 1) for schema in problem.operators for atom in schema.add_list}
    changing.update((fact.atom[0], len(fact.atom) - 1) for fact in problem.derived)
    facts = {(atom[0], len(atom) - 1) for atom in problem.facts}
    return frozenset(facts - changing - concluded)
