"""Asking the configured prover about goal wffs in world models, with the bookkeeping the
searches need: one prover session per problem (M0 indexed once), clause forms computed
once per goal, answers cached per (model, goal), and the time spent proving measured for
the paper's Table 2."""

from __future__ import annotations

import time

from strips_framework.logic.clauses import Clause
from strips_framework.logic.cnf import SkolemNames, negated_goal_clauses
from strips_framework.logic.formulas import Atomic, Formula, conjuncts
from strips_framework.logic.terms import EQUALITY, is_ground
from strips_framework.logic.unify import unify
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
                 "attempts", "_negations", "_cache", "derivable")  # fmt: skip

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
        #: Predicates, as ``(name, arity)``, that M0 can conclude other than by a ground
        #: fact: those of a positive literal of a non-unit or non-ground clause, or of a
        #: derived fact. An atom of any other predicate holds in a model only as a fact.
        self.derivable: frozenset[tuple[str, int]] = frozenset(
            (atom[0], len(atom) - 1)
            for clause in self.initial.clauses
            if not (clause.is_unit and is_ground(clause.literals[0][1]))
            for positive, atom in clause.literals
            if positive
        ) | frozenset((fact.atom[0], len(fact.atom) - 1) for fact in self.problem.derived)

    def cannot_hold(self, model: WorldModel, goal: Formula) -> bool:
        """True when a conjunct of ``goal`` is an atom that only a fact could prove and
        no fact of ``model`` matches: no proof exists, so none need be tried. An attempt
        that fails costs what its effort allows (every subset of a conjunctive goal's
        literals, resolved on each); on elevators of IPC 2008, the attempts that check
        whether an application made a deeper goal true took 22 of 57 s."""
        for part in conjuncts(goal):
            if not isinstance(part, Atomic):
                continue
            atom = part.atom
            if atom[0] == EQUALITY or (atom[0], len(atom) - 1) in self.derivable:
                continue
            if is_ground(atom):
                if not model.holds(atom):
                    return True
            elif not any(unify(atom, fact, {}) is not None for fact in model.facts_matching(atom)):
                return True
        return False

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
