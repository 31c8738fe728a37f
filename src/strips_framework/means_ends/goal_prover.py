"""Asking the configured prover about goal wffs in world models, with the bookkeeping the
searches need: one prover session per problem (M0 indexed once), clause forms computed
once per goal, answers cached per (model, goal), and the time spent proving measured for
the paper's Table 2."""

from __future__ import annotations

import time

from strips_framework.logic.clauses import Clause
from strips_framework.logic.cnf import SkolemNames, negated_goal_clauses
from strips_framework.logic.formulas import Formula
from strips_framework.worldmodel.problem import Problem
from strips_framework.worldmodel.proving import (
    ProofResult,
    ProverSession,
    TheoremProver,
    open_session,
)
from strips_framework.worldmodel.world import InitialModel, WorldModel, initial_model


class GoalProver:
    """One search's access to the prover. Mutable: it counts the attempts and the time
    spent proving, and caches clause forms and answers."""

    __slots__ = ("problem", "prover", "effort", "skolem", "initial", "session", "seconds",
                 "attempts", "_negations", "_cache")  # fmt: skip

    def __init__(
        self,
        problem: Problem,
        prover: TheoremProver,
        effort: int,
        skolem: SkolemNames | None = None,
    ) -> None:
        self.problem = problem
        self.prover = prover
        self.effort = effort
        self.skolem = SkolemNames() if skolem is None else skolem
        self.seconds = 0.0
        self.attempts = 0
        self._negations: dict[Formula, tuple[Clause, ...]] = {}
        self._cache: dict[tuple[WorldModel, Formula, int], ProofResult] = {}
        self._open()

    def _open(self) -> None:
        """Build M0 and open the prover's session on it (a method of its own, so that a
        benchmark can wrap it to time or record the session)."""
        self.initial: InitialModel = initial_model(self.problem, self.skolem)
        self.session: ProverSession = open_session(
            self.prover, self.initial, self.problem.unique_names
        )

    def root_model(self) -> WorldModel:
        return WorldModel(self.initial)

    def negated(self, goal: Formula) -> tuple[Clause, ...]:
        """The clauses of ¬goal (computed once per goal wff)."""
        clauses = self._negations.get(goal)
        if clauses is None:
            clauses = tuple(negated_goal_clauses(goal, self.skolem))
            self._negations[goal] = clauses
        return clauses

    def prove(self, model: WorldModel, goal: Formula, max_answers: int = 1) -> ProofResult:
        key = (model, goal, max_answers)
        cached = self._cache.get(key)
        if cached is not None:
            return cached
        negated = self.negated(goal)
        started = time.perf_counter()
        result = self.session.prove(model, negated, self.effort, max_answers)
        self.seconds += time.perf_counter() - started
        self.attempts += 1
        self._cache[key] = result
        return result
