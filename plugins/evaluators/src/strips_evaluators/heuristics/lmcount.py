"""The landmark-count heuristic (Richter, Helmert & Westphal 2008), evaluated per state.

Fast Downward's lmcount follows the search path: a landmark is *accepted* once some state
on the path made it true. The state-heuristic interface sees one state, so acceptance is
inferred from the state instead: the landmarks of the initial state and those true in the
state are accepted, and so is every landmark in the label of a fact true in the state,
since the labels say which landmarks every path reaches before that fact (Zhu & Givan; see
:mod:`strips_evaluators.heuristics.landmarks`). That is a subset of what the path would
accept, so the estimate is at least the path-based one's on the same landmarks.

h = (landmarks not accepted) + (landmarks *required again*: accepted, false in the state,
and either a goal or necessary for a landmark not accepted yet), each landmark weighing
the cost of its cheapest achiever (1 on unit-cost tasks). Not admissible: one operator
can achieve several landmarks.
"""

from __future__ import annotations

import math
from typing import ClassVar


from strips_evaluators.heuristics.exploration import holds
from strips_evaluators.heuristics.landmarks import LandmarkGraph, find_landmarks
from strips_evaluators.heuristics.relaxation import RelaxedTask, facts_in, relax
from strips_framework.capabilities import PREFERRED_OPERATORS
from strips_framework.grounding.task import GroundTask
from strips_framework.options import Configurable
from strips_framework.records import Record


class LandmarkCountEstimator(Record):
    graph: LandmarkGraph
    goal_mask: int
    #: Facts whose label holds a landmark: the ones worth looking at in a state.
    informative: int
    #: Landmarks of the initial state: accepted on every path.
    initially: int
    #: Cost of each landmark's cheapest achiever; None on unit-cost tasks (all 1).
    weight: list[int] | None
    #: The relaxed task: real operators of relaxed ones and their applicability masks.
    relaxed: RelaxedTask

    __slots__ = ("graph", "goal_mask", "informative", "initially", "weight", "relaxed")

    def __init__(
        self,
        graph: LandmarkGraph,
        goal_mask: int,
        informative: int,
        initially: int,
        weight: list[int] | None,
        relaxed: RelaxedTask,
    ) -> None:
        self.graph = graph
        self.goal_mask = goal_mask
        self.informative = informative
        self.initially = initially
        self.weight = weight
        self.relaxed = relaxed

    def estimate(self, state: int) -> float:
        return self._count(state)[0]

    def estimate_with_preferred(self, state: int) -> tuple[float, list[int]]:
        """Preferred: applicable operators that achieve a landmark that is required again,
        or one not accepted whose predecessors (the landmarks in its label) all are, as
        Fast Downward prefers achievers of such "interesting" landmarks."""
        value, missing, again = self._count(state)
        if not missing and not again:
            return value, []
        graph, relaxed = self.graph, self.relaxed
        operator = relaxed.operator
        label = graph.label
        ready = [fact for fact in facts_in(missing) if label[fact] & missing == 1 << fact]
        preferred = {
            operator[op]
            for fact in ready + facts_in(again)
            for op in graph.achievers[fact]
            if holds(relaxed, op, state)
        }
        return value, sorted(preferred)

    def _count(self, state: int) -> tuple[float, int, int]:
        """The estimate, the landmarks not accepted and those required again."""
        graph = self.graph
        if not graph.solvable:
            return math.inf, 0, 0
        if state & self.goal_mask == self.goal_mask:
            return 0, 0, 0
        label, landmarks = graph.label, graph.landmarks
        accepted = self.initially
        for fact in facts_in(state & self.informative):
            accepted |= label[fact]
        missing = landmarks & ~accepted
        needed = self.goal_mask
        necessary = graph.necessary
        for fact in facts_in(missing):
            needed |= necessary[fact]
        again = accepted & landmarks & needed & ~state
        counted = missing | again
        if self.weight is None:
            return counted.bit_count(), missing, again
        weight = self.weight
        return sum(weight[fact] for fact in facts_in(counted)), missing, again


class LandmarkCountHeuristic(Configurable):
    """lmcount: landmarks still to reach or required again; preferred operators.

    Landmarks are Zhu & Givan's, from the initial state; each weighs its cheapest
    achiever's cost. Acceptance is inferred from the state through the landmark labels
    (no search-path memory). Not admissible. Preferred operators: applicable achievers of
    the next landmarks. O(state facts + missing landmarks) big-int operations per state,
    after a one-off label propagation."""

    name: ClassVar[str] = "lmcount"
    capabilities: ClassVar[frozenset[str]] = frozenset({PREFERRED_OPERATORS})
    admissible: ClassVar[bool] = False

    def for_task(self, task: GroundTask) -> LandmarkCountEstimator:
        relaxed = relax(task)
        graph = find_landmarks(relaxed, task.init, task.derived)
        informative = 0
        for fact, fact_label in enumerate(graph.label):
            if fact_label & graph.landmarks:
                informative |= 1 << fact
        weight = None
        if not relaxed.unit_cost:
            weight = [min((relaxed.cost[op] for op in ops), default=0) for ops in graph.achievers]
        return LandmarkCountEstimator(
            graph=graph,
            goal_mask=task.goal_mask,
            informative=informative,
            initially=graph.landmarks & task.init,
            weight=weight,
            relaxed=relaxed,
        )
