"""The FF heuristic (Hoffmann & Nebel 2001) with hadd best supporters, as in Fast Downward.

A relaxed plan is extracted backwards from the goal: each goal fact not in the state is
achieved by its best supporter under hadd, whose preconditions become subgoals in turn.
hFF is the total cost of the distinct operators in that plan (an operator used for
several of its conditional effects counts once). Preferred operators are the relaxed
plan's operators applicable in the state (with the condition of the effect the plan uses):
they start a relaxed plan, so they are the moves most likely to make progress (FF's
"helpful actions").
"""

from __future__ import annotations

from typing import ClassVar


from strips_evaluators.heuristics.exploration import Explorer, explorer
from strips_evaluators.heuristics.factoring import SHARING
from strips_evaluators.heuristics.relaxation import relax
from strips_framework.capabilities import PREFERRED_OPERATORS
from strips_framework.grounding.task import GroundTask
from strips_framework.options import Configurable
from strips_framework.records import Record


class FFEstimator(Record):
    explorer: Explorer
    goal_mask: int

    __slots__ = ("explorer", "goal_mask")

    def __init__(self, explorer: Explorer, goal_mask: int) -> None:
        self.explorer = explorer
        self.goal_mask = goal_mask

    def estimate(self, state: int) -> float:
        if state & self.goal_mask == self.goal_mask:
            return 0
        return self.explorer.relaxed_plan(state)[0]

    def estimate_with_preferred(self, state: int) -> tuple[float, list[int]]:
        if state & self.goal_mask == self.goal_mask:
            return 0, []
        return self.explorer.preferred(state)


class FFHeuristic(Configurable):
    """hFF: cost of a relaxed plan from hadd best supporters; preferred operators.

    As Fast Downward's ``ff()``: each operator of the relaxed plan counts once, so it is
    much closer to the real cost than hadd, though not admissible. Preferred operators are
    the relaxed plan's operators applicable in the state. O(relaxed task size) per state
    (the hadd exploration, then a walk over the relaxed plan)."""

    name: ClassVar[str] = "ff"
    capabilities: ClassVar[frozenset[str]] = frozenset({PREFERRED_OPERATORS})
    admissible: ClassVar[bool] = False

    def for_task(self, task: GroundTask) -> FFEstimator:
        return FFEstimator(explorer(relax(task, factor_sharing=SHARING)), task.goal_mask)
