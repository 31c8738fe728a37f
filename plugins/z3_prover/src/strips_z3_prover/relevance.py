"""Which ground instances a session must assert: those whose conditions can hold.

A ground clause set without function symbols is unsatisfiable iff its instances over the
constants are; most of those instances are idle, though. The robot world's
``CONNECTS(x, y, z) -> CONNECTS(x, z, y)`` has 27^3 instances over 27 constants, of which
eight can ever fire. :class:`Relevance` keeps the set P of ground atoms that can hold: the
least set holding the positive atoms of every instance whose negative atoms are all in P
(semi-naive forward instantiation from the facts, as a Datalog engine computes a least
model, with every positive atom of a clause taken as a head). Only those instances are
asserted.

Why no answer changes (equality aside): given a model M of the asserted instances (and of
the goal's instances, whose positive atoms are put in P too), read it over the constants
(each constant its own element, atoms true as M makes them; without positive equations
no instance gets false), then make every atom outside P false. An asserted instance has
all its atoms in P, so keeps its truth; any other has a negative atom outside P, now
true. That is a model of *every* instance: the asserted ones are unsatisfiable exactly
when all are, and a model of them is a model of the axioms for the candidates' and
lemmas' searches. A positive equation (``x = y`` in a clause) can make two constants one
element, which breaks the reading over constants; a session that meets one grounds
every clause over the whole universe from then on (:attr:`Relevance.everything`).
"""

from __future__ import annotations

from collections.abc import Iterator, Sequence
from itertools import product

from strips_framework.logic.clauses import Clause
from strips_framework.logic.terms import EQUALITY, Param, Term

Key = tuple[str, int]  # a predicate and its arity
Binding = dict[Term, str]


def is_equation(atom: tuple) -> bool:
    return atom[0] == EQUALITY and len(atom) == 3


class Rule:
    """A clause of the session with the instances of it asserted so far."""

    def __init__(self, clause: Clause, selector: str) -> None:
        self.clause = clause
        self.selector = selector
        self.variables = sorted(
            {t for _, atom in clause.literals for t in atom[1:] if type(t) is int}
        )
        # Conditions: the negative atoms that are not equations, most arguments first
        # (matched against P they bind the most).
        self.conditions = sorted(
            (atom for positive, atom in clause.literals if not positive and not is_equation(atom)),
            key=lambda atom: -len(atom),
        )
        self.conclusions = [
            atom for positive, atom in clause.literals if positive and not is_equation(atom)
        ]
        self.equates = any(positive and is_equation(atom) for positive, atom in clause.literals)
        self.done: set[tuple[str, ...]] = set()


class Relevance:
    """The atoms that can hold (P), per predicate, and the rules waiting on them."""

    def __init__(self) -> None:
        self.atoms: dict[Key, set[tuple[str, ...]]] = {}
        self.rules: list[Rule] = []
        self._waiting: dict[Key, list[Rule]] = {}
        self._fresh: list[tuple] = []  # atoms added to P whose rules are not yet fired
        #: Set by a positive equation: then every instance over the universe is asserted.
        self.everything = False

    def add_rule(self, rule: Rule) -> None:
        self.rules.append(rule)
        for key in dict.fromkeys((atom[0], len(atom) - 1) for atom in rule.conditions):
            self._waiting.setdefault(key, []).append(rule)

    def possible(self, atom: tuple) -> bool:
        return self.everything or atom[1:] in self.atoms.get((atom[0], len(atom) - 1), ())

    def note(self, atom: tuple) -> None:
        """Put the ground ``atom`` in P (its rules fire at the next :meth:`fresh_pairs`)."""
        table = self.atoms.setdefault((atom[0], len(atom) - 1), set())
        if atom[1:] not in table:
            table.add(atom[1:])
            self._fresh.append(atom)

    def fresh_pairs(self) -> Iterator[tuple[Rule, tuple]]:
        """The rules waiting on an atom newly in P, with that atom, until none is left."""
        if self.everything:  # every instance is asserted already
            self._fresh.clear()
        while self._fresh:
            atom = self._fresh.pop()
            for rule in self._waiting.get((atom[0], len(atom) - 1), ()):
                yield rule, atom

    def bindings(
        self, rule: Rule, universe: Sequence[str], seed: tuple | None = None
    ) -> Iterator[Binding]:
        """Groundings of ``rule``'s variables whose conditions are all in P (all of
        them, with :attr:`everything`); with ``seed``, only those putting one of its
        conditions on that atom (the semi-naive step)."""
        if self.everything:
            for values in product(universe, repeat=len(rule.variables)):
                yield dict(zip(rule.variables, values))
            return
        if seed is None:
            yield from self._join(rule, rule.conditions, {}, universe)
            return
        for i, condition in enumerate(rule.conditions):
            binding: Binding = {}
            if condition[0] == seed[0] and _match(condition[1:], seed[1:], binding):
                rest = rule.conditions[:i] + rule.conditions[i + 1 :]
                yield from self._join(rule, rest, binding, universe)

    def _join(
        self, rule: Rule, conditions: Sequence[tuple], binding: Binding, universe: Sequence[str]
    ) -> Iterator[Binding]:
        if not conditions:
            free = [v for v in rule.variables if v not in binding]
            for values in product(universe, repeat=len(free)):
                yield {**binding, **dict(zip(free, values))}
            return
        first, rest = conditions[0], conditions[1:]
        # A snapshot: atoms noted meanwhile are fresh, and fire from their own seed.
        for row in tuple(self.atoms.get((first[0], len(first) - 1), ())):
            extended = dict(binding)
            if _match(first[1:], row, extended):
                yield from self._join(rule, rest, extended, universe)


def _match(args: Sequence[Term], row: Sequence[str], binding: Binding) -> bool:
    """Extend ``binding`` so that ``args`` become ``row``; False when they cannot."""
    for term, value in zip(args, row):
        if type(term) is int or type(term) is Param:
            bound = binding.setdefault(term, value)
            if bound != value:
                return False
        elif term != value:
            return False
    return True
