"""One Z3 solver holding ground instances of every clause it has seen, switched by selectors.

The world models of one search are M0 plus a few ADDITIONS and less a few DELETIONS
(:mod:`strips_framework.worldmodel.world`), so consecutive proof tasks share almost all their axioms.
A session asserts each distinct clause once, as ``selector -> instance`` for each of its
ground instances, and a task switches on exactly its own axioms by passing their selectors
as assumptions to ``check``: deleting a clause is leaving its selector out, adding one is
asserting it the first time it is seen. The goal's instances are pushed and popped.

Grounding is over the *universe*: every constant the session has seen. Constants are
admitted before clauses, and admitting one instantiates every clause already asserted on
it. For clauses without function symbols Herbrand's theorem makes the clauses
unsatisfiable iff their instances over the constants are (with Z3's equality for ``=``);
of those instances a session asserts only the ones whose negative atoms can all hold
(:mod:`strips_z3_prover.relevance`), found forward from the facts as clauses, constants
and goals arrive, which decides the same questions with a few hundred instances where
the whole universe gives tens of thousands. Unique names are
a ``Distinct`` over the task's own non-Skolem constants, behind a selector per set of
constants: constants the session kept from other tasks stay unconstrained, so they can
always be read as one of the task's objects and change no task's answer.
"""

from __future__ import annotations

from collections.abc import Iterable, Sequence
from itertools import product

import z3

from strips_framework.logic.clauses import Clause
from strips_framework.logic.terms import Param
from strips_z3_prover.encoding import Vocabulary, clause_variables
from strips_z3_prover.relevance import Binding, Relevance, Rule, is_equation
from strips_z3_prover.smtlib import Batch

#: Grounding needs a non-empty universe; Skolem-prefixed, so never a witness.
PLACEHOLDER = "sk!z3!individual"


class GroundSession:
    """A solver, its universe and one selector per asserted clause."""

    def __init__(self, seed: int) -> None:
        self.vocabulary = Vocabulary()
        self.solver = z3.Solver(ctx=self.vocabulary.context)
        self.solver.set("random_seed", seed)
        # Unconstrained atoms false: models then stay close to the least model, which
        # for Horn-like worlds holds exactly the entailed atoms, so the first model
        # already leaves few answer candidates (and few lemma candidates).
        self.solver.set("phase_selection", 0)
        self.universe: list[str] = []
        self._known: set[str] = set()
        self._selectors: dict[Clause, z3.BoolRef] = {}
        self.relevance = Relevance()
        self._distinct: dict[tuple[str, ...], z3.BoolRef] = {}
        self._declared: set[str] = set()
        self.solver.from_string("(declare-sort U 0)")

    def instances_needed(self, clauses: Iterable[Clause], constants: set[str]) -> int:
        """At most how many ground instances adding ``clauses`` and ``constants`` would
        assert (every instance over the universe: relevance only ever asserts fewer)."""
        size = len(self._known | constants)
        growth = sum(
            size ** len(rule.variables) - len(self.universe) ** len(rule.variables)
            for rule in self.relevance.rules
        )
        fresh = (c for c in dict.fromkeys(clauses) if c not in self._selectors)
        return growth + sum(size ** len(clause_variables(c)) for c in fresh)

    def admit(self, constants: Iterable[str]) -> None:
        """Add constants to the universe and instantiate the asserted clauses on them."""
        new = sorted(set(constants) - self._known)
        if not new:
            return
        self.universe.extend(new)
        self._known.update(new)
        batch = self.batch()
        for rule in self.relevance.rules:
            self._ground(batch, rule)
        self._propagate(batch)
        self.add(batch)

    def distinct(self, names: Sequence[str]) -> z3.BoolRef:
        """The selector of "``names`` are pairwise distinct" (unique names)."""
        key = tuple(sorted(names))
        found = self._distinct.get(key)
        if found is None:
            name = f"distinct!{len(self._distinct)}"
            batch = self.batch()
            batch.assert_distinct(key, name)
            self.add(batch)
            found = self._distinct[key] = z3.Bool(name, self.vocabulary.context)
        return found

    def selector(self, clause: Clause) -> z3.BoolRef:
        """The selector of ``clause``, asserting its relevant instances the first time."""
        found = self._selectors.get(clause)
        if found is not None:
            return found
        name = f"s!{len(self._selectors)}"
        selector = z3.Bool(name, self.vocabulary.context)
        self._selectors[clause] = selector
        rule = Rule(clause, name)
        self.relevance.add_rule(rule)
        batch = self.batch()
        if rule.equates:
            self._everything(batch)
        self._ground(batch, rule)
        self._propagate(batch)
        self.add(batch)
        return selector

    def expect(self, clauses: Sequence[Clause], binding: dict[Param, str]) -> None:
        """Make the positive atoms of the goal's instances ``clauses`` under ``binding``
        possible (a model may need them true), asserting the instances that then become
        relevant; outside any push scope, since they stay valid for later tasks."""
        batch = self.batch()
        for clause in clauses:
            for positive, atom in clause.literals:
                if positive and is_equation(atom):
                    self._everything(batch)
                elif positive:
                    terms = [t for t in atom[1:] if type(t) is int]
                    for values in product(self.universe, repeat=len(terms)):
                        instance = {**binding, **dict(zip(terms, values))}
                        self.relevance.note(_instance(atom, instance))
        self._propagate(batch)
        self.add(batch)

    def _ground(self, batch: Batch, rule: Rule, seed: tuple | None = None) -> None:
        """Write the instances of ``rule`` that became relevant, noting their conclusions."""
        for binding in self.relevance.bindings(rule, self.universe, seed):
            key = tuple(binding[v] for v in rule.variables)
            if key in rule.done:
                continue
            rule.done.add(key)
            batch.assert_clause(rule.clause, binding, rule.selector)
            for atom in rule.conclusions:
                self.relevance.note(_instance(atom, binding))

    def _propagate(self, batch: Batch) -> None:
        """Fire the rules on the atoms newly possible until none is (semi-naive)."""
        for rule, atom in self.relevance.fresh_pairs():
            self._ground(batch, rule, atom)

    def _everything(self, batch: Batch) -> None:
        """From now on assert every instance over the universe (a positive equation)."""
        if not self.relevance.everything:
            self.relevance.everything = True
            for rule in self.relevance.rules:
                self._ground(batch, rule)

    def write_instances(
        self,
        batch: Batch,
        clauses: Sequence[Clause],
        binding: dict[Param, str],
        selector: str | None = None,
    ) -> None:
        """Write every instance over the universe of ``clauses`` under ``binding``."""
        for clause in clauses:
            variables = sorted(clause_variables(clause))
            for values in product(self.universe, repeat=len(variables)):
                batch.assert_clause(clause, {**binding, **dict(zip(variables, values))}, selector)

    def batch(self) -> Batch:
        return Batch(self._declared)

    def declare(self, batch: Batch) -> None:
        """Make the declarations ``batch`` needs (outside any push scope, so that a pop
        never forgets a symbol the session still uses)."""
        text = batch.declarations()
        if text:
            self.solver.from_string(text)

    def add(self, batch: Batch) -> None:
        """Assert what ``batch`` holds, declaring what it needs first."""
        self.declare(batch)
        text = batch.assertions()
        if text:
            self.solver.from_string(text)


def _instance(atom: tuple, binding: Binding) -> tuple:
    return (atom[0], *(binding.get(t, t) for t in atom[1:]))
