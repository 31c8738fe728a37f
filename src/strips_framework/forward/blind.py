"""The blind heuristic: no guidance, but a valid lower bound.

A builtin (the other state heuristics come from strips-evaluators), so that the core
alone runs every ground-task strategy: breadth-first, which ignores its heuristic, and A*
as uniform-cost search."""

from __future__ import annotations

import math
from typing import ClassVar

from strips_framework.grounding.task import GroundTask
from strips_framework.options import Configurable
from strips_framework.records import Record


class BlindEstimator(Record):
    goal_mask: int
    #: What any step from a non-goal state costs at least (``math.inf`` with no operators).
    min_cost: float

    __slots__ = ("goal_mask", "min_cost")

    def __init__(self, goal_mask: int, min_cost: float) -> None:
        self.goal_mask = goal_mask
        self.min_cost = min_cost

    def estimate(self, state: int) -> float:
        return 0 if state & self.goal_mask == self.goal_mask else self.min_cost

    def estimate_with_preferred(self, state: int) -> tuple[float, tuple[int, ...]]:
        return self.estimate(state), ()


class BlindHeuristic(Configurable):
    """Blind: 0 at a goal, else the cheapest operator's cost. Admissible, no guidance.

    A non-goal state needs at least one more step, so the cheapest operator's cost (1 on
    unit-cost tasks) is a lower bound; it is also consistent. A* with it is uniform-cost
    search, the baseline the informed heuristics are measured against."""

    name: ClassVar[str] = "blind"
    admissible: ClassVar[bool] = True

    def for_task(self, task: GroundTask) -> BlindEstimator:
        min_cost = min((op.cost for op in task.operators), default=math.inf)
        return BlindEstimator(task.goal_mask, min_cost)
