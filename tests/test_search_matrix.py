"""Every registered strategy x evaluator pair solves a small problem, and its plan replays
in the independent simulator (so a new strategy or evaluator is tested the day it is
registered)."""

from pathlib import Path

import pytest

from strips_framework.plugin.registry import Registry
from strips_framework.worldmodel.simulate import replay

DATA = Path(__file__).resolve().parent / "data"
REGISTRY = Registry.from_plugins()
#: The strategies over world models (those over ground tasks are tested in search_forward).
WORLD_MODEL_STRATEGIES = REGISTRY.names("strategy")
PAIRS = [
    (strategy, evaluator)
    for strategy in WORLD_MODEL_STRATEGIES
    for evaluator in REGISTRY.names("evaluator")
]


@pytest.mark.parametrize(("strategy", "evaluator"), PAIRS)
def test_pair_solves_and_plan_replays(make_planner, strategy, evaluator):
    planner = make_planner(strategy=strategy, evaluator=evaluator, limits={"time": 60})
    problem = planner.load(DATA / "push-one-box.strips")
    result = planner.solve(problem)
    assert result.solved, result.status
    steps = [str(step) for step in result.plan]
    outcome = replay(problem, steps)
    assert outcome.valid, outcome.message
    assert 2 <= len(steps) <= 4  # two steps are needed; a detour or two is tolerated
    statistics = result.statistics
    assert statistics.path_applications == 2
    assert statistics.nodes >= statistics.path_nodes >= 3


def test_optimal_strategy_with_admissible_evaluator_is_optimal_on_the_matrix_problem(make_planner):
    planner = make_planner(strategy="model-astar", evaluator="breadth-first")
    result = planner.solve(planner.load(DATA / "push-one-box.strips"))
    assert len(result.plan) == 2
