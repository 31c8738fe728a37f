"""The additive heuristic hadd (Bonet & Geffner 2001), and the exploration hFF shares.

hadd(s) is the sum over goal facts of their cost, where a fact in ``s`` costs 0 and any
other fact costs the minimum, over its achievers, of the achiever's cost plus the sum of
its preconditions' costs. It counts shared subgoals once per use, so it overestimates:
informative for greedy search, not admissible.
"""

from __future__ import annotations

from heapq import heappop, heappush
from typing import ClassVar

from attrs import frozen

from strips_evaluators.heuristics.factoring import SHARING
from strips_evaluators.heuristics.relaxation import RelaxedTask, relax, start_exploration
from strips_framework.grounding.task import GroundTask

#: ``supporter`` entry of a fact that holds in the state (nothing achieves it).
IN_STATE = -1


def additive_exploration(relaxed: RelaxedTask, state: int) -> tuple[list[float], list[int]]:
    """Fact costs and best supporters under hadd, by a generalized Dijkstra from ``state``.

    A fact's cost is final when its bucket is taken, so the exploration stops once every
    goal fact has been taken; costs of facts not yet settled then are upper bounds, and
    unreached facts cost ``math.inf``. ``supporter[f]`` is the relaxed operator that gave
    ``f`` its cost (the first to reach the minimum), :data:`IN_STATE` for state facts.

    The queue is a dict of buckets (one list of facts per cost) with a heap of the costs
    that have a bucket: most pushes are a list append, and the heap only sees each
    distinct cost once. Facts reached at the cost being taken (by a zero-cost operator)
    go to a new bucket of that cost, taken next.
    """
    pre_of, add, is_goal = relaxed.pre_of, relaxed.add, relaxed.is_goal
    start, cost = start_exploration(relaxed, state)
    supporter = [IN_STATE] * relaxed.num_facts
    accumulator = relaxed.accumulator[:]
    bits = relaxed.count_bits
    left_mask = (1 << bits) - 1
    buckets = {0: start}
    levels = [0]
    goals_left = len(relaxed.goal)
    while levels:
        level = heappop(levels)
        # Adds the fact's cost and counts one precondition off, in one step.
        increment = (level << bits) - 1
        for fact in buckets.pop(level):
            if cost[fact] != level:
                continue  # reached more cheaply after it was put in this bucket
            if is_goal[fact]:
                goals_left -= 1
                if not goals_left:
                    return cost, supporter
            for op in pre_of[fact]:
                packed = accumulator[op] + increment
                accumulator[op] = packed
                if not packed & left_mask:
                    value = packed >> bits
                    for effect in add[op]:
                        if value < cost[effect]:
                            cost[effect] = value
                            supporter[effect] = op
                            bucket = buckets.setdefault(value, [])
                            if not bucket:
                                heappush(levels, value)
                            bucket.append(effect)
    return cost, supporter


@frozen
class AdditiveEstimator:
    relaxed: RelaxedTask
    goal_mask: int

    def estimate(self, state: int) -> float:
        if state & self.goal_mask == self.goal_mask:
            return 0
        cost, _ = additive_exploration(self.relaxed, state)
        return sum(cost[fact] for fact in self.relaxed.goal)

    def estimate_with_preferred(self, state: int) -> tuple[float, tuple[int, ...]]:
        return self.estimate(state), ()


@frozen
class AdditiveHeuristic:
    """hadd: the sum of the goal facts' relaxed costs. Not admissible.

    Each fact costs its cheapest achiever's cost plus the sum of its preconditions'
    costs, so shared subgoals are paid once per use. O(relaxed task size) per state (a
    bucket-queue Dijkstra over facts); no preferred operators (``ff`` has them)."""

    name: ClassVar[str] = "hadd"
    admissible: ClassVar[bool] = False

    def for_task(self, task: GroundTask) -> AdditiveEstimator:
        return AdditiveEstimator(relax(task, factor_sharing=SHARING), task.goal_mask)
