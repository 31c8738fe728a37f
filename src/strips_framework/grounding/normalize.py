"""Normalization of lifted formulas to what grounding joins: disjunctions of conjunctions
of literals.

``imply`` is rewritten, negation pushed to the atoms, ``forall`` expanded over the objects
of its types (or, when its body branches, replaced by the negation of an auxiliary derived
predicate for its violation, as Fast Downward does), and ``exists`` turned into extra
(renamed) variables of the conjunction, so that grounding binds them like action
parameters instead of trying every object. An
action whose precondition has several disjuncts becomes one ground operator per disjunct,
all with the action's IPC name.
"""

from __future__ import annotations

from itertools import product

from strips_framework.pddl.formulas import (
    And,
    Atom,
    Exists,
    Forall,
    Formula,
    Imply,
    Not,
    Or,
    Parameter,
)
from strips_framework.pddl.task import DerivedPredicate, PddlTask
from strips_framework.records import Record


class Clause(Record):
    """A conjunction of literals over the outer variables plus its own ``params``."""

    params: tuple[Parameter, ...]
    positive: tuple[Atom, ...]
    negative: tuple[Atom, ...]

    __slots__ = ("params", "positive", "negative")

    def __init__(
        self,
        params: tuple[Parameter, ...] = (),
        positive: tuple[Atom, ...] = (),
        negative: tuple[Atom, ...] = (),
    ) -> None:
        self.params = params
        self.positive = positive
        self.negative = negative

    def join(self, other: Clause) -> Clause:
        return Clause(
            self.params + other.params,
            self.positive + other.positive,
            self.negative + other.negative,
        )


def substitute_formula(formula: Formula, binding: dict[str, str]) -> Formula:
    """``formula`` with the variables of ``binding`` replaced (quantified ones shadow)."""
    if isinstance(formula, Atom):
        return Atom(formula.predicate, tuple(binding.get(arg, arg) for arg in formula.args))
    if isinstance(formula, Not):
        return Not(substitute_formula(formula.part, binding))
    if isinstance(formula, And | Or):
        return type(formula)(tuple(substitute_formula(part, binding) for part in formula.parts))
    if isinstance(formula, Imply):
        return Imply(
            substitute_formula(formula.condition, binding),
            substitute_formula(formula.consequence, binding),
        )
    inner = {name: value for name, value in binding.items() if name not in _names(formula.params)}
    return type(formula)(formula.params, substitute_formula(formula.body, inner))


def _names(params: tuple[Parameter, ...]) -> set[str]:
    return {param.name for param in params}


