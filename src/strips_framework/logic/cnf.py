"""Clause form of a wff: what the resolution prover and the world model store.

One recursive pass (:class:`_Clausifier`) does the textbook steps together, tracking
the polarity of each subformula instead of rewriting the tree several times:

- ``->`` and ``<->`` are read by their definitions, so negation is pushed to the atoms;
- a quantifier that is universal under its polarity binds a fresh integer variable
  (which standardizes variables apart); an existential one is Skolemized with a fresh
  function of the universal variables of the enclosing scope that occur free in its
  body (a Skolem constant when there are none);
- ``true``/``false`` are simplified away, conjunctions concatenate clause lists and
  disjunctions distribute.

Parameters stay :class:`~strips_framework.logic.terms.Param`: they are the schema
parameters the prover binds (paper, III.A). Skolem terms never take parameters as
arguments; the unifier's rule that a parameter may not be bound to a term containing a
Skolem function is what keeps that sound.

Distribution can blow up exponentially (``(a1 & b1) | ... | (an & bn)`` has 2^n
clauses). When a disjunction would yield more than ``distribution_limit`` clauses, its
largest disjuncts are renamed by fresh predicates ``def!k(free terms)`` with the
clauses ``~def!k(...) | C`` for each clause C of the disjunct. In negation normal form
every subformula occurs positively, so this one direction suffices (Plaisted and
Greenbaum, 1986): the result is satisfiable exactly when the input is, which is all a
refutation needs.
"""

from __future__ import annotations

from collections.abc import Iterator
from math import prod

from strips_framework.logic.clauses import Clause, Literal
from strips_framework.logic.formulas import (
    And,
    Atomic,
    Exists,
    Forall,
    Formula,
    Iff,
    Implies,
    Not,
    Or,
    Truth,
    Var,
    term_variables,
)
from strips_framework.logic.terms import EQUALITY, SKOLEM_PREFIX, Param, Term, subterms

#: Definitional predicates start with this prefix; no user-written name can (``!``).
DEFINITION_PREFIX = "def!"

#: A disjunction whose distribution would give more clauses than this is renamed; E's
#: default for its definitional CNF (``--definitional-cnf=24``).
DISTRIBUTION_LIMIT = 24

_Clause = tuple[Literal, ...]
_Cnf = list[_Clause]  # a conjunction of clauses; [] is true, [()] is false


class SkolemNames:
    """Hands out fresh Skolem and definition symbols: ``sk!1``, ``sk!2``, ``def!3``, ...

    Use one instance per problem (world model, axioms, operator preconditions, goals), so
    two clausified formulas never share a Skolem function by accident. Mutable: ``count``
    is the number of symbols handed out so far.
    """

    __slots__ = ("count",)

    def __init__(self, count: int = 0) -> None:
        self.count = count

    def fresh(self) -> str:
        """A new Skolem function or constant name."""
        self.count += 1
        return f"{SKOLEM_PREFIX}{self.count}"

    def fresh_predicate(self) -> str:
        """A new predicate name for a renamed subformula."""
        self.count += 1
        return f"{DEFINITION_PREFIX}{self.count}"


def clausify(
    formula: Formula,
    *,
    label: str = "",
    skolem: SkolemNames,
    distribution_limit: int = DISTRIBUTION_LIMIT,
) -> list[Clause]:
    """The clauses of ``formula``, each labelled ``label``.

    ``formula`` must be closed except for parameters: a :class:`Var` that no quantifier
    binds is a programming error (``ValueError``). Each clause numbers its variables
    0..k-1 in order of appearance; tautologies, duplicate literals and duplicate clauses
    are removed. ``true`` gives no clauses, ``false`` the empty clause.
    """
    clausifier = _Clausifier(skolem, distribution_limit)
    cnf = clausifier.walk(formula, True, {}) + clausifier.definitions
    if () in cnf:
        return [Clause((), label=label)]
    seen: set[_Clause] = set()
    clauses = []
    for literals in map(_renumbered, cnf):
        if literals not in seen:
            seen.add(literals)
            clauses.append(Clause(literals, label=label))
    return clauses


def negated_goal_clauses(goal: Formula, skolem: SkolemNames) -> list[Clause]:
    """The clauses of ``~goal``: STRIPS proves G(p) by refuting M ∪ {¬G(p)} (III.A)."""
    return clausify(Not(goal), label="negated goal", skolem=skolem)


