"""Time the paper's tasks for every registered prover x evaluator pair (means-ends).

    .venv/bin/python -m pytest benchmarks/bench_paper_tasks.py --benchmark-columns=min,mean,rounds

Each benchmark also records the paper's Table 2 figures in ``extra_info`` (shown with
``--benchmark-json``). In the normal test run every case runs once, as a smoke test.
"""

from pathlib import Path

import pytest

from strips_framework.config import Config
from strips_framework.planner import Planner
from strips_framework.plugins import Registry

EXAMPLES = Path(__file__).resolve().parents[1] / "examples"
TASKS = ["three-boxes", "robot-world/light", "robot-world/boxes", "robot-world/other-room"]
REGISTRY = Registry.from_plugins()
PAIRS = [(p, e) for p in REGISTRY.names("prover") for e in REGISTRY.names("evaluator")]


@pytest.mark.parametrize("task", TASKS)
@pytest.mark.parametrize(("prover", "evaluator"), PAIRS)
def test_paper_task(benchmark, task, prover, evaluator):
    config = Config.from_dict({
        "strategy": "means-ends", "prover": prover, "evaluator": evaluator,
        "limits": {"nodes": 300, "time": 30},
    })
    planner = Planner(REGISTRY, config)
    problem = planner.load(EXAMPLES / f"{task}.strips")
    result = benchmark.pedantic(planner.solve, args=(problem,), rounds=1, iterations=1)
    benchmark.extra_info.update(status=result.status, **result.statistics.as_dict())
    assert result.status in {"solved", "node-limit", "exhausted", "time-limit"}
    if evaluator == "paper":
        assert result.solved
