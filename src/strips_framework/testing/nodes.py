"""Hand-built search nodes, for testing a node evaluator's score term by term.

An evaluator scores a :class:`~strips_framework.means_ends.node.Node` from its goal list,
difference, plan, pending instances and successor count; a search makes such nodes only
as a side effect, so a test of "each factor counts with its weight" builds them here
instead, with every measured quantity given directly.
"""

from __future__ import annotations

from collections.abc import Sequence

from strips_framework.logic.clauses import Clause
from strips_framework.logic.formulas import And, Atomic, Formula
from strips_framework.logic.terms import Param
from strips_framework.means_ends.node import Difference, Goal, Node, RelevantInstance
from strips_framework.worldmodel.operators import OperatorInstance
from strips_framework.worldmodel.problem import OperatorSchema
from strips_framework.worldmodel.world import InitialModel, WorldModel

#: The empty model every hand-built node has.
M0 = WorldModel(InitialModel([]))
#: The one operator every goal above G0 belongs to, and every plan step is.
STEP_INSTANCE = OperatorInstance(OperatorSchema("step", [], Atomic(("READY",)), [("DONE",)], []), [])
#: The top goal, last on every goal list.
G0 = Goal(Atomic(("DONE",)))


def hand_built_node(
    subgoals: Sequence[Formula | str] = (),
    difference: Sequence[int] | None = (1,),
    cost: int = 0,
    successors: int = 0,
    pending: Sequence[int] = (),
) -> Node:
    """A node with ``subgoals`` above G0, first goal first, as formulas or as strings of
    0-ary predicate names (``"A B"`` is ``A & B``); a difference of clauses of the sizes
    ``difference`` lists (``None``: the first goal was proved); ``cost`` operators
    applied; ``successors`` generated; relevant instances pending whose resolvents have
    the sizes ``pending`` lists, next instance first."""
    goals = tuple(Goal(_formula(g), STEP_INSTANCE) for g in subgoals) + (G0,)
    return Node(
        id=0,
        model=M0,
        goals=goals,
        parent=None,
        plan=(STEP_INSTANCE,) * cost,
        difference=None if difference is None else Difference(map(_clause, difference)),
        pending=[RelevantInstance(STEP_INSTANCE, _clause(n)) for n in pending],
        successors_generated=successors,
    )


def _formula(goal: Formula | str) -> Formula:
    if not isinstance(goal, str):
        return goal
    parts = [Atomic((name,)) for name in goal.split()]
    return parts[0] if len(parts) == 1 else And(parts)


def _clause(size: int) -> Clause:
    return Clause([(False, (f"P{i}", Param("m"))) for i in range(size)])