class _Clausifier:
    """Negation normal form, Skolemization and distribution in one polarity-aware walk."""

    def __init__(self, skolem: SkolemNames, distribution_limit: int) -> None:
        self.skolem, self.limit = skolem, distribution_limit
        self.next_variable = 0
        self.definitions: _Cnf = []

    def walk(self, f: Formula, positive: bool, env: dict[Var, Term]) -> _Cnf:
        """CNF of ``f`` (of ``~f`` when not ``positive``), with ``env`` binding its Vars."""
        if isinstance(f, Atomic):
            return _literal(positive, (f.atom[0], *(_term(t, env) for t in f.atom[1:])))
        if isinstance(f, Truth):
            return [] if f.value == positive else [()]
        if isinstance(f, Not):
            return self.walk(f.body, not positive, env)
        if isinstance(f, (And, Or)):
            parts = [self.walk(part, positive, env) for part in f.parts]
            conjunctive = isinstance(f, And) == positive
            return _conjunction(parts) if conjunctive else self.disjunction(parts)
        if isinstance(f, Implies):
            premise = self.walk(f.premise, not positive, env)
            conclusion = self.walk(f.conclusion, positive, env)
            return self.disjunction([premise, conclusion]) if positive else premise + conclusion
        if isinstance(f, Iff):
            # A <-> B is (~A | B) & (A | ~B); ~(A <-> B) is (A | B) & (~A | ~B).
            one = [self.walk(f.left, False, env), self.walk(f.right, positive, env)]
            two = [self.walk(f.left, True, env), self.walk(f.right, not positive, env)]
            return self.disjunction(one) + self.disjunction(two)
        universal = isinstance(f, Forall) == positive
        inner = dict(env)
        if universal:
            for var in f.variables:
                inner[var] = self.next_variable
                self.next_variable += 1
        else:
            free = {var: _term(var, env) for var in _free_vars(f, set())}
            scope = sorted({v for value in free.values() for v in _variables(value)})
            for var in f.variables:
                name = self.skolem.fresh()
                inner[var] = (name, *scope) if scope else name
        return self.walk(f.body, positive, inner)

    def disjunction(self, parts: list[_Cnf]) -> _Cnf:
        """Distribute; rename the largest parts first while the product is too big."""
        for i in sorted(range(len(parts)), key=lambda i: len(parts[i]), reverse=True):
            if prod(map(len, parts)) <= self.limit or len(parts[i]) <= 1:
                break
            parts[i] = self.define(parts[i])
        result: _Cnf = [()]
        for part in parts:
            result = [c for a in result for b in part if (c := _merged(a, b)) is not None]
        return result

    def define(self, part: _Cnf) -> _Cnf:
        """Rename ``part`` by a fresh atom D(free terms), adding D -> part to the output."""
        free = sorted({t for c in part for _, atom in c for t in _free_terms(atom)}, key=_order)
        atom = (self.skolem.fresh_predicate(), *free)
        self.definitions.extend(((False, atom), *clause) for clause in part)
        return [((True, atom),)]


def _literal(positive: bool, atom: tuple) -> _Cnf:
    if atom[0] == EQUALITY and len(atom) == 3 and atom[1] == atom[2]:
        return [] if positive else [()]  # t = t is true
    return [((positive, atom),)]


def _conjunction(parts: list[_Cnf]) -> _Cnf:
    return [clause for part in parts for clause in part]


def _merged(a: _Clause, b: _Clause) -> _Clause | None:
    """The disjunction of two clauses without duplicates; ``None`` for a tautology."""
    merged = list(a)
    for literal in b:
        if (not literal[0], literal[1]) in merged:
            return None
        if literal not in merged:
            merged.append(literal)
    return tuple(merged)


def _term(t: Term | Var, env: dict[Var, Term]) -> Term:
    if isinstance(t, Var):
        if t not in env:
            raise ValueError(f"variable {t.name} is not bound by a quantifier")
        return env[t]
    if type(t) is tuple:
        return (t[0], *(_term(arg, env) for arg in t[1:]))
    return t


def _free_vars(f: Formula, bound: set[Var]) -> Iterator[Var]:
    """The Vars of ``f`` that no quantifier inside ``f`` binds (``bound`` excluded)."""
    if isinstance(f, Atomic):
        for arg in f.atom[1:]:
            yield from (v for v in term_variables(arg) if v not in bound)
    elif isinstance(f, Not):
        yield from _free_vars(f.body, bound)
    elif isinstance(f, (And, Or)):
        for part in f.parts:
            yield from _free_vars(part, bound)
    elif isinstance(f, Implies):
        yield from _free_vars(f.premise, bound)
        yield from _free_vars(f.conclusion, bound)
    elif isinstance(f, Iff):
        yield from _free_vars(f.left, bound)
        yield from _free_vars(f.right, bound)
    elif isinstance(f, (Forall, Exists)):
        yield from _free_vars(f.body, bound | set(f.variables))


def _variables(t: Term) -> Iterator[int]:
    return (s for s in subterms(t) if type(s) is int)


def _free_terms(atom: tuple) -> Iterator[Term]:
    """The variables and parameters in ``atom``: what a definition must be a function of."""
    for arg in atom[1:]:
        yield from (s for s in subterms(arg) if type(s) is int or type(s) is Param)


def _order(t: Term) -> tuple[int, int, str, int]:
    return (0, t, "", 0) if type(t) is int else (1, 0, t.name, t.tag)  # type: ignore[union-attr]


def _renumbered(literals: _Clause) -> _Clause:
    """Number the clause's variables 0..k-1 in order of appearance."""
    numbers: dict[int, int] = {}

    def term(t: Term) -> Term:
        if type(t) is int:
            return numbers.setdefault(t, len(numbers))
        if type(t) is tuple:
            return (t[0], *map(term, t[1:]))
        return t

    return tuple((positive, (atom[0], *map(term, atom[1:]))) for positive, atom in literals)
