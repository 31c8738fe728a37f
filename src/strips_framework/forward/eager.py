"""Eager best-first search: A*, weighted A* and greedy best-first search.

Every successor is evaluated when it is generated and goes into the open list under its
key; the goal test is made when a state is expanded, as in Fast Downward (so A* with an
admissible heuristic returns an optimal plan, and expansion counts compare). A state met
again on a cheaper path is updated, and reopened if it was already expanded, by the
strategies that care about cost (A*, weighted A*); greedy search keeps the first path.
With ``preferred = true``, states reached by one of the expanded state's preferred
operators also go into a second open list, and the two are alternated.

The loop runs compiled (``_search.pyx``) when it is built; :meth:`EagerSearch.reference_run`
is the pure-Python reference it is compared with, which ``STRIPS_PURE_PYTHON=1`` picks.
"""

from __future__ import annotations

import math
from typing import ClassVar

from strips_framework.capabilities import ADMISSIBLE_HEURISTIC, OPTIMAL, Requirement
from strips_framework.compiled import compiled_module
from strips_framework.forward.base import ForwardStrategy, SearchRun
from strips_framework.forward.components import with_preferred
from strips_framework.forward.openlists import open_list
from strips_framework.forward.space import NO_PARENT
from strips_framework.options import Option


class EagerSearch(ForwardStrategy):
    #: Whether a cheaper path to a known state replaces the old one (and reopens it).
    reopen: ClassVar[bool]
    preferred: bool = False
    boost: int = 0

    def key(self, g: float, h: float) -> object:
        """The open-list key of a state with path cost ``g`` and estimate ``h``."""
        raise NotImplementedError

    def run(self, run: SearchRun) -> int | None:
        module = compiled_module("strips_framework.forward._search")
        if module is None:
            return self.reference_run(run)
        preferred_of = with_preferred(run.estimator) if self.preferred else None
        return module.eager(
            run, run.estimator.estimate, preferred_of, self.key, self.reopen, self.boost
        )

    def reference_run(self, run: SearchRun) -> int | None:
        """The search in Python (the compiled loop's reference)."""
        task, space, budget = run.task, run.space, run.budget
        estimate = run.estimator.estimate
        preferred_of = with_preferred(run.estimator) if self.preferred else None
        applicable, successor = space.successors.applicable, space.successor
        find, state_of, costs, goal = space.number, space.state, space.costs, task.goal_mask
        key, reopen = self.key, self.reopen
        frontier = open_list(self.preferred, self.boost)
        h0 = estimate(task.init)
        run.evaluated += 1
        if h0 == math.inf:
            run.dead_ends += 1
            return None
        space.add(task.init, NO_PARENT, NO_PARENT)
        g, h, closed = [0], [h0], bytearray(1)
        frontier.push(key(0, h0), 0)
        best_h = h0
        while frontier:
            number = frontier.pop()
            if closed[number]:
                continue
            closed[number] = 1
            budget.check(run.expanded)
            run.expanded += 1  # counted before the goal test, as Fast Downward counts
            state = state_of(number)
            if state & goal == goal:
                return number
            preferred = frozenset(preferred_of(state)[1]) if preferred_of else frozenset()
            base = g[number]
            for op in applicable(state):
                child = successor(state, op)
                run.generated += 1
                child_g = base + costs[op]
                known = find(child)
                if known is None:
                    child_h = estimate(child)
                    run.evaluated += 1
                    space.add(child, number, op)
                    g.append(child_g)
                    h.append(child_h)
                    if child_h == math.inf:
                        run.dead_ends += 1
                        closed.append(1)
                        continue
                    closed.append(0)
                    frontier.push(key(child_g, child_h), len(g) - 1, op in preferred)
                    if child_h < best_h:
                        best_h = child_h
                        frontier.reward_progress()
                elif reopen and child_g < g[known] and h[known] != math.inf:
                    if closed[known]:
                        closed[known] = 0
                        run.reopened += 1
                    g[known] = child_g
                    space.reparent(known, number, op)
                    frontier.push(key(child_g, h[known]), known, op in preferred)
        return None


class AStarSearch(EagerSearch):
    """A*: lowest f = g + h first, then lowest h, then first in; reopens closed states.
    Optimal with an admissible heuristic."""

    name: ClassVar[str] = "astar"
    reopen: ClassVar[bool] = True
    capabilities: ClassVar[frozenset[str]] = frozenset({OPTIMAL})
    requires: ClassVar[tuple[Requirement, ...]] = (ADMISSIBLE_HEURISTIC,)

    def key(self, g: float, h: float) -> object:
        return (g + h, h)


class WeightedAStarSearch(EagerSearch):
    """Weighted A*: lowest g + weight * h first, then lowest h, then first in.

    With an admissible heuristic, plans cost at most ``weight`` times the optimum."""

    name: ClassVar[str] = "wastar"
    reopen: ClassVar[bool] = True
    options = (Option("weight", float, 2.0, minimum=1, doc="the weight of h in g + weight * h"),)
    weight: float

    def key(self, g: float, h: float) -> object:
        return (g + self.weight * h, h)


class GreedySearch(EagerSearch):
    """Eager greedy best-first search: lowest h first, then first in.

    With ``preferred``, alternates with a list of the states reached by preferred
    operators, which gets ``boost`` extra turns whenever h reaches a new low."""

    name: ClassVar[str] = "gbfs"
    reopen: ClassVar[bool] = False
    options = (
        Option("preferred", bool, True, doc="a second open list for preferred operators"),
        Option("boost", int, 0, minimum=0, doc="extra turns of that list on progress"),
    )

    def key(self, g: float, h: float) -> object:
        return h
