"""The FF heuristic (Hoffmann & Nebel 2001) with hadd best supporters, as in Fast Downward.

A relaxed plan is extracted backwards from the goal: each goal fact not in the state is
achieved by its best supporter under hadd, whose preconditions become subgoals in turn.
hFF is the total cost of the distinct operators in that plan. Preferred operators are
the relaxed plan's operators applicable in the state: they start a relaxed plan, so
they are the moves most likely to make progress (FF's "helpful actions").
"""

from __future__ import annotations

from typing import ClassVar

from attrs import frozen

from strips_evaluators.heuristics.additive import additive_exploration
from strips_evaluators.heuristics.factoring import SHARING
from strips_evaluators.heuristics.relaxation import RelaxedTask, relax
from strips_framework.capabilities import PREFERRED_OPERATORS
from strips_framework.grounding.task import GroundTask


@frozen
class FFEstimator:
    relaxed: RelaxedTask
    goal_mask: int
    #: Per relaxed operator: the real operator's precondition and negative-precondition
    #: masks (0 for axioms and conjunctions), to keep only the really applicable ones as
    #: preferred.
    pre_masks: list[int]
    neg_masks: list[int]

    def estimate(self, state: int) -> float:
        return self._relaxed_plan(state)[0]

    def estimate_with_preferred(self, state: int) -> tuple[float, list[int]]:
        value, plan = self._relaxed_plan(state)
        if not plan:
            return value, []
        operator, pre_masks, neg_masks = self.relaxed.operator, self.pre_masks, self.neg_masks
        preferred = [
            operator[op]
            for op in plan
            if operator[op] >= 0
            and state & pre_masks[op] == pre_masks[op]
            and not state & neg_masks[op]
        ]
        preferred.sort()
        return value, preferred

    def _relaxed_plan(self, state: int) -> tuple[float, set[int]]:
        """hFF and the relaxed operators of the relaxed plan (empty at goals and dead ends)."""
        if state & self.goal_mask == self.goal_mask:
            return 0, set()
        relaxed = self.relaxed
        cost, supporter = additive_exploration(relaxed, state)
        goal = relaxed.goal
        for fact in goal:
            if cost[fact] == float("inf"):
                return float("inf"), set()
        pre, op_cost = relaxed.pre, relaxed.cost
        plan: set[int] = set()
        total = 0
        subgoals = list(goal)
        while subgoals:
            op = supporter[subgoals.pop()]
            if op < 0 or op in plan:
                continue
            plan.add(op)
            total += op_cost[op]
            subgoals.extend(pre[op])
        return total, plan


@frozen
class FFHeuristic:
    """hFF: cost of a relaxed plan from hadd best supporters; preferred operators.

    As Fast Downward's ``ff()``: each operator of the relaxed plan counts once, so it is
    much closer to the real cost than hadd, though not admissible. Preferred operators are
    the relaxed plan's operators applicable in the state. O(relaxed task size) per state
    (the hadd exploration, then a walk over the relaxed plan)."""

    name: ClassVar[str] = "ff"
    capabilities: ClassVar[frozenset[str]] = frozenset({PREFERRED_OPERATORS})
    admissible: ClassVar[bool] = False

    def for_task(self, task: GroundTask) -> FFEstimator:
        relaxed = relax(task, factor_sharing=SHARING)
        operators = task.operators
        pre_masks = [operators[i].pre_mask if i >= 0 else 0 for i in relaxed.operator]
        neg_masks = [operators[i].pre_neg_mask if i >= 0 else 0 for i in relaxed.operator]
        return FFEstimator(relaxed, task.goal_mask, pre_masks, neg_masks)
