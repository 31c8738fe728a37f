"""The Z3 prover: the framework's proof tasks decided by an SMT solver.

It answers the questions the resolution prover answers, on the same clauses: whether the
goal follows from the axioms, for which parameter instances (answers), and, when it does
not, the uncompleted proof the means-ends search makes its difference from. Models
without function symbols (STRIPS worlds) are grounded over their constants and solved
incrementally (:mod:`strips_z3_prover.ground`); others go to Z3 with quantifiers
(:mod:`strips_z3_prover.quantified`).
"""

from __future__ import annotations

from typing import ClassVar

from attrs import define, field
from attrs.validators import ge, instance_of

from strips_framework.capabilities import (
    ANSWERS,
    EFFORT_BOUND,
    EQUALITY,
    QUANTIFIED_AXIOMS,
    SOUND,
    UNCOMPLETED_PROOF,
)
from strips_framework.logic.clauses import Clause
from strips_framework.proving import PROVED, ProofResult, ProofTask
from strips_z3_prover.budget import Budget
from strips_z3_prover.encoding import clause_params, has_functions, task_terms
from strips_z3_prover.ground import prove_ground
from strips_z3_prover.outcome import Outcome
from strips_z3_prover.quantified import prove_quantified
from strips_z3_prover.residuals import uncompleted_proof
from strips_z3_prover.session import PLACEHOLDER, GroundSession


@define(frozen=True)
class Z3Prover:
    """Z3 with ground instances where the model allows, quantifiers otherwise.

    Options: ``rlimit_per_effort`` is the scale of the effort bound: an attempt may use
    ``effort * rlimit_per_effort`` units of Z3's deterministic resource counter (the
    default gives the default effort of 300 the 3e5 units a robot-world task needs at
    most, grounding included, while effort 1 is too little for a pigeonhole
    problem). ``incremental`` keeps one solver for all tasks, so the
    shared part of successive world models is encoded once (see :mod:`.session`): a run
    is then reproducible as a whole, while the effort one task uses depends on what the
    session already holds (``false`` makes each task reproducible alone, and slower);
    ``max_ground_instances`` is the most ground instances one task may add before its
    attempt uses quantifiers instead; ``seed`` is Z3's random seed; ``max_residuals``
    bounds the uncompleted proof of a failed attempt.
    """

    name: ClassVar[str] = "z3"
    capabilities: ClassVar[frozenset[str]] = frozenset(
        {EQUALITY, QUANTIFIED_AXIOMS, ANSWERS, UNCOMPLETED_PROOF, SOUND, EFFORT_BOUND}
    )

    rlimit_per_effort: int = field(default=1000, validator=[instance_of(int), ge(1)])
    incremental: bool = field(default=True, validator=instance_of(bool))
    max_ground_instances: int = field(default=200_000, validator=[instance_of(int), ge(0)])
    seed: int = field(default=0, validator=[instance_of(int), ge(0)])
    max_residuals: int = field(default=200, validator=[instance_of(int), ge(1)])
    # The incremental solver: state that only speeds up later tasks, never changes answers.
    _sessions: list[GroundSession] = field(init=False, factory=list, eq=False, repr=False)

    def prove(self, task: ProofTask) -> ProofResult:
        """Refute ``task.axioms`` ∪ ``task.negated_goal`` for some parameter instance."""
        budget = Budget(task.effort, self.rlimit_per_effort)
        params = sorted(set().union(*map(clause_params, task.negated_goal)))
        outcome = self._attempt(task, params, budget)
        if outcome.status == PROVED:
            return ProofResult(PROVED, answers=outcome.answers, effort_used=budget.effort_used())
        facts = (*task.axioms, *(Clause([(True, atom)]) for atom in outcome.lemmas))
        uncompleted = uncompleted_proof(task.negated_goal, facts, self.max_residuals)
        return ProofResult(
            outcome.status, uncompleted=uncompleted, effort_used=budget.effort_used()
        )

    def _attempt(self, task: ProofTask, params: list, budget: Budget) -> Outcome:
        clauses = (*task.axioms, *task.negated_goal)
        if has_functions(task) or any(clause_params(c) for c in task.axioms):
            return prove_quantified(task, params, budget, self.seed)
        constants = {t for t in task_terms(clauses) if type(t) is str} or {PLACEHOLDER}
        session = self._session()
        needed = session.instances_needed(clauses, constants)
        if needed > self.max_ground_instances:
            return prove_quantified(task, params, budget, self.seed)
        session.admit(constants)
        return prove_ground(session, task, params, budget)

    def _session(self) -> GroundSession:
        if not self.incremental:
            return GroundSession(self.seed)
        if not self._sessions:
            self._sessions.append(GroundSession(self.seed))
        return self._sessions[0]
