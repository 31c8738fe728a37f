"""The goal-count heuristic: how many goal facts the state lacks."""

from __future__ import annotations

from typing import ClassVar

from strips_framework.grounding.task import GroundTask
from strips_framework.options import Configurable
from strips_framework.records import Record


class GoalCountEstimator(Record):
    """Counts the goal facts a state holds and subtracts them from the goal's size:
    ``goal_mask & state`` is as long as the goal mask, while the count of what is
    missing, ``goal_mask & ~state``, complements the whole state first (a negative
    int), a cost that grows with the task's facts, not with its goal."""

    goal_mask: int

    FIELDS = ("goal_mask",)
    __slots__ = (*FIELDS, "_goals")

    def __init__(self, goal_mask: int) -> None:
        self.goal_mask = goal_mask
        self._goals = goal_mask.bit_count()

    def estimate(self, state: int) -> float:
        return self._goals - (self.goal_mask & state).bit_count()

    def estimate_with_preferred(self, state: int) -> tuple[float, tuple[int, ...]]:
        return self._goals - (self.goal_mask & state).bit_count(), ()


class GoalCountHeuristic(Configurable):
    """Goal count: the goal facts false in the state. Not admissible.

    One bit count per state, so the cheapest informed heuristic. It overestimates when one
    operator adds several goal facts and ignores operator costs; it never detects dead
    ends and has no preferred operators."""

    name: ClassVar[str] = "goal-count"
    admissible: ClassVar[bool] = False

    def for_task(self, task: GroundTask) -> GoalCountEstimator:
        return GoalCountEstimator(task.goal_mask)