class Normalizer:
    """Turns formulas of one task into clause lists; fresh names for ``exists`` variables
    come from a counter, so the result does not depend on hashing."""

    def __init__(self, task: PddlTask) -> None:
        self.task = task
        self._fresh = 0
        #: Derived predicates made up for universal conditions (see :meth:`_auxiliary`),
        #: in order of creation; their bodies are normalized like any other.
        self.auxiliary: list[DerivedPredicate] = []

    def clauses(self, formula: Formula) -> list[Clause]:
        """The disjuncts of ``formula``; contradictory ones and false equalities dropped."""
        return [clause for clause in self._dnf(formula, False) if _consistent(clause)]

    def _dnf(self, formula: Formula, negated: bool) -> list[Clause]:
        if isinstance(formula, Atom):
            return [Clause(negative=(formula,))] if negated else [Clause(positive=(formula,))]
        if isinstance(formula, Not):
            return self._dnf(formula.part, not negated)
        if isinstance(formula, Imply):
            return self._dnf(Or((Not(formula.condition), formula.consequence)), negated)
        if isinstance(formula, And | Or):
            parts = [self._dnf(part, negated) for part in formula.parts]
            conjunctive = isinstance(formula, And) != negated
            return _conjoin(parts) if conjunctive else [c for part in parts for c in part]
        if isinstance(formula, Exists) != negated:
            return self._extra_variables(formula.params, formula.body, negated)
        if not _branches(formula.body, negated):
            return _conjoin([self._dnf(body, negated) for body in self._instances(formula)])
        return [Clause(negative=(self._auxiliary(formula, negated),))]

    def _auxiliary(self, formula: Exists | Forall, negated: bool) -> Atom:
        """The head of a new derived predicate that holds exactly when the universal
        ``formula`` (read under ``negated``) is violated. Expanding a universal whose body
        branches would multiply the branches of every instance (2^n clauses for n
        objects); the violation is a plain existential, so it normalizes to few clauses,
        and the formula itself becomes the single literal ``not (head)``."""
        free = sorted(_free_variables(formula))
        self._fresh += 1
        head = Atom(f"@forall{self._fresh}", tuple(free))
        violation = formula.body if isinstance(formula, Exists) else Not(formula.body)
        params = tuple(Parameter(name) for name in free)
        self.auxiliary.append(DerivedPredicate(head, params, Exists(formula.params, violation)))
        return head

    def _extra_variables(
        self, params: tuple[Parameter, ...], body: Formula, negated: bool
    ) -> list[Clause]:
        fresh = []
        for param in params:
            self._fresh += 1
            fresh.append(Parameter(f"{param.name}@{self._fresh}", param.types))
        renamed = substitute_formula(body, {p.name: f.name for p, f in zip(params, fresh)})
        head = Clause(params=tuple(fresh))
        return [head.join(clause) for clause in self._dnf(renamed, negated)]

    def _instances(self, formula: Exists | Forall) -> list[Formula]:
        """The body of a quantifier once for every binding of its variables to objects."""
        names = [param.name for param in formula.params]
        domains = [self.task.objects_of(param.types) for param in formula.params]
        return [
            substitute_formula(formula.body, dict(zip(names, values)))
            for values in product(*domains)
        ]


def _conjoin(parts: list[list[Clause]]) -> list[Clause]:
    result = [Clause()]
    for options in parts:
        result = [done.join(option) for done in result for option in options]
    return result


def _branches(formula: Formula, negated: bool) -> bool:
    """Whether ``formula`` (read under ``negated``) normalizes to more than one clause.
    Universal quantifiers inside never branch: they expand or become one literal."""
    if isinstance(formula, Atom):
        return False
    if isinstance(formula, Not):
        return _branches(formula.part, not negated)
    if isinstance(formula, Imply):
        return (
            not negated
            or _branches(formula.condition, False)
            or _branches(formula.consequence, True)
        )
    if isinstance(formula, And | Or):
        if isinstance(formula, Or) != negated and len(formula.parts) > 1:
            return True
        return any(_branches(part, negated) for part in formula.parts)
    if isinstance(formula, Exists) == negated:
        return False
    return _branches(formula.body, negated)


def _free_variables(formula: Formula) -> set[str]:
    if isinstance(formula, Atom):
        return {arg for arg in formula.args if arg.startswith("?")}
    if isinstance(formula, Not):
        return _free_variables(formula.part)
    if isinstance(formula, And | Or):
        return set().union(*(_free_variables(part) for part in formula.parts))
    if isinstance(formula, Imply):
        return _free_variables(formula.condition) | _free_variables(formula.consequence)
    return _free_variables(formula.body) - _names(formula.params)


def _consistent(clause: Clause) -> bool:
    """False when the clause contradicts itself or compares two different objects."""
    positive = set(clause.positive)
    if any(atom in positive for atom in clause.negative):
        return False
    for atom in clause.positive:
        if atom.predicate == "=" and _ground(atom) and atom.args[0] != atom.args[1]:
            return False
    for atom in clause.negative:
        if atom.predicate == "=" and _ground(atom) and atom.args[0] == atom.args[1]:
            return False
    return True


def _ground(atom: Atom) -> bool:
    return not any(arg.startswith("?") for arg in atom.args)
