"""Measurements of a search node that several evaluators combine.

Kept in one place so that "goals left" and "unproved literals" mean the same thing in
every evaluator that reports them, the core's (:mod:`.evaluator`) and the plugins'.
"""

from __future__ import annotations

from strips_framework.logic.formulas import Atomic, conjuncts
from strips_framework.logic.terms import EQUALITY, is_ground
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


def top_goal_atoms_missing(node: Node) -> int:
    """Ground atoms among the conjuncts of the top goal G0 that are not facts of the
    node's model: how much of the task is still to be done, wherever the node's goal
    list stands.

    The first goal's difference says how far the node is from its next application, not
    from G0: without this, a subgoal one step from an application counts the same in a
    model where three of four goal atoms hold as in M0. Conjuncts with variables are left
    out, and an atom only an axiom concludes (never a fact) always counts: either way
    alike in every model, so neither orders nodes differently.
    """
    return sum(
        1
        for part in conjuncts(node.goals[-1].formula)
        if isinstance(part, Atomic)
        and part.atom[0] != EQUALITY
        and is_ground(part.atom)
        and not node.model.holds(part.atom)
    )
