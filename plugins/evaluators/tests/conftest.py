"""Hand-built search nodes for the evaluator tests and ground tasks for the heuristic tests."""

from __future__ import annotations

from collections.abc import Callable, Sequence

import pytest

from strips_framework.grounding.task import GroundAxiom, GroundOperator, GroundTask, mask_of
from strips_framework.logic.clauses import Clause
from strips_framework.logic.formulas import And, Atomic, Formula
from strips_framework.logic.terms import Param
from strips_framework.means_ends.node import Difference, Goal, Node, RelevantInstance
from strips_framework.worldmodel.operators import OperatorInstance
from strips_framework.worldmodel.problem import OperatorSchema
from strips_framework.worldmodel.world import InitialModel, WorldModel

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


TaskFactory = Callable[..., GroundTask]


@pytest.fixture
def make_task() -> TaskFactory:
    """``make_task(operators, init, goal, axioms=(), uses_costs=False)`` builds a ground task
    from fact names: ``operators`` lists ``(name, pre, add, delete[, cost[, pre_neg]])``,
    each fact list a space-separated string; ``axioms`` lists ``(head, body[, body_neg])``;
    ``init`` and ``goal`` are strings. Facts are numbered in order of first mention; the
    initial state gets its derived facts by one pass over the axioms (enough for tests).
    """

    def build(
        operators: Sequence[tuple],
        init: str,
        goal: str,
        axioms: Sequence[tuple] = (),
        uses_costs: bool = False,
    ) -> GroundTask:
        numbers: dict[str, int] = {}

        def facts(names: str) -> tuple[int, ...]:
            return tuple(numbers.setdefault(name, len(numbers)) for name in names.split())

        ground_operators = []
        for name, pre, add, delete, *rest in operators:
            cost = rest[0] if rest else 1
            pre_neg = facts(rest[1]) if len(rest) > 1 else ()
            ground_operators.append(
                GroundOperator(name, facts(pre), facts(add), facts(delete), cost, pre_neg)
            )
        ground_axioms = [
            GroundAxiom(facts(head)[0], facts(body), facts(rest[0]) if rest else ())
            for head, body, *rest in axioms
        ]
        state = mask_of(facts(init))
        for axiom in ground_axioms:
            if all(state >> f & 1 for f in axiom.body) and not any(
                state >> f & 1 for f in axiom.body_neg
            ):
                state |= 1 << axiom.head
        goal_facts = facts(goal)
        return GroundTask(
            name="test",
            facts=tuple(numbers),
            operators=tuple(ground_operators),
            init=state,
            goal=goal_facts,
            axioms=tuple(ground_axioms),
            derived=tuple(axiom.head for axiom in ground_axioms),
            uses_costs=uses_costs,
        )

    return build


#: Small tasks whose heuristic values are worked out by hand in test_heuristic_values.py.
SMALL_TASKS: dict[str, dict] = {
    # a -> b -> c -> d
    "chain": {
        "operators": [("ab", "a", "b", "a"), ("bc", "b", "c", "b"), ("cd", "c", "d", "c")],
        "init": "a",
        "goal": "d",
    },
    # two independent subgoals p, q joined by a last step
    "fork": {
        "operators": [("sp", "s", "p", ""), ("sq", "s", "q", ""), ("join", "p q", "g", "")],
        "init": "s",
        "goal": "g",
    },
    # a shared subgoal m for two goal facts: hadd counts it twice, hFF once
    "shared": {
        "operators": [("sm", "s", "m", "s"), ("m1", "m", "g1", ""), ("m2", "m", "g2", "")],
        "init": "s",
        "goal": "g1 g2",
    },
    # a direct expensive step against a cheap detour
    "costs": {
        "operators": [
            ("direct", "s", "g", "", 5),
            ("to-m", "s", "m", "", 1),
            ("m-g", "m", "g", "", 2),
        ],
        "init": "s",
        "goal": "g",
        "uses_costs": True,
    },
    # the goal is a derived fact; an operator without preconditions starts the chain
    "axiom": {
        "operators": [("make-p", "", "p", ""), ("pq", "p", "q", "")],
        "axioms": [("d", "p q")],
        "init": "",
        "goal": "d",
    },
    # "careful" needs "q" false, which the relaxation ignores; "unlock" deletes "q"
    "negative": {
        "operators": [("careful", "s", "g", "", 1, "q"), ("unlock", "q", "", "q")],
        "init": "s q",
        "goal": "g",
    },
    # "g" has no achiever at all
    "dead": {"operators": [("ab", "a", "b", "")], "init": "a", "goal": "b g"},
}


@pytest.fixture
def small_task(make_task: TaskFactory) -> Callable[[str], GroundTask]:
    return lambda name: make_task(**SMALL_TASKS[name])
