"""The max heuristic hmax (Bonet & Geffner 2001).

hmax(s) is the largest goal-fact cost, where a fact in ``s`` costs 0 and any other fact
costs the minimum, over its achievers, of the achiever's cost plus its costliest
precondition. Every plan must reach the costliest goal fact through a chain of
operators at least that expensive, so hmax is admissible (and consistent).
"""

from __future__ import annotations

from typing import ClassVar

from strips_evaluators.heuristics.exploration import GoalCostEstimator, explorer
from strips_evaluators.heuristics.factoring import SHARING
from strips_evaluators.heuristics.relaxation import relax
from strips_framework.grounding.task import GroundTask
from strips_framework.options import Configurable


class MaxHeuristic(Configurable):
    """hmax: the costliest goal fact in the delete relaxation. Admissible.

    Each fact costs its cheapest achiever's cost plus the achiever's costliest
    precondition. Consistent too, but weak: it sees only the hardest goal. O(relaxed task
    size) per state: breadth-first layers that stop at the last goal fact on unit-cost
    tasks, a bucket-queue Dijkstra otherwise; no preferred operators."""

    name: ClassVar[str] = "hmax"
    admissible: ClassVar[bool] = True

    def for_task(self, task: GroundTask) -> GoalCostEstimator:
        relaxed = explorer(relax(task, factor_sharing=SHARING))
        return GoalCostEstimator(relaxed, task.goal_mask, "hmax")
