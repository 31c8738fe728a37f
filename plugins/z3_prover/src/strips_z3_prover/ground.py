"""Proof attempts on ground instances: the encoding for effectively propositional models.

Without function symbols the Herbrand universe is the finite set of constants, so the
axioms and the negated goal are decided on their ground instances (quantifier-free, with
equality), which Z3 solves fastest. Answers are found by counterexample-guided search:

1. a model of the axioms alone gives the candidates θ for which G(θ) holds in it
   (:mod:`strips_z3_prover.candidates`); an answer must be among them;
2. each candidate in turn is checked: ``axioms ∧ ¬G(θ)`` unsatisfiable makes θ an answer;
   a countermodel rejects θ and every other candidate that fails in it.

The search is complete: a goal that follows for some θ is proved when the resource limit
allows, and when the candidates run out the goal follows for no θ (``Satisfiable``).
"""

from __future__ import annotations

from collections.abc import Callable, Sequence
from collections.abc import Set as AbstractSet

import z3

from strips_framework.logic.clauses import Clause
from strips_framework.logic.terms import EQUALITY, Param
from strips_framework.logic.unify import unify
from strips_framework.worldmodel.proving import GAVE_UP, PROVED, SATURATED, Answer, ProofTask
from strips_z3_prover.budget import Budget
from strips_z3_prover.candidates import ModelTruth, surviving
from strips_z3_prover.encoding import is_named
from strips_z3_prover.outcome import Outcome, status_of
from strips_z3_prover.session import PLACEHOLDER, GroundSession


def prove_ground(
    session: GroundSession,
    task: ProofTask,
    params: Sequence[Param],
    budget: Budget,
    constants: AbstractSet[str],
) -> Outcome:
    """Decide ``task`` in ``session``, whose universe already holds the task's
    ``constants``."""
    return _Attempt(session, task, params, budget, constants).run()


