"""The lifted goal-count heuristic: how many goal atoms a state lacks. It needs nothing
but the goal, so the core's lifted search has a heuristic without any plugin installed
(the relaxation heuristics, hadd, hmax and hFF, come with the evaluators plugin).
:class:`GoalLiterals` is the count itself, which ``lifted-alt-bfws`` also keeps for
every state it generates, updated from the parent's by the atoms an action changed."""

from __future__ import annotations

from collections.abc import Collection, Sequence
from typing import ClassVar

from strips_framework.lifted.components import ActionInstance, GroundAtom, LiftedState
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


class GoalLiterals:
    """The goal as ground literals over the state's atoms, when it is one conjunction of
    ground atoms and negated ground atoms of predicates that are not derived
    (``simple``); then a state reaches the goal exactly when it lacks none of them.
    Static literals are settled once: ``unreachable`` when one is false in the task
    (or the goal is an empty disjunction), left out of the count otherwise."""

    def __init__(self, task: LiftedTask) -> None:
        goal = task.goal
        query = goal[0] if len(goal) == 1 else None
        self.simple = (
            query is not None
            and not query.distinct
            and all(
                not any(is_variable(a) for a in atom.args) and atom.predicate not in task.derived
                for atom in (*query.positive, *query.negative)
            )
        )
        self.positive: frozenset[GroundAtom] = frozenset()
        self.negative: frozenset[GroundAtom] = frozenset()
        self.unreachable = not goal
        if query is not None and self.simple:
            static = task.static_atoms
            positive = [(a.predicate, *a.args) for a in query.positive]
            negative = [(a.predicate, *a.args) for a in query.negative]
            self.positive = frozenset(a for a in positive if a[0] not in task.static)
            self.negative = frozenset(a for a in negative if a[0] not in task.static)
            self.unreachable = any(
                a[0] in task.static and a not in static for a in positive
            ) or any(a[0] in task.static and a in static for a in negative)

    def missing(self, state: Collection[GroundAtom]) -> int:
        """How many of the (fluent) literals ``state`` falsifies; ``simple`` goals only."""
        return sum(1 for atom in self.positive if atom not in state) + sum(
            1 for atom in self.negative if atom in state
        )

    def change(self, removed: Collection[GroundAtom], added: Collection[GroundAtom]) -> int:
        """How many more literals a state falsifies after losing ``removed`` (atoms it
        held) and gaining ``added`` (atoms it lacked): :meth:`missing` of the successor
        minus the parent's, in time linear in the change."""
        positive, negative = self.positive, self.negative
        # Intersections iterate the smaller side: the change, not the goal.
        change = len(positive.intersection(removed)) - len(positive.intersection(added))
        if negative:
            change += len(negative.intersection(added)) - len(negative.intersection(removed))
        return change


class _GoalCountEstimator:
    def __init__(self, task: LiftedTask) -> None:
        self.goal = GoalLiterals(task)
        self.successors = None if self.goal.simple else Successors(task)

    def estimate(self, state: LiftedState) -> float:
        if self.goal.unreachable:
            return float("inf")
        if self.successors is not None:
            return 0.0 if self.successors.is_goal(self.successors.facts(state)) else 1.0
        return float(self.goal.missing(state))

    def estimate_with_preferred(self, state: LiftedState) -> tuple[float, Sequence[ActionInstance]]:
        return self.estimate(state), ()
