"""Blind breadth-first search: the reference for shortest plans.

States are expanded in the order they were reached and the goal is tested as soon as a
state is generated, so the plan found has the fewest steps (action costs are ignored).
It calls no heuristic, which makes it the yardstick that optimal searches are tested
against.
"""

from __future__ import annotations

from collections import deque
from typing import ClassVar

from strips_framework.forward.base import ForwardStrategy, SearchRun
from strips_framework.forward.space import NO_PARENT


class BreadthFirstSearch(ForwardStrategy):
    """Blind breadth-first search: a plan with the fewest steps; ignores the heuristic."""

    name: ClassVar[str] = "breadth-first"

    def run(self, run: SearchRun) -> int | None:
        task, space, budget = run.task, run.space, run.budget
        applicable, successor, find, state_of = (
            space.successors.applicable,
            space.successor,
            space.number,
            space.state,
        )
        goal = task.goal_mask
        root = space.add(task.init, NO_PARENT, NO_PARENT)
        if task.init & goal == goal:
            return root
        waiting = deque([root])
        while waiting:
            number = waiting.popleft()
            state = state_of(number)
            budget.check(run.expanded)
            run.expanded += 1
            for op in applicable(state):
                child = successor(state, op)
                run.generated += 1
                if find(child) is not None:
                    continue
                child_number = space.add(child, number, op)
                if child & goal == goal:
                    return child_number
                waiting.append(child_number)
        return None
