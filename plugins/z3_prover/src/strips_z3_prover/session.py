"""One Z3 solver holding ground instances of every clause it has seen, switched by selectors.

The world models of one search are M0 plus a few ADDITIONS and less a few DELETIONS
(:mod:`strips_framework.worldmodel.world`), so consecutive proof tasks share almost all their axioms.
A session asserts each distinct clause once, as ``selector -> instance`` for each of its
ground instances, and a task switches on exactly its own axioms by passing their selectors
as assumptions to ``check``: deleting a clause is leaving its selector out, adding one is
asserting it the first time it is seen. The goal's instances are pushed and popped.

Grounding is over the *universe*: every constant the session has seen. Constants are
admitted before clauses, and admitting one instantiates every clause already asserted on
it, so each clause always has all its instances over the universe. For clauses without
function symbols this is exactly Herbrand's theorem: the clauses are unsatisfiable iff
their instances over the constants are (with Z3's equality for ``=``). Unique names are
a ``Distinct`` over the task's own non-Skolem constants, behind a selector per set of
constants: constants the session kept from other tasks stay unconstrained, so they can
always be read as one of the task's objects and change no task's answer.
"""

from __future__ import annotations

from collections.abc import Iterable, Iterator, Sequence
from itertools import product

import z3

from strips_framework.logic.clauses import Clause
from strips_framework.logic.terms import Param
from strips_z3_prover.encoding import Vocabulary, clause_variables
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
        self._open: list[tuple[Clause, list[int], str]] = []
        self._distinct: dict[tuple[str, ...], z3.BoolRef] = {}
        self._declared: set[str] = set()
        self.solver.from_string("(declare-sort U 0)")

    def instances_needed(self, clauses: Iterable[Clause], constants: set[str]) -> int:
        """How many ground instances adding ``clauses`` and ``constants`` would assert."""
        size = len(self._known | constants)
        growth = sum(
            size ** len(variables) - len(self.universe) ** len(variables)
            for _, variables, _ in self._open
        )
        fresh = (c for c in dict.fromkeys(clauses) if c not in self._selectors)
        return growth + sum(size ** len(clause_variables(c)) for c in fresh)

    def admit(self, constants: Iterable[str]) -> None:
        """Add constants to the universe and instantiate the asserted clauses on them."""
        new = sorted(set(constants) - self._known)
        if not new:
            return
        old = len(self.universe)
        self.universe.extend(new)
        self._known.update(new)
        batch = self.batch()
        for clause, variables, selector in self._open:
            for values in _tuples_using_new(self.universe, old, len(variables)):
                batch.assert_clause(clause, dict(zip(variables, values)), selector)
        self.add(batch)

    def distinct(self, names: Sequence[str]) -> z3.BoolRef:
        """The selector of "``names`` are pairwise distinct" (unique names)."""
        key = tuple(sorted(names))
        found = self._distinct.get(key)
        if found is None:
            found = z3.Bool(f"distinct!{len(self._distinct)}", self.vocabulary.context)
            constants = [self.vocabulary.constant(name) for name in key]
            self.solver.add(z3.Implies(found, z3.Distinct(constants)))
            self._distinct[key] = found
        return found

    def selector(self, clause: Clause) -> z3.BoolRef:
        """The selector of ``clause``, asserting its instances the first time."""
        found = self._selectors.get(clause)
        if found is not None:
            return found
        name = f"s!{len(self._selectors)}"
        selector = z3.Bool(name, self.vocabulary.context)
        self._selectors[clause] = selector
        variables = sorted(clause_variables(clause))
        batch = self.batch()
        self.write_instances(batch, [clause], {}, name)
        self.add(batch)
        if variables:
            self._open.append((clause, variables, name))
        return selector

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


def _tuples_using_new(universe: list[str], old: int, arity: int) -> Iterator[tuple[str, ...]]:
    """The ``arity``-tuples over ``universe`` with at least one of its elements from
    index ``old`` on (the tuples over the first ``old`` were instantiated before)."""
    for values in product(range(len(universe)), repeat=arity):
        if any(i >= old for i in values):
            yield tuple(universe[i] for i in values)
