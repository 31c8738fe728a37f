"""The relaxed explorations behind hadd, hFF and hmax (and LM-cut's hmax), and which
implementation runs them per state.

The functions here are the pure-Python reference. When the compiled module
(``_explore.pyx``, built by ``pip install`` with Cython) is importable, :func:`explorer`
gives its :class:`Explorer` instead: the same algorithms over C arrays, with the same
supporters, relaxed plans and values (``tests/test_compiled.py`` compares them state by
state and search by search). ``STRIPS_PURE_PYTHON=1`` in the environment picks the
reference anyway. LM-cut has its compiled counterpart there too (``_explore.LMCut``);
the landmark-count heuristic runs the reference only.
"""

from __future__ import annotations

import math
from heapq import heappop, heappush
from types import ModuleType
from typing import Protocol

from strips_evaluators.heuristics.relaxation import RelaxedTask, start_exploration
from strips_framework.allocation import collection_paused
from strips_framework.compiled import compiled_module as shared_compiled_module
from strips_framework.records import Record


class Explorer(Protocol):
    """Per-state relaxed values of one relaxed task (goal states are the caller's)."""

    def hadd(self, state: int) -> float: ...

    def hmax(self, state: int) -> float: ...

    def relaxed_plan(self, state: int) -> tuple[float, list[int]]: ...

    def preferred(self, state: int) -> tuple[float, list[int]]: ...


class GoalCostEstimator(Record):
    """A state's estimate as one of an :class:`Explorer`'s goal costs, named by
    ``measure`` (``"hadd"`` or ``"hmax"``): 0 at a goal state, which the explorer leaves to
    its caller. hadd and hmax differ only in how the explorer combines costs, so they share
    this estimator; neither has preferred operators (``ff`` has them)."""

    explorer: Explorer
    goal_mask: int
    measure: str

    __slots__ = ("explorer", "goal_mask", "measure")

    def __init__(self, explorer: Explorer, goal_mask: int, measure: str) -> None:
        self.explorer = explorer
        self.goal_mask = goal_mask
        self.measure = measure

    def estimate(self, state: int) -> float:
        if state & self.goal_mask == self.goal_mask:
            return 0
        cost: float = getattr(self.explorer, self.measure)(state)
        return cost

    def estimate_with_preferred(self, state: int) -> tuple[float, tuple[int, ...]]:
        return self.estimate(state), ()


def compiled_module(compiled: bool | None = None) -> ModuleType | None:
    """The compiled module when it is built (see
    :func:`strips_framework.compiled.compiled_module` for ``compiled``), else ``None``."""
    return shared_compiled_module("strips_evaluators.heuristics._explore", compiled)


@collection_paused()
def explorer(relaxed: RelaxedTask, compiled: bool | None = None) -> Explorer:
    """The compiled explorer of ``relaxed`` (see :func:`compiled_module`), else the
    pure-Python one."""
    module = compiled_module(compiled)
    return PythonExplorer(relaxed) if module is None else module.Explorer(relaxed)


class PythonExplorer:
    """The reference :class:`Explorer`: the functions of this module."""

    def __init__(self, relaxed: RelaxedTask) -> None:
        self.relaxed = relaxed

    def hadd(self, state: int) -> float:
        cost, _ = additive_exploration(self.relaxed, state)
        return sum(cost[fact] for fact in self.relaxed.goal)

    def hmax(self, state: int) -> float:
        relaxed = self.relaxed
        if relaxed.unit_cost:
            return unit_cost_hmax(relaxed, state)
        unused = [0] * len(relaxed.pre)
        cost = max_exploration(relaxed, state, relaxed.cost, unused, unused[:])
        return max(cost[fact] for fact in relaxed.goal)

    def relaxed_plan(self, state: int) -> tuple[float, list[int]]:
        value, plan = relaxed_plan(self.relaxed, state)
        return value, list(plan)

    def preferred(self, state: int) -> tuple[float, list[int]]:
        """hFF and the real operators of the relaxed plan whose relaxed operator's
        precondition (with the effect's condition) holds in ``state``, ascending."""
        value, plan = relaxed_plan(self.relaxed, state)
        relaxed = self.relaxed
        operator = relaxed.operator
        chosen = {
            operator[op] for op in plan if operator[op] >= 0 and holds(relaxed, op, state)
        }
        return value, sorted(chosen)


def holds(relaxed: RelaxedTask, op: int, state: int) -> bool:
    """Whether relaxed operator ``op``'s precondition (with its effect's condition) holds
    in ``state``, negative facts included."""
    return all(state >> fact & 1 for fact in relaxed.need[op]) and not any(
        state >> fact & 1 for fact in relaxed.lack[op]
    )


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
    distinct cost once. A bucket is a stack, last in first out, as Fast Downward's bucket
    queue is: among facts of equal cost the one reached last goes first (a fact reached
    at the cost being taken, by a zero-cost operator, comes out next), and the state's
    facts go in in causal-graph order (:mod:`.causal_order`). The order decides
    which of several equally cheap operators becomes a supporter, and so the relaxed
    plan, the preferred operators and LM-cut's landmarks; following Fast Downward's
    order keeps search behaviour close to its (``docs/heuristics.md``).
    """
    pre_of, add, is_goal = relaxed.pre_of, relaxed.add, relaxed.is_goal
    start, cost = start_exploration(relaxed, state)
    start.sort(key=relaxed.start_rank.__getitem__)  # causal order: see .causal_order
    supporter = [IN_STATE] * relaxed.num_facts
    accumulator = relaxed.accumulator[:]
    bits = relaxed.count_bits
    left_mask = (1 << bits) - 1
    buckets = {0: start}
    levels = [0]
    goals_left = len(relaxed.goal)
    while levels:
        level = levels[0]
        # Adds the fact's cost and counts one precondition off, in one step.
        increment = (level << bits) - 1
        bucket = buckets[level]
        while bucket:
            fact = bucket.pop()
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
                            queued = buckets.get(value)
                            if queued is None:  # a stack per cost: last in, first out
                                buckets[value] = [effect]
                                heappush(levels, value)
                            else:
                                queued.append(effect)
        del buckets[level]
        heappop(levels)
    return cost, supporter


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
        level = levels[0]
        bucket = buckets[level]
        while bucket:
            fact = bucket.pop()
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
                            queued = buckets.get(reached)
                            if queued is None:
                                buckets[reached] = [effect]
                                heappush(levels, reached)
                            else:
                                queued.append(effect)
        del buckets[level]
        heappop(levels)
    return cost



def relaxed_plan(relaxed: RelaxedTask, state: int) -> tuple[float, set[int]]:
    """hFF and the relaxed operators of the relaxed plan from hadd best supporters (empty
    at relaxed dead ends); an operator used for several effects counts once."""
    cost, supporter = additive_exploration(relaxed, state)
    goal = relaxed.goal
    for fact in goal:
        if cost[fact] == float("inf"):
            return float("inf"), set()
    pre, op_cost = relaxed.pre, relaxed.cost
    plan: set[int] = set()
    total = 0
    subgoals = list(goal)
    while subgoals:
        op = supporter[subgoals.pop()]
        if op < 0 or op in plan:
            continue
        plan.add(op)
        total += op_cost[op]
        subgoals.extend(pre[op])
    if relaxed.shared_costs:
        operator = relaxed.operator
        total = sum(op_cost[first] for first in {operator[op]: op for op in plan}.values())
    return total, plan
