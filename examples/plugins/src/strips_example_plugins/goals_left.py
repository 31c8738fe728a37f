"""An admissible evaluator: operators applied, plus one per goal above G0."""

from __future__ import annotations

from typing import ClassVar

from strips_framework.capabilities import ADMISSIBLE
from strips_framework.means_ends.node import Node
from strips_framework.options import Configurable, Option


class GoalsLeft(Configurable):
    """Operators applied plus goals left above G0, ties broken towards deeper nodes.

    Each goal above G0 is the precondition of an operator the plan must still apply, so
    the count never exceeds the cost still needed: the score is admissible.
    ``tie_break`` (< 1) is subtracted per goal to prefer nodes that subgoaled further among
    equals; 0 turns it off. A score lowered this way stays admissible.
    """

    name: ClassVar[str] = "goals-left"
    capabilities: ClassVar[frozenset[str]] = frozenset({ADMISSIBLE})
    admissible: ClassVar[bool] = True

    options = (
        Option("tie_break", float, 0.01, minimum=0, check=lambda v: None if v < 1 else "a value < 1",
               doc="subtracted per goal, to prefer deeper nodes among equals"),
    )
    tie_break: float

    def evaluate(self, node: Node) -> float:
        goals_left = len(node.goals) - 1
        return node.cost + goals_left * (1 - self.tie_break)
