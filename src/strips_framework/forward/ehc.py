"""Enforced hill-climbing (Hoffmann & Nebel's FF; Fast Downward's ``ehc``).

From the current state, a breadth-first search looks for any state with a strictly lower
estimate, then makes that state current and starts again, until a goal state is current.
With ``preferred = true`` (helpful actions) each breadth-first search follows only the
preferred operators of the states it expands, which is what makes the method fast, and
incomplete: when a breadth-first search runs out, the whole search gives up
(``exhausted``). A state for which the heuristic names no preferred operators
(every state, for heuristics that have none) has all its applicable operators followed,
as Fast Downward does without preferred-operator heuristics. States are never visited twice, across phases too.
"""

from __future__ import annotations

import math
from collections import deque
from collections.abc import Sequence
from typing import ClassVar

from strips_framework.forward.base import ForwardStrategy, SearchRun
from strips_framework.forward.components import with_preferred
from strips_framework.forward.space import NO_PARENT
from strips_framework.options import Option


class EnforcedHillClimbing(ForwardStrategy):
    """Enforced hill-climbing (FF): breadth-first to a better state, then commit to it.

    With ``preferred``, only along the heuristic's helpful actions. Incomplete."""

    name: ClassVar[str] = "ehc"
    complete: ClassVar[bool] = False
    options = (Option("preferred", bool, True, doc="follow only the helpful actions"),)
    preferred: bool

    def run(self, run: SearchRun) -> int | None:
        task, space, budget = run.task, run.space, run.budget
        evaluate = with_preferred(run.estimator)
        applicable, successor = space.successors.applicable, space.successor
        find, state_of, goal = space.number, space.state, task.goal_mask
        current = space.add(task.init, NO_PARENT, NO_PARENT)
        current_h, current_preferred = evaluate(task.init)
        run.evaluated += 1
        if current_h == math.inf:
            run.dead_ends += 1
            return None
        while True:
            if state_of(current) & goal == goal:
                return current
            # One phase: breadth-first from the current state to a strictly better one.
            waiting: deque[tuple[int, Sequence[int]]] = deque([(current, current_preferred)])
            better = None
            while waiting and better is None:
                number, preferred = waiting.popleft()
                state = state_of(number)
                budget.check(run.expanded)
                run.expanded += 1
                helpful = self.preferred and preferred
                for op in sorted(set(preferred)) if helpful else applicable(state):
                    child = successor(state, op)
                    run.generated += 1
                    if find(child) is not None:
                        continue
                    child_number = space.add(child, number, op)
                    h, child_preferred = evaluate(child)
                    run.evaluated += 1
                    if h == math.inf:
                        run.dead_ends += 1
                    elif h < current_h:
                        better = (child_number, h, child_preferred)
                        break
                    else:
                        waiting.append((child_number, child_preferred))
            if better is None:
                return None
            current, current_h, current_preferred = better
