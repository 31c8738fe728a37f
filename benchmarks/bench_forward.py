"""Forward search speed: states expanded per second on IPC tasks, per strategy.

    .venv/bin/python -m pytest benchmarks/bench_forward.py --benchmark-columns=min,mean,rounds
    .venv/bin/python benchmarks/bench_forward.py            # the scaling table below

The pytest cases time one search (grounding excluded) on a small task per configuration,
so the normal test run keeps them as a smoke test. Run as a script, it prints for the
smallest and largest gripper and logistics tasks the ground operators, grounding time,
and expansions and generated states per second of lazy GBFS + hFF and of breadth-first
search (capped at 20000 expansions): the search's own cost per state, and the
heuristic's on top. Without ``shared/bench/ipc`` everything skips.
"""

from __future__ import annotations

import sys
import time

import pytest
from shared_bench import shared_bench

from strips_framework.grounding import ground
from strips_framework.grounding.task import GroundTask
from strips_framework.limits import Limits
from strips_framework.pddl import find_domain, load_task
from strips_framework.plugin.registry import Registry
from strips_framework.result import Result

CONFIGS = [("lazy-gbfs", "ff"), ("gbfs", "ff"), ("astar", "lmcut"), ("breadth-first", "blind")]
SCALING = ["gripper/task01", "gripper/task20", "logistics/task01", "logistics/task28"]


BENCH = shared_bench("ipc")


def _task(name: str) -> GroundTask:
    if BENCH is None:
        pytest.skip("shared/bench/ipc is not available")
    problem = BENCH / f"{name}.pddl"
    return ground(load_task(find_domain(problem), problem))


def _search(registry: Registry, task: GroundTask, strategy: str, heuristic: str,
            limits: Limits) -> Result:
    estimator = registry.get("heuristic", heuristic).cls().for_task(task)
    return registry.get("ground-strategy", strategy).cls().search_task(task, estimator, limits)


@pytest.mark.parametrize(("strategy", "heuristic"), CONFIGS)
def test_search_logistics_task01(benchmark, strategy, heuristic):
    task, registry = _task("logistics/task01"), Registry.from_plugins()
    result = benchmark.pedantic(_search, args=(registry, task, strategy, heuristic, Limits()),
                                rounds=3, iterations=1)
    assert result.solved


def main(names: list[str]) -> None:
    registry = Registry.from_plugins()
    print("| task | operators | ground s | config | expanded | expanded/s | generated/s |")
    print("| --- | ---: | ---: | --- | ---: | ---: | ---: |")
    for name in names:
        started = time.process_time()
        task = _task(name)
        grounded = time.process_time() - started
        for strategy, heuristic in [("lazy-gbfs", "ff"), ("breadth-first", "blind")]:
            result = _search(registry, task, strategy, heuristic, Limits(expansions=20_000))
            s = result.statistics
            print(f"| {name} | {s.operators} | {grounded:.3f} | {strategy}+{heuristic} | "
                  f"{s.expanded} | {s.expanded / s.search_seconds:.0f} | "
                  f"{s.generated / s.search_seconds:.0f} |")


if __name__ == "__main__":
    main(sys.argv[1:] or SCALING)
