"""The additive heuristic hadd (Bonet & Geffner 2001).

hadd(s) is the sum over goal facts of their cost, where a fact in ``s`` costs 0 and any
other fact costs the minimum, over its achievers, of the achiever's cost plus the sum of
its preconditions' costs. It counts shared subgoals once per use, so it overestimates:
informative for greedy search, not admissible.
"""

from __future__ import annotations

from typing import ClassVar

from strips_evaluators.heuristics.exploration import GoalCostEstimator, explorer
from strips_evaluators.heuristics.factoring import SHARING
from strips_evaluators.heuristics.relaxation import relax
from strips_framework.grounding.task import GroundTask
from strips_framework.options import Configurable


class AdditiveHeuristic(Configurable):
    """hadd: the sum of the goal facts' relaxed costs. Not admissible.

    Each fact costs its cheapest achiever's cost plus the sum of its preconditions'
    costs, so shared subgoals are paid once per use. O(relaxed task size) per state (a
    bucket-queue Dijkstra over facts); no preferred operators (``ff`` has them)."""

    name: ClassVar[str] = "hadd"
    admissible: ClassVar[bool] = False

    def for_task(self, task: GroundTask) -> GoalCostEstimator:
        relaxed = explorer(relax(task, factor_sharing=SHARING))
        return GoalCostEstimator(relaxed, task.goal_mask, "hadd")
