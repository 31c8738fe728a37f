from __future__ import annotations

from strips_evaluators.goal_list_bound import GoalListBound


def test_forward_search_gets_the_unit_bound(make_node) -> None:
    evaluator = GoalListBound()
    assert evaluator.evaluate(make_node(difference=[4], cost=2)) == 3
    assert evaluator.evaluate(make_node(difference=None, cost=2)) == 2


def test_each_subgoal_still_needs_its_operator(make_node) -> None:
    evaluator = GoalListBound()
    # Two subgoals, first unproved: two operators to apply, and one to make the first
    # provable.
    assert evaluator.evaluate(make_node(subgoals=["A", "B"], difference=[1], cost=1)) == 4
    # First subgoal proved: its operator and the other subgoal's remain.
    assert evaluator.evaluate(make_node(subgoals=["A", "B"], difference=None, cost=1)) == 3
    assert GoalListBound.admissible


def test_bound_is_consistent_along_means_ends_steps(make_node) -> None:
    """f never drops along an edge: subgoaling costs 0, applying costs 1 and pops a goal."""
    f = GoalListBound().evaluate
    parent = make_node(subgoals=["A"], difference=[2], cost=1)
    for child in (
        make_node(subgoals=["B", "A"], difference=[1], cost=1),  # unproved subgoal
        make_node(subgoals=["A"], difference=[1], cost=2),  # B proved and applied
        make_node(subgoals=[], difference=[1], cost=3),  # then A proved and applied
        make_node(subgoals=[], difference=None, cost=3),  # ... which reached G0
    ):
        assert f(child) >= f(parent)
