"""The Z3 prover: the framework's proof tasks decided by an SMT solver.

It answers the questions the resolution prover answers, on the same clauses: whether the
goal follows from the axioms, for which parameter instances (answers), and, when it does
not, the uncompleted proof the means-ends search makes its difference from. Models
without function symbols (STRIPS worlds) are grounded over their constants and solved
incrementally (:mod:`strips_z3_prover.ground`); others go to Z3 with quantifiers
(:mod:`strips_z3_prover.quantified`).
"""

from __future__ import annotations

from collections.abc import Sequence
from typing import ClassVar

from strips_framework.capabilities import (
    ANSWERS,
    EFFORT_BOUND,
    EQUALITY,
    QUANTIFIED_AXIOMS,
    SOUND,
    UNCOMPLETED_PROOF,
)
from strips_framework.logic.clauses import Clause
from strips_framework.options import Configurable, Option
from strips_framework.worldmodel.proving import PROVED, ProofResult, ProofTask
from strips_framework.worldmodel.world import InitialModel, WorldModel
from strips_z3_prover.budget import Budget
from strips_z3_prover.encoding import ClauseTerms, clause_params
from strips_z3_prover.ground import prove_ground
from strips_z3_prover.outcome import Outcome
from strips_z3_prover.quantified import prove_quantified
from strips_z3_prover.residuals import uncompleted_proof
from strips_z3_prover.session import PLACEHOLDER, GroundSession


class Z3Prover(Configurable):
    """Z3 with ground instances where the model allows, quantifiers otherwise.

    Options: ``rlimit_per_effort`` is the scale of the effort bound: an attempt may use
    ``effort * rlimit_per_effort`` units of Z3's deterministic resource counter (the
    default gives the default effort of 300 the 3e5 units a robot-world task needs at
    most, grounding included, while effort 1 is too little for a pigeonhole
    problem). ``incremental`` keeps one solver for all the world models of a session
    (:meth:`open`), so the shared part of successive models is encoded once (see
    :mod:`.session`): a search is then reproducible as a whole, while the effort one
    attempt uses depends on what the session already holds (``false`` makes each attempt
    reproducible alone, and slower; a one-off :meth:`prove` always starts afresh);
    ``max_ground_instances`` is the most ground instances one task may add before its
    attempt uses quantifiers instead; ``seed`` is Z3's random seed; ``max_residuals``
    bounds the uncompleted proof of a failed attempt.
    """

    name: ClassVar[str] = "z3"
    capabilities: ClassVar[frozenset[str]] = frozenset(
        {EQUALITY, QUANTIFIED_AXIOMS, ANSWERS, UNCOMPLETED_PROOF, SOUND, EFFORT_BOUND}
    )

    options = (
        Option("rlimit_per_effort", int, 1000, minimum=1, doc="Z3 resource units per unit of effort"),
        Option("incremental", bool, True, doc="one solver for all the world models of a session"),
        Option("max_ground_instances", int, 200_000, minimum=0,
               doc="ground instances per task before quantifiers are used instead"),
        Option("seed", int, 0, minimum=0, doc="Z3's random seed"),
        Option("max_residuals", int, 200, minimum=1, doc="the uncompleted proof's clauses at most"),
    )
    rlimit_per_effort: int
    incremental: bool
    max_ground_instances: int
    seed: int
    max_residuals: int

    def prove(self, task: ProofTask) -> ProofResult:
        """Refute ``task.axioms`` ∪ ``task.negated_goal`` for some parameter instance."""
        initial = InitialModel(task.axioms)
        return self.open(initial, task.unique_names).prove(
            WorldModel(initial), task.negated_goal, task.effort, task.max_answers
        )

    def open(self, initial: InitialModel, unique_names: bool) -> Z3Session:
        """A session on M0: with ``incremental``, one solver for all its models."""
        return Z3Session(self, unique_names)


class Z3Session:
    """The prover opened on one M0. With ``incremental`` it keeps one
    :class:`~strips_z3_prover.session.GroundSession`, in which each clause of M0 is
    asserted once and a model switches on its own clauses by selector; that solver state
    only speeds up later attempts, never changes their answers."""

    def __init__(self, options: Z3Prover, unique_names: bool) -> None:
        self.options = options
        self.unique_names = unique_names
        self.ground = GroundSession(options.seed) if options.incremental else None
        self.terms = ClauseTerms()

    def prove(
        self,
        model: WorldModel,
        negated_goal: Sequence[Clause],
        effort: int,
        max_answers: int = 1,
    ) -> ProofResult:
        """Refute the clauses visible in ``model`` ∪ ``negated_goal``."""
        task = ProofTask.of_model(model, negated_goal, effort, max_answers, self.unique_names)
        options = self.options
        budget = Budget(task.effort, options.rlimit_per_effort)
        params = sorted(set().union(*map(clause_params, task.negated_goal)))
        outcome = self._attempt(task, params, budget)
        if outcome.status == PROVED:
            return ProofResult(PROVED, answers=outcome.answers, effort_used=budget.effort_used())
        facts = (*task.axioms, *(Clause([(True, atom)]) for atom in outcome.lemmas))
        uncompleted = uncompleted_proof(task.negated_goal, facts, options.max_residuals)
        return ProofResult(
            outcome.status, uncompleted=uncompleted, effort_used=budget.effort_used()
        )

    def _attempt(self, task: ProofTask, params: list, budget: Budget) -> Outcome:
        axioms = [self.terms.of(c) for c in task.axioms]
        goal = [self.terms.of(c) for c in task.negated_goal]
        seed = self.options.seed
        # A function symbol (Skolem functions included) makes the Herbrand universe
        # infinite, and grounding over the constants incomplete.
        if any(functions for functions, _, _ in (*axioms, *goal)) or any(p for _, p, _ in axioms):
            return prove_quantified(task, params, budget, seed)
        constants = set().union(*(names for _, _, names in (*axioms, *goal))) or {PLACEHOLDER}
        session = self.ground if self.ground is not None else GroundSession(seed)
        needed = session.instances_needed((*task.axioms, *task.negated_goal), constants)
        if needed > self.options.max_ground_instances:
            return prove_quantified(task, params, budget, seed)
        session.admit(constants)
        return prove_ground(session, task, params, budget, constants)
