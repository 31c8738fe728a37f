"""The lifted goal-count heuristic: how many goal atoms a state lacks. It needs nothing
but the goal, so the core's lifted search has a heuristic without any plugin installed
(the relaxation heuristics, hadd, hmax and hFF, come with the evaluators plugin)."""

from __future__ import annotations

from collections.abc import Sequence
from typing import ClassVar

from strips_framework.lifted.components import ActionInstance, LiftedState
from strips_framework.lifted.successors import Successors
from strips_framework.lifted.task import LiftedTask, is_variable
from strips_framework.pddl.task import PddlTask


class LiftedGoalCount:
    """Goal atoms false in the state (negated ones true), for a goal that is one
    conjunction of ground literals over the state's predicates; for any other goal, 0
    when it holds and 1 when not. Not admissible (one action may reach several)."""

    name: ClassVar[str] = "goal-count"
    admissible: ClassVar[bool] = False
    capabilities: ClassVar[frozenset[str]] = frozenset()

    def for_task(self, task: PddlTask) -> _GoalCountEstimator:
        return _GoalCountEstimator(LiftedTask(task))


class _GoalCountEstimator:
    def __init__(self, task: LiftedTask) -> None:
        self.positive: tuple[tuple[str, ...], ...] = ()
        self.negative: tuple[tuple[str, ...], ...] = ()
        self.successors: Successors | None = None
        goal = task.goal
        query = goal[0] if len(goal) == 1 else None
        simple = query is not None and not query.distinct and all(
            not any(is_variable(a) for a in atom.args) and atom.predicate not in task.derived
            for atom in (*query.positive, *query.negative)
        )
        if query is not None and simple:
            static = task.static_atoms
            fluent = lambda atom: atom.predicate not in task.static  # noqa: E731
            self.positive = tuple((a.predicate, *a.args) for a in query.positive if fluent(a))
            self.negative = tuple((a.predicate, *a.args) for a in query.negative if fluent(a))
            unreachable = [a for a in query.positive if not fluent(a) and (a.predicate, *a.args) not in static]
            self.dead = bool(unreachable) or not goal
        else:
            self.dead = not goal
            self.successors = Successors(task)

    def estimate(self, state: LiftedState) -> float:
        if self.dead:
            return float("inf")
        if self.successors is not None:
            return 0.0 if self.successors.is_goal(self.successors.facts(state)) else 1.0
        missing = sum(1 for atom in self.positive if atom not in state)
        return float(missing + sum(1 for atom in self.negative if atom in state))

    def estimate_with_preferred(self, state: LiftedState) -> tuple[float, Sequence[ActionInstance]]:
        return self.estimate(state), ()
