"""Hand-built search nodes for the evaluator tests."""

from __future__ import annotations

from collections.abc import Callable, Sequence

import pytest

from strips_framework.logic.clauses import Clause
from strips_framework.logic.formulas import And, Atomic, Formula
from strips_framework.logic.terms import Param
from strips_framework.operators import OperatorInstance
from strips_framework.problem import OperatorSchema
from strips_framework.search.node import Difference, Goal, Node, RelevantInstance
from strips_framework.world import InitialModel, WorldModel

M0 = WorldModel(InitialModel([]))
STEP = OperatorSchema("step", [], Atomic(("READY",)), [("DONE",)], [])
STEP_INSTANCE = OperatorInstance(STEP, [])
G0 = Goal(Atomic(("DONE",)))

NodeFactory = Callable[..., Node]


def _formula(goal: Formula | str) -> Formula:
    """``"A B"`` is the conjunction of the 0-ary atoms ``A`` and ``B``."""
    if not isinstance(goal, str):
        return goal
    parts = [Atomic((name,)) for name in goal.split()]
    return parts[0] if len(parts) == 1 else And(parts)


def clause(size: int) -> Clause:
    return Clause([(False, (f"P{i}", Param("m"))) for i in range(size)])


@pytest.fixture
def make_node() -> NodeFactory:
    """``make_node(subgoals=[...], difference=[sizes] | None, cost=, successors=, pending=)``.

    ``subgoals`` lists the goals above G0, first goal first, as formulas or as strings of
    predicate names (``"A B"``); ``difference`` lists clause sizes (``None``: first goal
    proved); ``pending`` lists resolvent sizes, next instance first.
    """

    def build(
        subgoals: Sequence[Formula | str] = (),
        difference: Sequence[int] | None = (1,),
        cost: int = 0,
        successors: int = 0,
        pending: Sequence[int] = (),
    ) -> Node:
        goals = tuple(Goal(_formula(g), STEP_INSTANCE) for g in subgoals) + (G0,)
        return Node(
            id=0,
            model=M0,
            goals=goals,
            parent=None,
            plan=(STEP_INSTANCE,) * cost,
            difference=None if difference is None else Difference(map(clause, difference)),
            pending=[RelevantInstance(STEP_INSTANCE, clause(n)) for n in pending],
            successors_generated=successors,
        )

    return build
