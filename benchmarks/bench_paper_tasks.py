"""Time the paper's tasks under every registered strategy x prover x evaluator.

    .venv/bin/python -m pytest benchmarks/bench_paper_tasks.py --benchmark-only

Combinations that cannot work are skipped, not failed: the registry is asked which names
exist, a combination whose config does not build is skipped with the reason, and so is
one whose strategy refuses the task (e.g. a strategy for grounded PDDL tasks given a
first-order one). Each benchmark records the paper's Table 2 figures in ``extra_info``
(shown with ``--benchmark-json``). In the normal test run (benchmarks disabled) every
case runs once, and only the paper's own combination (means-ends, paper evaluator) runs
every task: the others run the smallest one, which keeps them working without costing the
test suite minutes (z3 under model-astar needs about a second a node).
"""

import itertools
from pathlib import Path

import pytest

from strips_framework.config import Config
from strips_framework.errors import StripsError
from strips_framework.planner import Planner
from strips_framework.plugins import Registry

EXAMPLES = Path(__file__).resolve().parents[1] / "examples"
TASKS = ["three-boxes", "robot-world/light", "robot-world/boxes", "robot-world/other-room"]
REGISTRY = Registry.from_plugins()
COMBINATIONS = list(itertools.product(
    REGISTRY.names("strategy"), REGISTRY.names("prover"), REGISTRY.names("evaluator")
))
pytestmark = pytest.mark.filterwarnings(r"ignore:.*with 'admissible' \(its first plan")
PAPER_COMBINATION = ("means-ends", "paper")

#: Means-ends analysis solves every task in under 350 nodes; forward search over world
#: models (A*) needs some 760 nodes and 10 s on the light task, so its cases (and those
#: of any other strategy) time the first 40.
NODES = {"means-ends": 350}


def _planner(strategy: str, prover: str, evaluator: str) -> Planner:
    limits = {"nodes": NODES.get(strategy, 40), "time": 30}
    data = {"strategy": strategy, "prover": prover, "evaluator": evaluator, "limits": limits}
    try:
        return Planner.create(Config.from_dict(data))
    except StripsError as error:
        pytest.skip(f"cannot be configured: {error}")


@pytest.mark.parametrize("task", TASKS)
@pytest.mark.parametrize(("strategy", "prover", "evaluator"), COMBINATIONS)
def test_paper_task(benchmark, task, strategy, prover, evaluator):
    if benchmark.disabled and (strategy, evaluator) != PAPER_COMBINATION and task != TASKS[0]:
        pytest.skip("smoke run: only the smallest task (--benchmark-only runs every task)")
    planner = _planner(strategy, prover, evaluator)
    problem = planner.load(EXAMPLES / f"{task}.strips")

    def solve():
        try:
            return planner.solve(problem)
        except StripsError as error:
            pytest.skip(f"{strategy} cannot search this task: {error}")

    result = benchmark(solve)
    benchmark.extra_info.update(status=result.status, **result.statistics.as_dict())
    assert result.status in {"solved", "node-limit", "exhausted", "time-limit"}
    if strategy == "means-ends" and evaluator == "paper":
        assert result.solved
