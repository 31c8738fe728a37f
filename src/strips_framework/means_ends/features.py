"""Measurements of a search node that several evaluators combine.

Kept in one place so that "goals left" and "unproved literals" mean the same thing in
every evaluator that reports them, the core's (:mod:`.evaluator`) and the plugins'.
"""

from __future__ import annotations

from strips_framework.means_ends.node import Node


def subgoals(node: Node) -> int:
    """Goals on the goal list besides the top goal G0 (the last one, on every list).

    Each one is the precondition of an operator that must still be applied before G0 can be
    tried again, so it measures both remaining work and how deep the subgoaling went.
    """
    return len(node.goals) - 1


def unproved_literals(node: Node) -> int:
    """Literals of the smallest clause of the difference; 0 when the first goal was proved.

    The smallest clause is the partial proof closest to completion: each of its literals
    must still be resolved away, by a fact of a later model or by an operator's add list.
    """
    return node.difference.complexity if node.difference is not None else 0
