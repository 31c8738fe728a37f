"""Greedy-leaning best-first: goals left plus unproved literals, plus a share of the cost."""

from __future__ import annotations

from typing import ClassVar

from strips_framework.means_ends.features import subgoals, unproved_literals
from strips_framework.means_ends.node import Node
from strips_framework.means_ends.weights import weight
from strips_framework.options import Configurable


class GoalCount(Configurable):
    """Goals left and unproved literals, plus ``cost_weight`` times the operators applied.

    Score = h + ``cost_weight`` * operators applied so far, where
    h = (goals on the goal list - 1) + literals in the smallest difference clause.
    h counts the subgoals still to be achieved and the unproved literals of the best
    partial proof of the first goal: each usually needs at least one operator. It is not
    admissible, since one operator's add list can resolve away several literals (or a later
    model can hold them). ``cost_weight`` = 1 gives weighted-A*-like behaviour; 0 gives
    greedy best-first, fast but with longer plans.

    The score ignores how many successors a node has made, so under the means-ends
    strategy a node keeps winning until its relevant instances are used up: every
    alternative at a choice point is opened before the search goes deeper.
    """

    name: ClassVar[str] = "goal-count"
    admissible: ClassVar[bool] = False
    capabilities: ClassVar[frozenset[str]] = frozenset()

    options = (weight("cost_weight", 1.0, "times the operators applied so far"),)
    cost_weight: float

    def evaluate(self, node: Node) -> float:
        return subgoals(node) + unproved_literals(node) + self.cost_weight * node.cost

    def parts(self, node: Node) -> dict[str, float]:
        """The terms of the score, by name (the explorer page shows them)."""
        return {"goals": subgoals(node), "unproved literals": unproved_literals(node),
                "cost": self.cost_weight * node.cost}
