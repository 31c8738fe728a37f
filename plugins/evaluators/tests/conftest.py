"""Hand-built search nodes for the evaluator tests and ground tasks for the heuristic tests."""

from __future__ import annotations

from collections.abc import Callable, Sequence

import pytest

from strips_framework.grounding.task import GroundAxiom, GroundOperator, GroundTask, mask_of
from strips_framework.means_ends.node import Node
from strips_framework.testing.nodes import hand_built_node

NodeFactory = Callable[..., Node]


@pytest.fixture
def make_node() -> NodeFactory:
    """:func:`strips_framework.testing.nodes.hand_built_node`: ``make_node(subgoals=[...],
    difference=[sizes] | None, cost=, successors=, pending=)``."""
    return hand_built_node


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
