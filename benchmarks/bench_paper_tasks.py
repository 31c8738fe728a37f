"""Time the paper's tasks under every registered strategy x prover x evaluator.

    .venv/bin/python -m pytest benchmarks/bench_paper_tasks.py --benchmark-only

Only combinations that can run are collected: the registry is asked which names exist,
and a combination whose config does not build, or whose prover does not handle what the
task uses, is left out (a skip would say nothing). Each benchmark records the paper's
Table 2 figures in ``extra_info`` (shown with ``--benchmark-json``). In the normal test
run (benchmarks disabled) every case runs once, and only the paper's own combination
(means-ends, paper evaluator) runs every task: the others run the smallest one, which
keeps them working without costing the test suite minutes (z3 under model-astar needs
about a second a node).
"""

import itertools
import warnings
from functools import cache
from pathlib import Path

import pytest

from strips_framework.errors import StripsError
from strips_framework.planner import Planner
from strips_framework.plugin.checks import check_problem
from strips_framework.plugin.config import Config
from strips_framework.plugin.registry import Registry
from strips_framework.worldmodel.problem import Problem

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
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        return Planner.create(Config.from_dict(data))


@cache
def _problem(task: str) -> Problem:
    return REGISTRY.loader_for(".strips").cls().load(EXAMPLES / f"{task}.strips")


def _runs(strategy: str, prover: str, evaluator: str, task: str) -> bool:
    """True when the combination builds and its prover handles what ``task`` uses."""
    try:
        planner = _planner(strategy, prover, evaluator)
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")
            check_problem(_problem(task), planner.registry, planner.config)
    except StripsError:
        return False
    return True


def pytest_generate_tests(metafunc: pytest.Metafunc) -> None:
    """The runnable cases; with benchmarks disabled (the normal test run), only the
    paper's combination runs every task, the others the smallest one."""
    config = metafunc.config
    smoke = config.getoption("benchmark_disable") and not config.getoption("benchmark_enable")
    cases = [
        (strategy, prover, evaluator, task)
        for strategy, prover, evaluator in COMBINATIONS
        for task in TASKS
        if not (smoke and (strategy, evaluator) != PAPER_COMBINATION and task != TASKS[0])
        and _runs(strategy, prover, evaluator, task)
    ]
    metafunc.parametrize(("strategy", "prover", "evaluator", "task"), cases)


def test_paper_task(benchmark, task, strategy, prover, evaluator):
    planner = _planner(strategy, prover, evaluator)
    problem = planner.load(EXAMPLES / f"{task}.strips")
    result = benchmark(lambda: planner.solve(problem))
    benchmark.extra_info.update(status=result.status, **result.statistics.as_dict())
    assert result.status in {"solved", "node-limit", "exhausted", "time-limit"}
    if strategy == "means-ends" and evaluator == "paper":
        assert result.solved