class _Attempt:
    """One task in a session: its selectors and the models seen so far."""

    def __init__(
        self,
        session: GroundSession,
        task: ProofTask,
        params: Sequence[Param],
        budget: Budget,
        constants: AbstractSet[str],
    ) -> None:
        self.session, self.task, self.params, self.budget = session, task, params, budget
        self.assumptions = [session.selector(clause) for clause in task.axioms]
        # Answers are the task's own constants, never one the session kept from another.
        self.named = sorted(c for c in constants if is_named(c))
        if task.unique_names and len(self.named) > 1:
            self.assumptions.append(session.distinct(self.named))
        self.first: ModelTruth | None = None

    def run(self) -> Outcome:
        if not self.params:
            result, _ = self._refute(self.task.negated_goal, {})
            if result == z3.unsat:
                return Outcome(PROVED, ((),))
            return Outcome(status_of(result), lemmas=self._lemmas())
        result = self.budget.check(self.session.solver, self.assumptions)
        if result != z3.sat:  # inconsistent axioms entail every instance
            return Outcome(PROVED, ((),)) if result == z3.unsat else Outcome(GAVE_UP)
        self.first = self._truth(self.session.solver.model())
        candidates = surviving(self.first, self.task.negated_goal, self.params)
        answers: list[Answer] = []
        for values in sorted(candidates):
            if len(answers) >= self.task.max_answers:
                break
            if values not in candidates:
                continue  # rejected by a countermodel of an earlier candidate
            binding = dict(zip(self.params, values))
            result, model = self._refute(self.task.negated_goal, binding, countermodel=True)
            if result == z3.unsat:
                answers.append(tuple(binding.items()))
            elif model is not None:
                candidates &= surviving(self._truth(model), self.task.negated_goal, self.params)
            elif not answers:
                return Outcome(GAVE_UP, lemmas=self._lemmas())
            else:
                break
        if answers:
            return Outcome(PROVED, tuple(answers))
        if not self.named and self._holds_for_all():
            return Outcome(PROVED, ((),))
        return Outcome(SATURATED, lemmas=self._lemmas())

    def _holds_for_all(self) -> bool:
        """Whether the goal follows whatever the parameters denote (the answer then binds
        none of them, as a resolution refutation would leave them). Only asked when no
        constant could be an answer: otherwise any constant would have been one."""
        arbitrary = {p: f"{PLACEHOLDER}!{p.name}!{p.tag}" for p in self.params}
        self.session.admit(arbitrary.values())
        result, _ = self._refute(self.task.negated_goal, arbitrary)
        return result == z3.unsat

    def _lemmas(self) -> tuple[tuple, ...]:
        """Ground atoms that match a literal of the negated goal and that the axioms
        entail without being facts (``CONNECTS(DOOR4, ROOM5, ROOM4)`` by symmetry), for
        the uncompleted proof to resolve with.

        The candidates are the matching atoms true in a model of the axioms. They are
        assumed false all at once: if that is consistent none is entailed; if not, an
        unsatisfiable core of a single assumption shows its atom entailed, which is
        recorded and dropped before checking again (a larger core ends the search)."""
        facts = {c.literals[0][1] for c in self.task.axioms if c.is_unit and c.literals[0][0]}
        goal_atoms = [
            atom
            for clause in self.task.negated_goal
            for positive, atom in clause.literals
            if not positive and atom[0] != EQUALITY
        ]
        predicates = sorted({(atom[0], len(atom) - 1) for atom in goal_atoms})

        def admissible(atom: tuple) -> bool:
            # An atom that cannot hold (relevance) is true only by the model's whim.
            return (
                atom not in facts
                and self.session.relevance.possible(atom)
                and any(unify(goal, atom, {}) is not None for goal in goal_atoms)
            )

        if not self._may_have_lemmas(predicates, admissible):
            return ()
        if self.first is None:
            if self.budget.check(self.session.solver, self.assumptions) != z3.sat:
                return ()
            self.first = self._truth(self.session.solver.model())
        candidates = [atom for atom in self.first.true_atoms(predicates) if admissible(atom)]
        batch = self.session.batch()
        for i, atom in enumerate(candidates):
            batch.assert_clause(Clause([(False, atom)]), {}, f"lemma!{i}")
        self.session.declare(batch)
        context = self.session.vocabulary.context
        assumed = {f"lemma!{i}": z3.Bool(f"lemma!{i}", context) for i in range(len(candidates))}
        lemmas: list[tuple] = []
        self.session.solver.push()
        self.session.add(batch)
        while assumed and not self.budget.exhausted:
            result = self.budget.check(self.session.solver, [*self.assumptions, *assumed.values()])
            if result != z3.unsat:
                break
            core = [str(e) for e in self.session.solver.unsat_core() if str(e) in assumed]
            if len(core) != 1:
                break
            lemmas.append(candidates[int(core[0].removeprefix("lemma!"))])
            del assumed[core[0]]
        self.session.solver.pop()
        return tuple(lemmas)

    def _may_have_lemmas(
        self, predicates: Sequence[tuple[str, int]], admissible: Callable[[tuple], bool]
    ) -> bool:
        """Whether a lemma candidate may exist: one is an admissible atom over the task's
        named constants that a model of the axioms makes true, so with relevance it is
        among the atoms that can hold, which are known without asking Z3 for a model
        (most failed attempts have none, and then need no check)."""
        relevance = self.session.relevance
        if relevance.everything:
            return True
        named = set(self.named)
        return any(
            all(name in named for name in row) and admissible((predicate, *row))
            for predicate, arity in predicates
            for row in relevance.atoms.get((predicate, arity), ())
        )

    def _truth(self, model: z3.ModelRef) -> ModelTruth:
        session = self.session
        return ModelTruth(
            model, session.vocabulary, session.universe, self.named, session.relevance
        )

    def _refute(
        self, clauses: Sequence[Clause], binding: dict[Param, str], countermodel: bool = False
    ) -> tuple[z3.CheckSatResult, z3.ModelRef | None]:
        """Check the axioms with the instances of ``clauses`` under ``binding``; with
        ``countermodel``, the countermodel when there is one (Z3 builds a model only
        when asked, at a cost like the check's on a small world)."""
        session, solver = self.session, self.session.solver
        session.expect(clauses, binding)
        batch = session.batch()
        session.write_instances(batch, clauses, binding)
        session.declare(batch)
        solver.push()
        session.add(batch)
        result = self.budget.check(solver, self.assumptions)
        model = solver.model() if countermodel and result == z3.sat else None
        solver.pop()
        return result, model
