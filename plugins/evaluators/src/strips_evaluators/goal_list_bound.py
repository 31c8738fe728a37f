"""An admissible and consistent lower bound on the operators still to be applied."""

from __future__ import annotations

from typing import ClassVar

from strips_framework.capabilities import ADMISSIBLE
from strips_framework.means_ends.features import subgoals
from strips_framework.means_ends.node import Node
from strips_framework.options import Configurable


class GoalListBound(Configurable):
    """Admissible A* score: operators applied, plus one per goal left and unproved goal.

    Score = operators applied so far + h, where
    h = (goals on the goal list - 1) + (1 if the first goal is unproved else 0).

    Why h never overestimates the operators still needed on any plan through the node:

    - every goal but G0 is the precondition of an operator (``Goal.operator``) that a
      solution below this node applies after proving it: that is the only way a goal
      leaves the goal list; these operators are distinct;
    - if the first goal is unproved (the node has a difference) the model must change
      before it can be proved, since models change only by operator applications and the
      prover answers alike on equal models; that operator is applied before the first
      goal's own operator, so it is not one of the above.

    On a forward strategy, whose goal list is just (G0,), this is the unit bound: 1 unless
    the goal holds. It is also consistent (an application lowers h by at most 1 and costs
    1; a subgoal costs 0 and never lowers h), so strategies that prune revisited models
    stay optimal. The bound assumes a node's first goal is tried once per model, as both
    builtin strategies do; a strategy that retried it with more effort would break it.
    """

    name: ClassVar[str] = "astar-goals"
    admissible: ClassVar[bool] = True
    capabilities: ClassVar[frozenset[str]] = frozenset({ADMISSIBLE})

    def evaluate(self, node: Node) -> float:
        unproved = 1 if node.difference is not None else 0
        return float(node.cost + subgoals(node) + unproved)

    def parts(self, node: Node) -> dict[str, float]:
        """g and the two terms of h, by name (the explorer page shows them)."""
        return {"cost": node.cost, "goals": subgoals(node),
                "unproved": 1 if node.difference is not None else 0}
