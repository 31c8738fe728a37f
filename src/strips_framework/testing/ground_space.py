"""Exact costs to the goal on small ground tasks, for checking heuristics and strategies.

Every state reachable from the initial one is enumerated by applying each ground operator
the plain way (:meth:`GroundOperator.applicable`, :meth:`GroundOperator.apply`, then the
axioms), without forward search's successor generator, so a wrong answer cannot come
from the code under test; the cheapest cost from each state to a goal state is then found
by Dijkstra's algorithm backwards from the goal states. That is only feasible for small
tasks, which is what the kit uses.
"""

from __future__ import annotations

import heapq
import math
from collections import defaultdict

from strips_framework.grounding.axioms import AxiomEvaluator
from strips_framework.grounding.task import GroundTask


class TooLarge(Exception):
    """The task has more reachable states than the kit explores."""


class TaskSpace:
    """The reachable states of a ground task (in the order breadth-first search meets
    them) and the cheapest cost from each to the goal (``math.inf`` for a dead end)."""

    def __init__(self, task: GroundTask, max_states: int = 20_000) -> None:
        self.task = task
        derive = AxiomEvaluator(task).evaluate if task.axioms else None
        costs = [op.cost if task.uses_costs else 1 for op in task.operators]
        self.states: list[int] = [task.init]
        predecessors: dict[int, list[tuple[int, int]]] = defaultdict(list)
        seen = {task.init}
        for state in self.states:  # grows while it is walked: breadth-first
            for index, operator in enumerate(task.operators):
                if not operator.applicable(state):
                    continue
                after = operator.apply(state)
                if derive is not None:
                    after = derive(after)
                predecessors[after].append((state, costs[index]))
                if after not in seen:
                    if len(seen) >= max_states:
                        raise TooLarge(f"{task.name}: more than {max_states} reachable states")
                    seen.add(after)
                    self.states.append(after)
        self.cost_to_go = self._dijkstra_backwards(predecessors)

    def _dijkstra_backwards(
        self, predecessors: dict[int, list[tuple[int, int]]]
    ) -> dict[int, float]:
        distance: dict[int, float] = dict.fromkeys(self.states, math.inf)
        queue = [(0, state) for state in self.states if self.task.is_goal(state)]
        for _, state in queue:
            distance[state] = 0
        heapq.heapify(queue)
        while queue:
            cost, state = heapq.heappop(queue)
            if cost > distance[state]:
                continue
            for before, step in predecessors[state]:
                if cost + step < distance[before]:
                    distance[before] = cost + step
                    heapq.heappush(queue, (cost + step, before))
        return distance

    @property
    def optimum(self) -> float:
        """The cost of a cheapest plan (``math.inf`` when the task is unsolvable)."""
        return self.cost_to_go[self.task.init]
