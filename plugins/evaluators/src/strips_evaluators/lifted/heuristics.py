"""The lifted heuristics: goal count, hmax, hadd and hFF with preferred operators, computed
per state from the lifted task (:mod:`.program`, :mod:`.exploration`) without grounding it.
On a task small enough to ground they give the values of their ground namesakes in
:mod:`strips_evaluators.heuristics` (hFF up to the choice among equally cheap supporters).
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from typing import ClassVar

from strips_evaluators.lifted.closure import DerivedClosure
from strips_evaluators.lifted.exploration import (
    Exploration,
    Supporter,
    action_instance,
    relaxed_plan,
)
from strips_evaluators.lifted.program import AXIOM, Program
from strips_framework.capabilities import PREFERRED_OPERATORS
from strips_framework.lifted.components import ActionInstance, GroundAtom, Guidance, LiftedState
from strips_framework.options import Configurable
from strips_framework.pddl.task import PddlTask


class GoalCountEstimator:
    """The goal facts the state lacks; a goal that is not a conjunction of atoms counts
    as one fact, as grounding compiles it to one derived fact."""

    def __init__(self, program: Program) -> None:
        self.program = program
        self.closure = DerivedClosure(program)
        self.needs_closure = any(fact[0] in program.derived for fact in program.fluent_goal)

    def estimate(self, state: LiftedState) -> float:
        facts = self.closure.model(state) if self.needs_closure else state
        missing = sum(1 for fact in self.program.fluent_goal if fact not in facts)
        return missing + self.program.static_goal_missing

    def estimate_with_preferred(self, state: LiftedState) -> tuple[float, Sequence[ActionInstance]]:
        return self.estimate(state), ()


class LiftedGoalCount(Configurable):
    """Goal count over the lifted task: the goal atoms false in the state. Not admissible;
    no preferred operators."""

    name: ClassVar[str] = "goal-count"
    admissible: ClassVar[bool] = False

    def for_task(self, task: PddlTask) -> GoalCountEstimator:
        return GoalCountEstimator(Program(task))


class CostEstimator:
    """hadd (``additive``) or hmax: the sum or maximum of the goal facts' relaxed costs."""

    def __init__(self, program: Program, additive: bool) -> None:
        self.program = program
        self.exploration = Exploration(program)
        self.additive = additive

    def estimate(self, state: LiftedState) -> float:
        program = self.program
        if program.static_goal_missing:
            return math.inf
        cost, _ = self.exploration.costs(state, self.additive)
        values = [cost.get(fact, math.inf) for fact in program.fluent_goal]
        return (sum(values) if self.additive else max(values, default=0)) if values else 0

    def estimate_with_preferred(self, state: LiftedState) -> tuple[float, Sequence[ActionInstance]]:
        return self.estimate(state), ()


class LiftedAdditive(Configurable):
    """hadd over the lifted task (see the ground ``hadd``). Not admissible."""

    name: ClassVar[str] = "hadd"
    admissible: ClassVar[bool] = False

    def for_task(self, task: PddlTask) -> CostEstimator:
        return CostEstimator(Program(task), additive=True)


class LiftedMax(Configurable):
    """hmax over the lifted task (see the ground ``hmax``). Admissible."""

    name: ClassVar[str] = "hmax"
    admissible: ClassVar[bool] = True

    def for_task(self, task: PddlTask) -> CostEstimator:
        return CostEstimator(Program(task), additive=False)


class FFEstimator:
    """hFF from hadd best supporters; preferred operators are the relaxed plan's action
    instances applicable in the state, useful atoms the facts it achieves
    (:class:`~strips_framework.lifted.components.Guidance`)."""

    def __init__(self, program: Program) -> None:
        self.program = program
        self.exploration = Exploration(program)
        self.closure = DerivedClosure(program)

    def estimate(self, state: LiftedState) -> float:
        cost, supporter = self.exploration.costs(state, additive=True)
        return relaxed_plan(self.program, cost, supporter)[0]

    def estimate_with_preferred(self, state: LiftedState) -> tuple[float, Sequence[ActionInstance]]:
        cost, supporter = self.exploration.costs(state, additive=True)
        value, plan = relaxed_plan(self.program, cost, supporter)
        return value, self._preferred(state, plan)

    def estimate_with_guidance(self, state: LiftedState) -> Guidance:
        """The estimate, the preferred instances and the useful atoms: the facts the
        relaxed plan achieves, but for derived ones (axioms' heads, the normalizer's
        auxiliary atoms, the goal's), which no state holds."""
        cost, supporter = self.exploration.costs(state, additive=True)
        achieved: set[GroundAtom] = set()
        value, plan = relaxed_plan(self.program, cost, supporter, achieved=achieved)
        derived = self.program.derived
        useful = frozenset(fact for fact in achieved if fact[0] not in derived)
        return Guidance(value, self._preferred(state, plan), useful)

    def _preferred(self, state: LiftedState, plan: dict[tuple, Supporter]) -> list[ActionInstance]:
        """The relaxed plan's action instances applicable in ``state``."""
        if not plan:
            return []
        model = self.closure.model(state)
        preferred = set()
        for rule, body, slots in plan.values():
            if rule.action == AXIOM or not all(fact in model for fact in body):
                continue
            if any((name, *[slots[s] for s in terms]) in model for name, terms in rule.negative):
                continue
            preferred.add(action_instance(self.program, rule, slots))
        return sorted(preferred)


class LiftedFF(Configurable):
    """hFF over the lifted task, with preferred operators (see the ground ``ff``). Not
    admissible."""

    name: ClassVar[str] = "ff"
    capabilities: ClassVar[frozenset[str]] = frozenset({PREFERRED_OPERATORS})
    admissible: ClassVar[bool] = False

    def for_task(self, task: PddlTask) -> FFEstimator:
        return FFEstimator(Program(task))

