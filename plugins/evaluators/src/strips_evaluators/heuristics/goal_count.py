"""The goal-count heuristic: how many goal facts the state lacks."""

from __future__ import annotations

from collections.abc import Callable
from typing import ClassVar

from strips_framework.forward.packing import held_counter
from strips_framework.grounding.task import GroundTask
from strips_framework.options import Configurable
from strips_framework.records import Record


class GoalCountEstimator(Record):
    """Counts the goal facts a state holds and subtracts them from the goal's size. The
    count reads the goal's facts one by one (:func:`held_counter`, compiled): a mask
    operation, ``goal_mask & state``, costs as much as the mask is long, up to the
    highest goal fact's number (20 µs a state at 800,000 facts for a goal of three), and
    the count of what is missing, ``goal_mask & ~state``, complements the whole state
    first (a negative int). It reads a state's packing as well (``reads_packed``), so a
    packed state space's lazy search never makes the bitset for it."""

    reads_packed: ClassVar[bool] = True
    goal: tuple[int, ...]

    FIELDS = ("goal",)
    __slots__ = (*FIELDS, "_goals", "_held")

    def __init__(self, goal: tuple[int, ...]) -> None:
        self.goal = tuple(sorted(set(goal)))
        self._goals = len(self.goal)
        self._held: Callable[[int | bytes], int] = held_counter(self.goal)

    def estimate(self, state: int | bytes) -> float:
        return self._goals - self._held(state)

    def estimate_with_preferred(self, state: int | bytes) -> tuple[float, tuple[int, ...]]:
        return self._goals - self._held(state), ()


class GoalCountHeuristic(Configurable):
    """Goal count: the goal facts false in the state. Not admissible.

    One bit count per state, so the cheapest informed heuristic. It overestimates when one
    operator adds several goal facts and ignores operator costs; it never detects dead
    ends and has no preferred operators."""

    name: ClassVar[str] = "goal-count"
    admissible: ClassVar[bool] = False

    def for_task(self, task: GroundTask) -> GoalCountEstimator:
        return GoalCountEstimator(task.goal)
