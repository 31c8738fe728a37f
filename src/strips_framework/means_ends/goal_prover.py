"""Asking the configured prover about goal wffs in world models, with the bookkeeping the
searches need: one prover session per problem (M0 indexed once), clause forms computed
once per goal, answers cached per (model, goal), and the time spent proving measured for
the paper's Table 2."""

from __future__ import annotations

import time

from strips_framework.logic.clauses import Clause
from strips_framework.logic.cnf import SkolemNames, negated_goal_clauses
from strips_framework.logic.formulas import Atomic, Formula, conjuncts
from strips_framework.logic.horn import is_conjunctive_query
from strips_framework.logic.terms import EQUALITY, is_ground
from strips_framework.logic.unify import unify
from strips_framework.worldmodel.fact_join import facts_join
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

    __slots__ = ("problem", "prover", "effort", "difference_effort", "skolem", "initial",
                 "session", "seconds", "attempts", "_negations", "_cache", "derivable")  # fmt: skip

    def __init__(
        self,
        problem: Problem,
        prover: TheoremProver,
        effort: int,
        skolem: SkolemNames | None = None,
        difference_effort: int | None = None,
    ) -> None:
        self.problem = problem
        self.prover = prover
        self.effort = effort
        #: The effort of an attempt known to fail (see :meth:`attempt`); ``effort``
        #: when not given.
        self.difference_effort = effort if difference_effort is None else difference_effort
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

    def decide(self, model: WorldModel, goal: Formula) -> bool | None:
        """Whether ``goal`` is provable in ``model``, when the model's facts alone settle
        it; ``None`` when they do not (the prover must be asked). False when a conjunct
        :meth:`cannot_hold`; otherwise, for a conjunction of atoms that only facts
        conclude (and, under unique names, inequalities), the join of its atoms over the
        model's facts (:func:`~strips_framework.worldmodel.fact_join.facts_join`): a
        refutation of such a goal resolves each of its literals on a fact, so the prover,
        given effort enough, proves it exactly when the join finds a match."""
        if self.cannot_hold(model, goal):
            return False
        negated = self.negated(goal)
        if not is_conjunctive_query(negated, self.problem.unique_names):
            return None
        literals = negated[0].literals
        if any(not positive and (atom[0], len(atom) - 1) in self.derivable
               for positive, atom in literals):
            return None
        return facts_join(model, literals)

    def root_model(self) -> WorldModel:
        return WorldModel(self.initial)

    def negated(self, goal: Formula) -> tuple[Clause, ...]:
        """The clauses of ¬goal (computed once per goal wff)."""
        clauses = self._negations.get(goal)
        if clauses is None:
            clauses = tuple(negated_goal_clauses(goal, self.skolem))
            self._negations[goal] = clauses
        return clauses

    def attempt(self, model: WorldModel, goal: Formula) -> ProofResult:
        """The attempt on a node's first goal: its proof, or its uncompleted proof for
        the difference. When the model's facts already show the goal false
        (:meth:`decide`), the attempt can find no proof and runs only for the difference,
        within ``difference_effort``: a failed resolution attempt stops only at its
        effort bound, and a proof, when there is one, takes a few given clauses (on
        elevators of IPC 2008, 1 to 3 against a bound of 300), so one bound cannot suit
        both. The weight queue picks the lightest clauses first, so the smallest clauses
        of the uncompleted proof, which the difference keeps, come early."""
        known_false = self.difference_effort < self.effort and self.decide(model, goal) is False
        return self.prove(model, goal, effort=self.difference_effort if known_false else None)

    def prove(
        self, model: WorldModel, goal: Formula, max_answers: int = 1, effort: int | None = None
    ) -> ProofResult:
        """The prover's answer on ``goal`` in ``model``, within ``effort`` (this
        prover's ``effort`` by default). Cached per (model, goal, answers): an attempt
        with less effort is only made on a goal known to fail, which fails again with
        any effort."""
        key = (model, goal, max_answers)
        cached = self._cache.get(key)
        if cached is not None:
            return cached
        negated = self.negated(goal)
        bound = self.effort if effort is None else effort
        started = time.perf_counter()
        try:
            result = self.session.prove(model, negated, bound, max_answers)
        finally:
            # Counted when a limit ends the attempt too: the time went to proving, and a
            # run's statistics must say so (one attempt on organic synthesis took 3.2 s
            # of a 6 s run that reported 0.003 s proving).
            self.seconds += time.perf_counter() - started
            self.attempts += 1
        self._cache[key] = result
        return result
