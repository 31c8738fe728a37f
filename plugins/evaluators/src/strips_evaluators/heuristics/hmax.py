"""The max heuristic hmax (Bonet & Geffner 2001).

hmax(s) is the largest goal-fact cost, where a fact in ``s`` costs 0 and any other fact
costs the minimum, over its achievers, of the achiever's cost plus its costliest
precondition. Every plan must reach the costliest goal fact through a chain of
operators at least that expensive, so hmax is admissible (and consistent).
"""

from __future__ import annotations

import math
from heapq import heappop, heappush
from typing import ClassVar

from attrs import frozen

from strips_evaluators.heuristics.factoring import SHARING
from strips_evaluators.heuristics.relaxation import RelaxedTask, relax, start_exploration
from strips_framework.grounding.task import GroundTask


def unit_cost_hmax(relaxed: RelaxedTask, state: int) -> float:
    """hmax when operators cost 1 and axioms 0: breadth-first over fact layers.

    Layer ``k`` holds the facts of cost ``k``; an operator fires when its last
    precondition is reached, and that precondition's layer is its costliest. Facts an
    axiom reaches join the current layer (the loop sees items appended while it runs).
    Stops as soon as the last goal fact is reached.
    """
    pre_of, add, op_cost, is_goal = relaxed.pre_of, relaxed.add, relaxed.cost, relaxed.is_goal
    layer, cost = start_exploration(relaxed, state)
    remaining = relaxed.pre_count[:]
    goals_left = len(relaxed.goal)
    depth = 0
    while layer:
        following: list[int] = []
        for fact in layer:
            if cost[fact] != depth:
                continue  # reached again, more cheaply, by an axiom
            if is_goal[fact]:
                goals_left -= 1
                if not goals_left:
                    return depth
            for op in pre_of[fact]:
                left = remaining[op] - 1
                remaining[op] = left
                if not left:
                    if op_cost[op]:
                        target, reached = following, depth + 1
                    else:
                        target, reached = layer, depth
                    for effect in add[op]:
                        if reached < cost[effect]:
                            cost[effect] = reached
                            target.append(effect)
        layer = following
        depth += 1
    return math.inf


def max_exploration(
    relaxed: RelaxedTask,
    state: int,
    op_cost: list[int],
    supporter: list[int],
    supporter_cost: list[int],
) -> list[float]:
    """hmax of every fact under ``op_cost`` (any non-negative integers), by a Dijkstra over
    facts with a bucket queue as in :func:`~strips_evaluators.heuristics.additive.additive_exploration`.
    The last precondition of an operator to leave the queue is its costliest: it
    becomes the operator's ``supporter``, with its cost in ``supporter_cost`` (LM-cut
    needs both; operators never reached keep their entries)."""
    add, pre_of = relaxed.add, relaxed.pre_of
    start, cost = start_exploration(relaxed, state)
    remaining = relaxed.pre_count[:]
    buckets = {0: start}
    levels = [0]
    while levels:
        level = heappop(levels)
        for fact in buckets.pop(level):
            if cost[fact] != level:
                continue
            for op in pre_of[fact]:
                left = remaining[op] - 1
                remaining[op] = left
                if not left:
                    supporter[op] = fact
                    supporter_cost[op] = level
                    reached = level + op_cost[op]
                    for effect in add[op]:
                        if reached < cost[effect]:
                            cost[effect] = reached
                            bucket = buckets.setdefault(reached, [])
                            if not bucket:
                                heappush(levels, reached)
                            bucket.append(effect)
    return cost


@frozen
class MaxEstimator:
    relaxed: RelaxedTask
    goal_mask: int

    def estimate(self, state: int) -> float:
        if state & self.goal_mask == self.goal_mask:
            return 0
        relaxed = self.relaxed
        if relaxed.unit_cost:
            return unit_cost_hmax(relaxed, state)
        unused = [0] * len(relaxed.pre)
        cost = max_exploration(relaxed, state, relaxed.cost, unused, unused[:])
        return max(cost[fact] for fact in relaxed.goal)

    def estimate_with_preferred(self, state: int) -> tuple[float, tuple[int, ...]]:
        return self.estimate(state), ()


@frozen
class MaxHeuristic:
    """hmax: the costliest goal fact in the delete relaxation. Admissible.

    Each fact costs its cheapest achiever's cost plus the achiever's costliest
    precondition. Consistent too, but weak: it sees only the hardest goal. O(relaxed task
    size) per state: breadth-first layers that stop at the last goal fact on unit-cost
    tasks, a bucket-queue Dijkstra otherwise; no preferred operators."""

    name: ClassVar[str] = "hmax"
    admissible: ClassVar[bool] = True

    def for_task(self, task: GroundTask) -> MaxEstimator:
        return MaxEstimator(relax(task, factor_sharing=SHARING), task.goal_mask)
