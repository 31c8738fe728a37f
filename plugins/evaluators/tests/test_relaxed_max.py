"""relaxed-max: never above the true cost on any node of the kit's small tasks, and a real
guide (the light task's tree shrinks, its plan stays optimal)."""

from __future__ import annotations

import math

import pytest

from strips_evaluators.relaxed_max import RelaxedMaxEvaluator
from strips_framework.logic.cnf import SkolemNames
from strips_framework.means_ends.node import Difference, Goal, Node
from strips_framework.planner import Planner
from strips_framework.testing.search_checks import planner_for, recorded_search, state_space
from strips_framework.worldmodel.world import WorldModel, initial_model

PROBLEMS = ("three-boxes", "robot-light", "robot-door")


@pytest.mark.parametrize("strategy", ["model-astar", "means-ends"])
@pytest.mark.parametrize("problem", PROBLEMS)
def test_every_node_scores_at_most_its_cheapest_completion(strategy, problem):
    planner = planner_for("evaluator", RelaxedMaxEvaluator, {"strategy": strategy})
    result, recorder = recorded_search(planner, problem)
    assert result.plan is not None
    space = state_space(problem)
    tight = 0
    for node, score in recorder.scores:
        state = frozenset(node.model.facts())
        true_cost = node.cost + space.cost_to_go(state, node.goals)
        assert score <= true_cost + 1e-9, (node.id, score, true_cost)
        tight += score == true_cost
    assert tight > 0  # and it is a bound worth having: some nodes are scored exactly
    if strategy == "model-astar":
        assert result.cost == space.optimum


def test_the_layer_beats_the_goal_list_bound_on_the_root():
    """At the light task's root the goal-list bound says 1; the goal holds in layer 3
    (goto2(BOX1); then, relaxed, pushto and climbonbox at once; turnonlight), one below
    the optimum of 4."""
    planner = planner_for("evaluator", RelaxedMaxEvaluator, {"strategy": "model-astar"})
    result, recorder = recorded_search(planner, "robot-light")
    root_score = next(score for node, score in recorder.scores if node.parent is None)
    assert root_score == 3
    assert state_space("robot-light").optimum == 4
    assert result.cost == 4


def test_an_unreachable_goal_scores_infinity(tmp_path):
    path = tmp_path / "dead.strips"
    path.write_text(
        "problem dead\nconstants a\nfacts\n  P(a)\n"
        "operator make(x)\n  pre    Q(x)\n  add    G(x)\ngoal G(a)\n"
    )
    problem = Planner.create().load(path)
    initial = initial_model(problem, SkolemNames())
    scorer = RelaxedMaxEvaluator().for_problem(problem.operators, initial)
    root = Node(0, WorldModel(initial), (Goal(problem.goal),), None, difference=Difference(()))
    assert scorer.evaluate(root) == math.inf
