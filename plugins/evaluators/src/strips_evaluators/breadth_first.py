"""Blind search: the score is the number of operators applied so far."""

from __future__ import annotations

from typing import ClassVar

from strips_framework.capabilities import ADMISSIBLE
from strips_framework.means_ends.node import Node
from strips_framework.options import Configurable


class BreadthFirst(Configurable):
    """Blind search: the score is the operators applied so far (g, with h = 0).

    With first-in-first-out tie-breaking this explores world models in order of plan length,
    i.e. breadth-first; in an A*-style strategy it is uniform-cost search. Admissible:
    h = 0 never overestimates, so the first plan found that way is a shortest one. Use it
    as the optimality baseline, on small tasks; it grows exponentially with plan length.
    """

    name: ClassVar[str] = "breadth-first"
    admissible: ClassVar[bool] = True
    capabilities: ClassVar[frozenset[str]] = frozenset({ADMISSIBLE})

    def evaluate(self, node: Node) -> float:
        return float(node.cost)
