"""Evaluations per second of every registered state heuristic on a few IPC tasks.

    .venv/bin/python -m pytest benchmarks/bench_heuristics.py --benchmark-columns=min,mean,rounds

Each case evaluates the same 100 states (seeded random walks from the initial state) with
``estimate_with_preferred``, the call greedy search makes; ``extra_info`` records the
evaluations per second of the fastest round. In the normal test run every case runs three rounds,
as a smoke test. Without ``shared/bench/ipc`` beside the repository the cases skip.
For pyperplan's speed on the same states see ``heuristics_vs_pyperplan.py``.
"""

from __future__ import annotations

import random

import pytest
from shared_bench import shared_bench

from strips_framework.grounding import ground
from strips_framework.grounding.axioms import AxiomEvaluator
from strips_framework.grounding.task import GroundTask
from strips_framework.pddl import find_domain, load_task
from strips_framework.plugin.registry import Registry

TASKS = ["blocks/task05", "logistics/task05", "gripper/task05"]
STATES = 100
REGISTRY = Registry.from_plugins()


BENCH = shared_bench("ipc")


def random_walk_states(task: GroundTask, count: int, seed: int = 1) -> list[int]:
    rng = random.Random(seed)
    evaluate = AxiomEvaluator(task).evaluate
    states = [task.init]
    while len(states) < count:
        state = task.init
        for _ in range(rng.randint(1, 40)):
            applicable = [op for op in task.operators if op.applicable(state)]
            if not applicable:
                break
            state = evaluate(rng.choice(applicable).apply(state))
        states.append(state)
    return states


@pytest.fixture(scope="module", params=TASKS)
def task_and_states(request) -> tuple[GroundTask, list[int]]:
    if BENCH is None:
        pytest.skip("shared/bench/ipc not found")
    problem = BENCH / f"{request.param}.pddl"
    task = ground(load_task(find_domain(problem), problem))
    return task, random_walk_states(task, STATES)


@pytest.mark.parametrize("heuristic", REGISTRY.names("heuristic"))
def test_heuristic_speed(benchmark, task_and_states, heuristic) -> None:
    task, states = task_and_states
    estimator = REGISTRY.get("heuristic", heuristic).cls().for_task(task)
    evaluate = estimator.estimate_with_preferred
    values = benchmark.pedantic(lambda: [evaluate(s) for s in states], rounds=3, iterations=1)
    if benchmark.stats is not None:
        benchmark.extra_info["evaluations_per_second"] = STATES / benchmark.stats.stats.min
    assert values[0][0] == estimator.estimate(task.init)
