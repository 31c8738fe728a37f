from __future__ import annotations

import pytest

from strips_framework.options import OptionError

from strips_evaluators.breadth_first import BreadthFirst
from strips_evaluators.goal_count import GoalCount


def test_breadth_first_scores_operators_applied_only(make_node) -> None:
    evaluator = BreadthFirst()
    cheap = make_node(subgoals=["A B C", "D"], difference=[9], successors=4, pending=[5])
    dear = make_node(difference=None, cost=2)
    assert evaluator.evaluate(cheap) == 0
    assert evaluator.evaluate(dear) == 2
    assert BreadthFirst.admissible


def test_goal_count_adds_subgoals_unproved_literals_and_weighted_cost(make_node) -> None:
    node = make_node(subgoals=["A B", "C"], difference=[3, 2], cost=3, successors=7)
    assert GoalCount().evaluate(node) == 2 + 2 + 3
    assert GoalCount(cost_weight=0.5).evaluate(node) == 2 + 2 + 1.5
    assert GoalCount(cost_weight=0).evaluate(make_node(difference=None, cost=4)) == 0
    assert not GoalCount.admissible


def test_goal_count_prefers_nodes_nearer_a_proof(make_node) -> None:
    evaluator = GoalCount()
    near = make_node(subgoals=["A"], difference=[1])
    far = make_node(subgoals=["A", "B"], difference=[1])
    farther = make_node(subgoals=["A"], difference=[3])
    assert evaluator.evaluate(near) < evaluator.evaluate(far)
    assert evaluator.evaluate(near) < evaluator.evaluate(farther)


@pytest.mark.parametrize("value", [-0.1, "high"])
def test_goal_count_rejects_bad_cost_weight(value) -> None:
    with pytest.raises(OptionError, match="'cost_weight'"):
        GoalCount(cost_weight=value)
